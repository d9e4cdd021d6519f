// SPDX-License-Identifier: GPL-3.0-or-later
// A lesson in one file (.rlesson, lessons/format/RLESSON_FORMAT.md): packing, reading,
// loading and unpacking. The lesson inside is read by the lesson loader, its scene paths
// looked up among the scenes the file carries (never on disk, so that a file someone mails
// cannot make the lab read anything else); messages name places from the file's top.

#include "format/lesson_pack.h"

#include "format/atomic_file.h"
#include "format/json_reader.h"
#include "format/scene_loader.h"
#include "format/scene_path.h"

#include <QDate>
#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QRegularExpression>

namespace rigidlab::lessons {

using detail::FileMessages;
using detail::JsonReader;

namespace {

constexpr QStringView kVersionKey = u"rigidlab-lesson-file";
constexpr QStringView kScenesFolder = u"scenes/";
/// The longest "author" [characters].
constexpr int kMaxAuthor = 200;

/// A scene's name inside a pack: a plain file name under scenes/, so that unpacking can
/// write it nowhere else.
bool isSceneName(const QString& name)
{
    static const QRegularExpression pattern(
        QStringLiteral("\\Ascenes/[A-Za-z0-9_][A-Za-z0-9_.-]{0,79}\\.json\\z"));
    return pattern.match(name).hasMatch() && !name.contains(QStringLiteral(".."));
}

QString scenePlace(const QString& name)
{
    return QStringLiteral("scenes[\"%1\"]").arg(name);
}

/// A loader's line `SOURCE: PLACE: what` with PLACE put under `at`: `SOURCE: at.PLACE: what`.
QString under(const QString& message, const QString& source, const QString& at)
{
    const QString prefix = source + QStringLiteral(": ");
    if (!message.startsWith(prefix))
        return message;
    return prefix + at + u'.' + message.mid(prefix.size());
}

bool readInfo(JsonReader& in, const QJsonObject& root, LessonPackInfo& info)
{
    if (!in.string(root, u"author", {}, info.author) || !in.string(root, u"date", {}, info.date))
        return false;
    if (info.author.contains(u'\n') || info.author.contains(u'\r') ||
        info.author.size() > kMaxAuthor)
        return in.fail(
            QStringLiteral("author"),
            FileMessages::tr("must be one line of at most %1 characters").arg(kMaxAuthor));
    if (!info.date.isEmpty() && !QDate::fromString(info.date, Qt::ISODate).isValid())
        return in.fail(
            QStringLiteral("date"),
            FileMessages::tr("must be a date written YYYY-MM-DD, got \"%1\"").arg(info.date));
    return true;
}

bool readScenes(JsonReader& in, const QJsonObject& root, std::map<QString, QJsonObject>& out)
{
    if (!root.contains(u"scenes"))
        return true;
    const QString place = QStringLiteral("scenes");
    QJsonObject scenes;
    if (!in.asObject(root.value(u"scenes"), place, scenes))
        return false;
    if (scenes.size() > kMaxPackedScenes)
        return in.fail(place, FileMessages::tr("holds %1 scenes; a lesson file holds at most %2")
                                  .arg(scenes.size())
                                  .arg(kMaxPackedScenes));
    for (auto it = scenes.constBegin(); it != scenes.constEnd(); ++it) {
        if (!isSceneName(it.key()))
            return in.fail(place, FileMessages::tr("\"%1\" is not a scene's name in a lesson "
                                                   "file (scenes/NAME.json, NAME of letters, "
                                                   "digits, _ . -)")
                                      .arg(it.key()));
        QJsonObject scene;
        if (!in.asObject(it.value(), scenePlace(it.key()), scene))
            return false;
        out.emplace(it.key(), scene);
    }
    return true;
}

/// A file name as a scene's name in a pack: characters outside the allowed set become "_".
QString sceneNameFor(const QString& fileName, const std::map<QString, QJsonObject>& taken)
{
    QString stem = QFileInfo(fileName).completeBaseName();
    for (QChar& c : stem) {
        const bool plain = (c >= u'a' && c <= u'z') || (c >= u'A' && c <= u'Z') ||
                           (c >= u'0' && c <= u'9') || c == u'_' || c == u'-';
        if (!plain)
            c = u'_';
    }
    stem = stem.left(70);
    if (stem.isEmpty())
        stem = QStringLiteral("scene");
    QString name = kScenesFolder.toString() + stem + QStringLiteral(".json");
    for (int n = 2; taken.count(name) != 0; ++n)
        name =
            kScenesFolder.toString() + stem + u'-' + QString::number(n) + QStringLiteral(".json");
    return name;
}

LessonPackResult failed(const QString& error)
{
    LessonPackResult r;
    r.error = error;
    return r;
}

/// The parsed document at `path`, an object, at most `limit` bytes.
bool readObject(const QString& path, qint64 limit, QJsonObject& out, QString& error)
{
    const detail::FileBytes file = detail::readFileBytes(path, limit);
    if (!file.ok) {
        error = file.error;
        return false;
    }
    const detail::ParsedJson parsed = detail::parseJson(file.bytes, path, limit);
    if (!parsed.ok) {
        error = parsed.error;
        return false;
    }
    if (!parsed.document.isObject()) {
        error = path + FileMessages::tr(": the top level must be an object {...}, got an array");
        return false;
    }
    out = parsed.document.object();
    return true;
}

/// Packs a lesson folder's lesson file, already known to load.
LessonPackResult packFolderLesson(const QString& lessonPath, const LessonPackInfo& info)
{
    LessonPackResult r;
    QJsonObject root;
    if (!readObject(lessonPath, kMaxLessonFileBytes, root, r.error))
        return r;
    const QString folder = QFileInfo(lessonPath).absolutePath();
    std::map<QString, QString> nameOfFile; // canonical path → name in the pack
    QJsonArray steps = root.value(u"steps").toArray();
    for (qsizetype i = 0; i < steps.size(); ++i) {
        QJsonObject step = steps[i].toObject();
        if (!step.value(u"scene").isString())
            continue;
        const ScenePathResult where = resolveScenePath(folder, step.value(u"scene").toString());
        if (!where.ok)
            return failed(lessonPath + QStringLiteral(": steps[%1].scene: ").arg(i) + where.error);
        const QString file = QFileInfo(where.readPath).canonicalFilePath();
        auto known = nameOfFile.find(file);
        if (known == nameOfFile.end()) {
            QJsonObject scene;
            if (!readObject(where.readPath, kMaxSceneFileBytes, scene, r.error))
                return r;
            const QString name = sceneNameFor(QFileInfo(file).fileName(), r.pack.scenes);
            r.pack.scenes.emplace(name, scene);
            known = nameOfFile.emplace(file, name).first;
        }
        step.insert(u"scene", known->second);
        steps[i] = step;
    }
    root.insert(u"steps", steps);
    r.pack.lesson = root;
    r.pack.info = info;
    r.ok = true;
    return r;
}

} // namespace

bool isLessonPackPath(const QString& path)
{
    return path.endsWith(QStringLiteral(".rlesson"), Qt::CaseInsensitive);
}

bool isLessonDocument(const QString& path)
{
    if (isLessonPackPath(path))
        return true;
    const detail::FileBytes file = detail::readFileBytes(path, kMaxLessonFileBytes);
    return file.ok && QJsonDocument::fromJson(file.bytes).object().contains(u"rigidlab-lesson");
}

LessonPackResult readLessonPackObject(const QJsonObject& root, const QString& path)
{
    JsonReader in(path);
    LessonPackResult r;
    QJsonObject lesson;
    const bool ok =
        in.formatVersion(root, kVersionKey.toString(), FileMessages::tr("a lesson file (.rlesson)"),
                         kLessonPackFormatVersion) &&
        in.checkKeys(root, {}, {kVersionKey, u"author", u"date", u"lesson", u"scenes"}) &&
        readInfo(in, root, r.pack.info) &&
        (root.contains(u"lesson") ||
         in.fail(QStringLiteral("lesson"), FileMessages::tr("required, but missing"))) &&
        in.asObject(root.value(u"lesson"), QStringLiteral("lesson"), lesson) &&
        readScenes(in, root, r.pack.scenes);
    if (!ok)
        return failed(in.error());
    r.pack.lesson = lesson;
    r.ok = true;
    return r;
}

LessonPackResult readLessonPack(const QByteArray& bytes, const QString& path)
{
    const detail::ParsedJson parsed = detail::parseJson(bytes, path, kMaxLessonPackBytes);
    if (!parsed.ok)
        return failed(parsed.error);
    if (!parsed.document.isObject())
        return failed(path +
                      FileMessages::tr(": the top level must be an object {...}, got an array"));
    return readLessonPackObject(parsed.document.object(), path);
}

LessonLoadResult loadLessonPack(const LessonPack& pack, const QString& path,
                                const LessonLoadOptions& options)
{
    LessonLoadResult result;
    std::map<QString, Scene> scenes;
    for (const auto& [name, object] : pack.scenes) {
        const SceneLoadResult scene =
            loadSceneObject(object, path, SceneLoadOptions{options.language});
        for (const QString& w : scene.warnings)
            result.warnings.append(under(w, path, scenePlace(name)));
        if (!scene.ok) {
            result.error = under(scene.error, path, scenePlace(name));
            return result;
        }
        scenes.emplace(name, scene.scene);
    }
    LessonLoadOptions inside = options;
    inside.embeddedScenes = &scenes;
    LessonLoadResult loaded = loadLessonObject(pack.lesson, path, inside);
    for (const QString& w : loaded.warnings)
        result.warnings.append(under(w, path, QStringLiteral("lesson")));
    if (!loaded.ok) {
        result.error = under(loaded.error, path, QStringLiteral("lesson"));
        return result;
    }
    result.ok = true;
    result.lesson = std::move(loaded.lesson);
    return result;
}

LessonLoadResult loadLessonPack(const QByteArray& bytes, const QString& path,
                                const LessonLoadOptions& options)
{
    const LessonPackResult read = readLessonPack(bytes, path);
    if (!read.ok) {
        LessonLoadResult result;
        result.error = read.error;
        return result;
    }
    return loadLessonPack(read.pack, path, options);
}

LessonPackResult packLesson(const QString& lessonPath, const LessonPackInfo& info)
{
    const LessonLoadResult loaded = loadLessonFile(lessonPath);
    if (!loaded.ok)
        return failed(loaded.error);
    LessonPackResult r;
    if (isLessonPackPath(lessonPath)) {
        const detail::FileBytes file = detail::readFileBytes(lessonPath, kMaxLessonPackBytes);
        r = file.ok ? readLessonPack(file.bytes, lessonPath) : failed(file.error);
        if (r.ok && !info.author.isEmpty())
            r.pack.info.author = info.author;
        if (r.ok && !info.date.isEmpty())
            r.pack.info.date = info.date;
    } else {
        r = packFolderLesson(lessonPath, info);
    }
    r.warnings = loaded.warnings;
    return r;
}

QByteArray lessonPackBytes(const LessonPack& pack)
{
    QJsonObject root;
    root.insert(kVersionKey, kLessonPackFormatVersion);
    if (!pack.info.author.isEmpty())
        root.insert(u"author", pack.info.author);
    if (!pack.info.date.isEmpty())
        root.insert(u"date", pack.info.date);
    root.insert(u"lesson", pack.lesson);
    QJsonObject scenes;
    for (const auto& [name, scene] : pack.scenes)
        scenes.insert(name, scene);
    root.insert(u"scenes", scenes);
    return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

QString unpackLesson(const LessonPack& pack, const QString& folder, const QString& baseName,
                     QStringList& written)
{
    const QDir dir(folder);
    if (!dir.mkpath(QStringLiteral("scenes")))
        return QStringLiteral("cannot make the folder %1")
            .arg(dir.filePath(QStringLiteral("scenes")));
    for (const auto& [name, scene] : pack.scenes) {
        if (!isSceneName(name))
            return QStringLiteral("refusing to write the scene named \"%1\"").arg(name);
        const QString path = dir.filePath(name);
        const QString error =
            writeFileAtomically(path, QJsonDocument(scene).toJson(QJsonDocument::Indented));
        if (!error.isEmpty())
            return error;
        written.append(path);
    }
    const QString lessonPath = dir.filePath(baseName + QStringLiteral(".json"));
    const QString error =
        writeFileAtomically(lessonPath, QJsonDocument(pack.lesson).toJson(QJsonDocument::Indented));
    if (!error.isEmpty())
        return error;
    written.append(lessonPath);
    return {};
}

} // namespace rigidlab::lessons
