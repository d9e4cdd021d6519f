// SPDX-License-Identifier: GPL-3.0-or-later
#include "lesson_editor/lesson_editor.h"
#include "question_kinds/editor_parts.h"
#include "lesson_editor/question_editor.h"
#include "lesson_editor/step_checks.h"
#include "lesson_editor/step_settings_editor.h"
#include "lesson_player/step_text.h"

#include "common/accessible_names.h"
#include "common/job_progress.h"

#include "format/data_dirs.h"
#include "run/measurements.h"

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QLockFile>
#include <QMessageBox>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QSpinBox>
#include <QSplitter>
#include <QStyle>
#include <QTabWidget>
#include <QTimer>
#include <QUndoStack>
#include <QVBoxLayout>

namespace rigidlab::ui {

namespace {

/// The code of the editor's column `language` (editorLanguages: the window's first).
QString code(int language)
{
    return editorLanguages()[static_cast<std::size_t>(language)];
}

QString languageName(int language)
{
    return lessons::languageTitle(code(language));
}

constexpr int kColumns = static_cast<int>(kEditorLanguages);

/// How often the unsaved lesson is written to the autosave [ms].
constexpr int kAutosaveMs = 30'000;

/// A page of a tab widget that scrolls when the window is shorter than all of it, named after
/// its tab.
QScrollArea* scrolling(QWidget* page, const QString& name)
{
    auto* area = new QScrollArea;
    nameScrollArea(*area, name);
    area->setWidget(page);
    area->setWidgetResizable(true);
    area->setFrameShape(QFrame::NoFrame);
    area->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    return area;
}

} // namespace

LessonEditor::LessonEditor(QWidget* parent) : QWidget(parent, Qt::Window)
{
    setObjectName(QStringLiteral("lessonEditor"));
    setAccessibleName(tr("Lesson editor"));
    m_autosavePath = newAutosavePath();

    auto* layout = new QVBoxLayout(this);
    auto* grid = new QGridLayout;
    buildLessonFields(*grid);
    layout->addLayout(grid);
    auto* split = new QSplitter(Qt::Horizontal, this);
    split->addWidget(buildStepList());
    split->addWidget(buildStepTexts());
    split->setStretchFactor(1, 3);
    layout->addWidget(split, 1);
    m_problems = new QLabel(this);
    m_problems->setObjectName(QStringLiteral("lessonProblems"));
    m_problems->setWordWrap(true);
    m_problems->setTextInteractionFlags(Qt::TextSelectableByMouse | Qt::TextSelectableByKeyboard);
    m_problems->setAccessibleName(tr("Problems of the lesson"));
    layout->addWidget(m_problems);
    buildActions();
    m_checks = new StepChecks(this);
    connect(m_checks, &StepChecks::finished, this, &LessonEditor::refresh);
    auto* progress = new JobProgress(m_checks->job(), tr("Checking the steps' scenes"),
                                     tr("Cancel checking the steps' scenes"), this);
    progress->setObjectName(QStringLiteral("stepChecksProgress"));
    layout->addWidget(progress);

    m_autosaveTimer = new QTimer(this);
    m_autosaveTimer->setInterval(kAutosaveMs);
    connect(m_autosaveTimer, &QTimer::timeout, this, &LessonEditor::autosave);
    m_autosaveTimer->start();
    connect(&m_draft, &LessonDraft::changed, this, &LessonEditor::refresh);
    refresh();
}

LessonEditor::~LessonEditor() = default; // the lock is let go; the autosave stays

QString LessonEditor::newAutosavePath()
{
    static int made = 0;
    return QDir(lessons::userDataDir())
        .filePath(QStringLiteral("autosave-%1-%2-%3.rlesson")
                      .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss")))
                      .arg(QCoreApplication::applicationPid())
                      .arg(++made));
}

QStringList LessonEditor::keptLessons()
{
    const QFileInfoList files =
        QDir(lessons::userDataDir())
            .entryInfoList({QStringLiteral("autosave*.rlesson")}, QDir::Files, QDir::Time);
    QStringList out;
    for (const QFileInfo& f : files) {
        // A live editor holds its lock; a crashed one's lock is stale and taken over here.
        QLockFile probe(f.absoluteFilePath() + QStringLiteral(".lock"));
        probe.setStaleLockTime(0); // held for hours: stale only when its process is gone
        if (probe.tryLock(0)) {
            probe.unlock();
            out << f.absoluteFilePath();
        }
    }
    return out;
}

void LessonEditor::buildLessonFields(QGridLayout& grid)
{
    for (int l = 0; l < kColumns; ++l) {
        auto* head = new QLabel(languageName(l), this);
        grid.addWidget(head, 0, l + 1);
    }
    const std::array<std::pair<QString, std::array<QLineEdit*, kEditorLanguages>*>, 3> rows{{
        {tr("Lesson &title"), &m_title},
        {tr("&Summary"), &m_summary},
        {tr("&Level"), &m_level},
    }};
    const std::array<QString, 3> keys{QStringLiteral("title"), QStringLiteral("summary"),
                                      QStringLiteral("level")};
    for (int r = 0; r < 3; ++r) {
        auto* label = new QLabel(rows[r].first, this);
        grid.addWidget(label, r + 1, 0);
        for (int l = 0; l < kColumns; ++l) {
            auto* edit = new QLineEdit(this);
            QString plain = rows[r].first;
            plain.remove(u'&');
            edit->setAccessibleName(QStringLiteral("%1 (%2)").arg(plain, languageName(l)));
            edit->setObjectName(QStringLiteral("lesson_%1_%2").arg(keys[r], code(l)));
            edit->installEventFilter(this);
            if (l == 0)
                label->setBuddy(edit);
            connect(edit, &QLineEdit::textEdited, this,
                    [this, key = keys[r], l](const QString& t) { textEdited(-1, key, l, t); });
            (*rows[r].second)[static_cast<std::size_t>(l)] = edit;
            grid.addWidget(edit, r + 1, l + 1);
        }
    }
    auto* minutesLabel = new QLabel(tr("M&inutes"), this);
    m_minutes = new QSpinBox(this);
    m_minutes->setObjectName(QStringLiteral("lessonMinutes"));
    m_minutes->setRange(0, 600);
    m_minutes->setSpecialValueText(tr("not said"));
    m_minutes->setSuffix(tr("\u00a0min"));
    nameWithUnit(*m_minutes, tr("Minutes the lesson takes"));
    minutesLabel->setBuddy(m_minutes);
    connect(m_minutes, &QSpinBox::valueChanged, this, [this](int v) {
        if (!m_refreshing)
            m_draft.setValue(-1, QStringLiteral("minutes"), v > 0 ? QJsonValue(v) : QJsonValue(),
                             tr("minutes"));
    });
    grid.addWidget(minutesLabel, 4, 0);
    grid.addWidget(m_minutes, 4, 1);
}

QPushButton* LessonEditor::makeButton(const QString& text, const QString& name,
                                      const QKeySequence& keys, void (LessonEditor::*slot)())
{
    auto* button = new QPushButton(text, this);
    button->setObjectName(name);
    QString plain = text;
    plain.remove(u'&');
    button->setAccessibleName(plain);
    button->setToolTip(
        QStringLiteral("%1 (%2)").arg(plain, keys.toString(QKeySequence::NativeText)));
    connect(button, &QPushButton::clicked, this, slot);
    auto* action = new QAction(this);
    action->setShortcut(keys);
    action->setShortcutContext(Qt::WindowShortcut);
    connect(action, &QAction::triggered, this, slot);
    addAction(action);
    return button;
}

QWidget* LessonEditor::buildStepList()
{
    auto* box = new QWidget(this);
    auto* layout = new QVBoxLayout(box);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* label = new QLabel(tr("St&eps"), box);
    m_steps = new QListWidget(box);
    m_steps->setObjectName(QStringLiteral("lessonSteps"));
    m_steps->setAccessibleName(tr("Steps of the lesson"));
    fitRowsToWidth(m_steps);
    label->setBuddy(m_steps);
    connect(m_steps, &QListWidget::currentRowChanged, this, [this] {
        if (!m_refreshing)
            refreshStepTexts();
    });
    layout->addWidget(label);
    layout->addWidget(m_steps, 1);
    auto* buttons = new QGridLayout;
    buttons->addWidget(makeButton(tr("Add step"), QStringLiteral("addStep"),
                                  QKeySequence(QStringLiteral("Ctrl+Shift+N")),
                                  &LessonEditor::addStep),
                       0, 0);
    buttons->addWidget(makeButton(tr("Remove step"), QStringLiteral("removeStep"),
                                  QKeySequence(QStringLiteral("Ctrl+Del")),
                                  &LessonEditor::removeStep),
                       0, 1);
    buttons->addWidget(makeButton(tr("Move up"), QStringLiteral("moveStepUp"),
                                  QKeySequence(QStringLiteral("Alt+Up")), &LessonEditor::moveUp),
                       1, 0);
    buttons->addWidget(makeButton(tr("Move down"), QStringLiteral("moveStepDown"),
                                  QKeySequence(QStringLiteral("Alt+Down")),
                                  &LessonEditor::moveDown),
                       1, 1);
    buttons->addWidget(makeButton(tr("Duplicate step"), QStringLiteral("duplicateStep"),
                                  QKeySequence(QStringLiteral("Ctrl+D")),
                                  &LessonEditor::duplicateStep),
                       2, 0);
    buttons->addWidget(makeButton(tr("Try as a student"), QStringLiteral("tryAsStudent"),
                                  QKeySequence(QStringLiteral("F5")), &LessonEditor::trySelected),
                       2, 1);
    // The step's scene is drawn in the window's scene editor: sent there, and taken back.
    auto* editScene = new QPushButton(tr("Edit t&he step's scene in the window"), box);
    editScene->setObjectName(QStringLiteral("editStepScene"));
    editScene->setToolTip(tr("Opens this step's scene in the main window's scene editor"));
    connect(editScene, &QPushButton::clicked, this, &LessonEditor::sendStepScene);
    buttons->addWidget(editScene, 3, 0, 1, 2);
    auto* takeScene = new QPushButton(tr("Take the &window's scene for this step"), box);
    takeScene->setObjectName(QStringLiteral("takeWindowScene"));
    takeScene->setToolTip(tr("The scene open in the main window, as edited there, becomes "
                             "this step's scene"));
    connect(takeScene, &QPushButton::clicked, this, [this] {
        if (currentStep() >= 0)
            emit stepSceneWanted(currentStep());
    });
    buttons->addWidget(takeScene, 4, 0, 1, 2);
    layout->addLayout(buttons);
    return box;
}

QWidget* LessonEditor::buildStepTexts()
{
    auto* box = new QWidget(this);
    auto* grid = new QGridLayout(box);
    grid->setContentsMargins(0, 0, 0, 0);
    for (int l = 0; l < kColumns; ++l) {
        const QString lang = languageName(l);
        auto* titleLabel = new QLabel(tr("Step title (%1)").arg(lang), box);
        auto* title = new QLineEdit(box);
        title->setObjectName(QStringLiteral("stepTitle_%1").arg(code(l)));
        title->setAccessibleName(tr("Step title (%1)").arg(lang));
        titleLabel->setBuddy(title);
        title->installEventFilter(this);
        connect(title, &QLineEdit::textEdited, this, [this, l](const QString& t) {
            textEdited(currentStep(), QStringLiteral("title"), l, t);
        });
        auto* text = new QPlainTextEdit(box);
        text->setObjectName(QStringLiteral("stepText_%1").arg(code(l)));
        text->setAccessibleName(tr("Step text (%1)").arg(lang));
        text->setTabChangesFocus(true);
        // The markup shown where a new step has no text yet.
        text->setPlaceholderText(tr("What the student reads in this step: **bold**, *italic*, "
                                    "a line that starts with “- ” is a list item"));
        text->installEventFilter(this);
        connect(text, &QPlainTextEdit::textChanged, this, [this, l, text] {
            textEdited(currentStep(), QStringLiteral("text"), l, text->toPlainText());
        });
        auto* missing = new QLabel(box);
        missing->setObjectName(QStringLiteral("missing_%1").arg(code(l)));
        missing->setTextFormat(Qt::PlainText);
        auto* preview = new StepText(box);
        preview->setObjectName(QStringLiteral("preview_%1").arg(code(l)));
        preview->setAccessibleName(tr("Preview (%1)").arg(lang));
        grid->addWidget(titleLabel, 0, l);
        grid->addWidget(title, 1, l);
        grid->addWidget(missing, 2, l);
        grid->addWidget(text, 3, l);
        grid->addWidget(new QLabel(tr("As the student sees it (%1)").arg(lang), box), 4, l);
        grid->addWidget(preview, 5, l);
        m_stepTitle[static_cast<std::size_t>(l)] = title;
        m_stepText[static_cast<std::size_t>(l)] = text;
        m_missing[static_cast<std::size_t>(l)] = missing;
        m_preview[static_cast<std::size_t>(l)] = preview;
    }
    // The text being written gets more room than its preview.
    grid->setRowStretch(3, 3);
    grid->setRowStretch(5, 2);
    for (StepText* preview : m_preview)
        preview->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Ignored);
    auto* split = new QSplitter(Qt::Vertical, this);
    split->addWidget(box);
    // Below the texts: the step's questions, and what it shows and lets the student change.
    auto* pages = new QTabWidget(split);
    pages->setObjectName(QStringLiteral("stepPages"));
    pages->setAccessibleName(tr("The step's questions and settings"));
    m_questions = new QuestionEditor(m_draft, pages);
    pages->addTab(scrolling(m_questions, tr("Questions")), tr("Questions"));
    m_settings = new StepSettingsEditor(m_draft, pages);
    pages->addTab(scrolling(m_settings, tr("Shown and locked")), tr("Shown and locked"));
    split->addWidget(pages);
    // Half for the texts, half for the questions: the questions are what a step is for.
    split->setStretchFactor(0, 1);
    split->setStretchFactor(1, 1);
    split->setSizes({1, 1});
    return split;
}

