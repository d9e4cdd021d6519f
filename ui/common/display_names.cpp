// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/display_names.h"

#include "format/view_text.h"

#include <QCoreApplication>

#include <array>
#include <string_view>

namespace rigidlab::ui {

namespace {

struct IntegratorWords {
    physics::IntegratorKind kind;
    const char* words; ///< for QT_TRANSLATE_NOOP
};

// One row per integrator; a kind missing here shows its code name (see the test).
constexpr std::array<IntegratorWords, 6> kIntegratorWords{{
    {physics::IntegratorKind::Euler,
     QT_TRANSLATE_NOOP("rigidlab::ui::displayNames", "Explicit Euler")},
    {physics::IntegratorKind::SymplecticEuler,
     QT_TRANSLATE_NOOP("rigidlab::ui::displayNames", "Symplectic Euler")},
    {physics::IntegratorKind::Verlet,
     QT_TRANSLATE_NOOP("rigidlab::ui::displayNames", "Velocity Verlet")},
    {physics::IntegratorKind::RK4,
     QT_TRANSLATE_NOOP("rigidlab::ui::displayNames", "Runge–Kutta 4")},
    {physics::IntegratorKind::DormandPrince,
     QT_TRANSLATE_NOOP("rigidlab::ui::displayNames", "Dormand–Prince 5(4), adaptive")},
    {physics::IntegratorKind::ImplicitMidpoint,
     QT_TRANSLATE_NOOP("rigidlab::ui::displayNames", "Implicit midpoint")},
}};

struct StageWords {
    physics::Stage stage;
    const char* words; ///< for QT_TRANSLATE_NOOP
};

// One row per stage of a step, in the order of physics::Stage.
constexpr std::array<StageWords, physics::kStageCount> kStageWords{{
    {physics::Stage::BroadPhase, QT_TRANSLATE_NOOP("rigidlab::ui::displayNames", "broad phase")},
    {physics::Stage::NarrowPhase, QT_TRANSLATE_NOOP("rigidlab::ui::displayNames", "narrow phase")},
    {physics::Stage::Islands, QT_TRANSLATE_NOOP("rigidlab::ui::displayNames", "islands")},
    {physics::Stage::Forces, QT_TRANSLATE_NOOP("rigidlab::ui::displayNames", "forces")},
    {physics::Stage::Integration, QT_TRANSLATE_NOOP("rigidlab::ui::displayNames", "integration")},
    {physics::Stage::ContactSolve,
     QT_TRANSLATE_NOOP("rigidlab::ui::displayNames", "contact solve")},
    {physics::Stage::Sleep, QT_TRANSLATE_NOOP("rigidlab::ui::displayNames", "sleep")},
    {physics::Stage::Diagnostics, QT_TRANSLATE_NOOP("rigidlab::ui::displayNames", "diagnostics")},
}};

struct SolverWords {
    physics::SolverKind kind;
    const char* words;
};

constexpr std::array<SolverWords, 3> kSolverWords{{
    {physics::SolverKind::PaperImpulse,
     QT_TRANSLATE_NOOP("rigidlab::ui::displayNames", "The paper's impulse")},
    {physics::SolverKind::SequentialImpulse,
     QT_TRANSLATE_NOOP("rigidlab::ui::displayNames", "Sequential impulse")},
    {physics::SolverKind::SoftStep,
     QT_TRANSLATE_NOOP("rigidlab::ui::displayNames", "Soft step (substepping)")},
}};

QString translated(const char* words)
{
    return QCoreApplication::translate("rigidlab::ui::displayNames", words);
}

} // namespace

QString stageDisplayName(physics::Stage stage)
{
    for (const StageWords& row : kStageWords)
        if (row.stage == stage)
            return translated(row.words);
    return QString::fromLatin1(physics::stageName(stage));
}

QString integratorDisplayName(physics::IntegratorKind kind)
{
    for (const IntegratorWords& row : kIntegratorWords)
        if (row.kind == kind)
            return translated(row.words);
    return lessons::textFromView(physics::integratorName(kind));
}

QString solverDisplayName(physics::SolverKind kind)
{
    for (const SolverWords& row : kSolverWords)
        if (row.kind == kind)
            return translated(row.words);
    return lessons::textFromView(physics::solverName(kind));
}

QString methodDisplayName(const QString& codeName)
{
    const QByteArray utf8 = codeName.toUtf8();
    const std::string_view name(utf8.constData(), static_cast<std::size_t>(utf8.size()));
    if (const auto integrator = physics::integratorFromName(name))
        return integratorDisplayName(*integrator);
    if (const auto solver = physics::solverFromName(name))
        return solverDisplayName(*solver);
    return codeName;
}

QString menuEntryText(const QString& name)
{
    QString text = name;
    return text.replace(u'&', QStringLiteral("&&"));
}

} // namespace rigidlab::ui
