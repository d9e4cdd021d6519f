#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""compare_exports.py LINUX_DIR WINDOWS_DIR: a lesson's --export from Windows against Linux's.

The same files (but the SVGs, which the Windows build does not write), and in each CSV the same
cells: text equal, numbers equal to 1e-9 relative (the C libraries' maths differ in the last
bits), or both below 1e-12 in size. Prints what differs, and exits 1 if anything does.
"""
import csv
import math
import os
import sys

RELATIVE = 1e-9
NEGLIGIBLE = 1e-12


def files(root):
    found = set()
    for folder, _, names in os.walk(root):
        for name in names:
            found.add(os.path.relpath(os.path.join(folder, name), root))
    return found


def number(text):
    try:
        value = float(text)
    except ValueError:
        return None
    return value if math.isfinite(value) else None


def cells_agree(a, b):
    if a == b:
        return True
    x, y = number(a), number(b)
    if x is None or y is None:
        return False
    if abs(x) < NEGLIGIBLE and abs(y) < NEGLIGIBLE:
        return True
    return abs(x - y) <= RELATIVE * max(abs(x), abs(y))


def compare_csv(path_a, path_b, name, problems):
    with open(path_a, newline="", encoding="utf-8-sig") as fa, \
         open(path_b, newline="", encoding="utf-8-sig") as fb:
        rows_a, rows_b = list(csv.reader(fa)), list(csv.reader(fb))
    if len(rows_a) != len(rows_b):
        problems.append(f"{name}: {len(rows_a)} rows on Linux, {len(rows_b)} on Windows")
        return 0
    cells = 0
    for i, (ra, rb) in enumerate(zip(rows_a, rows_b), start=1):
        if len(ra) != len(rb):
            problems.append(f"{name}:{i}: {len(ra)} cells on Linux, {len(rb)} on Windows")
            continue
        for j, (a, b) in enumerate(zip(ra, rb), start=1):
            cells += 1
            if not cells_agree(a, b):
                problems.append(f"{name}:{i}:{j}: Linux {a!r}, Windows {b!r}")
    return cells


def main(linux, windows):
    problems = []
    expected = {f for f in files(linux) if not f.endswith(".svg")}
    got = files(windows)
    for f in sorted(expected - got):
        problems.append(f"{f}: written on Linux, not on Windows")
    for f in sorted(got - expected):
        problems.append(f"{f}: written on Windows, not on Linux")
    cells = 0
    for f in sorted(expected & got):
        if f.endswith(".csv"):
            cells += compare_csv(os.path.join(linux, f), os.path.join(windows, f), f, problems)
        elif os.path.getsize(os.path.join(windows, f)) == 0:
            problems.append(f"{f}: empty on Windows")
    for p in problems[:40]:
        print("compare_exports:", p)
    if len(problems) > 40:
        print(f"compare_exports: ... and {len(problems) - 40} more")
    print(f"compare_exports: {len(expected & got)} files, {cells} CSV cells compared, "
          f"{len(problems)} differences")
    return 1 if problems else 0


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: compare_exports.py LINUX_DIR WINDOWS_DIR")
    sys.exit(main(sys.argv[1], sys.argv[2]))
