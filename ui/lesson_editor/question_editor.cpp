// SPDX-License-Identifier: GPL-3.0-or-later
#include "lesson_editor/question_editor.h"
#include "lesson_editor/choice_editor.h"
#include "lesson_editor/editor_parts.h"
#include "lesson_editor/lesson_draft.h"
#include "lesson_editor/measure_names.h"
#include "lesson_editor/question_set_editor.h"

#include "question_kinds/question_kinds.h"

#include "common/accessible_names.h"

#include "format/lesson_schema.h"
#include "run/measurements.h"

#include "rigidlab/physics/integrator.h"
#include "rigidlab/physics/overloaded.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QLocale>
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

/// The kind of a question as the draft holds it, as a fresh one of that kind.
lessons::QuestionKind kindIn(const QJsonObject& q)
{
    return lessons::schema::newQuestionKind(lessons::schema::questionKindIn(q));
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
    m_kind = new QComboBox(this);
    m_kind->setObjectName(QStringLiteral("questionKind"));
    m_kind->setAccessibleName(tr("What is measured"));
    for (const MeasureName& k : kMeasureNames)
        m_kind->addItem(tr(k.name), QLatin1String(k.id));
    m_body = new QComboBox(this);
    m_body->setObjectName(QStringLiteral("questionBody"));
    m_body->setAccessibleName(tr("Body measured"));
    m_time = new QDoubleSpinBox(this);
    m_time->setObjectName(QStringLiteral("questionTime"));
    m_time->setRange(0, 3600);
    m_time->setDecimals(2);
    m_time->setSuffix(QStringLiteral("\u00a0s"));
    nameWithUnit(*m_time, tr("Time of the measurement"));
    m_unit = new QLineEdit(this);
    m_unit->setObjectName(QStringLiteral("questionUnit"));
    m_unit->setAccessibleName(tr("Unit of the answer"));
    m_tolerance = new QDoubleSpinBox(this);
    m_tolerance->setObjectName(QStringLiteral("questionTolerance"));
    m_tolerance->setRange(0.1, 100);
    m_tolerance->setDecimals(1);
    m_tolerance->setSuffix(QStringLiteral("\u00a0%"));
    nameWithUnit(*m_tolerance, tr("Tolerance of the answer"));
    m_holdRun = new QCheckBox(tr("Predict first: the run waits until it is answered"), this);
    m_holdRun->setObjectName(QStringLiteral("questionHoldRun"));
    m_answer = new QLabel(this);
    m_answer->setObjectName(QStringLiteral("questionAnswer"));
    m_answer->setWordWrap(true);
    m_answer->setAccessibleName(tr("The answer the lab measures"));
    form->addRow(tr("Measu&red"), m_kind);
    form->addRow(tr("&Body"), m_body);
    form->addRow(tr("&At time"), m_time);
    form->addRow(tr("&Unit"), m_unit);
    form->addRow(tr("Toleran&ce"), m_tolerance);
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
    connect(m_kind, &QComboBox::activated, this, &QuestionEditor::edited);
    connect(m_body, &QComboBox::activated, this, &QuestionEditor::edited);
    connect(m_time, &QDoubleSpinBox::valueChanged, this, &QuestionEditor::edited);
    connect(m_unit, &QLineEdit::textEdited, this, &QuestionEditor::edited);
    connect(m_tolerance, &QDoubleSpinBox::valueChanged, this, &QuestionEditor::edited);
    connect(m_holdRun, &QCheckBox::toggled, this, &QuestionEditor::edited);
    connect(m_set, &QuestionSetEditor::edited, this, &QuestionEditor::edited);
    return form;
}

