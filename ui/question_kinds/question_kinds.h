// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What each kind of question shows in the window, one file per kind (kind_ui.h says what a kind
// has there): the one list of them, as lessons/format/question_kinds.h lists the kinds. The
// lesson player, the worksheet and the lesson editor include this list and find a kind's rows,
// lines and page by its type; a kind of lessons::QuestionKind missing here does not compile.

#include "question_kinds/choice.h"
#include "question_kinds/kind_ui.h"
#include "question_kinds/measured.h"
#include "question_kinds/number_given.h"
