// SPDX-License-Identifier: GPL-3.0-or-later
// The translations against the sources: every message of the sources is in
// translations/rigidlab_cs.ts (lupdate run afresh over them), English plural forms are
// written, every text the window asks to translate is one lupdate found, and Qt's own
// dialogs speak Czech in the Czech window.

#include "build_paths.h"
#include "common/language.h"
#include "lesson_player/lesson_player.h"
#include "plots/plot_widget.h"
#include "simulation/simulation_controller.h"
#include "window/main_window.h"
#include "window/qt_texts.h"

#include "shipped_lessons.h"
#include "test_main.h"

#include <qcustomplot.h>

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QFileDialog>
#include <QFileIconProvider>
#include <QFileInfo>
#include <QLibraryInfo>
#include <QLocale>
#include <QMap>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QSettings>
#include <QTemporaryDir>
#include <QTranslator>
#include <QXmlStreamReader>
#include <QtTest>

#include <cmath>
#include <memory>
#include <optional>

using namespace rigidlab;
using rigidlab::ui::MainWindow;

namespace {

/// Whether the Czech text must be complete: unfinished and obsolete entries in rigidlab_cs.ts
/// fail the test. On since the translation landed: a new string needs its Czech to pass.
constexpr bool kRequireCompleteTranslation = true;

/// One message of a .ts file.
struct TsMessage {
    bool numerus = false;
    bool unfinished = false;
    bool obsolete = false; ///< "obsolete" or "vanished": no longer in the sources
    QStringList translations;
};

/// A message's key: its context, source text and disambiguation.
QString messageKey(const QString& context, const QString& source, const QString& comment)
{
    return context + QChar(0x1f) + source + QChar(0x1f) + comment;
}

/// "Context: source" for a failure message.
QString readable(const QString& key)
{
    const QStringList parts = key.split(QChar(0x1f));
    return parts.value(0) + QStringLiteral(": \"") + parts.value(1) + u'"' +
           (parts.value(2).isEmpty() ? QString() : QStringLiteral(" (") + parts.value(2) + u')');
}

/// Every message of a .ts file by messageKey; nothing when it cannot be read.
std::optional<QMap<QString, TsMessage>> readTs(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return std::nullopt;
    QMap<QString, TsMessage> out;
    QXmlStreamReader xml(&file);
    QString context, source, comment;
    TsMessage message;
    while (!xml.atEnd()) {
        xml.readNext();
        if (xml.isStartElement()) {
            const auto name = xml.name();
            if (name == QLatin1String("context")) {
                context.clear();
            } else if (name == QLatin1String("name")) {
                context = xml.readElementText();
            } else if (name == QLatin1String("message")) {
                source.clear();
                comment.clear();
                message = TsMessage{};
                message.numerus =
                    xml.attributes().value(QLatin1String("numerus")) == QLatin1String("yes");
            } else if (name == QLatin1String("source")) {
                source = xml.readElementText();
            } else if (name == QLatin1String("comment")) {
                comment = xml.readElementText();
            } else if (name == QLatin1String("translation")) {
                const auto type = xml.attributes().value(QLatin1String("type"));
                message.unfinished = type == QLatin1String("unfinished");
                message.obsolete =
                    type == QLatin1String("obsolete") || type == QLatin1String("vanished");
                if (!message.numerus)
                    message.translations << xml.readElementText();
            } else if (name == QLatin1String("numerusform")) {
                message.translations << xml.readElementText();
            }
        } else if (xml.isEndElement() && xml.name() == QLatin1String("message")) {
            out.insert(messageKey(context, source, comment), message);
        }
    }
    if (xml.hasError())
        return std::nullopt;
    return out;
}

/// Runs lupdate over the translated sources (the list CMake wrote) into `ts`; its output on
/// failure.
QString runLupdate(const QString& ts, const QStringList& extra)
{
    QProcess p;
    p.start(QStringLiteral(RIGIDLAB_LUPDATE),
            QStringList{QLatin1Char('@') + rigidlab::test::translatedSourcesList(),
                        QStringLiteral("-ts"), ts, QStringLiteral("-no-obsolete"),
                        QStringLiteral("-locations"), QStringLiteral("none")} +
                extra);
    if (!p.waitForFinished(120000)) {
        p.kill();
        p.waitForFinished();
        return QStringLiteral("lupdate did not finish");
    }
    if (p.exitStatus() != QProcess::NormalExit || p.exitCode() != 0)
        return QString::fromLocal8Bit(p.readAllStandardError());
    return QString();
}

QString committedTs(const char* name)
{
    return rigidlab::test::sourcePath(u"/translations/") + QLatin1String(name);
}

/// Remembers every text the application asks to translate, translating none.
class RecordingTranslator : public QTranslator {
public:
    QString translate(const char* context, const char* source, const char* disambiguation,
                      int) const override
    {
        if (context && source && *source)
            m_seen.insert(messageKey(QString::fromUtf8(context), QString::fromUtf8(source),
                                     QString::fromUtf8(disambiguation ? disambiguation : "")));
        return QString();
    }
    bool isEmpty() const override { return false; }
    QSet<QString> seen() const { return m_seen; }

private:
    mutable QSet<QString> m_seen;
};

QString shippedScene(const char* name)
{
    return QDir(MainWindow::scenesFolder()).filePath(QLatin1String(name));
}

} // namespace

