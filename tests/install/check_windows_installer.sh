#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The Windows installer under Wine, as a school's administrator and a teacher would use it:
#
#   tests/install/check_windows_installer.sh [SETUP.exe [OUT]]   (or: ./lab package-windows --check)
#
#   SETUP  the installer; default: the newest build-windows/rigidlab-*-windows-x64-setup.exe
#   OUT    where the screenshots, exports and worksheet are kept to look at; default
#          /tmp/rigidlab-wine-check
#
# In a fresh Wine prefix (WINEPREFIX under /tmp, removed at the end) on an Xvfb display of its
# own (:77, or RIGIDLAB_WINE_DISPLAY): installs silently (/S), runs rigidlab-cli.exe (--version,
# a scene, a lesson's --validate, --export compared with the Linux export when a Linux
# rigidlab-cli is at hand, a Czech worksheet read back by pdftotext), the window's
# --screenshots at 1024x768 in English and Czech, then uninstalls silently and checks that the
# installed files went and the teacher's own lesson stayed. Not part of ./lab test: it needs the
# installer, which needs the cached Qt for Windows. Needs wine64, xvfb, xdotool and poppler-utils.
# Stops only what it started (Xvfb by its PID, the prefix's own wineserver).
set -euo pipefail

here=$(cd "$(dirname "$0")/../.." && pwd)
say() { printf 'check_windows_installer: %s\n' "$*" >&2; }
die() {
    say "FAILED: $*"
    exit 1
}
ok() { say "ok: $*"; }

# shellcheck disable=SC2012 # the newest by time
setup=${1:-$(ls -t "$here"/build-windows/rigidlab-*-windows-x64-setup.exe 2>/dev/null | head -n 1)}
[ -f "$setup" ] || die "no installer: run ./lab package-windows, or name it"
out=${2:-/tmp/rigidlab-wine-check}
# A Linux rigidlab-cli to compare the exports with: RIGIDLAB_LINUX_CLI, else this tree's build.
linux_cli=${RIGIDLAB_LINUX_CLI:-$here/build/app/rigidlab-cli}
display=${RIGIDLAB_WINE_DISPLAY:-:77}
wine=$(command -v wine64 || command -v wine || true)
[ -n "$wine" ] || [ -x /usr/lib/wine/wine64 ] || die "no wine64 (apt-get install wine64)"
[ -n "$wine" ] || wine=/usr/lib/wine/wine64
wineserver=$(command -v wineserver || echo /usr/lib/wine/wineserver)
command -v Xvfb >/dev/null || die "no Xvfb (apt-get install xvfb)"
command -v pdftotext >/dev/null || die "no pdftotext (apt-get install poppler-utils)"

export WINEPREFIX
WINEPREFIX=$(mktemp -d /tmp/rigidlab-wineprefix.XXXXXX)
export WINEARCH=win64 WINEDEBUG=${WINEDEBUG:--all} DISPLAY=$display WINEDLLOVERRIDES="mscoree,mshtml="
rm -rf "$out"
mkdir -p "$out"
xvfb_pid=
cleanup() {
    "$wineserver" -k 2>/dev/null || true
    [ -n "$xvfb_pid" ] && kill "$xvfb_pid" 2>/dev/null || true
    rm -rf "$WINEPREFIX"
}
trap cleanup EXIT

Xvfb "$display" -screen 0 1280x1024x24 -nolisten tcp >"$out/xvfb.log" 2>&1 &
xvfb_pid=$!
start=$SECONDS
"$wine" wineboot --init >"$out/wineboot.log" 2>&1
"$wineserver" -w
say "fresh Wine prefix $WINEPREFIX in $((SECONDS - start)) s (display $display)"

# win PROGRAM ARGS...: runs a Windows program and waits for it (its exit status is the program's).
win() { "$wine" "$@"; }
winpath() { "$wine" winepath -w "$1" 2>/dev/null | tr -d '\r'; }

# --- The silent install, for everybody (Wine's user is an administrator).
start=$SECONDS
win "$setup" /S
"$wineserver" -w
instdir=$WINEPREFIX/drive_c/Program\ Files/RigidLab
[ -f "$instdir/bin/rigidlab.exe" ] || die "no rigidlab.exe in $instdir after setup /S"
ok "setup /S installed into C:\\Program Files\\RigidLab in $((SECONDS - start)) s ($(du -sm "$instdir" | cut -f1) MB)"
for f in bin/rigidlab-cli.exe bin/qt.conf bin/Qt6Core.dll bin/libstdc++-6.dll plugins/platforms/qwindows.dll \
    plugins/styles/qwindowsvistastyle.dll translations/qtbase_cs.qm uninstall.exe \
    share/rigidlab/lessons/restitution.json share/rigidlab/scenes/ball_drop.json \
    share/rigidlab/measure/samples; do
    [ -e "$instdir/$f" ] || die "$f missing from the installed folder"
done
lnk=$(find "$WINEPREFIX/drive_c" -iname 'RigidLab.lnk' -ipath '*Start Menu*' | head -n 1)
[ -n "$lnk" ] || die "no Start menu entry"
ok "Start menu entry: ${lnk#"$WINEPREFIX"/}"
reg=$(win reg query 'HKLM\Software\Classes\RigidLab.Lesson\shell\open\command' /ve 2>/dev/null | tr -d '\r')
grep -q 'rigidlab.exe" "%1"' <<<"$reg" || die ".rlesson is not associated with the lab: $reg"
ok ".rlesson opens with: $(grep -o '"C:.*' <<<"$reg")"

