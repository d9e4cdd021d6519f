// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/calm_text.h"

#include "common/spoken_numbers.h"

#include <QElapsedTimer>
#include <QLabel>
#include <QTimer>

#include <algorithm>

namespace rigidlab::ui {

namespace {

const char* const kCalmNameObject = "rigidlabCalmName";
const char* const kCalmDescriptionObject = "rigidlabCalmDescription";

/// Holds its widget's next accessible name (or description) until the calm interval since the
/// last is over.
class CalmName : public QObject {
public:
    CalmName(QWidget& widget, bool description)
        : QObject(&widget), m_widget(widget), m_description(description)
    {
        setObjectName(QLatin1String(description ? kCalmDescriptionObject : kCalmNameObject));
        m_later.setSingleShot(true);
        connect(&m_later, &QTimer::timeout, this, &CalmName::tell);
    }

    void ask(const QString& name, bool now)
    {
        m_name = name;
        if (now) {
            m_later.stop();
            tell();
            return;
        }
        if (m_later.isActive())
            return; // the pending change takes the newest name when it comes
        if (!m_since.isValid() || m_since.elapsed() >= kCalmIntervalMs)
            tell();
        else
            m_later.start(kCalmIntervalMs - static_cast<int>(m_since.elapsed()));
    }

private:
    void tell()
    {
        if ((m_description ? m_widget.accessibleDescription() : m_widget.accessibleName()) ==
            m_name)
            return;
        m_since.restart();
        if (m_description)
            m_widget.setAccessibleDescription(m_name);
        else
            m_widget.setAccessibleName(m_name);
    }

    QWidget& m_widget;
    bool m_description;
    QString m_name;
    QElapsedTimer m_since;
    QTimer m_later;
};

/// The widget's calm name or description, made when first asked for.
CalmName& calmOf(QWidget& widget, bool description)
{
    // Found by its name: CalmName has no meta-object of its own for findChild to cast to.
    auto* calm = static_cast<CalmName*>(widget.findChild<QObject*>(
        QLatin1String(description ? kCalmDescriptionObject : kCalmNameObject),
        Qt::FindDirectChildrenOnly));
    return calm ? *calm : *new CalmName(widget, description);
}

} // namespace

void setCalmAccessibleName(QWidget& widget, const QString& name, bool now)
{
    calmOf(widget, false).ask(name, now);
}

void setCalmAccessibleDescription(QWidget& widget, const QString& description, bool now)
{
    calmOf(widget, true).ask(description, now);
}

void setCalmText(QLabel& label, const QString& text)
{
    if (label.text() == text)
        return;
    // Named before its first text, so that QLabel does not tell that text as well.
    if (label.accessibleName().isEmpty())
        label.setAccessibleName(spokenSigns(text));
    label.setText(text);
    setCalmAccessibleName(label, spokenSigns(text));
}

void setSteadyText(QLabel& label, const QString& text, bool hold, int minimumWidth)
{
    setCalmText(label, text);
    if (!hold) {
        label.setMinimumSize(minimumWidth, 0);
        label.setMaximumSize(QWIDGETSIZE_MAX, QWIDGETSIZE_MAX);
        return;
    }
    // A widget whose least and largest size are one asks no layout for room when its text
    // changes (QWidget::updateGeometry). The height it is laid out at now is kept: fixed at
    // its text's, it would stand at the top of a taller bar. (A label not on screen has no
    // laid-out height yet, only a default one.)
    const QSize held = label.minimumSize() == label.maximumSize() ? label.maximumSize() : QSize();
    const QSize hint = label.sizeHint();
    const int laidOut = label.isVisible() ? label.height() : 0;
    const QSize needed(std::max(hint.width(), minimumWidth), std::max(hint.height(), laidOut));
    if (held.isValid() && needed.width() <= held.width() && needed.height() <= held.height())
        return;
    label.setFixedSize(std::max(needed.width(), held.width()), needed.height());
}

} // namespace rigidlab::ui
