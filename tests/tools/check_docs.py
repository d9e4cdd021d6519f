#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""The user's documents hold together: the English manual (docs/manual.md), its Czech
translation (docs/manual.cs.md), both READMEs and docs/accessibility.md; and the speed's
documents (docs/performance.md, docs/performance-profile.md for where the step's time goes, and
the logs: docs/performance-log.md for the benchmark's full runs,
docs/performance-log-precision.md for the soft step's precision and substeps,
docs/performance-log-collision.md for the collision stage (the broad and the narrow phase),
docs/performance-log-memory.md for the contact passes' memory and the soft step's bookkeeping,
docs/performance-log-window.md for the window's frames) find the rounds and sections they name.

- Every relative link names a file that exists, and every #anchor names a heading of the file
  it points into (GitHub's heading anchors: lower case, punctuation dropped, spaces to '-').
- A round named from another document is a heading of the log it is in: the log's "TITLE" (or
  a list of "TITLE"s) in docs/performance-log.md, the precision log's "TITLE" in
  docs/performance-log-precision.md, the collision log's "TITLE" in
  docs/performance-log-collision.md, the memory log's "TITLE" in docs/performance-log-memory.md,
  the window log's "TITLE" in docs/performance-log-window.md, and "TITLE" in [name](FILE.md) in
  FILE.md. TITLE may be the heading's start, and the reference and TITLE may break across
  lines.
- A section named beside a file's name without a link is a heading of that file:
  performance.md's "TITLE", performance.md, "TITLE", performance.md under "TITLE" (also after
  a link, [name](FILE.md) under "TITLE"), performance.md ("TITLE", "TITLE", …) and
  "TITLE" (performance.md …).
- In the speed's documents, "TITLE" below and "TITLE" above (then a punctuation mark) name a
  heading of the same file, after or before the reference: a section moved to another file
  must be named with its file.
- The two manuals link to each other, and each README to the manual in its language.
- The Czech manual has the English one's sections: the same sequence of heading levels.
- Every key the English manual names (F6, Ctrl+Shift+S, Alt+Up, …) appears in the Czech one,
  and every key of the English Keys table in the Czech Keys table (Space is "Mezerník" there,
  as the Czech window writes it). Alt with a single letter is a menu or field mnemonic,
  which differs between the languages, so it is not compared.

Exit 0 when everything holds; otherwise one line per finding and exit 1.

