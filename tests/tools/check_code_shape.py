#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The code's shape, as docs/design.md promises it: no source or test file over 600 lines, no
function over 80 lines except those named in design.md's "Long on purpose" table, no ui/
subfolder that includes another which includes it back, no ui/ folder that includes one of
its own or a later layer (UI_LAYERS), and no language code written as a string ("cs", "en") in
production code outside the languages table (lessons/format/languages.h and .cpp): every code
path reads that table; no stage of a step (physics/src/stages, physics/src/fast) reads the
world's settings (`ctx.def`): it reads the step context's values, computed once; and the
readers of the run-time settings (SETTING_READERS) name no setting: they walk the settings
table; each rule of the engine written once (ONE_HOME: the bounce -e vn, drag's power,
the state gather, the material that falls back to the world's) appears only in its home file;
no plot is named outside the plots' table (ui/plots/plot_table.h); and no production code
tests a question's kind by a flag (`isChoice()`, an empty `choices`, `holds_alternative` of a
kind): where the kinds differ it visits Question::kind, so that a new kind does not compile
until every such place handles it; and the lesson editor (QUESTION_KEY_READERS) writes no
question's key as a string: it names them through the lesson schema's question_keys
(lessons/format/lesson_schema.h), which its rows are written with.

Functions are found by Universal Ctags (their first and last line); a file is every tracked
.cpp/.h under physics/, lessons/, ui/, app/, bench/ and tests/. Exit 0 when everything holds;
otherwise one line per finding and exit 1.

