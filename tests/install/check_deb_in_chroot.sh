#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# The package on a bare Debian 12, as a user meets it (issue 17): `apt install ./rigidlab_*.deb`
# must pull every dependency by itself, and the installed rigidlab-cli and rigidlab must work.
#
#   tests/install/check_deb_in_chroot.sh CHROOT [DEB [SHOTS]]     (or: ./lab package-check CHROOT)
#
#   CHROOT  a bare Debian 12, e.g. made with
#             debootstrap --variant=minbase bookworm CHROOT http://deb.debian.org/debian
#           It is changed (packages get installed): give it a copy, not the only bare one.
#   DEB     the package; default: the newest build-package/rigidlab_*.deb (./lab package)
#   SHOTS   where two of the window's screenshots are copied to look at; default
#           /tmp/chroot-shots
#
# Needs root (chroot, mount) and the network (apt-get in the chroot). Not part of ./lab test.
# It mounts proc, sys, dev and dev/pts in the chroot and unmounts them when it ends, whatever
# happens. The programs run first with nothing but the package and its dependencies installed
# (apt-get --no-install-recommends: the Depends alone must be enough); only then are the test
# tools (xvfb, xauth) installed, for the window's screenshots under an X server.
set -euo pipefail

die() {
    printf 'check_deb_in_chroot: %s\n' "$*" >&2
    exit 1
}

