#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""nsis_file_lists.py STAGE OUTDIR: the installer's lists of files (app/windows/rigidlab.nsi).

Writes OUTDIR/install_files.nsh (a File command per file of STAGE, into the same place under
$INSTDIR) and OUTDIR/uninstall_files.nsh (a Delete per file, then an RMDir per folder, deepest
first: RMDir without /r removes a folder only when it is empty, so what a user put there stays).
"""
import os
import sys


def nsis_path(rel):
    return rel.replace("/", "\\")


def main(stage, out):
    stage = os.path.abspath(stage)
    install, remove, folders = [], [], []
    for folder, dirs, files in os.walk(stage):
        dirs.sort()
        rel = os.path.relpath(folder, stage)
        rel = "" if rel == "." else rel
        target = "$INSTDIR" + ("\\" + nsis_path(rel) if rel else "")
        if rel:
            folders.append(target)
        if not files:
            continue
        install.append(f'SetOutPath "{target}"')
        for name in sorted(files):
            if '"' in name or "$" in name:
                sys.exit(f"nsis_file_lists.py: {os.path.join(folder, name)}: a name NSIS cannot quote")
            install.append(f'File "{os.path.join(folder, name)}"')
            remove.append(f'Delete "{target}\\{name}"')
    install.append('SetOutPath "$INSTDIR"')
    remove += [f'RMDir "{f}"' for f in sorted(folders, key=lambda f: -f.count("\\"))]
    os.makedirs(out, exist_ok=True)
    for name, lines in (("install_files.nsh", install), ("uninstall_files.nsh", remove)):
        with open(os.path.join(out, name), "w", encoding="utf-8") as f:
            f.write("; Written by app/windows/nsis_file_lists.py: do not edit.\n")
            f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: nsis_file_lists.py STAGE OUTDIR")
    main(sys.argv[1], sys.argv[2])