class TestTranslations : public QObject {
    Q_OBJECT

private slots:
    void init() { ui::applyLanguage(QStringLiteral("en")); }
    void cleanupTestCase() { ui::applyLanguage(QStringLiteral("en")); }

    // --- The .ts files against the sources ---------------------------------------------

    void everySourceMessageIsInTheTs()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString fresh = dir.filePath(QStringLiteral("fresh_cs.ts"));
        const QString error = runLupdate(fresh, {});
        QVERIFY2(error.isEmpty(), qPrintable(error));
        const auto sources = readTs(fresh);
        const auto committed = readTs(committedTs("rigidlab_cs.ts"));
        QVERIFY(sources && committed);
        // Not empty by accident: the window's own menu is among the messages.
        QVERIFY(sources->contains(messageKey(QStringLiteral("rigidlab::ui::MainWindow"),
                                             QStringLiteral("&File"), QString())));
        QStringList missing, unfinished, stale;
        for (auto it = sources->cbegin(); it != sources->cend(); ++it)
            if (!committed->contains(it.key()))
                missing << readable(it.key());
        for (auto it = committed->cbegin(); it != committed->cend(); ++it) {
            if (!sources->contains(it.key()) || it->obsolete)
                stale << readable(it.key());
            else if (it->unfinished ||
                     std::any_of(it->translations.cbegin(), it->translations.cend(),
                                 [](const QString& t) { return t.isEmpty(); }))
                unfinished << readable(it.key());
        }
        const QString regenerate =
            QStringLiteral("\nregenerate: cmake --build build --target update_translations\n");
        QVERIFY2(
            missing.isEmpty(),
            qPrintable(QStringLiteral("%1 messages not in rigidlab_cs.ts:\n").arg(missing.size()) +
                       missing.join(u'\n') + regenerate));
        if (!unfinished.isEmpty() || !stale.isEmpty())
            qInfo("rigidlab_cs.ts: %d unfinished, %d obsolete", int(unfinished.size()),
                  int(stale.size()));
        if (kRequireCompleteTranslation) {
            QVERIFY2(stale.isEmpty(), qPrintable(QStringLiteral("obsolete in rigidlab_cs.ts:\n") +
                                                 stale.join(u'\n') + regenerate));
            QVERIFY2(unfinished.isEmpty(),
                     qPrintable(QStringLiteral("unfinished in rigidlab_cs.ts:\n") +
                                unfinished.join(u'\n')));
        }
    }

    // One Czech word for the one who learns: "žák", as the school says, never "student" as
    // well (a reader hears both as different people).
    void czechCallsTheLearnerZak()
    {
        const auto committed = readTs(committedTs("rigidlab_cs.ts"));
        QVERIFY(committed);
        static const QRegularExpression student(QStringLiteral("\\bstudent"),
                                                QRegularExpression::CaseInsensitiveOption);
        QStringList mixed;
        int zak = 0;
        for (auto it = committed->cbegin(); it != committed->cend(); ++it)
            for (const QString& t : it->translations) {
                if (t.contains(student))
                    mixed << t;
                if (t.contains(QStringLiteral("žák"), Qt::CaseInsensitive))
                    ++zak;
            }
        QVERIFY2(zak >= 10, qPrintable(QString::number(zak))); // the word is used
        QVERIFY2(mixed.isEmpty(), qPrintable(mixed.join(u'\n')));
    }

    // English needs its own words only where a count picks the form ("1 step", "2 steps"):
    // each of those messages is in rigidlab_en.ts with both forms written.
    void englishPluralsAreWritten()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString fresh = dir.filePath(QStringLiteral("fresh_en.ts"));
        const QString error = runLupdate(fresh, {QStringLiteral("-pluralonly")});
        QVERIFY2(error.isEmpty(), qPrintable(error));
        const auto sources = readTs(fresh);
        const auto committed = readTs(committedTs("rigidlab_en.ts"));
        QVERIFY(sources && committed);
        QStringList wrong;
        for (auto it = sources->cbegin(); it != sources->cend(); ++it) {
            if (!it->numerus)
                continue;
            const auto written = committed->constFind(it.key());
            if (written == committed->cend() || written->translations.size() != 2 ||
                written->translations.contains(QString()))
                wrong << readable(it.key());
        }
        QVERIFY2(wrong.isEmpty(),
                 qPrintable(QStringLiteral("English plural forms missing in rigidlab_en.ts:\n") +
                            wrong.join(u'\n')));
    }

    // lupdate sees a message only where the code says tr("...") or QT_TRANSLATE_NOOP in the
    // same context as the call that translates it at run time. Every text the window asks for,
    // on the welcome scene and on every step of every shipped lesson, must be one it found.
    void everyTextTheWindowTranslatesIsInTheTs()
    {
        const auto committed = readTs(committedTs("rigidlab_cs.ts"));
        QVERIFY(committed);
        QSet<QString> contexts;
        for (auto it = committed->cbegin(); it != committed->cend(); ++it)
            contexts.insert(it.key().section(QChar(0x1f), 0, 0));
        RecordingTranslator recorder;
        QCoreApplication::installTranslator(&recorder);
        {
            MainWindow w;
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            QCOMPARE(w.openScene(shippedScene("welcome.json"), true), QString());
            for (int i = 0; i < 30; ++i)
                w.controller().stepForward();
            w.controlsHelpText();
            w.statusText();
            // What the loaders say about broken files reaches the window too.
            QTemporaryDir broken;
            QVERIFY(broken.isValid());
            const QList<QByteArray> files{
                "{\"rigidlab\": 1, \"bodies\": [{\"id\": \"a\", \"shape\": 3}]}",
                "{\"rigidlab\": 1, \"world\": {\"dt\": -1}, \"bodies\": []}",
                "{\"rigidlab\": 1, \"bodies\": [], \"extra\": true}",
                "{\"rigidlab\": 1, \"bodies\": [",
                "{\"rigidlab-lesson\": 1, \"title\": \"\", \"steps\": []}",
            };
            for (int i = 0; i < files.size(); ++i) {
                const QString path = broken.filePath(QStringLiteral("broken%1.json").arg(i));
                QFile f(path);
                QVERIFY(f.open(QIODevice::WriteOnly));
                f.write(files[i]);
                f.close();
                const QString error = files[i].contains("rigidlab-lesson")
                                          ? w.openLesson(path, true)
                                          : w.openScene(path, true);
                QVERIFY2(!error.isEmpty(), files[i].constData());
            }
            for (const QString& path : test::shippedLessons()) {
                QCOMPARE(w.openLesson(path, true), QString());
                const int steps = static_cast<int>(w.lessonPlayer().lesson()->steps.size());
                for (int s = 0; s < steps; ++s) {
                    w.lessonPlayer().goToStep(s);
                    for (int i = 0; i < 10; ++i)
                        w.controller().stepForward();
                    w.statusText();
                }
            }
        }
        QCoreApplication::removeTranslator(&recorder);
        QStringList unknown;
        for (const QString& key : recorder.seen()) {
            const QString context = key.section(QChar(0x1f), 0, 0);
            // Qt's own contexts (QDialogButtonBox, QLineEdit...) are qtbase's to translate.
            const bool ours = contexts.contains(context) || context.startsWith(u"rigidlab");
            if (ours && !committed->contains(key))
                unknown << readable(key);
        }
        unknown.sort();
        QVERIFY2(unknown.isEmpty(),
                 qPrintable(QStringLiteral("%1 texts translated at run time that lupdate does "
                                           "not find (tr() on a variable? another context?):\n")
                                .arg(unknown.size()) +
                            unknown.join(u'\n')));
        QVERIFY(recorder.seen().size() > 50); // the recorder did see the window's texts
    }

    // Qt's own dialogs speak Czech in the Czech window: Qt's translation is loaded, and the
    // texts it lacks for Qt 6 (the file dialog's "Folder") come from the lab's.
    void qtDialogsSpeakCzech()
    {
        QVERIFY(ui::applyLanguage(QStringLiteral("cs")));
        QFileDialog dialog;
        dialog.setOption(QFileDialog::DontUseNativeDialog);
        QVERIFY2(dialog.labelText(QFileDialog::LookIn) != QLatin1String("Look in:"),
                 qPrintable(dialog.labelText(QFileDialog::LookIn)));
        QVERIFY2(dialog.labelText(QFileDialog::Reject) != QLatin1String("Cancel"),
                 qPrintable(dialog.labelText(QFileDialog::Reject)));
        const QString folderType = QFileIconProvider().type(QFileInfo(QDir::tempPath()));
        QVERIFY2(folderType != QLatin1String("Folder") && !folderType.isEmpty(),
                 qPrintable(folderType));
        for (const ui::QtText& t : ui::supplementedQtTexts()) {
            const QString czech = QCoreApplication::translate(
                t.context, t.text.source, *t.text.comment ? t.text.comment : nullptr);
            QVERIFY2(czech != QLatin1String(t.text.source), t.text.source);
        }
        QVERIFY(ui::applyLanguage(QStringLiteral("en")));
        QCOMPARE(QFileIconProvider().type(QFileInfo(QDir::tempPath())), QStringLiteral("Folder"));
    }
};

RIGIDLAB_TEST_MAIN(TestTranslations)
#include "test_translations.moc"
