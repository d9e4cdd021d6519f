// SPDX-License-Identifier: GPL-3.0-or-later
#include "worksheet/worksheet.h"

#include "common/display_names.h"
#include "common/number_format.h"
#include "plots/lesson_export.h"
#include "plots/plot_widget.h"
#include "question_kinds/question_kinds.h"
#include "worksheet/worksheet_page.h"
#include "worksheet/worksheet_plots.h"

#include "format/atomic_file.h"
#include "format/scene_schema.h"
#include "run/measurements.h"

#include <QCoreApplication>
#include <QDate>
#include <QDir>
#include <QFileInfo>
#include <QPdfWriter>

#include <memory>
#include <variant>

namespace rigidlab::ui {

namespace {

struct Worksheet {
    Q_DECLARE_TR_FUNCTIONS(Worksheet)
};

/// What a question needs on the page below its prompt to start there rather than on the next
/// page: an answer line or two [device pixels].
constexpr int kQuestionRoom = 90;

/// The verdicts of a question's tries, judged again in order as the lesson player judged
/// them.
std::vector<lessons::Verdict> judgeTries(const lessons::Question& q,
                                         const std::vector<lessons::AnswerTry>& tries)
{
    std::vector<lessons::Verdict> out;
    lessons::TryCount count;
    for (const lessons::AnswerTry& t : tries)
        out.push_back(lessons::judgeTry(q, t, count));
    return out;
}

/// The verdict in a word with a sign, so that it is told without colour.
QString verdictWord(const lessons::Verdict& v, bool showMe)
{
    if (!v.measured)
        return Worksheet::tr("… not measured yet");
    if (showMe)
        return Worksheet::tr("◆ shown");
    return v.right ? Worksheet::tr("✓ right") : Worksheet::tr("✗ not right");
}

/// "integrator Verlet · dt = 0.001 s · solver The paper's impulse": what repeats the run, as
/// the window's status line names the solver.
QString settingsLine(const lessons::LessonStep& step, const physics::WorldDef& ran)
{
    const auto names = [&] {
        QStringList list;
        for (int i = 0; i < step.compare->count(); ++i)
            list.append(methodDisplayName(step.compare->label(i)));
        return list.join(QStringLiteral(", "));
    };
    const bool byIntegrator = step.compare && !step.compare->integrators.empty();
    const bool bySolver = step.compare && !step.compare->solvers.empty();
    const QString solver = bySolver ? names() : solverDisplayName(ran.solver);
    QString line = Worksheet::tr("Settings: integrator %1 · dt = %2 s · solver %3")
                       .arg(byIntegrator ? names() : integratorDisplayName(ran.integrator),
                            formatReadable(ran.dt, 6), solver);
    // Every other setting the step (or a question the student answered) set: e = 0 is what
    // "set e = 0 and run again" ran with.
    for (const lessons::schema::Field& f : lessons::schema::settings()) {
        const lessons::schema::Value v = step.settings.value(f.key);
        if (f.key == "integrator" || f.key == "dt" || f.key == "solver" || f.key == "timeScale" ||
            std::holds_alternative<std::monostate>(v))
            continue;
        const QString shown = std::holds_alternative<double>(v)
                                  ? formatReadable(std::get<double>(v), 6)
                              : std::holds_alternative<bool>(v)
                                  ? (std::get<bool>(v) ? Worksheet::tr("on") : Worksheet::tr("off"))
                                  : lessons::schema::text(v);
        line += QStringLiteral(" · %1 = %2")
                    .arg(QCoreApplication::translate(lessons::schema::kContext, f.label), shown);
    }
    return line;
}

class SheetWriter {
public:
    SheetWriter(const lessons::Lesson& lesson, const lessons::Answers& answers, WorksheetKind kind,
                WorksheetPages& pages)
        : m_lesson(lesson), m_answers(answers), m_kind(kind), m_pages(pages)
    {
        m_bold = pages.baseFont();
        m_bold.setBold(true);
        m_heading = m_bold;
        m_heading.setPointSizeF(m_bold.pointSizeF() * 1.3);
        m_small = pages.baseFont();
        m_small.setPointSizeF(m_small.pointSizeF() * 0.9);
    }
    void write(std::vector<int>& figures);

private:
    void writeTitle();
    void writeStep(int index, int& figures);
    void writeQuestion(const lessons::LessonStep& step, int s, int q);
    /// The lines the question's kind writes under its prompt (ui/question_kinds/).
    void writeLines(const SheetQuestion& at, const std::vector<SheetLine>& lines);
    /// The tries with their verdicts, a typed answer in `unit`.
    void writeTries(const SheetQuestion& at, const QString& unit);
    const std::vector<lessons::AnswerTry>& triesOf(int step, int question) const;

