// SPDX-License-Identifier: GPL-3.0-or-later
#include "window/demo_class.h"

#include "format/answers_file.h"
#include "format/atomic_file.h"

#include <QDir>

#include <optional>
#include <vector>

namespace rigidlab::ui {

namespace {

using lessons::AnswerTry;

/// A checked answer judged against `measured` (the run had got there).
AnswerTry checked(double answer, double measured)
{
    AnswerTry t;
    t.answer = answer;
    t.measured = measured;
    return t;
}

/// "Show me" after the run measured `measured`.
AnswerTry showMe(double measured)
{
    AnswerTry t;
    t.measured = measured;
    return t;
}

// What the lab measures in restitution.json's questions, step by step (rounded: the demo
// only needs values near them) [m, m/s, rad/s].
constexpr double kSecondBounce = 0.41, kThirdBounce = 0.0156;
constexpr double kHeavyAfter = 0.333, kLightAfter = 1.333;
constexpr double kLightHalf = 1.0, kTogether = 0.667, kSpin = 3.2;

struct DemoStudent {
    QString file; ///< the answers file's name, plain ASCII
    lessons::Answers answers;
};

lessons::Answers student(const QString& name, const QString& date,
                         std::vector<std::vector<std::vector<AnswerTry>>> steps)
{
    lessons::Answers a;
    a.lessonFile = QStringLiteral("restitution.json");
    // As the window's Hand in writes it: the title in the language played (this class's).
    a.lessonTitle = QStringLiteral("Odrazy a srážky: koeficient restituce");
    a.student = name;
    a.className = QStringLiteral("2.B");
    a.date = date;
    for (auto& questions : steps)
        a.steps.push_back({std::move(questions), std::nullopt, std::nullopt, std::nullopt});
    return a;
}

std::vector<DemoStudent> demoStudents()
{
    const QString day = QStringLiteral("2026-12-03");
    return {
        {QStringLiteral("restitution-jana.answers.json"),
         student(QStringLiteral("Jana Nováková"), day,
                 {{{checked(0.41, kSecondBounce)}, {checked(0.0156, kThirdBounce)}},
                  {{checked(0.33, kHeavyAfter)}, {checked(1.33, kLightAfter)}},
                  {{checked(1.0, kLightHalf)}, {checked(0.67, kTogether)}},
                  {{checked(3.2, kSpin)}}})},
        {QStringLiteral("restitution-petr.answers.json"),
         student(QStringLiteral("Petr Svoboda"), day,
                 {{{checked(0.64, kSecondBounce), checked(0.41, kSecondBounce)},
                   {checked(0.125, kThirdBounce), showMe(kThirdBounce)}},
                  {{checked(0.5, kHeavyAfter), checked(0.333, kHeavyAfter)},
                   {checked(1.33, kLightAfter)}}})},
        {QStringLiteral("restitution-eva.answers.json"),
         student(QStringLiteral("Eva Dvořáková"), day,
                 {{{checked(0.41, kSecondBounce)}, {checked(0.0625, kThirdBounce)}},
                  {{checked(0.333, kHeavyAfter)}, {checked(1.0, kLightAfter)}},
                  {{checked(1.0, kLightHalf)}, {checked(0.5, kTogether)}}})},
        {QStringLiteral("restitution-tomas.answers.json"),
         student(QStringLiteral("Tomáš Černý"), QStringLiteral("2026-12-04"),
                 {{{showMe(kSecondBounce)}, {checked(0.0156, kThirdBounce)}}})},
        {QStringLiteral("restitution-lucie.answers.json"),
         student(QStringLiteral("Lucie Veselá"), day,
                 {{{checked(0.4, kSecondBounce)}, {checked(0.016, kThirdBounce)}},
                  {{checked(0.333, kHeavyAfter)}, {checked(1.333, kLightAfter)}},
                  {{checked(1.0, kLightHalf)}, {checked(0.667, kTogether)}},
                  {{checked(2.0, kSpin), checked(3.2, kSpin)}}})},
    };
}

} // namespace

QString writeDemoClass(const QString& folder)
{
    const QDir dir(folder);
    const std::vector<DemoStudent> students = demoStudents();
    for (const DemoStudent& s : students)
        if (const QString error =
                lessons::writeFileAtomically(dir.filePath(s.file), lessons::answersJson(s.answers));
            !error.isEmpty())
            return error;
    // A file cut short in the copying, and a hand-in of another lesson.
    lessons::Answers other = students.front().answers;
    other.lessonFile = QStringLiteral("tunnelling.json");
    other.lessonTitle = QStringLiteral("Tunelování a spojitá detekce srážek");
    other.steps.clear();
    other.student = QStringLiteral("Karel Malý");
    for (const auto& [name, bytes] :
         {std::pair{QStringLiteral("restitution-adam.answers.json"),
                    lessons::answersJson(students.back().answers).left(90)},
          std::pair{QStringLiteral("tunnelling-karel.answers.json"), lessons::answersJson(other)}})
        if (const QString error = lessons::writeFileAtomically(dir.filePath(name), bytes);
            !error.isEmpty())
            return error;
    return QString();
}

} // namespace rigidlab::ui
