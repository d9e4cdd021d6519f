// SPDX-License-Identifier: GPL-3.0-or-later
// The rules test_untranslated reads the window's texts by (text_scan.h), on their own: what
// reads the same in both languages, and how a text is cut into sentences.

#include "test_main.h"
#include "text_scan.h"

#include <QtTest>

using rigidlab::test::invariant;
using rigidlab::test::pieces;

class TestTextScan : public QObject {
    Q_OBJECT

private slots:
    // The check itself: what counts as the same in both languages.
    void invariantCheck_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<bool>("same");
        QTest::newRow("number") << QStringLiteral("0.25") << true;
        QTest::newRow("unit") << QStringLiteral("kg·m/s") << true;
        QTest::newRow("radians") << QStringLiteral("ω [rad/s]") << true;
        QTest::newRow("drift") << QStringLiteral("drift [%]") << true;
        QTest::newRow("symbol") << QStringLiteral("E_k [J]") << true;
        QTest::newRow("name") << QStringLiteral("RigidLab") << true;
        QTest::newRow("word") << QStringLiteral("Energy") << false;
        QTest::newRow("word with unit") << QStringLiteral("time [s]") << false;
        QTest::newRow("name in a sentence") << QStringLiteral("Euler drifts") << false;
    }
    void invariantCheck()
    {
        QFETCH(QString, text);
        QFETCH(bool, same);
        QCOMPARE(invariant(text), same);
    }

    void piecesAreSentences()
    {
        QCOMPARE(pieces(QStringLiteral("&Open scene...")),
                 QStringList{QStringLiteral("Open scene...")});
        QCOMPARE(
            pieces(QStringLiteral("<p>One. Two?</p><p>Three</p>")),
            (QStringList{QStringLiteral("One."), QStringLiteral("Two?"), QStringLiteral("Three")}));
        QCOMPARE(pieces(QStringLiteral("Runge–Kutta 4. řádu")),
                 QStringList{QStringLiteral("Runge–Kutta 4. řádu")});
        QCOMPARE(pieces(QStringLiteral("A puck — RigidLab")),
                 (QStringList{QStringLiteral("A puck"), QStringLiteral("RigidLab")}));
        QCOMPARE(pieces(QStringLiteral("a\nb")),
                 (QStringList{QStringLiteral("a"), QStringLiteral("b")}));
    }
};

RIGIDLAB_TEST_MAIN(TestTextScan)
#include "test_text_scan.moc"
