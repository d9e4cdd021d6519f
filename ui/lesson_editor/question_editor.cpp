// SPDX-License-Identifier: GPL-3.0-or-later
#include "lesson_editor/question_editor.h"
#include "lesson_editor/lesson_draft.h"
#include "lesson_editor/question_set_editor.h"

#include "question_kinds/editor_parts.h"
#include "question_kinds/measure_names.h"
#include "question_kinds/question_kinds.h"

#include "format/lesson_schema.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>
#include <optional>
#include <utility>
#include <variant>

namespace rigidlab::ui {

namespace {

/// The code of the editor's column `l` (editorLanguages: the window's first).
QString langCode(int l)
{
    return editorLanguages()[static_cast<std::size_t>(l)];
}

constexpr int kColumns = static_cast<int>(kEditorLanguages);

namespace keys = lessons::schema::question_keys;
using lessons::schema::jsonKey;

/// Whether a question of the kind at `kind` in lessons::QuestionKind is asked to set settings
/// first (its rows have "set").
bool kindSets(std::size_t kind)
{
    return lessons::schema::questionKindKeys(kind).contains(jsonKey(keys::kSet));
}

/// The labels of `form`'s rows and of the forms in its kinds' `pages` (each a row of its own)
/// as wide as the widest, so that a page's fields line up with the form's: a page's own form,
/// and a form in a widget of the page, below a block as wide as the page (the choice's right
/// option, under the table of options).
void alignLabels(QFormLayout* form, const std::vector<KindPage*>& pages)
{
    std::vector<QFormLayout*> forms{form};
    for (KindPage* page : pages)
        for (QFormLayout* pageForm : page->findChildren<QFormLayout*>())
            forms.push_back(pageForm);
    std::vector<QWidget*> labels;
    int widest = 0;
    for (QFormLayout* f : forms)
        for (int row = 0; row < f->rowCount(); ++row)
            if (QLayoutItem* item = f->itemAt(row, QFormLayout::LabelRole);
                item && item->widget()) {
                labels.push_back(item->widget());
                widest = std::max(widest, item->widget()->sizeHint().width());
            }
    for (QWidget* label : labels)
        label->setMinimumWidth(widest);
}

} // namespace

QuestionEditor::QuestionEditor(LessonDraft& draft, QWidget* parent)
    : QWidget(parent), m_draft(draft)
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* label = new QLabel(tr("Questions o&f the step"), this);
    m_list = new QListWidget(this);
    m_list->setObjectName(QStringLiteral("questionList"));
    m_list->setAccessibleName(tr("Questions of the step"));
    m_list->setMaximumHeight(70);
    fitRowsToWidth(m_list);
    label->setBuddy(m_list);
    connect(m_list, &QListWidget::currentRowChanged, this, [this] {
        if (!m_refreshing)
            refresh();
    });
    auto* buttons = new QHBoxLayout;
    const auto button = [this, buttons](const QString& text, const char* name, auto slot) {
        QPushButton* b = addEditorButton(this, buttons, text, name);
        connect(b, &QPushButton::clicked, this, slot);
    };
    button(tr("Add a &measured question"), "addMeasuredQuestion", [this] { addQuestion(false); });
    button(tr("Add a &predict-first question"), "addPredictQuestion",
           [this] { addQuestion(true); });
    button(tr("Remove &question"), "removeQuestion", [this] { removeQuestion(); });
    layout->addWidget(label);
    layout->addWidget(m_list);
    layout->addLayout(buttons);
    // The selected question's fields, shown only when there is one to edit.
    m_form = new QWidget(this);
    m_form->setLayout(buildForm());
    m_form->layout()->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_form);
    layout->addWidget(m_answer);
    layout->addStretch(1); // the list and the fields at the top, not spread down the pane
    refresh();
}

