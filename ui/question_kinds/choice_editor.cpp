// SPDX-License-Identifier: GPL-3.0-or-later
#include "question_kinds/choice_editor.h"
#include "question_kinds/editor_parts.h"

#include "format/lesson.h"
#include "format/lesson_schema.h"

#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QJsonArray>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <array>

namespace rigidlab::ui {

namespace {

namespace keys = lessons::schema::question_keys;
using lessons::schema::jsonKey;

/// The table's columns, as in the rest of the lesson editor: the window's language first.
QString columnLanguage(int column)
{
    return editorLanguages()[static_cast<std::size_t>(column)];
}

constexpr int kColumns = static_cast<int>(kEditorLanguages);

} // namespace

ChoiceEditor::ChoiceEditor(QWidget* parent) : QWidget(parent)
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    auto* label = new QLabel(tr("&Options (one language is enough)"), this);
    m_table = new QTableWidget(0, kColumns, this);
    m_table->setObjectName(QStringLiteral("choiceOptions"));
    m_table->setAccessibleName(tr("Options of the choice"));
    QStringList heads;
    for (int c = 0; c < kColumns; ++c)
        heads << lessons::languageTitle(columnLanguage(c));
    m_table->setHorizontalHeaderLabels(heads);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    m_table->setSelectionMode(QAbstractItemView::SingleSelection);
    m_table->setTabKeyNavigation(false); // Tab leaves the table for the buttons
    m_table->setMaximumHeight(140);
    label->setBuddy(m_table);
    connect(m_table, &QTableWidget::itemChanged, this, [this] {
        if (!m_showing)
            emit edited();
    });
    connect(m_table, &QTableWidget::currentCellChanged, this, &ChoiceEditor::showButtons);
    auto* buttons = new QHBoxLayout;
    const auto button = [this, buttons](const QString& text, const char* name, auto slot) {
        QPushButton* b = addEditorButton(this, buttons, text, name);
        connect(b, &QPushButton::clicked, this, slot);
        return b;
    };
    m_add = button(tr("Add optio&n"), "addChoiceOption", [this] { addOption(currentLanguage()); });
    m_remove = button(tr("Remove option"), "removeChoiceOption", [this] { removeOption(); });
    m_up = button(tr("Option up"), "choiceOptionUp", [this] { moveOption(-1); });
    m_down = button(tr("Option down"), "choiceOptionDown", [this] { moveOption(1); });
    m_right = new QComboBox(this);
    m_right->setObjectName(QStringLiteral("choiceRight"));
    m_right->setAccessibleName(tr("The right option"));
    connect(m_right, &QComboBox::activated, this, [this] { emit edited(); });
    auto* right = new QFormLayout;
    right->setContentsMargins(0, 0, 0, 0);
    right->addRow(tr("Ri&ght option"), m_right);
    layout->addWidget(label);
    layout->addWidget(m_table);
    layout->addLayout(buttons);
    layout->addLayout(right);
}

void ChoiceEditor::setQuestion(const QJsonObject& q)
{
    showOptions(q.value(jsonKey(keys::kChoices)).toArray(),
                q.value(jsonKey(keys::kAnswer)).toInt());
}

QJsonArray ChoiceEditor::options() const
{
    QJsonArray out;
    for (int r = 0; r < m_table->rowCount(); ++r) {
        // A language left empty is not written: the student reads the option in one it has
        // (an option with none is refused, and marked, by the loader).
        QJsonValue option = QJsonObject();
        for (int c = 0; c < kColumns; ++c) {
            const QTableWidgetItem* item = m_table->item(r, c);
            option = withWrittenText(option, columnLanguage(c), item ? item->text() : QString());
        }
        out.append(option.isNull() ? QJsonValue(QJsonObject()) : option);
    }
    return out;
}

QJsonObject ChoiceEditor::applyTo(QJsonObject q) const
{
    q.insert(jsonKey(keys::kChoices), options());
    q.insert(jsonKey(keys::kAnswer), std::max(m_right->currentIndex(), 0));
    return q;
}

void ChoiceEditor::showOptions(const QJsonArray& options, int right)
{
    m_showing = true;
    const int current = m_table->currentRow();
    m_table->setRowCount(static_cast<int>(options.size()));
    m_right->clear();
    for (int r = 0; r < options.size(); ++r) {
        for (int c = 0; c < kColumns; ++c) {
            // The items are kept, not made anew: this runs while one of them reports its edit.
            const QString text = writtenText(options.at(r), columnLanguage(c));
            if (QTableWidgetItem* item = m_table->item(r, c))
                item->setText(text);
            else
                m_table->setItem(r, c, new QTableWidgetItem(text));
        }
        m_right->addItem(QStringLiteral("%1. %2").arg(r + 1).arg(shownText(options.at(r))));
    }
    m_right->setCurrentIndex(std::clamp(right, 0, static_cast<int>(options.size()) - 1));
    if (current >= 0 && current < m_table->rowCount())
        m_table->setCurrentCell(current, std::max(m_table->currentColumn(), 0));
    m_showing = false;
    showButtons();
}

void ChoiceEditor::showButtons()
{
    const int rows = m_table->rowCount();
    const int at = m_table->currentRow();
    m_add->setEnabled(rows < lessons::kMaxChoices);
    m_remove->setEnabled(at >= 0 && rows > lessons::kMinChoices);
    m_up->setEnabled(at > 0);
    m_down->setEnabled(at >= 0 && at < rows - 1);
}

QString ChoiceEditor::optionName(int n)
{
    return tr("Option %1").arg(n);
}

void ChoiceEditor::addOption(const QString& language)
{
    QJsonArray all = options();
    if (all.size() >= lessons::kMaxChoices)
        return;
    all.append(QJsonObject{{language, optionName(static_cast<int>(all.size()) + 1)}});
    showOptions(all, m_right->currentIndex());
    m_table->setCurrentCell(static_cast<int>(all.size()) - 1, 0);
    emit edited();
}

void ChoiceEditor::removeOption()
{
    QJsonArray all = options();
    const int at = m_table->currentRow();
    if (at < 0 || at >= all.size() || all.size() <= lessons::kMinChoices)
        return;
    all.removeAt(at);
    int right = m_right->currentIndex();
    if (right > at || right == static_cast<int>(all.size()))
        --right; // the right option keeps pointing at the same text where it can
    showOptions(all, right);
    emit edited();
}

void ChoiceEditor::moveOption(int by)
{
    QJsonArray all = options();
    const int at = m_table->currentRow();
    const int to = at + by;
    if (at < 0 || to < 0 || to >= all.size())
        return;
    const QJsonValue moved = all.at(at);
    all.removeAt(at);
    all.insert(to, moved);
    int right = m_right->currentIndex();
    if (right == at)
        right = to;
    else if (right == to)
        right = at;
    showOptions(all, right);
    m_table->setCurrentCell(to, std::max(m_table->currentColumn(), 0));
    emit edited();
}

} // namespace rigidlab::ui