usage: check_code_shape.py SOURCE_DIR
"""
import re
import subprocess
import sys
from pathlib import Path

MAX_FILE_LINES = 600
MAX_FUNCTION_LINES = 80
TOP_FOLDERS = ["physics", "lessons", "ui", "app", "bench", "tests"]


def sources(root):
    out = []
    for folder in TOP_FOLDERS:
        base = root / folder
        if base.is_dir():
            out += [p for p in base.rglob("*") if p.suffix in (".cpp", ".h") and p.is_file()]
    return sorted(out)


def exceptions(root):
    """Rows `| path | function | reason |` under the heading "Long on purpose" in design.md."""
    design = root / "docs" / "design.md"
    allowed = set()
    if not design.is_file():
        return allowed
    inside = False
    for line in design.read_text(encoding="utf-8").splitlines():
        if line.startswith("#"):
            inside = "long on purpose" in line.lower()
            continue
        if inside and line.startswith("|"):
            cells = [c.strip().strip("`") for c in line.strip().strip("|").split("|")]
            if len(cells) >= 3 and cells[0] and not set(cells[0]) <= set("-: "):
                allowed.add((cells[0], cells[1]))
    return allowed


def functions(root, files):
    """(path, first line, last line, name) of every function defined in `files`."""
    cmd = ["ctags", "-x", "--_xformat=%F\t%n\t%e\t%N", "--kinds-c++=f", "--language-force=c++",
           "-f", "-"] + [str(f.relative_to(root)) for f in files]
    out = subprocess.run(cmd, cwd=root, capture_output=True, text=True, check=True).stdout
    found = []
    for line in out.splitlines():
        parts = line.split("\t")
        if len(parts) != 4 or not parts[2].isdigit():
            continue
        found.append((parts[0], int(parts[1]), int(parts[2]), parts[3]))
    return found


def long_functions(all_functions):
    return [(path, name, end - start + 1) for path, start, end, name in all_functions
            if end - start + 1 > MAX_FUNCTION_LINES]


# The readers of the run-time settings (docs/design.md, "A run-time setting of the world"):
# each walks schema::settings() or the world rows, so none may name a setting itself.
SETTING_ROWS = ["lessons/format/scene_schema_rows.cpp", "lessons/format/scene_schema_links.cpp"]
SETTING_READERS = [
    ("lessons/format/lesson.cpp", "applySettings"),
    ("lessons/format/lesson.cpp", "askedStep"),
    ("lessons/format/lesson_settings.cpp", "readSettingsObject"),
    ("ui/simulation/setting_edit.cpp", "editsAtStart"),
    ("ui/simulation/simulation_controller.cpp", "reset"),
    ("ui/simulation/simulation_controller.cpp", "applyEdit"),
    ("ui/simulation/simulation_controller.cpp", "setSetting"),
    ("ui/lesson_player/asked_run.cpp", "changes"),
    ("ui/lesson_player/asked_run.cpp", "askedRun"),
    ("ui/panels/control_panel.cpp", "setAllowed"),
]


def setting_keys(root):
    """The keys of the rows that are run-time settings (those with `.setting = N`)."""
    keys = set()
    for rel in SETTING_ROWS:
        text = (root / rel).read_text(encoding="utf-8")
        for chunk in re.split(r"(?=\.key = \")", text)[1:]:
            key = re.match(r'\.key = "(\w+)"', chunk).group(1)
            if re.search(r"\.setting = [1-9]", chunk):
                keys.add(key)
    return keys


def settings_restated(root, all_functions):
    """(path, function, what) of each settings reader that names a setting or is gone."""
    keys = setting_keys(root)
    pattern = re.compile(r'"(' + "|".join(sorted(keys)) + r')"') if keys else None
    out = []
    if len(keys) < 8:
        out.append((SETTING_ROWS[0], "", f"only {len(keys)} settings found (.setting = N)"))
    for path, name in SETTING_READERS:
        spans = [(a, b) for p, a, b, n in all_functions if p == path and n == name]
        if not spans:
            out.append((path, name, "not found (update SETTING_READERS)"))
            continue
        lines = (root / path).read_text(encoding="utf-8").splitlines()
        for a, b in spans:
            for number in range(a, b + 1):
                code = lines[number - 1].split("//")[0]
                if pattern and pattern.search(code):
                    out.append((f"{path}:{number}", name, "names a setting"))
    return out


# The ui/ folders in their layers, lowest first (docs/design.md, "Layers and folders"): a
# folder includes only folders of a lower layer. Folders of one layer (editor, lesson_player)
# do not include each other. A folder not listed here is only checked for include cycles.
UI_LAYERS = {"common": 0, "simulation": 1, "question_kinds": 1, "plots": 2, "worksheet": 3,
             "view": 4, "panels": 5, "instruments": 5, "editor": 6, "lesson_player": 6, "measure": 7,
             "lesson_editor": 7, "window": 8}


def layer_breaches(root):
    ui = root / "ui"
    if not ui.is_dir():
        return []
    pattern = re.compile(r'#include\s+"([a-z_]+)/')
    found = set()
    for folder in sorted(p.name for p in ui.iterdir() if p.is_dir() and p.name in UI_LAYERS):
        for f in sorted((ui / folder).rglob("*")):
            if f.suffix not in (".cpp", ".h"):
                continue
            for m in pattern.finditer(f.read_text(encoding="utf-8", errors="replace")):
                used = m.group(1)
                if used != folder and UI_LAYERS.get(used, -1) >= UI_LAYERS[folder]:
                    found.add((f.relative_to(root).as_posix(), used))
    return sorted(found)


def include_cycles(root):
    ui = root / "ui"
    if not ui.is_dir():
        return []
    folders = sorted(p.name for p in ui.iterdir() if p.is_dir())
    uses = {r: set() for r in folders}
    pattern = re.compile(r'#include\s+"([a-z_]+)/')
    for r in folders:
        for f in (ui / r).rglob("*"):
            if f.suffix in (".cpp", ".h"):
                for m in pattern.finditer(f.read_text(encoding="utf-8", errors="replace")):
                    if m.group(1) in uses and m.group(1) != r:
                        uses[r].add(m.group(1))
    return [(a, b) for a in folders for b in folders if a < b and b in uses[a] and a in uses[b]]


LANGUAGE_TABLE = {"lessons/format/languages.h", "lessons/format/languages.cpp"}
PRODUCTION = ["physics", "lessons", "ui", "app"]


def production_code(root, files, table):
    """(path, line number, the line without its comment) of each line of production code outside
    the files of `table`, the one place allowed to write what a check looks for."""
    for f in files:
        rel = f.relative_to(root).as_posix()
        if rel.split("/")[0] not in PRODUCTION or rel in table:
            continue
        for number, line in enumerate(f.read_text(encoding="utf-8", errors="replace").splitlines(), 1):
            yield rel, number, line.split("//")[0]


def language_literals(root, files):
    """(path, line number) of each "cs" or "en" string literal outside the languages table."""
    pattern = re.compile(r'(?:u|QStringLiteral\(|QLatin1String\()?"(?:cs|en)"')
    return [(rel, number) for rel, number, code in production_code(root, files, LANGUAGE_TABLE)
            if pattern.search(code)]


STAGE_FOLDERS = ["physics/src/stages", "physics/src/fast"]


def settings_read_in_stages(root, files):
    """(path, line number) of each `ctx.def` in a stage file: a stage reads its context only."""
    pattern = re.compile(r"\bctx\s*\.\s*def\b")
    out = []
    for f in files:
        rel = f.relative_to(root).as_posix()
        if not any(rel.startswith(folder + "/") for folder in STAGE_FOLDERS):
            continue
        for number, line in enumerate(f.read_text(encoding="utf-8", errors="replace").splitlines(), 1):
            if pattern.search(line.split("//")[0]):
                out.append((rel, number))
    return out


# A physics rule, the one file that writes it, and what writing it again looks like.
ONE_HOME = [
    ("the bounce -e vn", "physics/src/stages/restitution.h",
     re.compile(r"-\s*(?:\w+\s*(?:\.|->)\s*)*(?:restitution|e)\s*\*")),
    ("drag's power", "physics/src/stages/dynamics.h",
     re.compile(r"\bdrag\s*\*\s*\(\s*\w+\s*(?:\.|->)\s*mass\b")),
    ("the gather of the ODE state", "physics/src/stages/dynamics.h",
     re.compile(r"segment<3>\(\s*\w+\s*\)\s*<<")),
    ("the world's material for a body without its own", "physics/include/rigidlab/physics/body.h",
     re.compile(r"\b(?:restitution|friction)\s*>=\s*0(?:\.0)?\s*\?")),
]


def rules_restated(root, files):
    """(path, line number, rule) of each physics rule written outside its home (ONE_HOME)."""
    return [(rel, number, rule, home) for rel, number, code in production_code(root, files, set())
            for rule, home, pattern in ONE_HOME if rel != home and pattern.search(code)]


# The plots' table (ui/plots/plot_table.h): the window, the lesson steps, the exports, the CLI
# and the lesson editor make and name the plots from its rows, so no production file but the
# table and the lesson format's list names a plot, takes a row by its place in the table
# (kPlotRows[i]) or, above the lesson format, tells a kind of plot by its name's prefix
# ("compare-": the row says).
PLOT_TABLE = {"ui/plots/plot_table.h", "ui/plots/plot_table.cpp", "lessons/format/lesson.h"}


def plot_names(root):
    text = (root / "lessons/format/lesson.h").read_text(encoding="utf-8")
    m = re.search(r"kStepPlotNames\{([^}]*)\}", text)
    return re.findall(r'"([\w-]+)"', m.group(1)) if m else []


def plots_named(root, files):
    """(path, line number) of each plot named outside the plots' table: its name written as a Qt
    string, its row taken by index, or its kind told by the name's prefix."""
    names = plot_names(root)
    if not names:
        return [("lessons/format/lesson.h", 0)]
    pattern = re.compile(r'(?:QLatin1String\(|QStringLiteral\(|\bu)"(?:' +
                         "|".join(re.escape(n) for n in names) + r')"|\bkPlotRows\s*\[')
    # The lesson loader (lessons/, below the table) refuses a compared worlds' plot in a step
    # that compares none by the format's own rule: their names start with "compare-".
    prefix = re.compile(r'"compare-"')
    return [(rel, number) for rel, number, code in production_code(root, files, PLOT_TABLE)
            if pattern.search(code) or (not rel.startswith("lessons/") and prefix.search(code))]