QFormLayout* QuestionEditor::buildForm()
{
    auto* form = new QFormLayout;
    addLanguageFields(form, QStringLiteral("questionPrompt"), tr("Question (%1)"), m_prompt);
    addKindRows(form);
    m_fields = form;
    m_holdRun = new QCheckBox(tr("Predict first: the run waits until it is answered"), this);
    m_holdRun->setObjectName(QStringLiteral("questionHoldRun"));
    m_answer = new QLabel(this);
    m_answer->setObjectName(QStringLiteral("questionAnswer"));
    m_answer->setWordWrap(true);
    m_answer->setAccessibleName(tr("The right answer")); // each kind names its own line
    m_set = new QuestionSetEditor(this);
    m_set->setToolTip(tr("A setting the student changes with the controls before the run "
                         "this question measures (\"Set e = 0 and run again\")"));
    form->addRow(tr("Stu&dent sets first"), m_set);
    // The hint, per language: what the student reads after a wrong first try.
    addLanguageFields(form, QStringLiteral("questionHint"), tr("Hint (%1)"), m_hint);
    for (QLineEdit* e : m_hint)
        e->setToolTip(tr("What the student reads after a wrong first answer; empty: \"Try once "
                         "more.\""));
    form->addRow(m_holdRun);
    connect(m_holdRun, &QCheckBox::toggled, this, &QuestionEditor::edited);
    connect(m_set, &QuestionSetEditor::edited, this, &QuestionEditor::edited);
    alignLabels(form, m_pages);
    return form;
}

void QuestionEditor::addKindRows(QFormLayout* form)
{
    m_questionKind = new QComboBox(this);
    m_questionKind->setObjectName(QStringLiteral("questionType"));
    m_questionKind->setAccessibleName(tr("Kind of question"));
    // One item per kind of question, its index in Question::kind as its data, and the page of
    // each, shown for a question of its kind.
    m_pages.assign(std::variant_size_v<lessons::QuestionKind>, nullptr);
    for (std::size_t k = 0; k < m_pages.size(); ++k)
        std::visit(
            [&](const auto& kind) {
                using Kind = std::decay_t<decltype(kind)>;
                m_questionKind->addItem(kindTitle(std::type_identity<Kind>{}),
                                        QVariant::fromValue(k));
                m_pages[k] = editorPage(std::type_identity<Kind>{}, this);
                m_pages[k]->edited = [this] { edited(); };
            },
            lessons::schema::newQuestionKind(k));
    connect(m_questionKind, &QComboBox::activated, this,
            [this] { setKind(m_questionKind->currentData().value<std::size_t>()); });
    form->addRow(tr("&Kind"), m_questionKind);
    for (KindPage* page : m_pages)
        form->addRow(page);
}

void QuestionEditor::addLanguageFields(QFormLayout* form, const QString& name, const QString& label,
                                       std::array<QLineEdit*, kEditorLanguages>& fields)
{
    for (int l = 0; l < kColumns; ++l) {
        auto* e = new QLineEdit(this);
        e->setObjectName(name + u'_' + langCode(l));
        const QString shown = label.arg(lessons::languageTitle(langCode(l)));
        e->setAccessibleName(shown);
        connect(e, &QLineEdit::textEdited, this, &QuestionEditor::edited);
        fields[static_cast<std::size_t>(l)] = e;
        form->addRow(shown, e);
    }
}

void QuestionEditor::setStep(int step)
{
    if (step != m_step) {
        m_step = step;
        m_list->setCurrentRow(0);
    }
    refresh();
}

int QuestionEditor::currentQuestion() const
{
    return m_list->currentRow();
}

QJsonObject QuestionEditor::question() const
{
    return m_draft.value(m_step, QStringLiteral("questions"))
        .toArray()
        .at(currentQuestion())
        .toObject();
}

void QuestionEditor::store(const QJsonObject& q)
{
    QJsonArray all = m_draft.value(m_step, QStringLiteral("questions")).toArray();
    const int at = currentQuestion();
    if (at < 0 || at >= all.size())
        return;
    all[at] = q;
    m_draft.setValue(m_step, QStringLiteral("questions"), all, tr("question"));
}

