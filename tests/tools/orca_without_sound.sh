#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# Orca on a machine without a sound card (a server, a CI runner, a container), so that the
# screen-reader check (../shared/tools/screen_reader.sh: the lab under Orca on a private
# display, printing what Orca said after each key) shows Orca's speech there.
#
#   orca_without_sound.sh setup [--force]  as root: speech-dispatcher speaks into ALSA's null
#                                          device (refused where there is a sound card,
#                                          unless --force)
#   orca_without_sound.sh undo             as root: takes that back
#   orca_without_sound.sh run [ARGS]       the screen-reader tool with ARGS, Orca's debug log
#                                          written line by line
#
# Why: without a sound device speech-dispatcher's default output (PulseAudio, then its own
# "server audio") fails to open, and Orca waits on it after its first words: nothing more is
# spoken. ALSA's "null" device takes the sound at the pace of real time and drops it, so speech
# goes on. And Orca writes its debug log, which the tool reads, in blocks of 8 KB: on a busy
# machine a spoken line shows a key or two late, or not at all. Orca runs the user's
# orca-customizations.py from $XDG_DATA_HOME/orca at start; the one written here makes the
# log line-buffered. The tool sets HOME but passes XDG_DATA_HOME on, so `run` gives it a
# fresh one for each run.
set -euo pipefail

conf=/etc/speech-dispatcher/speechd.conf
begin="# BEGIN rigidlab orca_without_sound.sh"
end="# END rigidlab orca_without_sound.sh"
here=$(cd "$(dirname "$0")" && pwd)
tool=${RIGIDLAB_SCREEN_READER_TOOL:-$here/../../../shared/tools/screen_reader.sh}

say() { printf 'orca_without_sound: %s\n' "$*" >&2; }

need_root() {
    [ "$(id -u)" -eq 0 ] || { say "run as root (it writes $conf)"; exit 1; }
}

drop_block() {
    [ -f "$conf" ] && sed -i "/^$begin\$/,/^$end\$/d" "$conf"
    return 0
}

setup() {
    need_root
    if [ "${1:-}" != --force ] && compgen -G "/dev/snd/pcm*" >/dev/null; then
        say "this machine has a sound card (/dev/snd): with the null device nobody would hear"
        say "Orca. Pass --force to do it all the same."
        exit 1
    fi
    if [ ! -f "$conf" ]; then
        say "installing speech-dispatcher and espeak-ng"
        DEBIAN_FRONTEND=noninteractive apt-get install -y -qq speech-dispatcher espeak-ng >/dev/null
    fi
    drop_block
    cat >>"$conf" <<EOF
$begin
# No sound card here: speech goes to ALSA's null device (taken at the pace of real time and
# dropped) instead of a device that fails to open and stalls the screen reader.
AudioOutputMethod "alsa"
AudioALSADevice "null"
$end
EOF
    say "$conf: speech into ALSA's null device (undo: $0 undo)"
}

run() {
    grep -qx "$begin" "$conf" 2>/dev/null ||
        say "warning: $conf has no null device: run '$0 setup' as root first"
    [ -x "$tool" ] || { say "no screen-reader tool at $tool (set RIGIDLAB_SCREEN_READER_TOOL)"; exit 2; }
    data=""
    data=$(mktemp -d)
    trap 'rm -rf "${data:-}"' EXIT
    mkdir -p "$data/orca"
    cat >"$data/orca/orca-customizations.py" <<'EOF'
# Orca's debug log line by line, so that the screen-reader check sees each spoken line at once.
from orca import debug
if debug.debugFile is not None:
    debug.debugFile.reconfigure(line_buffering=True)
EOF
    XDG_DATA_HOME=$data "$tool" "$@"
}

cmd=${1:-}
shift || true
case "$cmd" in
    setup) setup "$@" ;;
    undo) need_root; drop_block; say "$conf as it was" ;;
    run) run "$@" ;;
    *) sed -n '3,12p' "$0" | sed 's/^# \{0,1\}//'; exit 2 ;;
esac
