#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""No path of the checkout on a compiler's command line but where it is needed.

ccache (./lab sets CCACHE_BASEDIR) makes the paths of include folders and sources relative, so
that a second clone, the CI's fresh one, gets the objects an earlier clone compiled. It cannot
do that for a path inside a definition (-DNAME="/home/.../rigidlab"): one such definition on a
target's command line turns every object of that target into a miss in every new clone. The
few files that must know a path say so below; everything else asks tests/build_paths.h.

Usage: check_portable_objects.py BUILD_DIR SOURCE_DIR   (reads BUILD_DIR/compile_commands.json)
"""
import json
import os
import shlex
import sys

# Files that may carry a path of the checkout in a definition, each one object.
MAY_KNOW_A_PATH = {
    "lessons/format/data_dirs.cpp",  # the shipped lessons read from the source tree
    "tests/build_paths.cpp",  # written into the build folder: the tests' paths
}


def relative_name(path, source, build):
    path = os.path.realpath(path)
    for root in (build, source):
        if path.startswith(root + os.sep):
            rel = os.path.relpath(path, root)
            return rel
    return path


def findings(build, source):
    with open(os.path.join(build, "compile_commands.json"), encoding="utf-8") as f:
        entries = json.load(f)
    out = []
    for entry in entries:
        args = entry["arguments"] if "arguments" in entry else shlex.split(entry["command"])
        name = relative_name(os.path.join(entry["directory"], entry["file"]), source, build)
        if name in MAY_KNOW_A_PATH:
            continue
        for i, arg in enumerate(args):
            definition = arg[2:] if arg.startswith("-D") else None
            if arg == "-D" and i + 1 < len(args):
                definition = args[i + 1]
            if definition and (source in definition or build in definition):
                out.append(f"{name}: -D{definition}")
    return len(entries), out


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    build, source = (os.path.realpath(p) for p in sys.argv[1:3])
    count, found = findings(build, source)
    if count == 0:
        print(f"{build}/compile_commands.json lists no objects")
        return 1
    for line in found:
        print(line)
    print(f"{count} objects read, {len(found)} definitions with a path of the checkout")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
