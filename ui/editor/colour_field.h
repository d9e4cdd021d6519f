// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A body's colour in the Properties dock: a swatch that opens a colour dialog, a text field
// for "#rrggbb" and a Default button that takes the body's own colour away (the view then
// colours it itself). It only reports what was chosen (colourChosen); the scene edit, and its
// refusal in the loader's words, are the caller's.

#include <QColor>
#include <QString>
#include <QWidget>

#include <functional>
#include <optional>

class QLineEdit;
class QToolButton;

namespace rigidlab::ui {

class ColourField : public QWidget {
    Q_OBJECT
public:
    /// Asks for a colour, starting from `initial`; nullopt when cancelled.
    using Picker = std::function<std::optional<QColor>(const QColor& initial, QWidget* parent)>;

    explicit ColourField(QWidget* parent = nullptr);

    /// Shows `colour` ("#rrggbb", or empty for the view's own).
    void setColour(const QString& colour);
    const QString& colour() const { return m_colour; }
    /// The colour the view paints the body in now: where the picker starts when the body has
    /// no colour of its own.
    void setShownColour(const QColor& shown) { m_shown = shown; }
    /// Replaces the modal QColorDialog (tests pick without a dialog).
    void setPicker(Picker picker) { m_picker = std::move(picker); }

    QLineEdit* textField() const { return m_text; }
    QToolButton* swatchButton() const { return m_swatch; }
    QToolButton* defaultButton() const { return m_default; }

signals:
    /// The user chose `colour`: "#rrggbb" as typed or picked, or empty for the default. What
    /// was typed is passed on unchecked, for the edit to refuse with the loader's message.
    void colourChosen(const QString& colour);

private:
    void pick();
    void typed();
    void showSwatch();

    QString m_colour;
    QColor m_shown = Qt::white;
    QLineEdit* m_text = nullptr;
    QToolButton* m_swatch = nullptr;
    QToolButton* m_default = nullptr;
    Picker m_picker;
};

} // namespace rigidlab::ui
