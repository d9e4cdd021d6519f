// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The properties of what Edit mode has selected, and of the world, as fields: a body's id,
// type, density or mass, restitution, friction, velocity and angular velocity, colour; a spring's
// stiffness, damping and rest length; the world's gravity, dt, integrator, solver and
// iterations. Each change is one edit of the document (lessons/edit/), refused with the scene
// loader's words when out of range (the fields refuse first, with the same limits); changes of
// one field in a row merge into one step of the history.

#include <QWidget>

class QComboBox;
class QFormLayout;
class QGroupBox;
class QLineEdit;

namespace rigidlab::lessons::edit {
struct EditResult;
}

namespace rigidlab::ui {

class ColourField;
class EditTools;
class NumberField;
class SceneDocument;

class SceneProperties : public QWidget {
    Q_OBJECT
public:
    SceneProperties(EditTools& tools, SceneDocument& document, QWidget* parent = nullptr);

    /// The fields, by their objectName ("density", "stiffness", "gravityY", ...), for tests.
    NumberField* field(const QString& name) const;
    QLineEdit* idField() const { return m_id; }
    QComboBox* typeBox() const { return m_type; }
    /// The selected body's colour: swatch, "#rrggbb" and Default (editor/colour_field.h).
    ColourField* colourField() const { return m_colour; }

signals:
    /// Something typed was refused; `message` says why (for the status bar).
    void refused(const QString& message);

public slots:
    /// Shows the document's values for the selection.
    void refresh();

private:
    NumberField* addNumber(QFormLayout* form, const QString& name, const QString& label);
    void addColourRow(QFormLayout* form);
    /// A lesson step's locks (EditTools::propertyLocked): a locked property's fields disabled,
    /// their tooltip saying so.
    void applyLocks();
    /// Whether a lesson step locks what `field` edits; if so, says so and shows the value in
    /// force again (a change that reached a locked field some other way is refused).
    bool refuseLocked(const QWidget* field);
    void apply(const QString& what, const lessons::edit::EditResult& result, int mergeId);

    EditTools& m_tools;
    SceneDocument& m_document;
    QGroupBox* m_bodyBox = nullptr;
    QGroupBox* m_springBox = nullptr;
    QLineEdit* m_id = nullptr;
    QComboBox* m_type = nullptr;
    ColourField* m_colour = nullptr;
    QComboBox* m_integrator = nullptr;
    QComboBox* m_solver = nullptr;
};

} // namespace rigidlab::ui
