// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The step's questions below the lesson's scrolling text, above its buttons: always in sight.
// As tall as the questions where the column has the room, else as tall as the room the text
// leaves it (the later questions scroll), but never shorter than the first question with its
// answer box, Check and verdict.

#include <QScrollArea>

namespace rigidlab::ui {

/// The property a widget carries whose font follows another widget's (the questions follow
/// the step's text): presentation mode scales the one it follows, not this one as well.
inline constexpr const char* kFontFollowsProperty = "rigidlabFontFollows";

class QuestionArea : public QScrollArea {
    Q_OBJECT
public:
    /// Shows `questions`, a widget whose layout holds one widget per question.
    explicit QuestionArea(QWidget* questions, QWidget* parent = nullptr);

    /// The height the column leaves the questions once the step's text has its share [px];
    /// fits the area to it and to the questions as they are now.
    void setRoom(int px);
    /// Fits the height to the questions as they are now (a new step, a verdict, a font).
    void fit();
    /// The first question's height at the current width, with the space around it [px].
    int firstQuestionHeight() const;

protected:
    void resizeEvent(QResizeEvent* event) override;
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    /// fit() once the events queued now are handled.
    void fitSoon();
    int contentWidth() const;
    int contentHeight() const;

    int m_room = QWIDGETSIZE_MAX;
    int m_fittedWidth = -1; ///< the width of the last fit() [px]
};

} // namespace rigidlab::ui
