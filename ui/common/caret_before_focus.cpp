// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/caret_before_focus.h"

#include <QApplication>
#include <QEvent>
#include <QLineEdit>

namespace rigidlab::ui {

namespace {

class CaretPlacer : public QObject {
public:
    using QObject::QObject;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override
    {
        // Polish comes once, before a widget is first shown; the caret stays where it is,
        // but Qt now knows it as placed.
        if (event->type() == QEvent::Polish)
            if (auto* field = qobject_cast<QLineEdit*>(watched))
                field->setCursorPosition(field->cursorPosition());
        return false;
    }
};

} // namespace

void placeCaretsBeforeFocus()
{
    static const bool installed = [] {
        qApp->installEventFilter(new CaretPlacer(qApp));
        return true;
    }();
    Q_UNUSED(installed);
}

} // namespace rigidlab::ui