QUESTION_KIND_FLAG = re.compile(
    r"\bisChoice\s*\(\s*\)|\bchoices\s*\.\s*(?:isEmpty|empty)\s*\(\s*\)"
    r"|holds_alternative\s*<\s*(?:lessons::)?\w+Question\s*>")


def question_kind_flags(root, files):
    """A finding for each test of a question's kind by a flag in production code."""
    return [f"{rel}:{number}: a question's kind tested by a flag; visit Question::kind "
            f"(lessons/format/lesson.h) with one case per kind"
            for rel, number, code in production_code(root, files, set())
            if QUESTION_KIND_FLAG.search(code)]


# Where the question keys are spelt: every question's, and each kind's in its own file.
QUESTION_KEY_HEADERS = ["lessons/format/lesson_rows.h", "lessons/format/question_kinds/"]
QUESTION_KEY_READERS = ["ui/lesson_editor/", "ui/question_kinds/"]


def question_key_literals(root, files):
    """A finding for each question row's key written as a string literal in the lesson editor:
    the keys are the ones lesson_schema.h spells in its `question_keys` namespace."""
    headers = [root / QUESTION_KEY_HEADERS[0]] + sorted(
        (root / QUESTION_KEY_HEADERS[1]).glob("*.h"))
    header = "".join(h.read_text(encoding="utf-8") for h in headers)
    keys = re.findall(r'inline constexpr std::string_view k\w+ = "(\w+)";', header)
    if not keys:
        return [f"{QUESTION_KEY_HEADERS[0]}: no question keys found (namespace question_keys)"]
    pattern = re.compile(r'"(' + "|".join(keys) + r')"')
    out = []
    for f in files:
        rel = f.relative_to(root).as_posix()
        if not any(rel.startswith(reader) for reader in QUESTION_KEY_READERS):
            continue
        for number, line in enumerate(f.read_text(encoding="utf-8", errors="replace").splitlines(), 1):
            for m in pattern.finditer(line.split("//")[0]):
                out.append(f"{rel}:{number}: the question key \"{m.group(1)}\" written out; name "
                           f"it through lessons::schema::question_keys (lesson_rows.h, its kind's file)")
    return out


