// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A push button of the lesson editor's panes: named for tests, read by a screen reader
// without its mnemonic's '&', added to its row.

#include <QBoxLayout>
#include <QPushButton>

namespace rigidlab::ui {

inline QPushButton* addEditorButton(QWidget* parent, QBoxLayout* row, const QString& text,
                                    const char* objectName)
{
    auto* b = new QPushButton(text, parent);
    b->setObjectName(QLatin1String(objectName));
    QString plain = text;
    b->setAccessibleName(plain.remove(u'&'));
    row->addWidget(b);
    return b;
}

} // namespace rigidlab::ui
