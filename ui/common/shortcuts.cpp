// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/shortcuts.h"

#include <QCoreApplication>

namespace rigidlab::ui {

namespace {

QString trControls(const char* text)
{
    return QCoreApplication::translate("Controls", text);
}

QString row(const QString& what, const QString& description)
{
    return QStringLiteral("<tr><td style='padding-right:12px'><b>%1</b></td><td>%2</td></tr>")
        .arg(what, description.toHtmlEscaped());
}

QString keysText(const QList<QKeySequence>& keys)
{
    QStringList names;
    for (const QKeySequence& k : keys)
        names << k.toString(QKeySequence::NativeText);
    return names.join(QCoreApplication::translate("Controls", " or "));
}

} // namespace

QList<QKeySequence> controlKeys(std::string_view action)
{
    for (const ControlInfo& c : kControls)
        if (c.keys && c.action == action)
            return QKeySequence::listFromString(QString::fromLatin1(c.keys),
                                                QKeySequence::PortableText);
    return {};
}

QString controlKeysText(std::string_view action)
{
    return keysText(controlKeys(action));
}

QString controlsHelpHtml(const QList<ControlHelpRow>& extra)
{
    QString keyboard, mouse;
    for (const ControlInfo& c : kControls) {
        if (c.keys)
            keyboard +=
                row(keysText(controlKeys(c.action)).toHtmlEscaped(), trControls(c.description));
        else
            mouse += row(trControls(c.gesture).toHtmlEscaped(), trControls(c.description));
    }
    for (const ControlHelpRow& r : extra)
        keyboard += row(keysText(r.keys).toHtmlEscaped(), r.description);
    return QStringLiteral("<h3>%1</h3><table>%2</table><h3>%3</h3><table>%4</table>")
        .arg(QCoreApplication::translate("Controls", "Keyboard"), keyboard,
             QCoreApplication::translate("Controls", "Mouse"), mouse);
}

} // namespace rigidlab::ui
