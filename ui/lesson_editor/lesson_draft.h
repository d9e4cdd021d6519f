// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The lesson being written in the lesson editor: a lesson in one file (format/lesson_pack.h)
// held as its JSON, changed only by the edits below, each one step of the undo stack. What
// the editor shows is read back from it; what it saves is its bytes (lessonPackBytes), so a
// lesson opened and saved unchanged is the same file. Its problems are the lesson loader's
// own (the file, the place, what is wrong), so the editor and the player never disagree.

#include "format/lesson.h"
#include "format/lesson_pack.h"

#include <QJsonArray>
#include <QJsonValue>
#include <QObject>
#include <QString>
#include <QStringList>

class QUndoStack;

namespace rigidlab::ui {

class LessonDraft : public QObject {
    Q_OBJECT
public:
    explicit LessonDraft(QObject* parent = nullptr);

    /// A new lesson titled `title` (in the language the lab shows) with one step on `scene`.
    void newLesson(const QString& title, const lessons::Scene& scene);
    /// Opens a lesson file (a folder's .json or a .rlesson) with the scenes it uses. A shipped
    /// one opens as a copy: path() is empty and Save asks where. Returns the loader's error.
    QString open(const QString& path);
    /// Opens what an autosave kept (a .rlesson) as unsaved work: path() is empty, so Save
    /// asks where, and the draft counts as modified. Returns the loader's error.
    QString openKept(const QString& path);

    const lessons::LessonPack& pack() const { return m_pack; }
    /// The file Save writes; empty for a new lesson or a copy.
    const QString& path() const { return m_path; }
    QUndoStack* undoStack() const { return m_undo; }
    bool isModified() const;

    int stepCount() const;
    /// A text of the lesson (`step` -1: "title", "summary", "level", "description") or of a
    /// step ("title", "text") in `language`; empty when it has none there.
    QString text(int step, const QString& key, const QString& language) const;
    /// The shipped languages (languages.h) a text has not been written in.
    QStringList missingLanguages(int step, const QString& key) const;
    /// A value of the lesson or of a step as the file holds it (Null when absent).
    QJsonValue value(int step, const QString& key) const;
    /// The scene document of a step, inline or the pack's copy of its file; empty when none.
    QJsonObject sceneObject(int step) const;
    /// The step's scene read in `language`, whatever the rest of the lesson says; nothing
    /// with `error` set when the scene itself does not load.
    std::optional<lessons::Scene> stepScene(int step, const QString& language,
                                            QString& error) const;

    // Edits, each one undo step; `name` is what Edit › Undo says.
    void setText(int step, const QString& key, const QString& language, const QString& text);
    /// Sets (or, given Null, removes) a key: "minutes", "plots", "panels", "allow",
    /// "exportTime", "autoplay", "questions", ...
    void setValue(int step, const QString& key, const QJsonValue& value, const QString& name);
    /// A new step after `after` (-1: first) on the scene of the step before it.
    void addStep(int after);
    void removeStep(int index);
    void moveStep(int from, int to);
    void duplicateStep(int index);
    /// The step's scene, from the scene editor.
    void setStepScene(int index, const lessons::Scene& scene);
    void setAuthor(const QString& author);

    /// What the lesson loader says of the lesson as it is now: its first error (empty when it
    /// loads) and its warnings, each `FILE: PLACE: what`, read in `language`.
    struct Check {
        QString error;
        QStringList warnings;
        /// The step each line is about (-1: the lesson), error first.
        QList<int> steps;
    };
    Check check(const QString& language) const;
    /// What running the steps depends on (their scenes, settings, locks and questions, not
    /// their texts), as bytes that change exactly when that does.
    QByteArray runKey() const;
    /// The lesson as the player reads it, or nothing with `error` set.
    std::optional<lessons::Lesson> lesson(const QString& language, QString& error) const;

    /// Writes to path(), dated today, atomically; a lesson with problems is saved too (work is
    /// never lost). Returns the error, empty on success.
    QString save();
    /// The same to `path` (it must end in .rlesson), which becomes path().
    QString saveAs(const QString& path);
    /// Writes the lesson as it is to `path` without changing path() or the saved state: the
    /// autosave that a crash leaves behind.
    QString writeCopy(const QString& path) const;

signals:
    /// Anything in the lesson changed (an edit, undo, redo, open).
    void changed();

private:
    class Edit;
    void apply(const lessons::LessonPack& after, const QString& name, int mergeId = -1);
    QJsonObject stepObject(int index) const;
    QJsonArray stepArray() const;
    /// The lesson with its steps replaced by `steps`, as one edit named `name`.
    void applySteps(const QJsonArray& steps, const QString& name);
    /// The lesson with a key of the lesson (`step` -1) or of a step set (removed when Null).
    lessons::LessonPack withValue(int step, const QString& key, const QJsonValue& v) const;

    lessons::LessonPack m_pack;
    QString m_path;
    QUndoStack* m_undo;
};

} // namespace rigidlab::ui