if [ $# -lt 1 ] || [ $# -gt 3 ]; then
    die "usage: $0 CHROOT [DEB [SHOTS]]"
fi
[ "$(id -u)" -eq 0 ] || die "needs root (chroot, mount)"
root=$(realpath "$1")
[ -x "$root/usr/bin/apt-get" ] || die "$root is not a Debian root (no usr/bin/apt-get)"
here=$(cd "$(dirname "$0")/../.." && pwd)
# shellcheck disable=SC2012 # the newest by time; the names are rigidlab_VERSION_ARCH.deb
deb=${2:-$(ls -t "$here"/build-package/rigidlab_*.deb 2>/dev/null | head -n 1)}
[ -f "$deb" ] || die "no package: run ./lab package, or name the .deb"
shots=${3:-/tmp/chroot-shots}

mounted=()
cleanup() {
    local i
    for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do
        umount "${mounted[i]}" || umount -l "${mounted[i]}" || true
    done
}
trap cleanup EXIT
mount_in() { # mount_in TARGET MOUNT-ARGS...
    local target=$root/$1
    shift
    mountpoint -q "$target" && die "$target is mounted already"
    mount "$@" "$target"
    mounted+=("$target")
}
mount_in proc -t proc proc
mount_in sys -t sysfs sysfs
mount_in dev --bind /dev
mount_in dev/pts --bind /dev/pts

cp /etc/resolv.conf "$root/etc/resolv.conf"
rm -f "$root"/tmp/rigidlab_*.deb
cp "$deb" "$root/tmp/"
debname=$(basename "$deb")
printf 'check_deb_in_chroot: %s in %s\n' "$debname" "$root"

# What runs inside the chroot, in a clean environment (a file, not stdin: apt-get and the
# programs must not read the script as their input).
cat >"$root/tmp/check_deb.sh" <<'CHROOT'
step() { printf '\n### %s\n' "$*"; }
fail() { printf 'FAILED: %s\n' "$*"; exit 1; }
# A Qt program's complaints that mean a part of the installation is missing.
no_complaints() { # no_complaints LOG
    if grep -E "Cannot find font directory|Could not (find|load) the Qt platform plugin|\
cannot open shared object|Cannot load library" "$1"; then
        fail "the program complained (above)"
    fi
}

step "apt-get install --no-install-recommends $DEB"
apt-get update -qq
apt-get install -y -q --no-install-recommends "$DEB" >/tmp/apt.log 2>&1 ||
    { cat /tmp/apt.log; fail "apt-get install"; }
printf 'packages set up by this install: %s\n' "$(grep -c '^Setting up' /tmp/apt.log)"
printf 'installed: %s\n' "$(dpkg-query -W -f='${Package} ${Version}' rigidlab)"
printf 'packages now: %s\n' "$(dpkg-query -W | wc -l)"

step "rigidlab-cli --version; rigidlab --version"
rigidlab-cli --version
rigidlab --version

step "rigidlab-cli lessons"
rigidlab-cli lessons | tee /tmp/lessons.txt
[ "$(wc -l </tmp/lessons.txt)" -ge 1 ] || fail "no lessons listed"
lesson=$(head -n 1 /tmp/lessons.txt | cut -f 1)

step "rigidlab-cli lesson $lesson --export /tmp/out"
rm -rf /tmp/out
rigidlab-cli lesson "$lesson" --export /tmp/out 2>/tmp/export.err | tail -n 4
cat /tmp/export.err
no_complaints /tmp/export.err
n=$(find /tmp/out -type f | wc -l)
pngs=$(find /tmp/out -name '*.png' -size +1k | wc -l)
printf '%s files written, %s PNGs over 1 kB\n' "$n" "$pngs"
[ "$pngs" -ge 1 ] || fail "no plot written"
find /tmp/out -name '*.pdf' -size +1k | grep -q . || fail "no PDF written"

step "a lesson of the user's own: listed by rigidlab-cli lessons"
own=/root/.local/share/rigidlab/lessons
mkdir -p "$own/scenes"
cp /usr/share/rigidlab/scenes/ball_drop.json "$own/scenes/drop.json"
printf '%s\n' '{"rigidlab-lesson": 1, "title": "My own drop",' \
    ' "steps": [{"title": "Drop", "scene": "scenes/drop.json"}]}' >"$own/mine.json"
rigidlab-cli lessons | tail -n 1 | tee /tmp/own.txt
grep -q "^$own/mine.json	My own drop	your own\$" /tmp/own.txt || fail "own lesson not listed"
rm -rf /root/.local/share/rigidlab

step "apt-get install --no-install-recommends xvfb xauth (test tools only)"
apt-get install -y -q --no-install-recommends xvfb xauth >/tmp/apt-x.log 2>&1 ||
    { cat /tmp/apt-x.log; fail "apt-get install xvfb"; }
echo "done"

step "Xvfb :5; DISPLAY=:5 rigidlab --screenshots /tmp/shots --size 1024x768"
Xvfb :5 -screen 0 1280x1024x24 -nolisten tcp >/tmp/xvfb.log 2>&1 &
xvfb=$!
trap 'kill "$xvfb" 2>/dev/null || true' EXIT
for _ in $(seq 50); do [ -e /tmp/.X11-unix/X5 ] && break; sleep 0.1; done
[ -e /tmp/.X11-unix/X5 ] || { cat /tmp/xvfb.log; fail "Xvfb did not start"; }
rm -rf /tmp/shots
DISPLAY=:5 rigidlab --screenshots /tmp/shots --size 1024x768 >/tmp/shots.out 2>/tmp/shots.err ||
    { cat /tmp/shots.out /tmp/shots.err; fail "rigidlab --screenshots"; }
tail -n 3 /tmp/shots.out
cat /tmp/shots.err
no_complaints /tmp/shots.err
n=$(find /tmp/shots -name '*.png' | wc -l)
empty=$(find /tmp/shots -name '*.png' -size -2k | wc -l)
printf '%s screenshots, %s of them under 2 kB\n' "$n" "$empty"
[ "$n" -ge 1 ] && [ "$empty" -eq 0 ] || fail "screenshots missing or empty"
kill "$xvfb"
wait "$xvfb" 2>/dev/null || true
trap - EXIT
CHROOT
chroot "$root" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LANG=C.UTF-8 \
    DEBIAN_FRONTEND=noninteractive DEB="/tmp/$debname" /bin/bash -euo pipefail \
    /tmp/check_deb.sh </dev/null

mkdir -p "$shots"
# Two to look at: the first lesson view and the last one written.
mapfile -t pngs < <(find "$root/tmp/shots" -name '*.png' | sort)
cp "${pngs[0]}" "${pngs[${#pngs[@]} - 1]}" "$shots/"
printf '\ncheck_deb_in_chroot: all passed; screenshots copied to %s: %s %s\n' "$shots" \
    "$(basename "${pngs[0]}")" "$(basename "${pngs[${#pngs[@]} - 1]}")"
