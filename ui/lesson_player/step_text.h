// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A lesson step's text: as tall as its words at the width it is given, so that it scrolls with
// the lesson around it rather than inside a box of its own. A table's text shrinks to fit that
// width; a table still too wide then scrolls sideways, its words whole, never broken.

#include <QTextBrowser>

namespace rigidlab::ui {

class StepText : public QTextBrowser {
    Q_OBJECT
public:
    explicit StepText(QWidget* parent = nullptr);

    /// Shows `markdown`, fitted to the current width.
    void showMarkdown(const QString& markdown);
    /// The accessible name while no text is shown; with a text, the text is its name.
    void setNameWhenEmpty(const QString& name);

    bool hasHeightForWidth() const override { return true; }
    int heightForWidth(int width) const override;
    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void resizeEvent(QResizeEvent* event) override;
    void changeEvent(QEvent* event) override;

private:
    /// Lays the text out again at the viewport's width, its tables' text as large as fits.
    void fit();
    /// Names the widget for assistive technology by its text (setNameWhenEmpty()).
    void tellName();

    QString m_markdown;
    QString m_nameWhenEmpty;
    int m_fittedWidth = -1;   ///< viewport width of the last fit() [px]
    bool m_overflows = false; ///< a table is wider than the column: the text scrolls sideways
};

} // namespace rigidlab::ui
