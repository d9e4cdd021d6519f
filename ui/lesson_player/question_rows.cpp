// SPDX-License-Identifier: GPL-3.0-or-later
#include "lesson_player/question_rows.h"

#include "common/announcer.h"
#include "panels/number_field.h"
#include "question_kinds/question_kinds.h"

#include <QAbstractButton>
#include <QButtonGroup>
#include <QCoreApplication>
#include <QEvent>
#include <QFont>
#include <QLabel>
#include <QLineEdit>
#include <QPalette>
#include <QPointer>
#include <QPushButton>
#include <QScrollArea>
#include <QTimer>
#include <QVBoxLayout>

#include <cmath>
#include <variant>

namespace rigidlab::ui {

namespace {

/// Keeps a verdict scrolled into sight in `area` while the layout makes room for it, for a
/// moment after it is shown, then goes.
class VerdictRevealer : public QObject {
public:
    VerdictRevealer(QLabel& result, QScrollArea& area)
        : QObject(&result), m_result(&result), m_area(&area)
    {
        result.installEventFilter(this);
        if (area.widget())
            area.widget()->installEventFilter(this);
        revealSoon();
        QTimer::singleShot(kWatchMs, this, &QObject::deleteLater);
    }

protected:
    bool eventFilter(QObject*, QEvent* event) override
    {
        if (event->type() == QEvent::Resize || event->type() == QEvent::Move)
            revealSoon();
        return false;
    }

private:
    /// How long sizes are followed [ms]: the layout's passes take a few event loop turns.
    static constexpr int kWatchMs = 1000;

    /// After the scroll area has taken the new size in (its own filter comes after this one).
    void revealSoon()
    {
        QTimer::singleShot(0, this, [this] {
            // The whole label, not only its first line (ensureWidgetVisible() keeps a
            // selectable label's text cursor in sight, which is at its start).
            if (m_result && m_area && m_area->widget() && m_result->isVisible()) {
                const QPoint centre = m_result->mapTo(m_area->widget(), m_result->rect().center());
                m_area->ensureVisible(centre.x(), centre.y(), 0, m_result->height() / 2 + 8);
            }
        });
    }

