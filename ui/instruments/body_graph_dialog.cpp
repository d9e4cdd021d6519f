// SPDX-License-Identifier: GPL-3.0-or-later
#include "instruments/body_graph_dialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QListWidget>

#include <algorithm>

namespace rigidlab::ui {

BodyGraphDialog::BodyGraphDialog(const QStringList& labels, const BodyGraphSpec& initial,
                                 QWidget* parent)
    : QDialog(parent), m_quantity(new QComboBox(this)), m_bodies(new QListWidget(this)),
      m_each(new QCheckBox(tr("A curve for each body"), this)),
      m_sum(new QCheckBox(tr("A curve of their sum"), this)),
      m_centreOfMass(new QCheckBox(tr("In the centre-of-mass frame of these bodies"), this))
{
    setWindowTitle(tr("Graph of bodies"));
    for (int q = 0; q < kBodyQuantityCount; ++q)
        m_quantity->addItem(
            QStringLiteral("%1 [%2]").arg(quantityName(static_cast<BodyQuantity>(q)),
                                          quantityUnit(static_cast<BodyQuantity>(q))));
    m_quantity->setCurrentIndex(static_cast<int>(initial.quantity));
    m_quantity->setAccessibleName(tr("Quantity"));
    m_bodies->setAccessibleName(tr("Bodies"));
    for (int i = 0; i < labels.size(); ++i) {
        auto* item = new QListWidgetItem(labels[i], m_bodies);
        item->setFlags(item->flags() | Qt::ItemIsUserCheckable);
        const bool ticked =
            std::find(initial.bodies.begin(), initial.bodies.end(), i) != initial.bodies.end();
        item->setCheckState(ticked ? Qt::Checked : Qt::Unchecked);
    }
    m_each->setChecked(initial.eachBody);
    m_sum->setChecked(initial.sum);
    m_centreOfMass->setChecked(!initial.frame.isLab());
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* form = new QFormLayout(this);
    auto* quantityLabel = new QLabel(tr("&Quantity"), this);
    quantityLabel->setBuddy(m_quantity);
    form->addRow(quantityLabel, m_quantity);
    auto* bodiesLabel = new QLabel(tr("&Bodies"), this);
    bodiesLabel->setBuddy(m_bodies);
    form->addRow(bodiesLabel, m_bodies);
    form->addRow(m_each);
    form->addRow(m_sum);
    form->addRow(m_centreOfMass);
    form->addRow(buttons);
}

BodyGraphSpec BodyGraphDialog::spec() const
{
    BodyGraphSpec s;
    s.quantity = static_cast<BodyQuantity>(m_quantity->currentIndex());
    for (int i = 0; i < m_bodies->count(); ++i)
        if (m_bodies->item(i)->checkState() == Qt::Checked)
            s.bodies.push_back(i);
    s.eachBody = m_each->isChecked();
    s.sum = m_sum->isChecked();
    if (m_centreOfMass->isChecked())
        s.frame.bodies = s.bodies;
    return s;
}

} // namespace rigidlab::ui
