// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Reading a lesson file: the parts kept apart from lesson_loader.cpp (lesson_questions.cpp).

#include "format/json_reader.h"

#include "format/lesson.h"

#include <optional>
#include <utility>
#include <vector>

namespace rigidlab::lessons::detail {

/// The step's "sat": {"a": ID, "b": ID}, two different polygons of `scene`; `out` is left
/// empty when the step has none.
bool readSat(JsonReader& in, const QJsonObject& step, const QString& place, const Scene& scene,
             std::optional<std::pair<QString, QString>>& out);

/// The step's "questions", their measures naming bodies of its scene and what they hold
/// back naming panels and plots it shows.
bool readQuestions(JsonReader& in, const QJsonObject& object, const QString& place,
                   const LessonStep& step, std::vector<Question>& out);

} // namespace rigidlab::lessons::detail
