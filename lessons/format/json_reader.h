// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Checked reading of a parsed JSON document. Every getter names the place it reads (a JSON
// path such as `bodies[2].shape.radius`), and the first thing found wrong becomes the one
// error line the user sees: `FILE: PLACE: what is wrong`. Later problems are not reported,
// so a getter returns false once anything has failed and the caller simply stops.

#include "format/limits.h"
#include "rigidlab/physics/math.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonValue>
#include <QString>
#include <QStringList>

#include <initializer_list>
#include <optional>

namespace rigidlab::lessons::detail {

/// The translation context of what the scene and lesson loaders say about a file. The window
/// shows these messages in its language; rigidlab-cli installs no translation, so
/// its messages stay English.
struct FileMessages {
    Q_DECLARE_TR_FUNCTIONS(FileMessages)
};

/// `place.key`, or `key` at the top level.
QString joinPlace(const QString& place, QStringView key);
/// `place[index]`.
QString indexPlace(const QString& place, qsizetype index);

/// A value as a message quotes it: `-0.5`, `"abc"`, `true`, `null`, `an array`, `an object`.
QString describeJson(const QJsonValue& value);
/// A number in its shortest form that reads back exactly.
QString formatNumber(double value);

/// What a number must be.
enum class NumberRule {
    Finite,      ///< any finite number
    Positive,    ///< > 0
    NonNegative, ///< >= 0
    UnitInterval ///< in [0, 1]
};

/// Reads what a file holds: at most `limit` bytes, or an error naming the OS reason.
struct FileBytes {
    bool ok = false;
    QString error; ///< one line, starting with the path
    QByteArray bytes;
};
FileBytes readFileBytes(const QString& path, qint64 limit);

/// "from 1e-09 to 1e+12 kg": how messages state an allowed range.
QString describeRange(const limits::Range& range);

/// "unknown integrator "NAME" (expected euler, symplectic-euler, verlet, rk4)": the paper's four
/// are listed, though every name physics::integratorFromName knows is accepted.
QString unknownIntegrator(const QString& name);
/// "unknown solver "NAME" (expected seed-impulse, sequential-impulse, soft-step)".
QString unknownSolver(const QString& name);

/// Parses JSON; a syntax error becomes `SOURCE: line L, column C: what`. Arrays and objects
/// nested deeper than limits::kMaxJsonDepth are refused before the parser sees them.
struct ParsedJson {
    bool ok = false;
    QString error;
    QJsonDocument document;
};
ParsedJson parseJson(const QByteArray& bytes, const QString& sourceName, qint64 limit);

class JsonReader {
public:
    explicit JsonReader(QString sourceName) : m_source(std::move(sourceName)) {}

    bool failed() const { return !m_error.isEmpty(); }
    /// The one error line, empty when nothing failed.
    const QString& error() const { return m_error; }
    const QStringList& warnings() const { return m_warnings; }
    const QString& sourceName() const { return m_source; }

    /// Records an error (only the first counts). Always returns false.
    bool fail(const QString& place, const QString& what);
    /// Records a warning; loading goes on.
    void warn(const QString& place, const QString& what);

    /// Every key of `object` must be one of `allowed`; the first other one is an error.
    bool checkKeys(const QJsonObject& object, const QString& place,
                   std::initializer_list<QStringView> allowed);
    bool checkKeys(const QJsonObject& object, const QString& place, const QStringList& allowed);

    /// The document's first key, `key`, must hold `version`; `document` names the kind of file
    /// in the message ("a scene file").
    bool formatVersion(const QJsonObject& root, const QString& key, const QString& document,
                       int version);

    /// `value` must be an object / an array.
    bool asObject(const QJsonValue& value, const QString& place, QJsonObject& out);
    bool asArray(const QJsonValue& value, const QString& place, QJsonArray& out);

    /// Getters for `object[key]`. An absent key leaves `out` as it was and is fine unless
    /// `required`. They return false on any error (and once anything has failed).
    bool number(const QJsonObject& object, QStringView key, const QString& place, double& out,
                NumberRule rule = NumberRule::Finite, bool required = false);
    bool integer(const QJsonObject& object, QStringView key, const QString& place, int& out,
                 int min, int max, bool required = false);
    bool string(const QJsonObject& object, QStringView key, const QString& place, QString& out,
                bool required = false);
    bool boolean(const QJsonObject& object, QStringView key, const QString& place, bool& out,
                 bool required = false);
    bool vec2(const QJsonObject& object, QStringView key, const QString& place, physics::Vec2& out,
              bool required = false);

    /// Reads a value that is already at hand (an array element, say).
    bool numberValue(const QJsonValue& value, const QString& place, double& out,
                     NumberRule rule = NumberRule::Finite);
    bool vec2Value(const QJsonValue& value, const QString& place, physics::Vec2& out);

    // The same, with a magnitude limit (limits.h) checked after the rule: a value outside
    // `range` fails with "must be from MIN to MAX UNIT, got V". For a pair, each component.
    bool number(const QJsonObject& object, QStringView key, const QString& place, double& out,
                NumberRule rule, const limits::Range& range, bool required = false);
    bool vec2(const QJsonObject& object, QStringView key, const QString& place, physics::Vec2& out,
              const limits::Range& range, bool required = false);
    bool vec2Value(const QJsonValue& value, const QString& place, physics::Vec2& out,
                   const limits::Range& range);
    /// Fails unless `value` is in `range`.
    bool checkRange(double value, const QString& place, const limits::Range& range);

private:
    QString m_source;
    QString m_error;
    QStringList m_warnings;
};

} // namespace rigidlab::lessons::detail