    const lessons::Lesson& m_lesson;
    const lessons::Answers& m_answers;
    WorksheetKind m_kind;
    WorksheetPages& m_pages;
    QFont m_bold, m_heading, m_small;
};

const std::vector<lessons::AnswerTry>& SheetWriter::triesOf(int step, int question) const
{
    static const std::vector<lessons::AnswerTry> none;
    if (step >= static_cast<int>(m_answers.steps.size()))
        return none;
    const auto& questions = m_answers.steps[static_cast<std::size_t>(step)].questions;
    return question < static_cast<int>(questions.size())
               ? questions[static_cast<std::size_t>(question)]
               : none;
}

void SheetWriter::write(std::vector<int>& figures)
{
    writeTitle();
    for (int i = 0; i < static_cast<int>(m_lesson.steps.size()); ++i) {
        int drawn = 0;
        writeStep(i, drawn);
        figures.push_back(drawn);
    }
}

void SheetWriter::writeTitle()
{
    QFont title = m_heading;
    title.setPointSizeF(m_heading.pointSizeF() * 1.35);
    m_pages.text(m_lesson.title, title);
    m_pages.gap(4);
    const QString what = m_kind == WorksheetKind::Answers ? Worksheet::tr("Worksheet")
                         : m_kind == WorksheetKind::Empty
                             ? Worksheet::tr("Worksheet to fill in")
                             : Worksheet::tr("Teacher's key: the measured answers");
    m_pages.text(what, m_bold);
    m_pages.gap(8);
    if (m_kind == WorksheetKind::Key) {
        m_pages.gap(12);
        return;
    }
    // What the student has not given is left to be written by hand.
    const auto field = [this](const QString& label, const QString& value) {
        m_pages.text(label.arg(value), m_pages.baseFont());
        if (value.isEmpty())
            m_pages.writingLines(1);
    };
    field(Worksheet::tr("Name: %1"), m_answers.student);
    field(Worksheet::tr("Class: %1"), m_answers.className);
    const QDate date = QDate::fromString(m_answers.date, Qt::ISODate);
    field(Worksheet::tr("Date: %1"),
          date.isValid() ? QLocale().toString(date, QLocale::LongFormat) : m_answers.date);
    m_pages.gap(12);
}

void SheetWriter::writeStep(int index, int& figures)
{
    const lessons::StepAnswers noAnswers;
    const auto at = static_cast<std::size_t>(index);
    const lessons::StepAnswers& ran =
        at < m_answers.steps.size() && m_kind == WorksheetKind::Answers ? m_answers.steps[at]
                                                                        : noAnswers;
    const lessons::LessonStep step = stepAsRun(m_lesson.steps[at], ran);
    auto holder = std::make_unique<QWidget>();
    const StepPlots plots = runStepPlots(step, holder.get());

    // The step's heading stays on the page of what follows it: its first question, else its
    // first figure.
    const QString heading = Worksheet::tr("Step %1: %2").arg(index + 1).arg(step.title);
    const QString settings = settingsLine(step, plots.settings);
    int first = 0;
    if (!step.questions.empty())
        first = m_pages.heightOf(step.questions.front().prompt, m_bold) + kQuestionRoom;
    else if (!plots.plots.empty())
        first = m_pages.heightOf(plots.plots.front()->title(), m_small) + m_pages.figureHeight();
    m_pages.keepRoom(m_pages.heightOf(heading, m_heading) + m_pages.heightOf(settings, m_small) +
                     first);
    m_pages.text(heading, m_heading);
    m_pages.text(settings, m_small);
    m_pages.gap(6);
    for (int q = 0; q < static_cast<int>(step.questions.size()); ++q)
        writeQuestion(step, index, q);
    const QString caption = stepCaption(m_lesson, index, plots.settings);
    for (std::size_t k = 0; k < plots.plots.size(); ++k) {
        PlotWidget* plot = plots.plots[k];
        plot->setCaption(caption);
        m_pages.keepRoom(m_pages.heightOf(plot->title(), m_small) + m_pages.figureHeight());
        m_pages.text(Worksheet::tr("Figure %1.%2: %3")
                         .arg(index + 1)
                         .arg(static_cast<int>(k) + 1)
                         .arg(plot->title()),
                     m_small);
        m_pages.figure(*plot);
        ++figures;
    }
    m_pages.gap(14);
}

void SheetWriter::writeQuestion(const lessons::LessonStep& step, int s, int q)
{
    const lessons::Question& question = step.questions[static_cast<std::size_t>(q)];
    const QString prompt = Worksheet::tr("Question %1.%2: %3")
                               .arg(s + 1)
                               .arg(q + 1)
                               .arg(lessons::keepUnitsTogether(question.prompt));
    m_pages.keepRoom(m_pages.heightOf(prompt, m_bold) + kQuestionRoom);
    m_pages.text(prompt, m_bold);
    const std::vector<lessons::AnswerTry>& tries = triesOf(s, q);
    const std::vector<lessons::Verdict> verdicts = judgeTries(question, tries);
    const SheetQuestion at{m_kind, &step, &question, tries, verdicts};
    std::visit([&](const auto& kind) { writeLines(at, worksheetLines(kind, at)); }, question.kind);
    m_pages.gap(6);
}

void SheetWriter::writeLines(const SheetQuestion& at, const std::vector<SheetLine>& lines)
{
    const int indent = 18;
    for (const SheetLine& line : lines) {
        switch (line.is) {
        case SheetLine::Is::Text:
            m_pages.text(line.text, m_pages.baseFont(), indent);
            break;
        case SheetLine::Is::Bold:
            m_pages.text(line.text, m_bold, indent);
            break;
        case SheetLine::Is::WritingLine:
            m_pages.writingLines(1, indent);
            break;
        case SheetLine::Is::Tries:
            writeTries(at, line.text);
            break;
        }
    }
}

void SheetWriter::writeTries(const SheetQuestion& at, const QString& unit)
{
    const int indent = 18;
    if (at.tries.empty()) {
        m_pages.text(Worksheet::tr("Not answered."), m_pages.baseFont(), indent);
        return;
    }
    for (std::size_t k = 0; k < at.tries.size(); ++k) {
        const lessons::AnswerTry& t = at.tries[k];
        const lessons::Verdict& v = at.verdicts[k];
        // A try before the run measured anything, or judged by a run ahead, is a prediction.
        const bool given = t.answer || t.choice;
        const QString label = t.answer && (t.ahead || !t.measured)
                                  ? Worksheet::tr("Prediction %1").arg(k + 1)
                              : given ? Worksheet::tr("Answer %1").arg(k + 1)
                                      : Worksheet::tr("Show me");
        const QString answer = t.choice   ? QStringLiteral("“%1”").arg(t.choiceText)
                               : t.answer ? sheetQuantity(*t.answer, unit)
                                          : Worksheet::tr("(no answer)");
        m_pages.text(
            QStringLiteral("%1: %2 — %3. %4").arg(label, answer, verdictWord(v, !given), v.message),
            m_pages.baseFont(), indent);
    }
}

/// `text` in a bidirectional isolate (Unicode's FSI … PDI): a name written right to left
/// keeps to itself and does not reorder the parts around it ("أحمد محمد" beside "2.B").
QString isolated(const QString& text)
{
    return QChar(0x2068) + text + QChar(0x2069);
}

QString headerLine(const lessons::Lesson& lesson, const lessons::Answers& answers,
                   WorksheetKind kind)
{
    QStringList parts{isolated(lesson.title)};
    if (kind == WorksheetKind::Answers) {
        for (const QString& part : {answers.student, answers.className, answers.date})
            if (!part.isEmpty())
                parts << isolated(part);
    } else if (kind == WorksheetKind::Key) {
        parts << Worksheet::tr("teacher's key");
    }
    return parts.join(QStringLiteral(" · "));
}

} // namespace

WorksheetResult writeWorksheet(const lessons::Lesson& lesson, const lessons::Answers& answers,
                               WorksheetKind kind, const QString& path)
{
    WorksheetResult result;
    if (const QString bad = lessons::answersMismatch(answers, QFileInfo(lesson.path).fileName(),
                                                     lessons::questionCounts(lesson));
        !bad.isEmpty()) {
        result.error =
            Worksheet::tr("%1 does not fit the lesson: %2")
                .arg(answers.lessonFile.isEmpty() ? lesson.title : answers.lessonFile, bad);
        return result;
    }
    const std::optional<QByteArray> bytes =
        drawPdf(headerLine(lesson, answers, kind), [&](QPdfWriter& pdf) {
            WorksheetPages pages(pdf, headerLine(lesson, answers, kind));
            if (!pages.began())
                return false;
            SheetWriter(lesson, answers, kind, pages).write(result.figures);
            result.pages = pages.pages();
            pages.end();
            return true;
        });
    if (!bytes) {
        result.error = Worksheet::tr("cannot write %1: could not start drawing the PDF")
                           .arg(QDir::toNativeSeparators(path));
        return result;
    }
    if (const QString error = lessons::writeFileAtomically(path, *bytes); !error.isEmpty()) {
        result.error = error;
        result.figures.clear();
        return result;
    }
    result.ok = true;
    return result;
}

QString answersPathFor(const QString& pdfPath)
{
    const QFileInfo info(pdfPath);
    return info.dir().filePath(info.completeBaseName() + QStringLiteral(".answers.json"));
}

QString worksheetFileName(const lessons::Lesson& lesson, const QString& student)
{
    const QString stem = QFileInfo(lesson.path).completeBaseName();
    const QString who = lessons::schema::safeFileStem(student, QString());
    return (who.isEmpty() ? stem : stem + u'-' + who) + QStringLiteral(".pdf");
}

} // namespace rigidlab::ui