void QuestionEditor::addKindRows(QFormLayout* form)
{
    m_questionKind = new QComboBox(this);
    m_questionKind->setObjectName(QStringLiteral("questionType"));
    m_questionKind->setAccessibleName(tr("Kind of question"));
    // One item per kind of question, its index in Question::kind as its data.
    for (std::size_t k = 0; k < std::variant_size_v<decltype(lessons::Question::kind)>; ++k)
        m_questionKind->addItem(
            std::visit(physics::Overloaded{
                           [](const lessons::MeasuredQuestion&) {
                               return tr("a number measured from the run");
                           },
                           [](const lessons::ChoiceQuestion&) { return tr("a choice of answers"); },
                           [](const auto& kind) {
                               return kindTitle(std::type_identity<std::decay_t<decltype(kind)>>{});
                           }},
                       lessons::schema::newQuestionKind(k)),
            QVariant::fromValue(k));
    connect(m_questionKind, &QComboBox::activated, this,
            [this] { setKind(m_questionKind->currentData().value<std::size_t>()); });
    form->addRow(tr("&Kind"), m_questionKind);
    m_choices = new ChoiceEditor(this);
    connect(m_choices, &ChoiceEditor::edited, this, &QuestionEditor::edited);
    form->addRow(m_choices);
    // The page of each kind of ui/question_kinds/ (the older kinds' fields are this form's).
    m_pages.assign(std::variant_size_v<lessons::QuestionKind>, nullptr);
    for (std::size_t k = 0; k < m_pages.size(); ++k)
        std::visit(physics::Overloaded{[](const lessons::MeasuredQuestion&) {},
                                       [](const lessons::ChoiceQuestion&) {},
                                       [&](const auto& kind) {
                                           m_pages[k] = editorPage(
                                               std::type_identity<std::decay_t<decltype(kind)>>{},
                                               this);
                                           m_pages[k]->edited = [this] { edited(); };
                                           form->addRow(m_pages[k]);
                                       }},
                   lessons::schema::newQuestionKind(k));
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

QJsonObject QuestionEditor::defaultMeasured() const
{
    const MeasureName& k = kMeasureNames[1]; // speed at a time: any body, any scene
    QJsonObject measure{{QStringLiteral("kind"), QLatin1String(k.id)}, {QStringLiteral("time"), 1}};
    const QList<std::pair<QString, QString>> bodies = movingBodies();
    if (!bodies.isEmpty())
        measure.insert(QStringLiteral("body"), bodies.front().first);
    return QJsonObject{{jsonKey(keys::kMeasure), measure},
                       {jsonKey(keys::kUnit), QLatin1String(k.unit)},
                       {jsonKey(keys::kTolerance), 0.05}};
}

QJsonObject QuestionEditor::defaultChoice() const
{
    return QJsonObject{{jsonKey(keys::kChoices),
                        QJsonArray{QJsonObject{{currentLanguage(), tr("Option %1").arg(1)}},
                                   QJsonObject{{currentLanguage(), tr("Option %1").arg(2)}}}},
                       {jsonKey(keys::kAnswer), 0}};
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
    const QJsonObject fresh =
        std::visit(physics::Overloaded{
                       [this](const lessons::MeasuredQuestion&) { return defaultMeasured(); },
                       [this](const lessons::ChoiceQuestion&) { return defaultChoice(); },
                       [this](const auto& kind) {
                           return newKindKeys(std::type_identity<std::decay_t<decltype(kind)>>{});
                       }},
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
    QJsonObject q = defaultMeasured();
    const QJsonObject measure = q.value(jsonKey(keys::kMeasure)).toObject();
    q.insert(jsonKey(keys::kPrompt),
             QJsonObject{{currentLanguage(),
                          defaultPrompt(measure, bodyName(measure.value(u"body").toString()))}});
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
    const QJsonObject before = q;
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
    std::visit(physics::Overloaded{
                   [&](const lessons::MeasuredQuestion&) { applyMeasured(q); },
                   [&](const lessons::ChoiceQuestion&) { q = m_choices->applyTo(q); },
                   [&](const auto&) { m_pages[lessons::schema::questionKindIn(q)]->applyTo(q); }},
               kindIn(q));
    followMeasure(before, q);
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

void QuestionEditor::followMeasure(const QJsonObject& before, QJsonObject& q) const
{
    // The prompt the editor wrote follows what is measured, until the teacher writes their own.
    const QJsonObject was = before.value(jsonKey(keys::kMeasure)).toObject();
    const QJsonObject now = q.value(jsonKey(keys::kMeasure)).toObject();
    if (was == now || now.isEmpty())
        return;
    const QString language = currentLanguage();
    const QJsonValue prompt = q.value(jsonKey(keys::kPrompt));
    if (writtenText(prompt, language) !=
        defaultPrompt(was, bodyName(was.value(u"body").toString())))
        return;
    q.insert(jsonKey(keys::kPrompt),
             withWrittenText(prompt, language,
                             defaultPrompt(now, bodyName(now.value(u"body").toString()))));
}

QList<std::pair<QString, QString>> QuestionEditor::movingBodies() const
{
    // Read from the scene itself, so that they are listed even while the lesson has an error.
    QList<std::pair<QString, QString>> out;
    for (const QJsonValue b : m_draft.sceneObject(m_step).value(u"bodies").toArray()) {
        const QJsonObject body = b.toObject();
        const QString id = body.value(u"id").toString();
        if (id.isEmpty() || body.value(u"type").toString() == u"static")
            continue;
        const QString label = shownText(body.value(u"label"));
        out.append({id, label.isEmpty() ? id : label});
    }
    return out;
}

QString QuestionEditor::bodyName(const QString& id) const
{
    for (const auto& [bodyId, name] : movingBodies())
        if (bodyId == id)
            return name;
    return id;
}

void QuestionEditor::applyMeasured(QJsonObject& q)
{
    const MeasureName& k = measureName(m_kind->currentData().toString());
    QJsonObject measure{{QStringLiteral("kind"), QLatin1String(k.id)}};
    const QJsonObject old = q.value(jsonKey(keys::kMeasure)).toObject();
    if (k.body && m_body->currentIndex() >= 0)
        measure.insert(QStringLiteral("body"), m_body->currentData().toString());
    if (k.time)
        measure.insert(QStringLiteral("time"), m_time->value());
    else // an apex keeps its bounce and floor
        for (const char* key : {"n", "above"})
            if (old.contains(QLatin1String(key)) && old.value(u"kind").toString() == u"apex")
                measure.insert(QLatin1String(key), old.value(QLatin1String(key)));
    q.insert(jsonKey(keys::kMeasure), measure);
    if (old.value(u"kind").toString() != QLatin1String(k.id) &&
        m_unit->text() == measureName(old.value(u"kind").toString()).unit)
        m_unit->setText(QLatin1String(k.unit)); // the new quantity's unit, unless typed
    q.insert(jsonKey(keys::kUnit), m_unit->text());
    q.insert(jsonKey(keys::kTolerance), m_tolerance->value() / 100.0);
    if (m_set->value().isEmpty())
        q.remove(jsonKey(keys::kSet));
    else
        q.insert(jsonKey(keys::kSet), m_set->value());
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

    // The bodies of the step's scene that move, by their labels (the id where there is none),
    // each kept by its id.
    const QJsonObject q = question();
    const QJsonObject measure = q.value(jsonKey(keys::kMeasure)).toObject();
    m_body->clear();
    for (const auto& [id, name] : movingBodies())
        m_body->addItem(name, id);
    const QString body = measure.value(u"body").toString();
    if (!body.isEmpty() && m_body->findData(body) < 0)
        m_body->addItem(tr("%1 (not in the scene)").arg(body), body);
    m_body->setCurrentIndex(m_body->findData(body));

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
    const MeasureName& k = measureName(measure.value(u"kind").toString());
    m_kind->setCurrentIndex(m_kind->findData(QLatin1String(k.id)));
    m_body->setEnabled(k.body);
    m_time->setEnabled(k.time);
    m_time->setValue(measure.value(u"time").toDouble());
    showText(m_unit, q.value(jsonKey(keys::kUnit)).toString());
    m_tolerance->setValue(q.value(jsonKey(keys::kTolerance)).toDouble(0.05) * 100.0);
    m_set->show(q.value(jsonKey(keys::kSet)).toObject());
    m_holdRun->setChecked(
        q.value(jsonKey(keys::kHoldBack)).toArray().contains(QStringLiteral("run")));
    // Each kind shows its own fields only: the measured kind's rows, the options of a choice,
    // the page of a kind of ui/question_kinds/.
    const std::size_t kind = lessons::schema::questionKindIn(q);
    const bool measured = kind == lessons::schema::questionKindIndex<lessons::MeasuredQuestion>();
    const bool choice = kind == lessons::schema::questionKindIndex<lessons::ChoiceQuestion>();
    m_questionKind->setCurrentIndex(m_questionKind->findData(QVariant::fromValue(kind)));
    for (QWidget* w :
         std::initializer_list<QWidget*>{m_kind, m_body, m_time, m_unit, m_tolerance, m_set})
        m_fields->setRowVisible(w, measured);
    m_fields->setRowVisible(m_choices, choice);
    if (choice)
        m_choices->setQuestion(q);
    for (std::size_t k = 0; k < m_pages.size(); ++k)
        if (m_pages[k]) {
            m_fields->setRowVisible(m_pages[k], k == kind);
            if (k == kind)
                m_pages[k]->showQuestion(q);
        }
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
    std::visit(physics::Overloaded{
                   [&](const lessons::MeasuredQuestion& q) { showMeasured(step, question, q); },
                   [&](const lessons::ChoiceQuestion& q) {
                       // Nothing is measured for a choice: its line says which option is right.
                       m_answer->setAccessibleName(tr("The right option"));
                       m_answer->setText(
                           tr("The student chooses one of %1 options; the right one is “%2”.")
                               .arg(q.choices.size())
                               .arg(q.choices.value(q.answer)));
                   },
                   [&](const auto& kind) {
                       m_answer->setAccessibleName(tr("The right answer"));
                       m_answer->setText(lessons::keepUnitsTogether(answerLine(kind)));
                   }},
               question.kind);
}

void QuestionEditor::showMeasured(const lessons::LessonStep& step,
                                  const lessons::Question& question,
                                  const lessons::MeasuredQuestion& q)
{
    m_answer->setAccessibleName(tr("The answer the lab measures"));
    const std::optional<double> value =
        lessons::measureAhead(lessons::askedStep(step, question), q.measure);
    const QLocale locale;
    if (!value) {
        m_answer->setText(tr("⚠ The run does not get there (or diverges first): raise the step's "
                             "export time or choose an earlier time."));
        return;
    }
    const double band = std::abs(*value) * q.tolerance + q.absoluteTolerance;
    QString text = tr("The lab measures %1 %3; answers from %2 to %4 %3 are right.")
                       .arg(locale.toString(*value, 'g', 4), locale.toString(*value - band, 'g', 4),
                            q.unit, locale.toString(*value + band, 'g', 4));
    // Whether the integrators a student may choose measure wider apart than this is said in
    // the step's problems (lesson_editor/step_checks.h): those runs take a worker thread.
    m_answer->setText(lessons::keepUnitsTogether(text));
}

} // namespace rigidlab::ui
