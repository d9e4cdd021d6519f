// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The tools that act on the body clicked: Delete (with its springs and pins) and Duplicate
// (a copy placed beside it). Delete deletes the selected body in every tool; Enter duplicates
// it with the Duplicate tool.

#include "editor/tools/tool.h"

namespace rigidlab::ui {

class DeleteTool : public Tool {
    Q_DECLARE_TR_FUNCTIONS(rigidlab::ui::EditTools)

public:
    using Tool::Tool;
    bool press(const ToolPointer& pointer) override;
    QString status() const override;
    bool busy() const override { return false; }
    void cancel() override {}
    bool marksSnaps() const override { return false; }
};

class DuplicateTool : public Tool {
    Q_DECLARE_TR_FUNCTIONS(rigidlab::ui::EditTools)

public:
    using Tool::Tool;
    bool press(const ToolPointer& pointer) override;
    bool wantsKey(int key) const override;
    void key(int key) override;
    QString status() const override;
    bool busy() const override { return false; }
    void cancel() override {}
    bool marksSnaps() const override { return false; }

private:
    void duplicate(int body);
};

} // namespace rigidlab::ui
