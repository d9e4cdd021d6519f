// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The properties of the scene, of what Edit mode has selected, and of the world, as fields:
// one row for each field of the scene schema the editor offers (lessons/format/scene_schema.h),
// in its order: the scene's title and description; a body's id, label, type, size, position,
// angle, velocities, density or mass, restitution, friction and colour; a spring's stiffness,
// damping and rest length; the world's gravity, dt, integrator, solver and iterations. Each
// change is one edit of the document (lessons/edit/), refused with the scene loader's words
// when out of range (the fields refuse first, with the same limits); changes of one field in a
// row merge into one step of the history. Return in a field hands the keyboard back to the
// scene view, so that the next key is a tool's or Ctrl+Z again.

#include "format/scene_schema.h"

#include <QWidget>

#include <vector>

class QComboBox;
class QFormLayout;
class QGroupBox;
class QLineEdit;

namespace rigidlab::ui {

class ColourField;
class EditTools;
class NumberField;
class SceneDocument;

class SceneProperties : public QWidget {
    Q_OBJECT
public:
    SceneProperties(EditTools& tools, SceneDocument& document, QWidget* parent = nullptr);

    /// The number fields, by their objectName: the key ("density", "dt"), a pair's key and
    /// component ("gravityY", "positionX"), for tests.
    NumberField* field(const QString& name) const;
    /// A text row by its key: "id", "label", "title", "description".
    QLineEdit* textField(const QString& key) const;
    QLineEdit* idField() const { return textField(QStringLiteral("id")); }
    QComboBox* typeBox() const;
    /// The selected body's colour: swatch, "#rrggbb" and Default (editor/colour_field.h).
    ColourField* colourField() const { return m_colour; }

signals:
    /// Something typed was refused; `message` says why (for the status bar).
    void refused(const QString& message);

public slots:
    /// Shows the document's values for the selection.
    void refresh();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    /// One schema field shown: its widgets (a pair has two number fields).
    struct Row {
        lessons::schema::Object object;
        const lessons::schema::Field* field;
        std::vector<QWidget*> widgets;
        QFormLayout* form;
    };
    QFormLayout* addGroup(QGroupBox* box);
    void addRows(lessons::schema::Object object, QFormLayout* form);
    void addNumbers(Row& row, int mergeId);
    void addChoice(Row& row);
    void addText(Row& row);
    void addColour(Row& row);
    /// The object the rows of `object` show: the selected body or spring, or 0; -1 for none.
    int indexOf(lessons::schema::Object object) const;
    void showRow(const Row& row, int index);
    /// A lesson step's locks (EditTools::propertyLocked): a locked property's fields disabled,
    /// their tooltip saying so.
    void applyLocks();
    /// Whether a lesson step locks `row`; if so, says so and shows the value in force again (a
    /// change that reached a locked field some other way is refused).
    bool refuseLocked(const Row& row, int component = 0);
    /// Sets the row's field to `value` as one step of the history.
    void edit(const Row& row, const lessons::schema::Value& value, int component, int mergeId);
    /// "Set restitution e of ball", "Set stiffness k of spring 2", "Set gravity gy".
    QString editName(const Row& row, int component) const;

    EditTools& m_tools;
    SceneDocument& m_document;
    QGroupBox* m_bodyBox = nullptr;
    QGroupBox* m_springBox = nullptr;
    ColourField* m_colour = nullptr;
    std::vector<Row> m_rows;
};

} // namespace rigidlab::ui