def main():
    root = Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
    files = sources(root)
    problems = []
    for f in files:
        n = len(f.read_text(encoding="utf-8", errors="replace").splitlines())
        if n > MAX_FILE_LINES:
            problems.append(f"{f.relative_to(root)}: {n} lines (at most {MAX_FILE_LINES})")
    allowed = exceptions(root)
    all_functions = functions(root, files)
    for path, name, length in long_functions(all_functions):
        if (path, name) not in allowed:
            problems.append(f"{path}: function {name} is {length} lines (at most "
                            f"{MAX_FUNCTION_LINES}, or listed in docs/design.md, Long on purpose)")
    for a, b in include_cycles(root):
        problems.append(f"ui/{a} and ui/{b} include each other")
    for path, used in layer_breaches(root):
        problems.append(f"{path}: includes ui/{used}, a folder of its own or a later layer")
    for path, number in language_literals(root, files):
        problems.append(f"{path}:{number}: a language code written out; read lessons::kLanguages "
                        f"(lessons/format/languages.h) instead")
    for path, name, what in settings_restated(root, all_functions):
        problems.append(f"{path}: {name} {what}; read schema::settings() (lessons/format/"
                        f"scene_schema.h) instead")
    for path, number in plots_named(root, files):
        problems.append(f"{path}:{number}: a plot named by hand; take it from the plots' table "
                        f"(ui/plots/plot_table.h)")
    for path, number in settings_read_in_stages(root, files):
        problems.append(f"{path}:{number}: a stage reads the world's settings; take the value "
                        f"from the step context (step_context.h), computed once in World::context()")
    for path, number, rule, home in rules_restated(root, files):
        problems.append(f"{path}:{number}: {rule} written again; call the function in {home}")
    problems += question_kind_flags(root, files) + question_key_literals(root, files)
    for p in problems:
        print(p)
    print(f"{len(files)} files read, {len(problems)} findings")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
