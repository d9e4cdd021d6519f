// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A verdict on a student's try at a question, and how its numbers are written: what every kind
// of question judges with (format/question_kinds/), the measured kind in lessons/run/judge.cpp.

#include "format/answers_file.h"

#include <QCoreApplication>
#include <QString>

namespace rigidlab::lessons {

// Every verdict is one whole sentence, its numbers as %1 placeholders, so that a translator
// can reorder it: no sentence is assembled from words.
struct Judge {
    Q_DECLARE_TR_FUNCTIONS(Judge)
};

struct Verdict {
    bool measured = false; ///< false: run the simulation further first
    bool right = false;
    bool shown = false; ///< the message gives the measured value
    double value = 0;   ///< what was measured
    QString message;    ///< what the student reads
};

/// Where a question's tries stand: the tries judged against a measured value, and whether
/// the value has been given (after which every try is judged as a later one).
struct TryCount {
    int attempts = 0;
    bool answered = false;
};

/// `text` with a word joiner after the slash of every unit that follows a number and a
/// no-break space ("3 m/s", "4 kg m/s" with no-break spaces), so that no line breaks inside
/// the unit.
QString keepUnitsTogether(QString text);

/// A number as a student would write it, in the window's locale, with its unit after a
/// no-break space: enough significant digits to tell a relative tolerance apart (three at the
/// usual 5 %), no rounding noise, no "-0".
QString formatAnswer(double value, double relativeTolerance, const QString& unit);

} // namespace rigidlab::lessons
