// SPDX-License-Identifier: GPL-3.0-or-later
#include "editor/colour_field.h"

#include <QColorDialog>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QPainter>
#include <QPixmap>
#include <QToolButton>

namespace rigidlab::ui {

namespace {

/// The swatch's size [px].
constexpr int kSwatchPixels = 16;

} // namespace

ColourField::ColourField(QWidget* parent) : QWidget(parent)
{
    auto* row = new QHBoxLayout(this);
    row->setContentsMargins(0, 0, 0, 0);
    m_swatch = new QToolButton(this);
    m_swatch->setObjectName(QStringLiteral("colourPick"));
    m_swatch->setToolTip(tr("Choose the body's colour"));
    m_swatch->setIconSize(QSize(kSwatchPixels, kSwatchPixels));
    m_text = new QLineEdit(this);
    m_text->setObjectName(QStringLiteral("colour"));
    m_text->setPlaceholderText(tr("default"));
    m_text->setToolTip(tr("The body's colour as \"#rrggbb\" (six hexadecimal digits, as "
                          "\"#d04030\"); empty for the default"));
    m_text->setMaxLength(64);
    m_default = new QToolButton(this);
    m_default->setObjectName(QStringLiteral("colourDefault"));
    m_default->setText(tr("Default"));
    m_default->setToolTip(tr("Take the body's own colour away: the view colours it"));
    row->addWidget(m_swatch);
    row->addWidget(m_text, 1);
    row->addWidget(m_default);

    m_picker = [](const QColor& initial, QWidget* parent) -> std::optional<QColor> {
        const QColor chosen = QColorDialog::getColor(initial, parent, tr("Body colour"));
        return chosen.isValid() ? std::optional<QColor>(chosen) : std::nullopt;
    };
    connect(m_swatch, &QToolButton::clicked, this, &ColourField::pick);
    connect(m_text, &QLineEdit::editingFinished, this, &ColourField::typed);
    connect(m_default, &QToolButton::clicked, this, [this] {
        if (!m_colour.isEmpty()) {
            emit colourChosen(QString());
        }
    });
    showSwatch();
}

void ColourField::setColour(const QString& colour)
{
    m_colour = colour;
    m_text->setText(colour);
    showSwatch();
}

void ColourField::pick()
{
    const QColor initial = m_colour.isEmpty() ? m_shown : QColor::fromString(m_colour);
    if (const auto chosen = m_picker(initial, this)) {
        const QString name = chosen->name(QColor::HexRgb);
        if (name != m_colour) {
            emit colourChosen(name);
        }
    }
}

void ColourField::typed()
{
    QString text = m_text->text().trimmed();
    // The placeholder's word, typed, asks for the default as the button does.
    if (text.compare(tr("default"), Qt::CaseInsensitive) == 0) {
        text.clear();
    }
    if (text.compare(m_colour, Qt::CaseInsensitive) == 0) {
        m_text->setText(m_colour);
        return;
    }
    emit colourChosen(text);
}

void ColourField::showSwatch()
{
    QPixmap pixmap(kSwatchPixels, kSwatchPixels);
    if (m_colour.isEmpty()) {
        // No colour of its own: an empty box with a diagonal, as "none" in a vector editor.
        pixmap.fill(Qt::white);
        QPainter painter(&pixmap);
        painter.setPen(QColor(0xc0, 0x30, 0x30));
        painter.drawLine(0, kSwatchPixels - 1, kSwatchPixels - 1, 0);
        painter.setPen(Qt::gray);
        painter.drawRect(0, 0, kSwatchPixels - 1, kSwatchPixels - 1);
    } else {
        pixmap.fill(QColor::fromString(m_colour));
        QPainter painter(&pixmap);
        painter.setPen(Qt::black);
        painter.drawRect(0, 0, kSwatchPixels - 1, kSwatchPixels - 1);
    }
    m_swatch->setIcon(QIcon(pixmap));
    m_default->setEnabled(!m_colour.isEmpty());
}

} // namespace rigidlab::ui