cli=$instdir/bin/rigidlab-cli.exe
gui=$instdir/bin/rigidlab.exe
data=$instdir/share/rigidlab

# --- rigidlab-cli.exe
version=$(win "$cli" --version | tr -d '\r')
[[ $version == "rigidlab-cli "* ]] || die "rigidlab-cli.exe --version said: $version"
ok "rigidlab-cli.exe --version: $version"
start=$SECONDS
win "$cli" run "$(winpath "$data/scenes/ball_drop.json")" --time 2 >"$out/run.txt"
ok "rigidlab-cli.exe run ball_drop.json --time 2 ($((SECONDS - start)) s): $(tr -d '\r' <"$out/run.txt" | head -n 1)"
lesson=$data/lessons/restitution.json
win "$cli" lesson "$(winpath "$lesson")" --validate >"$out/validate.txt"
ok "lesson restitution.json --validate: $(tr -d '\r' <"$out/validate.txt" | head -n 1)"

start=$SECONDS
win "$cli" lesson "$(winpath "$lesson")" --export "$(winpath "$out/export-windows")" >"$out/export.txt"
[ -n "$(find "$out/export-windows" -name '*.csv')" ] || die "lesson --export wrote no CSV"
ok "lesson --export: $(find "$out/export-windows" -type f | wc -l) files in $((SECONDS - start)) s"
if [ -x "$linux_cli" ]; then
    "$linux_cli" lesson "$here/lessons/lessons/restitution.json" --export "$out/export-linux" >/dev/null
    python3 "$here/tests/install/compare_exports.py" "$out/export-linux" "$out/export-windows" ||
        die "the Windows export differs from the Linux one"
    ok "the export matches Linux's ($linux_cli): same files but SVG, numbers to 1e-9 relative"
else
    say "not compared with Linux: no Linux rigidlab-cli at $linux_cli (RIGIDLAB_LINUX_CLI names one)"
fi

student="Žofie Řeháková"
win "$cli" lesson "$(winpath "$lesson")" --worksheet "$(winpath "$out/worksheet-cs.pdf")" --lang cs \
    --student "$student" >/dev/null
# NFKC: the fonts may set "fi" as one ligature glyph, which pdftotext gives back as "ﬁ".
pdftotext "$out/worksheet-cs.pdf" - |
    python3 -c 'import sys, unicodedata; print(unicodedata.normalize("NFKC", sys.stdin.read()))' \
        >"$out/worksheet-cs.txt"
grep -q "$student" "$out/worksheet-cs.txt" || die "the Czech worksheet lacks the name $student"
ok "lesson --worksheet --lang cs: pdftotext reads \"$student\""

# --- The window: its screenshots of every shipped view, in English and in Czech.
for lang in en cs; do
    start=$SECONDS
    win "$gui" --screenshots "$(winpath "$out/shots-$lang")" --size 1024x768 --lang "$lang" \
        >"$out/shots-$lang.txt" 2>&1 || die "rigidlab.exe --screenshots --lang $lang: $(cat "$out/shots-$lang.txt")"
    n=$(find "$out/shots-$lang" -name '*.png' | wc -l)
    [ "$n" -gt 0 ] || die "rigidlab.exe --screenshots --lang $lang wrote no PNG"
    ok "rigidlab.exe --screenshots --size 1024x768 --lang $lang: $n PNGs in $((SECONDS - start)) s ($out/shots-$lang)"
done

# --- The window on a lesson, started as a double click starts it, for a few seconds.
start=$SECONDS
win "$gui" --lang cs "$(winpath "$lesson")" >"$out/window.txt" 2>&1 &
window_pid=$!
first=
if timeout 30 xdotool search --sync --name RigidLab >/dev/null 2>&1; then
    first=$((SECONDS - start))
fi
[ -n "$first" ] || die "no RigidLab window within 30 s"
ok "rigidlab.exe --lang cs restitution.json: its window is up after ${first} s"
if command -v import >/dev/null; then
    sleep 3 # the lesson's first paint
    import -display "$display" -window root "$out/window-cs.png" && ok "the window: $out/window-cs.png"
fi
kill "$window_pid" 2>/dev/null || true
"$wineserver" -k 2>/dev/null || true

# --- The teacher's own lesson, then the silent uninstall.
own=$WINEPREFIX/drive_c/users/${USER:-$(id -un)}/AppData/Local/rigidlab/lessons
mkdir -p "$own"
cp "$lesson" "$own/moje-lekce.json"
win "$instdir/uninstall.exe" /S
"$wineserver" -w
[ ! -e "$instdir" ] || die "the installed folder is still there: $(find "$instdir" | head -n 5)"
[ -z "$(find "$WINEPREFIX/drive_c" -iname 'RigidLab.lnk')" ] || die "a shortcut is still there"
if win reg query 'HKLM\Software\Classes\RigidLab.Lesson' >/dev/null 2>&1; then
    die "the .rlesson association is still there"
fi
[ -f "$own/moje-lekce.json" ] || die "the uninstaller removed the teacher's own lesson"
ok "uninstall.exe /S: the folder, shortcuts and associations gone, the teacher's own lesson kept"
say "all checks passed; screenshots, exports and the worksheet are in $out"
