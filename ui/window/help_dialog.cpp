// SPDX-License-Identifier: GPL-3.0-or-later
#include "window/help_dialog.h"

#include <QDialog>
#include <QDialogButtonBox>
#include <QGuiApplication>
#include <QPushButton>
#include <QScreen>
#include <QTextBrowser>
#include <QVBoxLayout>

namespace rigidlab::ui {

namespace {

/// The help's size where the screen allows it [px]: the table's two columns side by side.
constexpr QSize kPreferred(620, 640);

} // namespace

QDialog* showControlsHelp(QWidget* parent, const QString& title, const QString& html)
{
    auto* dialog = new QDialog(parent);
    dialog->setObjectName(QStringLiteral("controlsHelpDialog"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    dialog->setWindowTitle(title);
    auto* column = new QVBoxLayout(dialog);
    auto* text = new QTextBrowser(dialog);
    text->setObjectName(QStringLiteral("controlsHelpText"));
    text->setHtml(html);
    text->setAccessibleName(dialog->windowTitle());
    column->addWidget(text, 1);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, dialog);
    QObject::connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::reject);
    column->addWidget(buttons);
    // Never taller or wider than the screen leaves room for: the table scrolls inside.
    const QScreen* screen =
        parent && parent->screen() ? parent->screen() : QGuiApplication::primaryScreen();
    const QSize room = screen ? screen->availableGeometry().size() * 9 / 10 : kPreferred;
    dialog->resize(kPreferred.boundedTo(room));
    dialog->setMaximumSize(screen ? screen->availableGeometry().size() : QSize(1024, 768));
    dialog->open();
    buttons->button(QDialogButtonBox::Close)->setFocus();
    return dialog;
}

} // namespace rigidlab::ui