void LessonEditor::buildActions()
{
    m_undo = m_draft.undoStack()->createUndoAction(this, tr("&Undo"));
    m_undo->setObjectName(QStringLiteral("lessonUndo"));
    m_undo->setShortcut(QKeySequence::Undo);
    m_redo = m_draft.undoStack()->createRedoAction(this, tr("&Redo"));
    m_redo->setObjectName(QStringLiteral("lessonRedo"));
    // Both usual keys for Redo, whatever the platform's own.
    QList<QKeySequence> redoKeys = QKeySequence::keyBindings(QKeySequence::Redo);
    for (const QKeySequence& k :
         {QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)})
        if (!redoKeys.contains(k))
            redoKeys.append(k);
    m_redo->setShortcuts(redoKeys);
    addAction(m_undo);
    addAction(m_redo);
    auto* save = new QAction(tr("&Save lesson"), this);
    save->setObjectName(QStringLiteral("lessonSave"));
    save->setShortcut(QKeySequence::Save);
    connect(save, &QAction::triggered, this, [this] { LessonEditor::save(); });
    addAction(save);
    auto* saveAs = new QAction(tr("Save lesson &as…"), this);
    saveAs->setObjectName(QStringLiteral("lessonSaveAs"));
    saveAs->setShortcut(QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S));
    connect(saveAs, &QAction::triggered, this, &LessonEditor::saveAsDialog);
    addAction(saveAs);
    // The same actions as buttons, so that the mouse finds them too.
    auto* row = new QHBoxLayout;
    for (QAction* a : {m_undo, m_redo, save, saveAs}) {
        auto* b = new QPushButton(this);
        b->setObjectName(a->objectName() + QStringLiteral("Button"));
        const auto sync = [a, b] {
            QString plain = a->text();
            plain.remove(u'&');
            b->setText(plain);
            b->setAccessibleName(plain);
            b->setEnabled(a->isEnabled());
            b->setToolTip(a->shortcut().toString(QKeySequence::NativeText));
        };
        sync();
        connect(a, &QAction::changed, b, sync);
        connect(b, &QPushButton::clicked, a, &QAction::trigger);
        b->setFocusPolicy(Qt::TabFocus);
        row->addWidget(b);
    }
    row->addStretch(1);
    static_cast<QVBoxLayout*>(layout())->insertLayout(0, row);
}

} // namespace rigidlab::ui
