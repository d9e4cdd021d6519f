// SPDX-License-Identifier: GPL-3.0-or-later
#include "panels/impulse_formula_view.h"

#include "common/number_format.h"

#include <QCoreApplication>
#include <QLabel>
#include <QTextDocumentFragment>
#include <QToolButton>
#include <QVBoxLayout>

namespace rigidlab::ui {

namespace {

/// The translation context of the formula.
struct ImpulseFormula {
    Q_DECLARE_TR_FUNCTIONS(ImpulseFormula)
};

QString num(double v)
{
    return formatReadable(v, 4);
}

QString vec(const physics::Vec2& v)
{
    return ImpulseFormula::tr("(%1, %2)").arg(num(v.x()), num(v.y()));
}

QString withUnit(const QString& number, const QString& unit)
{
    return number + QChar(0x00A0) + unit;
}

/// The formula in symbols, as the lessons write it.
QString symbols()
{
    return QStringLiteral("j = −(1 + e) (v<sub>A</sub> − v<sub>B</sub>)·n / (1/m<sub>A</sub> + "
                          "1/m<sub>B</sub> + (r<sub>A</sub> × n)²/I<sub>A</sub> + "
                          "(r<sub>B</sub> × n)²/I<sub>B</sub>)");
}

/// (r × n)² / I of one body, 0 for a body that does not turn (static, infinite I).
double rotationalTerm(const physics::Vec2& lever, const physics::Vec2& n, const physics::Body& b)
{
    const double rn = lever.x() * n.y() - lever.y() * n.x();
    return rn * rn * b.invInertia;
}

} // namespace

ImpulseFormulaView::ImpulseFormulaView(QWidget* parent)
    : QWidget(parent), m_toggle(new QToolButton(this)), m_formula(new QLabel(this))
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    // Short: the toolbutton does not wrap, and a longer text made the collision panel wider
    // than the window's right-hand column at 1024 x 768 (its "after" column out of sight).
    m_toggle->setText(tr("Impulse formula"));
    m_toggle->setToolTip(tr("The impulse formula with this collision's numbers"));
    m_toggle->setCheckable(true);
    m_toggle->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    m_toggle->setArrowType(Qt::RightArrow);
    m_toggle->setAccessibleName(tr("Show the impulse formula"));
    layout->addWidget(m_toggle);
    m_formula->setWordWrap(true);
    m_formula->setTextFormat(Qt::RichText);
    m_formula->setTextInteractionFlags(Qt::TextSelectableByMouse | Qt::TextSelectableByKeyboard);
    m_formula->setAccessibleName(tr("Impulse formula"));
    m_formula->setVisible(false);
    layout->addWidget(m_formula);
    connect(m_toggle, &QToolButton::toggled, this, &ImpulseFormulaView::setOpen);
    showNone();
}

QString ImpulseFormulaView::text() const
{
    return m_formula->text();
}

void ImpulseFormulaView::setOpen(bool open)
{
    m_toggle->setChecked(open);
    m_toggle->setArrowType(open ? Qt::DownArrow : Qt::RightArrow);
    m_formula->setVisible(open);
}

namespace {

/// Gives `label` the plain text of `html` as its description, told to a screen reader only
/// when it changes: the panel is refreshed every frame, and every description set is an event.
void describe(QLabel& label, const QString& html)
{
    const QString plain = QTextDocumentFragment::fromHtml(html).toPlainText();
    if (label.accessibleDescription() != plain)
        label.setAccessibleDescription(plain);
}

} // namespace

void ImpulseFormulaView::showHit(const lessons::CollisionEvent& hit, const physics::Body& a,
                                 const physics::Body& b, const QString& nameA, const QString& nameB,
                                 bool held)
{
    const QString text = impulseFormulaText(hit, a, b, nameA, nameB, held);
    m_formula->setText(text);
    describe(*m_formula, text);
}

void ImpulseFormulaView::showNone()
{
    m_formula->setText(QStringLiteral("<p>") + symbols() + QStringLiteral("</p><p>") +
                       tr("The numbers of the first collision appear here when it happens.") +
                       QStringLiteral("</p>"));
    describe(*m_formula, m_formula->text());
}

QString impulseFormulaText(const lessons::CollisionEvent& hit, const physics::Body& a,
                           const physics::Body& b, const QString& nameA, const QString& nameB,
                           bool held)
{
    // The record's normal points from a to b; the lessons write n from B to A, which leaves
    // each term as it is: (v_A − v_B)·n_BA = (v_b − v_a)·n_ab, and (r × n)² keeps its sign.
    const physics::Vec2 n = -hit.normal;
    const double rotA = rotationalTerm(hit.lever[0], n, a);
    const double rotB = rotationalTerm(hit.lever[1], n, b);
    const QString perKg = QStringLiteral("1/kg");
    const QString j =
        held ? QStringLiteral("?") : withUnit(num(hit.impulse), QStringLiteral("N·s"));
    QString html = QStringLiteral("<p><b>") +
                   ImpulseFormula::tr("The impulse of this collision, term by term (A: %1, B: %2)")
                       .arg(nameA.toHtmlEscaped(), nameB.toHtmlEscaped()) +
                   QStringLiteral("</b></p><p>") + symbols() + QStringLiteral("<br>= −(1 + ") +
                   num(hit.restitution) + QStringLiteral(") × (") +
                   withUnit(num(hit.approach), QStringLiteral("m/s")) + QStringLiteral(") / (") +
                   num(a.invMass) + QStringLiteral(" + ") + num(b.invMass) + QStringLiteral(" + ") +
                   num(rotA) + QStringLiteral(" + ") + num(rotB) + QStringLiteral(")&nbsp;") +
                   perKg + QStringLiteral("<br>= ") + j + QStringLiteral("</p><ul>");
    const auto item = [&html](const QString& line) {
        html += QStringLiteral("<li>") + line + QStringLiteral("</li>");
    };
    item(ImpulseFormula::tr("e = %1: the coefficient of restitution").arg(num(hit.restitution)));
    item(ImpulseFormula::tr("n = %1: the contact normal, from B to A").arg(vec(n)));
    item(ImpulseFormula::tr("(v<sub>A</sub> − v<sub>B</sub>)·n = %1: how fast the contact "
                            "points approach along n (negative: approaching)")
             .arg(withUnit(num(hit.approach), QStringLiteral("m/s"))));
    item(ImpulseFormula::tr("1/m<sub>A</sub> = %1, 1/m<sub>B</sub> = %2: the masses (0 for a "
                            "body that does not move)")
             .arg(withUnit(num(a.invMass), perKg), withUnit(num(b.invMass), perKg)));
    item(ImpulseFormula::tr("r<sub>A</sub> = %1: the lever arm of A, from its centre of mass "
                            "to the contact point; (r<sub>A</sub> × n)²/I<sub>A</sub> = %2")
             .arg(withUnit(vec(hit.lever[0]), QStringLiteral("m")), withUnit(num(rotA), perKg)));
    item(ImpulseFormula::tr("r<sub>B</sub> = %1: the lever arm of B; (r<sub>B</sub> × "
                            "n)²/I<sub>B</sub> = %2")
             .arg(withUnit(vec(hit.lever[1]), QStringLiteral("m")), withUnit(num(rotB), perKg)));
    html += QStringLiteral("</ul>");
    if (held)
        html += QStringLiteral("<p>") +
                ImpulseFormula::tr("j is shown once you have answered the lesson's question.") +
                QStringLiteral("</p>");
    return html;
}

} // namespace rigidlab::ui
