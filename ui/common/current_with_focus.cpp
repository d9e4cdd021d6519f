// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/current_with_focus.h"

#include <QAbstractItemView>
#include <QEvent>
#include <QItemSelectionModel>
#include <QPointer>

namespace rigidlab::ui {

namespace {

class CurrentWithFocus : public QObject {
public:
    explicit CurrentWithFocus(QAbstractItemView& view) : QObject(&view), m_view(&view)
    {
        view.installEventFilter(this);
        watch();
        clearUnlessFocused();
    }

    bool eventFilter(QObject* watched, QEvent* event) override
    {
        if (watched != m_view)
            return false;
        switch (event->type()) {
        case QEvent::FocusIn:
            // Before the view's own focusInEvent, which makes its first row current when
            // none is: in a QUndoView that would undo every edit.
            if (QItemSelectionModel* s = m_view->selectionModel();
                s && !s->currentIndex().isValid() && !s->selectedIndexes().isEmpty())
                s->setCurrentIndex(s->selectedIndexes().constFirst(),
                                   QItemSelectionModel::NoUpdate);
            break;
        case QEvent::FocusOut:
            clearUnlessFocused();
            break;
        default:
            break;
        }
        return false;
    }

private:
    /// Follows the view's selection model (set again when the view gets a new model).
    void watch()
    {
        QItemSelectionModel* s = m_view->selectionModel();
        if (s == m_watched)
            return;
        if (m_watched)
            disconnect(m_watched, nullptr, this, nullptr);
        m_watched = s;
        if (s)
            connect(s, &QItemSelectionModel::currentChanged, this,
                    &CurrentWithFocus::clearUnlessFocused);
    }

    void clearUnlessFocused()
    {
        watch();
        QItemSelectionModel* s = m_view->selectionModel();
        if (s && !m_view->hasFocus() && s->currentIndex().isValid())
            s->setCurrentIndex(QModelIndex(), QItemSelectionModel::NoUpdate);
    }

    QAbstractItemView* m_view;
    QPointer<QItemSelectionModel> m_watched;
};

} // namespace

void keepCurrentOnlyWhileFocused(QAbstractItemView& view)
{
    new CurrentWithFocus(view);
}

} // namespace rigidlab::ui
