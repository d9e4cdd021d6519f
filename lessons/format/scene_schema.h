// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The scene format's fields, one row each: the one place that says what a scene's title, its
// world, a body, a spring, a joint and a lesson step's settings hold. The loader reads these
// rows, the writer writes them, the comparer compares them, the scene edits change them, and
// the editor's property rows, a lesson's property locks and the inspector show them. Adding a
// body field is one row here (and its physics).
//
// A row reaches its value through two accessors, so that the rest of the lab never touches a
// physics struct's representation: physics::BodyDef keeps "restitution < 0: the world's" and
// "mass 0: from the density", which reach the lab as an unset value (std::monostate).

#include "format/json_reader.h"
#include "format/limits.h"
#include "format/scene.h"
#include "format/schema_value.h"

#include <QString>
#include <QStringList>

#include <span>
#include <string_view>
#include <variant>
#include <vector>

namespace rigidlab::lessons::schema {

/// The objects of a scene that have fields.
enum class Object { Scene, World, Body, Spring, Joint };

/// What a field holds, and so how it is read, written, compared and edited.
enum class Kind {
    Number,    ///< double with a NumberRule and a range
    Integer,   ///< int in a range
    Vec2,      ///< [x, y], each in a range
    Bool,      ///< true / false
    Choice,    ///< one name of a list (QString)
    Text,      ///< a line of text (QString), checked by the object's rules
    LocalText, ///< a text in the scene's languages (shown: QString)
    Colour,    ///< "#rrggbb" or unset
    Shape,     ///< a body's shape: read, written and compared whole; edited through Size rows
    Size,      ///< one measure of a shape (a box's width): never written on its own
    End,       ///< a spring's or joint's body: its id (QString; set also takes the index, int),
               ///< unset for the world
};

/// The translation context of the rows' labels.
inline constexpr const char* kContext = "SceneSchema";

template <class Target> struct FieldOf {
    std::string_view key; ///< the JSON key (and a lesson's property name)
    /// The row's label, QT_TRANSLATE_NOOP(kContext, ...); for a pair, its x component.
    const char* label = nullptr;
    const char* labelY = nullptr; ///< a pair's y component
    Kind kind = Kind::Number;
    limits::Range range{}; ///< numbers: allowed values, with the unit messages name
    detail::NumberRule rule = detail::NumberRule::Finite;
    Value (*get)(const Target&, std::size_t index) = nullptr;
    void (*set)(Target&, std::size_t index, const Value&) = nullptr;
    /// Whether the writer writes it; nullptr: always.
    bool (*written)(const Target&, std::size_t index) = nullptr;
    /// Whether it means something for this object (a box's width, a moving body's velocity);
    /// nullptr: always. The editor hides the rows that do not.
    bool (*applies)(const Target&, std::size_t index) = nullptr;
    bool required = false;           ///< the file must give it
    bool optional = false;           ///< may be unset (the world's value, the world as an end)
    bool inEditor = false;           ///< the editor offers it as a row (and a lesson may lock it)
    double shownScale = 1;           ///< the editor shows value * shownScale (dt in ms)
    const char* shownUnit = nullptr; ///< the unit then shown, QT_TRANSLATE_NOOP(kContext, ...)
    /// Choice: whether a name is one; the loader's refusal of another; the names the editor
    /// offers.
    bool (*accepts)(const QString&) = nullptr;
    QString (*unknown)(const QString&) = nullptr;
    QStringList (*options)() = nullptr;
    /// The world's field an unset value stands for ("restitution"), or empty.
    std::string_view fallback = {};
    bool writtenLast = false; ///< written after the others (where older files have it)
    /// LocalText: every language's text where the file gave an object of languages.
    LocalTextMap (*texts)(const Target&, std::size_t index) = nullptr;

    // A run-time setting: a world row that a lesson step may set, the controls change during a
    // run, "allow" may leave free and a reset keeps (schema::settings()).
    /// Where the settings list it (the controls, a step's settings), from 1; 0: not one.
    int setting = 0;
    /// The setting's change to a running world, with a value as this row holds it.
    void (*apply)(physics::World&, const Value&) = nullptr;
    /// The row a lesson step gives it by, when a step gives it otherwise than a scene
    /// (gravity: on or off); null: this row.
    const FieldOf* stepRow = nullptr;
    /// The worlds a step compares keep their own (the integrator, the solver): a change in a
    /// run reaches the main world only.
    bool mainWorldOnly = false;
};

using Field = FieldOf<Scene>;

/// The rows of `object`, in the order of the file.
std::span<const Field> fields(Object object);
/// The row of `object` with this key, or null.
const Field* findField(Object object, std::string_view key);
/// The run-time settings, in the order the controls and a step's settings list them: the
/// world rows that are one (each as a step gives it: its stepRow, else itself), then the
/// window's time scale (no apply: the window's clock, not the world's). A step's "settings", a
/// question's "set", "allow", the controls' locks, a reset and the edits of a run read it;
/// adding a world setting is one world row with `setting` and `apply`.
std::span<const Field> settings();
/// The setting with this key, or null.
const Field* findSetting(std::string_view key);
/// The world row a setting changes (gravity's vector for its on/off), or null (time scale).
const Field* worldRowOf(const Field& setting);
/// Whether `value` is one `row` takes: a number in its range, a name it accepts.
bool takes(const Field& row, const Value& value);

/// The keys of `object` in file order, the extra keys of the format appended ("rigidlab").
QStringList keys(Object object);
/// The names a lesson may lock in the editor (its "editor": {"properties": [...]}): the keys
/// of every row the editor offers, scene, body, spring and world.
const std::vector<std::string_view>& editorPropertyNames();
/// The controls a lesson step may allow (its "allow"): the settings' keys.
const std::vector<std::string_view>& stepControlNames();

/// How many objects of this kind the scene has (1 for the scene and the world).
std::size_t count(const Scene& scene, Object object);
/// "world", "bodies[2]", "springs[0]": where an object is in a file; empty for the scene.
QString placeOf(Object object, std::size_t index);

/// The field's label, translated; empty when it has none.
QString label(const Field& field, int component = 0);
/// The value a default object has (a body as BodyDef{} makes it).
Value defaultValue(const Field& field);
/// A value as a message or a comparison shows it: `0.5`, `[0, 1]`, `"ball"`, `unset`.
QString text(const Value& value);
/// The value in force: an unset field with a fallback shows the world's.
Value effective(const Scene& scene, const Field& field, std::size_t index);

/// The body types' names in files ("dynamic", "static", "kinematic") and for people.
QString bodyTypeName(physics::BodyType type);
std::optional<physics::BodyType> bodyTypeFromName(const QString& name);
QString bodyTypeLabel(physics::BodyType type); ///< translated: "dynamic" → "dynamický"

/// A file name for a scene titled `title`: lower-case ASCII letters, digits and underscores,
/// with ".json": "Nová scéna" → "nova_scena.json", "Srážka vozíků!" → "srazka_voziku.json".
/// Diacritics lose their marks; what a Windows share or a USB stick would mangle goes.
QString safeFileName(const QString& title);
/// The same name without its ending, or `fallback` when nothing of the title is left.
QString safeFileStem(const QString& title, const QString& fallback);

} // namespace rigidlab::lessons::schema
