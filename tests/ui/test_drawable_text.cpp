// SPDX-License-Identifier: GPL-3.0-or-later
// Characters no font of the machine has are shown as a placeholder naming them, never lost:
// drawableText itself, and a lesson whose title, step title and text hold an emoji, in the
// window. Whether a font has a character is fontconfig's answer (fc-list), independent of Qt.
// (The worksheet PDF read back by pdftotext: test_worksheet_cli.)

#include "common/drawable_text.h"
#include "lesson_player/lesson_player.h"
#include "window/main_window.h"

#include "test_main.h"

#include <QFile>
#include <QLabel>
#include <QProcess>
#include <QTemporaryDir>
#include <QTextEdit>
#include <QtTest>

using namespace rigidlab;
using namespace rigidlab::ui;

namespace {

/// Whether fontconfig knows a font with the code point.
bool someFontHas(char32_t c)
{
    QProcess fc;
    fc.start(QStringLiteral("fc-list"),
             {QStringLiteral(":charset=") + QString::number(c, 16), QStringLiteral("family")});
    if (!fc.waitForFinished(30'000) || fc.exitCode() != 0)
        qFatal("fc-list failed (is fontconfig installed?)");
    return !fc.readAllStandardOutput().trimmed().isEmpty();
}

/// How `c` must appear: itself where a font has it, else its placeholder.
QString shown(char32_t c)
{
    return someFontHas(c) ? QString::fromUcs4(&c, 1)
                          : QStringLiteral("[U+%1]").arg(QString::number(c, 16).toUpper());
}

constexpr char32_t kCrab = 0x1F980;
constexpr char32_t kTestTube = 0x1F9EA;

} // namespace

class TestDrawableText : public QObject {
    Q_OBJECT
private slots:
    void placeholdersOnlyWhereNoFontHasIt()
    {
        const QFont font;
        const QString plain = QStringLiteral("Žofie Řeháková, 2.B: e = 0.8 ± 0.01 m·s⁻¹");
        QCOMPARE(drawableText(plain, font), plain);
        // Format characters draw nothing by design: kept (a name's bidirectional isolates,
        // an emoji's joiner and variation selector, line breaks).
        const QString format = QChar(0x2068) + QStringLiteral("Jana") + QChar(0x2069) +
                               QChar(0x200D) + QChar(0xFE0F) + QStringLiteral("\n");
        QCOMPARE(drawableText(format, font), format);
        const QString crab = QString::fromUcs4(&kCrab, 1);
        QCOMPARE(drawableText(QStringLiteral("Anna ") + crab, font),
                 QStringLiteral("Anna ") + shown(kCrab));
        QCOMPARE(canDraw(kCrab, font), someFontHas(kCrab));
        // A character of the private use area that no font of this machine has.
        const char32_t privateUse = 0x10FFFD;
        if (!someFontHas(privateUse))
            QCOMPARE(drawableText(QString::fromUcs4(&privateUse, 1), font),
                     QStringLiteral("[U+10FFFD]"));
    }

    void lessonTextsInTheWindow()
    {
        // A lesson whose title, step title and text hold emoji: the player shows each one,
        // or its placeholder, never an empty box.
        const QString crab = QString::fromUcs4(&kCrab, 1);
        const QString tube = QString::fromUcs4(&kTestTube, 1);
        const QString lesson =
            QStringLiteral(R"({"rigidlab-lesson": 1, "title": {"en": "Falling %1"},
                "steps": [{"title": {"en": "A drop %2"}, "text": {"en": ["Watch the crab %1 fall."]},
                "scene": {"rigidlab": 1, "bodies": [{"id": "ball",
                "shape": {"type": "circle", "radius": 0.1}, "position": [0, 1]}]}}]})")
                .arg(crab, tube);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("emoji.json"));
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(lesson.toUtf8());
        file.close();
        MainWindow w;
        QCOMPARE(w.openLesson(path, true), QString());
        QStringList labels;
        for (const QLabel* label : w.lessonPlayer().findChildren<QLabel*>())
            labels << label->text();
        QVERIFY2(labels.contains(QStringLiteral("Falling ") + shown(kCrab)),
                 qPrintable(labels.join(u'|')));
        QVERIFY2(labels.contains(QStringLiteral("A drop ") + shown(kTestTube)),
                 qPrintable(labels.join(u'|')));
        bool textShown = false;
        for (const QTextEdit* text : w.lessonPlayer().findChildren<QTextEdit*>())
            textShown = textShown || text->toPlainText().contains(QStringLiteral("crab ") +
                                                                  shown(kCrab) + " fall");
        QVERIFY(textShown);
    }
};

RIGIDLAB_TEST_MAIN(TestDrawableText)
#include "test_drawable_text.moc"