void QuestionEditor::setKind(std::size_t kind)
{
    QJsonObject q = question();
    const std::size_t was = lessons::schema::questionKindIn(q);
    if (m_step < 0 || q.isEmpty() || was == kind)
        return;
    // The keys of the kind it was go (its rows say which); the new kind's start as a new
    // question of that kind does.
    for (const QString& key : lessons::schema::questionKindKeys(was))
        q.remove(key);
    const QJsonObject fresh = std::visit(
        [this](const auto& k) {
            return newKindKeys(std::type_identity<std::decay_t<decltype(k)>>{},
                               m_draft.sceneObject(m_step));
        },
        lessons::schema::newQuestionKind(kind));
    for (auto it = fresh.begin(); it != fresh.end(); ++it)
        q.insert(it.key(), it.value());
    store(q);
}

void QuestionEditor::addQuestion(bool predict)
{
    if (m_step < 0)
        return;
    QJsonArray all = m_draft.value(m_step, QStringLiteral("questions")).toArray();
    // A new question is a measured one, asking in the words the editor writes for its measure.
    const QJsonObject scene = m_draft.sceneObject(m_step);
    QJsonObject q = newKindKeys(std::type_identity<lessons::MeasuredQuestion>{}, scene);
    const QJsonObject measure = q.value(jsonKey(keys::kMeasure)).toObject();
    q.insert(
        jsonKey(keys::kPrompt),
        QJsonObject{{currentLanguage(),
                     defaultPrompt(measure, bodyName(scene, measure.value(u"body").toString()))}});
    if (predict)
        q.insert(jsonKey(keys::kHoldBack), QJsonArray{QStringLiteral("run")});
    all.append(q);
    m_draft.setValue(m_step, QStringLiteral("questions"), all, tr("question"));
    m_list->setCurrentRow(static_cast<int>(all.size()) - 1);
    refresh();
}

void QuestionEditor::removeQuestion()
{
    QJsonArray all = m_draft.value(m_step, QStringLiteral("questions")).toArray();
    const int at = currentQuestion();
    if (at < 0 || at >= all.size())
        return;
    all.removeAt(at);
    m_draft.setValue(m_step, QStringLiteral("questions"),
                     all.isEmpty() ? QJsonValue() : QJsonValue(all), tr("question"));
}

void QuestionEditor::edited()
{
    if (m_refreshing)
        return;
    QJsonObject q = question();
    // A language left empty is not written: the student reads the text in one it has.
    for (const auto& [key, fields] :
         {std::pair{jsonKey(keys::kPrompt), &m_prompt}, std::pair{jsonKey(keys::kHint), &m_hint}}) {
        QJsonValue text = q.value(key);
        for (int l = 0; l < kColumns; ++l)
            text =
                withWrittenText(text, langCode(l), (*fields)[static_cast<std::size_t>(l)]->text());
        if (text.isNull())
            q.remove(key);
        else
            q.insert(key, text);
    }
    const std::size_t kind = lessons::schema::questionKindIn(q);
    m_pages[kind]->applyTo(q);
    if (kindSets(kind) && !m_set->value().isEmpty())
        q.insert(jsonKey(keys::kSet), m_set->value());
    else
        q.remove(jsonKey(keys::kSet));
    QJsonArray hold = q.value(jsonKey(keys::kHoldBack)).toArray();
    const bool held = hold.contains(QStringLiteral("run"));
    if (m_holdRun->isChecked() && !held)
        hold.append(QStringLiteral("run"));
    if (!m_holdRun->isChecked() && held)
        for (qsizetype i = hold.size() - 1; i >= 0; --i)
            if (hold.at(i).toString() == u"run")
                hold.removeAt(i);
    if (hold.isEmpty())
        q.remove(jsonKey(keys::kHoldBack));
    else
        q.insert(jsonKey(keys::kHoldBack), hold);
    store(q);
}