usage: check_docs.py SOURCE_DIR
"""
import re
import sys
from pathlib import Path

DOCUMENTS = ["docs/manual.md", "docs/manual.cs.md", "README.md", "README.cs.md",
             "docs/accessibility.md"]
# The speed's documents: their links, the rounds and sections they name, and their "below" and
# "above" are checked.
SPEED_DOCUMENTS = ["docs/performance.md", "docs/performance-profile.md", "docs/performance-log.md",
                   "docs/performance-log-precision.md", "docs/performance-log-collision.md",
                   "docs/performance-log-memory.md", "docs/performance-log-window.md"]
LOGS = {"the log's": "docs/performance-log.md",
        "the precision log's": "docs/performance-log-precision.md",
        "the collision log's": "docs/performance-log-collision.md",
        "the memory log's": "docs/performance-log-memory.md",
        "the window log's": "docs/performance-log-window.md"}
NAMED_ROUNDS = re.compile(r"(the\s+(?:(?:window|precision|collision|memory)\s+)?log's)"
                          r"(?:\s+full table)?\s*\(?(\s*\"[^\"]+\"(?:,\s*\"[^\"]+\")*)")
ROUND_IN_FILE = re.compile(r"\"([^\"]+)\"\s+in\s+\[[^\]]*\]\(([\w.-]+\.md)\)")
# A file's name (not a path, not a link's text) and the sections named beside it.
FILE_THEN_TITLES = re.compile(r"(?<![\w/\[.-])([\w-]+\.md)\)?(?:'s)?,?\s+(?:under\s+)?"
                              r"\(?(\"[^\"]+\"(?:,\s*\"[^\"]+\")*)")
# Every quoted text, in order (so that quotes pair up), with what may follow it: below or above
# and a punctuation mark or bracket (not "fast" above a quarter of its width), or a file's name
# in brackets.
QUOTED = re.compile(r"\"([^\"]+)\"(?:,?\s+(below|above)(?=\s*[^\w\s])|\s+\(([\w-]+\.md)\b)?")
LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)\)")
KEY = re.compile(r"(?<![\w+])((?:(?:Ctrl|Shift|Alt)\+)+(?:F\d{1,2}|[A-Z]\b|Up|Down|Left|Right|"
                 r"Del|PgUp|PgDown|Backspace|Space)|F\d{1,2}\b)")
# The Czech window's names of keys that Qt translates (Help › Controls shows them so).
CZECH_KEY_NAMES = {"Space": "Mezerník"}


def prose(text):
    """The text without fenced code blocks, where '#' starts a shell comment, not a heading."""
    return re.sub(r"^```.*?^```", "", text, flags=re.S | re.M)


def headings(text):
    return [(len(m.group(1)), m.group(2).strip())
            for m in re.finditer(r"^(#{1,6}) +(.+)$", prose(text), re.M)]


def slug(title):
    title = re.sub(r"[`*]", "", title).lower()
    return re.sub(r"[^\w\- ]", "", title).replace(" ", "-")


def check_links(root, name, text, problems):
    for target in LINK.findall(prose(text)):
        if re.match(r"[a-z]+:", target):
            continue  # a web address or mailto: not checked offline
        path, _, anchor = target.partition("#")
        file = (root / name).parent / path if path else root / name
        if not file.exists():
            problems.append(f"{name}: link to {target}: no such file")
            continue
        if anchor and file.suffix == ".md":
            slugs = {slug(t) for _, t in headings(file.read_text(encoding="utf-8"))}
            if anchor not in slugs:
                problems.append(f"{name}: link to {target}: no heading with that anchor")


def one_line(text):
    return " ".join(text.split())


def check_rounds(root, name, text, problems):
    """Every round another document names by its title is a heading of the log named."""
    def check(title, log):
        if not (root / log).exists():
            problems.append(f'{name}: "{one_line(title)}" in {log}: no such file')
            return
        titles = [one_line(t) for _, t in headings((root / log).read_text(encoding="utf-8"))]
        if not any(t.startswith(one_line(title)) for t in titles):
            problems.append(f'{name}: "{one_line(title)}": no such heading in {log}')

    for which, titles in NAMED_ROUNDS.findall(text):
        for title in re.findall(r'"([^"]+)"', titles):
            check(title, LOGS[one_line(which)])
    for title, file in ROUND_IN_FILE.findall(text):
        check(title, str(((root / name).parent / file).relative_to(root)))
    for file, titles in FILE_THEN_TITLES.findall(prose(text)):
        for title in re.findall(r'"([^"]+)"', titles):
            check(title, str(((root / name).parent / file).relative_to(root)))
    for match in QUOTED.finditer(prose(text)):
        if match.group(3):
            check(match.group(1), str(((root / name).parent / match.group(3)).relative_to(root)))


def check_here(name, text, problems):
    """A "TITLE" below (above) names a heading of this file after (before) the reference."""
    text = prose(text)
    spots = [(m.start(), one_line(m.group(2)))
             for m in re.finditer(r"^(#{1,6}) +(.+)$", text, re.M)]
    for match in QUOTED.finditer(text):
        title, where = one_line(match.group(1)), match.group(2)
        if not where:
            continue
        if where == "below":
            found = any(at > match.end() and t.startswith(title) for at, t in spots)
        else:
            found = any(at < match.start() and t.startswith(title) for at, t in spots)
        if not found:
            problems.append(f'{name}: "{title}" {where}: no such heading {where} it in {name}')


def keys_table(text):
    """The first column of the table under the '## Keys' (or '## Klávesy') heading."""
    section = re.search(r"^## (?:Keys|Klávesy)\n(.*?)(?=^## )", text, re.S | re.M)
    if not section:
        return ""
    return "\n".join(line.split("|")[1] for line in section.group(1).splitlines()
                     if line.startswith("|") and "---" not in line)


def table_keys(column):
    words = set(re.findall(r"(?:(?:Ctrl|Shift|Alt)\+)*[^\s/()]+", column))
    return {w for w in words if w not in {"or", "nebo", "key", "klávesa"}}


def check_keys(english, czech, problems):
    def named(text):
        return {k for k in KEY.findall(text) if not re.fullmatch(r"Alt\+[A-Z]", k)}

    for key in sorted(named(english) - named(czech)):
        problems.append(f"docs/manual.cs.md: the key {key} of the English manual is not named")
    english_table, czech_table = table_keys(keys_table(english)), table_keys(keys_table(czech))
    if not english_table:
        problems.append("docs/manual.md: no Keys table found")
    for key in sorted(english_table):
        if CZECH_KEY_NAMES.get(key, key) not in czech_table:
            problems.append(f"docs/manual.cs.md: the Keys table lacks {key}")


def main(root):
    root = Path(root)
    texts = {name: (root / name).read_text(encoding="utf-8") for name in DOCUMENTS}
    speed = {name: (root / name).read_text(encoding="utf-8") for name in SPEED_DOCUMENTS}
    problems = []
    for name, text in {**texts, **speed}.items():
        check_links(root, name, text, problems)
        check_rounds(root, name, text, problems)
    for name, text in speed.items():
        check_here(name, text, problems)
    for name, target in [("docs/manual.md", "manual.cs.md"), ("docs/manual.cs.md", "manual.md"),
                         ("README.md", "docs/manual.md"), ("README.cs.md", "docs/manual.cs.md")]:
        if f"]({target}" not in texts[name]:
            problems.append(f"{name}: no link to {target}")
    english, czech = texts["docs/manual.md"], texts["docs/manual.cs.md"]
    levels_en = [level for level, _ in headings(english)]
    levels_cs = [level for level, _ in headings(czech)]
    if levels_en != levels_cs:
        problems.append(f"docs/manual.cs.md: heading levels {levels_cs} differ from the English "
                        f"manual's {levels_en}")
    check_keys(english, czech, problems)
    for line in problems:
        print(line)
    print(f"{len(problems)} problem(s) in {len(texts) + len(speed)} documents")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
