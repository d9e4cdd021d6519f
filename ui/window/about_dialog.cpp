// SPDX-License-Identifier: GPL-3.0-or-later
#include "window/about_dialog.h"

#include "rigidlab/version.h"

#include <Eigen/Core>
#include <QCoreApplication>
#include <QMessageBox>
#include <qcustomplot.h>

namespace rigidlab::ui {

namespace {

/// The translation context of the About texts.
struct About {
    Q_DECLARE_TR_FUNCTIONS(About)
};

} // namespace

QString aboutText()
{
    const QString eigen = QStringLiteral("%1.%2.%3")
                              .arg(EIGEN_WORLD_VERSION)
                              .arg(EIGEN_MAJOR_VERSION)
                              .arg(EIGEN_MINOR_VERSION);
    return About::tr("<h3>RigidLab %1</h3>"
                     "<p>A lab for teaching 2D rigid-body mechanics: integrators and their energy "
                     "drift, collision detection by separating axes, and impulses.</p>"
                     "<p>It grows from the paper <i>Simulace mechaniky tuhých těles v reálném "
                     "čase</i> (<i>Real-time simulation of rigid-body mechanics</i>).</p>"
                     "<p>Licence: GNU General Public License, version 3 or any later version "
                     "(GPL-3.0-or-later), as QCustomPlot, which it links, requires. "
                     "See the LICENSE file.</p>"
                     "<p>Built with Qt %2 (running on Qt %3), QCustomPlot %4 and Eigen %5.</p>")
        .arg(QStringLiteral(RIGIDLAB_VERSION), QStringLiteral(QT_VERSION_STR),
             QString::fromLatin1(qVersion()), QStringLiteral(QCUSTOMPLOT_VERSION_STR), eigen);
}

void showAbout(QWidget* parent)
{
    // Not blocking: the window can check and close it like any other dialog.
    auto* box = new QMessageBox(QMessageBox::Information, About::tr("About RigidLab"), aboutText(),
                                QMessageBox::Ok, parent);
    box->setObjectName(QStringLiteral("aboutBox"));
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->setTextFormat(Qt::RichText);
    box->open();
}

} // namespace rigidlab::ui
