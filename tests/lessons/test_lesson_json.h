// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Small lessons as JSON, for the loader's tests (test_lesson_loader.cpp,
// test_lesson_languages.cpp).

#include <QByteArray>

namespace rigidlab::test::lesson_json {

/// A scene with a ball, a floor and a box, as JSON.
inline const char* kScene =
    R"({"rigidlab": 1, "bodies": [)"
    R"({"id": "ball", "shape": {"type": "circle", "radius": 0.1}, "position": [0, 1]},)"
    R"({"id": "floor", "type": "static", "shape": {"type": "box", "width": 4, "height": 0.2}},)"
    R"({"id": "box", "shape": {"type": "box", "width": 0.5, "height": 0.5}, "position": [2, 2]},)"
    R"({"id": "wedge", "shape": {"type": "polygon", "vertices": [[0, 0], [1, 0], [0, 1]]}}]})";

/// A lesson with one step holding the inline scene and `fields`.
inline QByteArray oneStep(const char* fields)
{
    return QByteArray(
               R"({"rigidlab-lesson": 1, "title": "t", "steps": [{"title": "s", "scene": )") +
           kScene + (fields[0] ? QByteArray(", ") + fields : QByteArray()) + "}]}";
}

/// A lesson with one step whose scene is the file at `scene`.
inline QByteArray stepWithScene(const char* scene)
{
    return QByteArray(
               R"({"rigidlab-lesson": 1, "title": "t", "steps": [{"title": "s", "scene": )") +
           scene + "}]}";
}

} // namespace rigidlab::test::lesson_json