    QPointer<QLabel> m_result;
    QPointer<QScrollArea> m_area;
};

/// The largest answer taken, in the question's unit: far beyond any measured value, and small
/// enough that |answer - measured| stays finite.
constexpr double kMaxAnswer = 1e15;

/// What a line under a question says, each kind drawn alike: bold, as large as the questions
/// (the step's text), in its kind's colour, its words saying which besides the colour
/// ("Right: …", "Not quite …", "Run … first").
enum class Said { Right, Wrong, Wait };

void drawAs(QLabel& line, Said said)
{
    // A font and a palette that set only the weight and the colour: the size is still the
    // questions' as it changes. (A style sheet's font-weight fixed the size the line had when
    // it was polished: one verdict stayed small after the text grew.)
    QFont bold;
    bold.setBold(true);
    line.setFont(bold);
    QPalette colour;
    colour.setColor(QPalette::WindowText, said == Said::Right   ? QColor(0x1e, 0x7b, 0x34)
                                          : said == Said::Wrong ? QColor(0xb3, 0x26, 0x1e)
                                                                : QColor(0xa0, 0x5a, 0x00));
    line.setPalette(colour);
}

} // namespace

QuestionRows::QuestionRows(QWidget* parent) : QWidget(parent), m_layout(new QVBoxLayout(this))
{
    setObjectName(QStringLiteral("lessonQuestions"));
    m_layout->setContentsMargins(0, 0, 0, 0);
}

void QuestionRows::build(const std::vector<lessons::Question>& questions,
                         const std::function<RowHooks(std::size_t)>& hooks)
{
    while (QLayoutItem* item = m_layout->takeAt(0)) {
        delete item->widget();
        delete item;
    }
    m_rows.clear();
    for (std::size_t i = 0; i < questions.size(); ++i) {
        const lessons::Question& q = questions[i];
        auto* box = new QWidget(this);
        auto* v = new QVBoxLayout(box);
        v->setContentsMargins(0, 4, 0, 4);
        auto* prompt = new QLabel(lessons::keepUnitsTogether(q.prompt), box);
        prompt->setWordWrap(true);
        v->addWidget(prompt);
        m_layout->addWidget(box);
        // Each kind builds its row (ui/question_kinds/).
        m_rows.push_back(std::visit(
            [&](const auto& kind) { return answerRow(kind, prompt, v, hooks(i)); }, q.kind));
    }
}

std::optional<double> QuestionRows::typedNumber(std::size_t i)
{
    const std::optional<double> parsed = parseNumber(m_rows.at(i).edit->text());
    if (!parsed) {
        askFirst(i,
                 QCoreApplication::translate("rigidlab::ui::LessonPlayer", "Type a number first."));
        return std::nullopt;
    }
    if (std::abs(*parsed) > kMaxAnswer) {
        askFirst(i, QCoreApplication::translate("rigidlab::ui::LessonPlayer",
                                                "Type a number from %1 to %2.")
                        .arg(formatNumber(-kMaxAnswer), formatNumber(kMaxAnswer)));
        return std::nullopt;
    }
    return parsed;
}

void QuestionRows::askFirst(std::size_t i, const QString& text)
{
    const AnswerRow& row = m_rows.at(i);
    drawAs(*row.result, Said::Wait);
    row.result->setText(text);
    row.result->setVisible(true);
    revealResult(i);
    // Check pressed on an empty box: the focus goes to the box, where the number is typed
    // (typed at the button, it was lost), and a reader names the question with it.
    if (row.edit && row.check && row.check->hasFocus() && row.edit->text().trimmed().isEmpty())
        row.edit->setFocus(Qt::OtherFocusReason);
    // Told, as a verdict is: the line changes out of the focus, and a reader would say nothing.
    announce(*row.result, text);
}

void QuestionRows::showVerdict(std::size_t i, const lessons::Verdict& v,
                               const lessons::AnswerTry& attempt, bool tell)
{
    const AnswerRow& row = m_rows.at(i);
    drawAs(*row.result, !v.measured ? Said::Wait : v.right ? Said::Right : Said::Wrong);
    // A choice's verdict is marked as well as worded and coloured (a number's says its value).
    const QString mark = !row.choices || !v.measured                 ? QString()
                         : v.right                                   ? QStringLiteral("✓ ")
                         : v.shown && attempt.choice == std::nullopt ? QStringLiteral("◆ ")
                                                                     : QStringLiteral("✗ ");
    row.result->setText(mark + v.message);
    row.result->setVisible(true);
    revealResult(i);
    // The verdict is told, where the focus stays on the answer or the Check button: a label
    // that changes out of the focus is not read.
    if (tell)
        announce(*row.result, row.result->text());
}

void QuestionRows::setGiven(std::size_t i)
{
    m_rows.at(i).show->setEnabled(false);
}

void QuestionRows::revealResult(std::size_t i)
{
    // The questions are in sight below the text, but a later question's verdict may lie below
    // the bottom of their area when they do not all fit. It is scrolled into sight (the
    // question's box with it, so that the answer stays beside its verdict) each time the
    // layout makes more room for it: the verdict wraps to its lines and the questions' box
    // grows a moment after it is shown, and a scroll made before that left it cut in half.
    QWidget* viewport = parentWidget();
    auto* area = qobject_cast<QScrollArea*>(viewport ? viewport->parentWidget() : nullptr);
    if (area)
        new VerdictRevealer(*m_rows[i].result, *area);
}

QStringList QuestionRows::typed() const
{
    QStringList out;
    // A choice question's "box" is the option chosen, by its index.
    for (const AnswerRow& row : m_rows)
        out << (row.edit                       ? row.edit->text()
                : row.choices->checkedId() < 0 ? QString()
                                               : QString::number(row.choices->checkedId()));
    return out;
}

void QuestionRows::setTyped(std::size_t i, const QString& typed)
{
    const AnswerRow& row = m_rows.at(i);
    if (row.edit)
        row.edit->setText(typed);
    else if (QAbstractButton* option = row.choices->button(typed.toInt());
             option && !typed.isEmpty())
        option->setChecked(true);
}

QList<QWidget*> QuestionRows::tabStops() const
{
    QList<QWidget*> out;
    for (QWidget* w : findChildren<QWidget*>())
        if (w->focusPolicy() & Qt::TabFocus)
            out << w;
    return out;
}

QWidget* QuestionRows::firstAnswer() const
{
    const auto open = [](QWidget* w) { return w && w->isVisible() && w->isEnabled(); };
    for (const AnswerRow& row : m_rows) {
        if (open(row.edit))
            return row.edit;
        if (!row.choices)
            continue;
        if (QAbstractButton* chosen = row.choices->checkedButton(); open(chosen))
            return chosen;
        const QList<QAbstractButton*> options = row.choices->buttons();
        if (!options.isEmpty() && open(options.first()))
            return options.first();
    }
    return nullptr;
}

const AnswerRow* QuestionRows::row(int question) const
{
    if (question < 0 || question >= static_cast<int>(m_rows.size()))
        return nullptr;
    return &m_rows[static_cast<std::size_t>(question)];
}

void QuestionRows::answer(int question, const QString& text)
{
    if (const AnswerRow* r = row(question); r && r->edit) {
        r->edit->setText(text);
        emit r->edit->returnPressed();
    }
}

void QuestionRows::choose(int question, int option)
{
    if (const AnswerRow* r = row(question); r && r->choices) {
        if (QAbstractButton* b = r->choices->button(option))
            b->setChecked(true);
        r->check->click();
    }
}

void QuestionRows::showMe(int question)
{
    if (const AnswerRow* r = row(question))
        r->show->click();
}

QString QuestionRows::result(int question) const
{
    const AnswerRow* r = row(question);
    return r ? r->result->text() : QString();
}

} // namespace rigidlab::ui