void QuestionEditor::refresh()
{
    m_refreshing = true;
    const QJsonArray all = m_draft.value(m_step, QStringLiteral("questions")).toArray();
    const int keep = std::clamp(currentQuestion(), 0, std::max<int>(all.size() - 1, 0));
    while (m_list->count() > all.size())
        delete m_list->takeItem(m_list->count() - 1);
    while (m_list->count() < all.size())
        m_list->addItem(QString());
    for (int i = 0; i < all.size(); ++i) {
        const QString text = shownText(all.at(i).toObject().value(jsonKey(keys::kPrompt)));
        const bool predict = all.at(i)
                                 .toObject()
                                 .value(jsonKey(keys::kHoldBack))
                                 .toArray()
                                 .contains(QStringLiteral("run"));
        // The kind first: a long prompt ends in "…", its tooltip has all of it.
        m_list->item(i)->setText(predict ? tr("%1. Predict first: %2").arg(i + 1).arg(text)
                                         : QStringLiteral("%1. %2").arg(i + 1).arg(text));
        m_list->item(i)->setToolTip(text);
    }
    m_list->setCurrentRow(all.isEmpty() ? -1 : keep);

    const QJsonObject q = question();

    for (const auto& [key, fields] :
         {std::pair{jsonKey(keys::kPrompt), &m_prompt}, std::pair{jsonKey(keys::kHint), &m_hint}}) {
        const QJsonValue v = q.value(key);
        for (int l = 0; l < kColumns; ++l) {
            QLineEdit* field = (*fields)[static_cast<std::size_t>(l)];
            showText(field, writtenText(v, langCode(l)));
            // The quiet mark of a language not written: the text the student reads instead.
            field->setPlaceholderText(shownText(v));
        }
    }
    m_set->show(q.value(jsonKey(keys::kSet)).toObject());
    m_holdRun->setChecked(
        q.value(jsonKey(keys::kHoldBack)).toArray().contains(QStringLiteral("run")));
    // Each kind shows its own page only, and what the student sets first where it has that.
    const std::size_t kind = lessons::schema::questionKindIn(q);
    m_questionKind->setCurrentIndex(m_questionKind->findData(QVariant::fromValue(kind)));
    for (std::size_t k = 0; k < m_pages.size(); ++k)
        m_fields->setRowVisible(m_pages[k], k == kind);
    m_pages[kind]->showQuestion(q, m_draft.sceneObject(m_step));
    m_fields->setRowVisible(m_set, kindSets(kind));
    const bool any = currentQuestion() >= 0;
    m_form->setVisible(any);
    m_refreshing = false;
    showAnswer();
}

void QuestionEditor::showAnswer()
{
    // The run is measured again only when what it depends on changed, not at every key typed
    // into a text of the lesson.
    QJsonObject depends{{QStringLiteral("question"), question()}};
    for (const char* key : {"scene", "settings", "exportTime", "compare", "allow"})
        depends.insert(QLatin1String(key), m_draft.value(m_step, QLatin1String(key)));
    depends.insert(QStringLiteral("step"), m_step);
    if (depends == m_measuredFor)
        return;
    m_measuredFor = depends;
    const int at = currentQuestion();
    if (at < 0) {
        m_answer->setText(m_step < 0 ? QString() : tr("This step asks no question."));
        return;
    }
    QString error;
    const std::optional<lessons::Lesson> lesson = m_draft.lesson(currentLanguage(), error);
    if (!lesson || m_step >= static_cast<int>(lesson->steps.size())) {
        // Said again at the next refresh: the problem may be in a text, which `depends` leaves
        // out, and a line about it must not stay once it is fixed.
        m_measuredFor = {};
        m_answer->setText(tr("⚠ The lesson has a problem to fix first (see below): %1").arg(error));
        return;
    }
    const lessons::LessonStep& step = lesson->steps[static_cast<std::size_t>(m_step)];
    const lessons::Question& question = step.questions.at(static_cast<std::size_t>(at));
    const AnswerLine line = std::visit(
        [&](const auto& kind) { return answerLine(kind, step, question); }, question.kind);
    m_answer->setAccessibleName(line.name);
    m_answer->setText(line.text);
}

} // namespace rigidlab::ui
