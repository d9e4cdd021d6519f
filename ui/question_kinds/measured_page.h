// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The lesson editor's fields of a measured question (measured.h): what is measured (the
// quantity, the body by its label, the time), the unit and the tolerance of the answer. The
// prompt the editor wrote for a measure follows it, until the teacher writes their own.

#include "question_kinds/kind_ui.h"

#include <QJsonObject>

class QComboBox;
class QDoubleSpinBox;
class QLineEdit;

namespace rigidlab::ui {

class MeasuredPage : public KindPage {
public:
    explicit MeasuredPage(QWidget* parent);
    void showQuestion(const QJsonObject& q, const QJsonObject& scene) override;
    void applyTo(QJsonObject& q) const override;

private:
    /// The prompt of `q` rewritten for its measure when it is still the one the editor wrote
    /// for `was`, the measure before.
    void followMeasure(const QJsonObject& was, QJsonObject& q) const;

    QComboBox* m_kind = nullptr;
    QComboBox* m_body = nullptr;
    QDoubleSpinBox* m_time = nullptr;
    QLineEdit* m_unit = nullptr;
    QDoubleSpinBox* m_tolerance = nullptr;
    QJsonObject m_scene; ///< the scene of the step the question shown is asked in
};

} // namespace rigidlab::ui
