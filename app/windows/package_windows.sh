#!/usr/bin/env bash
# SPDX-License-Identifier: GPL-3.0-or-later
# ./lab package-windows [--check]: the 64-bit Windows build of rigidlab and rigidlab-cli and
# its installer rigidlab-VERSION-windows-x64-setup.exe, made on Debian 12 with MinGW-w64 and
# NSIS. docs/windows.md says more.
#
# Qt for Windows is built once from Debian's own Qt 6.4.2 source (the version the Linux build
# uses), only the modules the lab needs, and installed into a cache outside the source tree;
# QCustomPlot 2.1.0 likewise. Later runs reuse the cache:
#   RIGIDLAB_WINDOWS_CACHE  the cache (default ~/.cache/rigidlab)
#   RIGIDLAB_WINDOWS_BUILD  the lab's Windows build (default build-windows/ in the source tree)
#   RIGIDLAB_WINDOWS_JOBS   parallel jobs for the Qt build (default 2), which runs niced
# --qt-only builds the cache and stops; --check also installs the setup into a fresh Wine
# prefix and runs the programs there (tests/install/check_windows_installer.sh).
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
CACHE=${RIGIDLAB_WINDOWS_CACHE:-$HOME/.cache/rigidlab}
BUILD=${RIGIDLAB_WINDOWS_BUILD:-$ROOT/build-windows}
JOBS=${RIGIDLAB_WINDOWS_JOBS:-2}
QT_VERSION=6.4.2
QT_PREFIX=$CACHE/qt-$QT_VERSION-mingw
TOOLCHAIN=$ROOT/cmake/mingw-w64-x86_64.cmake
SRC=$CACHE/src

say() { printf 'package-windows: %s\n' "$*" >&2; }
die() { say "$*"; exit 1; }

# What the cross build needs from Debian: the compilers, NSIS, Wine for --check, the host Qt
# whose moc, rcc and uic the cross-built Qt uses (QT_HOST_PATH), dpkg-dev for apt-get source.
WINDOWS_PACKAGES=(g++-mingw-w64-x86-64-posix gcc-mingw-w64-x86-64-posix binutils-mingw-w64-x86-64
                  nsis ninja-build dpkg-dev qt6-base-dev qt6-base-dev-tools qt6-tools-dev
                  qt6-l10n-tools qt6-translations-l10n libeigen3-dev libboost-dev)
CHECK_PACKAGES=(wine64 xvfb xdotool poppler-utils)

install_packages() {
    local p missing=()
    for p in "$@"; do
        dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
    done
    [ ${#missing[@]} -eq 0 ] && return 0
    say "installing: ${missing[*]}"
    local sudo=()
    [ "$(id -u)" -ne 0 ] && sudo=(sudo)
    "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -qq
    "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
        "${missing[@]}" >/dev/null
}

# apt-get source needs a deb-src line; Debian 12's deb822 form, beside the deb one.
ensure_deb_src() {
    grep -rqs '^Types:.*deb-src' /etc/apt/sources.list.d/ && return 0
    grep -qs '^deb-src' /etc/apt/sources.list /etc/apt/sources.list.d/*.list 2>/dev/null && return 0
    say "adding a deb-src entry (/etc/apt/sources.list.d/debian-src.sources) for apt-get source"
    local sudo=()
    [ "$(id -u)" -ne 0 ] && sudo=(sudo)
    printf '%s\n' 'Types: deb-src' 'URIs: http://deb.debian.org/debian' \
        'Suites: bookworm bookworm-updates' 'Components: main' \
        'Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg' |
        "${sudo[@]}" tee /etc/apt/sources.list.d/debian-src.sources >/dev/null
    "${sudo[@]}" apt-get update -qq
}

# fetch_source PACKAGE DIR-GLOB: Debian's source, patches applied, unpacked under $SRC.
fetch_source() {
    local dir
    dir=$(ls -d "$SRC"/$2 2>/dev/null | head -n 1 || true)
    if [ -z "$dir" ]; then
        ensure_deb_src
        mkdir -p "$SRC"
        (cd "$SRC" && apt-get source -qq "$1" >/dev/null 2>&1) || die "apt-get source $1 failed"
        dir=$(ls -d "$SRC"/$2 | head -n 1)
    fi
    echo "$dir"
}

elapsed() { local s=$(($(date +%s) - $1)); printf '%d min %02d s' $((s / 60)) $((s % 60)); }

# Qt 6.4.2 for Windows: Core, Gui, Widgets, PrintSupport, Concurrent, the Windows platform
# plugin, the Windows styles and the image formats (PNG built in, ICO, JPEG, GIF); not the
# Direct2D platform plugin (a second Windows platform, 58 more files). Debian's
# source leaves out wintab (hence no tablet events), IAccessible2 (Qt 6 speaks UI Automation)
# and SQLite (no SQL here). Everything else of Qt's own 3rd-party code is bundled: the target
# has none of it.
# The Qt targets the lab loads: its libraries, the platform and style plugins, the image formats.
QT_TARGETS=(Core Gui Widgets PrintSupport Concurrent QWindowsIntegrationPlugin
            QWindowsVistaStylePlugin QICOPlugin QJpegPlugin QGifPlugin)

build_qt() {
    if [ -f "$QT_PREFIX/lib/cmake/Qt6Widgets/Qt6WidgetsConfig.cmake" ]; then
        say "Qt $QT_VERSION for Windows: reusing the cache $QT_PREFIX"
        return 0
    fi
    local qtsrc start qtbuild=$CACHE/build/qtbase-mingw
    qtsrc=$(fetch_source qt6-base "qt6-base-$QT_VERSION*")
    say "building Qt $QT_VERSION for Windows once, into $QT_PREFIX (log: $qtbuild.log)"
    say "this takes about an hour on two cores; later runs reuse it"
    mkdir -p "$qtbuild"
    # The time counts from the first start, over runs that were stopped and went on.
    [ -f "$qtbuild/started" ] || date +%s >"$qtbuild/started"
    start=$(cat "$qtbuild/started")
    local launcher=()
    command -v ccache >/dev/null && launcher=(-DQT_USE_CCACHE=ON)
    {
        # Configured once: a run that was stopped goes on where it was.
        [ -f "$qtbuild/CMakeCache.txt" ] || cmake -S "$qtsrc" -B "$qtbuild" -G Ninja \
            -DCMAKE_TOOLCHAIN_FILE="$TOOLCHAIN" \
            -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX="$QT_PREFIX" \
            -DQT_HOST_PATH=/usr -DQT_HOST_PATH_CMAKE_DIR=/usr/lib/x86_64-linux-gnu/cmake \
            -DQT_BUILD_EXAMPLES=OFF -DQT_BUILD_TESTS=OFF -DQT_BUILD_BENCHMARKS=OFF \
            -DBUILD_SHARED_LIBS=ON "${launcher[@]}" \
            -DFEATURE_sql=OFF -DFEATURE_network=OFF -DFEATURE_dbus=OFF -DFEATURE_opengl=OFF \
            -DINPUT_opengl=no -DFEATURE_vulkan=OFF -DFEATURE_testlib=OFF -DFEATURE_xml=OFF \
            -DFEATURE_tabletevent=OFF -DFEATURE_direct2d=OFF \
            -DFEATURE_system_zlib=OFF -DFEATURE_system_pcre2=OFF -DFEATURE_system_harfbuzz=OFF \
            -DFEATURE_system_freetype=OFF -DFEATURE_system_doubleconversion=OFF \
            -DFEATURE_system_libpng=OFF -DFEATURE_system_jpeg=OFF \
            -DFEATURE_concurrent=ON -DFEATURE_printsupport=ON -DFEATURE_widgets=ON
        # What the lab loads first, the rest of Qt's default targets after.
        nice -n 10 cmake --build "$qtbuild" -j "$JOBS" --target "${QT_TARGETS[@]}"
        nice -n 10 cmake --build "$qtbuild" -j "$JOBS"
        cmake --install "$qtbuild"
    } >>"$qtbuild.log" 2>&1 || die "the Qt build failed: see the end of $qtbuild.log"
    say "Qt $QT_VERSION for Windows built in $(elapsed "$start"): $QT_PREFIX"
    echo "$(elapsed "$start")" >"$QT_PREFIX/build-time.txt"
}

# Qt's own toolchain file for programs built with it: it chains to ours and adds the Qt prefix
# to the places CMake looks (the host Qt for moc, rcc and uic).
qt_cmake_args() {
    echo -DCMAKE_TOOLCHAIN_FILE="$QT_PREFIX/lib/cmake/Qt6/qt.toolchain.cmake" \
        -DQT_CHAINLOAD_TOOLCHAIN_FILE="$TOOLCHAIN" \
        -DQT_HOST_PATH=/usr -DQT_HOST_PATH_CMAKE_DIR=/usr/lib/x86_64-linux-gnu/cmake
}

# QCustomPlot 2.1.0 from Debian's source (its CMakeLists.txt builds QCustomPlotQt6), installed
# beside Qt.
build_qcustomplot() {
    if [ -f "$QT_PREFIX/lib/cmake/QCustomPlotQt6/QCustomPlotQt6Config.cmake" ]; then
        return 0
    fi
    local src start dir=$CACHE/build/qcustomplot-mingw
    src=$(fetch_source qcustomplot "qcustomplot-2.1.0*")
    start=$(date +%s)
    say "building QCustomPlot 2.1.0 for Windows (log: $dir.log)"
    # shellcheck disable=SC2046
    {
        cmake -S "$src" -B "$dir" -G Ninja $(qt_cmake_args) -DCMAKE_BUILD_TYPE=Release \
            -DCMAKE_INSTALL_PREFIX="$QT_PREFIX" -DCMAKE_INSTALL_LIBDIR=lib -DUSE_QT_VERSION=6 -DBUILD_SHARED_LIBS=ON
        nice -n 10 cmake --build "$dir" -j "$JOBS"
        cmake --install "$dir"
    } >"$dir.log" 2>&1 || die "the QCustomPlot build failed: see the end of $dir.log"
    say "QCustomPlot built in $(elapsed "$start")"
}

# Eigen and Boost are headers only: Debian's, made visible in the Windows prefix (which the
# toolchain lets CMake search), the Linux system's include folder staying out of the build.
provide_header_libraries() {
    mkdir -p "$QT_PREFIX/include" "$QT_PREFIX/share/eigen3/cmake"
    ln -sfn /usr/include/eigen3 "$QT_PREFIX/include/eigen3"
    ln -sfn /usr/include/boost "$QT_PREFIX/include/boost"
    cp /usr/share/eigen3/cmake/Eigen3*.cmake "$QT_PREFIX/share/eigen3/cmake/"
}

# render-icon renders the icon at build time, so it is built for this machine, against the
# system's Qt (app/desktop/render_icon.cpp, as the Linux build has it).
build_host_render_icon() {
    local out=$BUILD/host/render-icon src=$ROOT/app/desktop/render_icon.cpp
    [ -x "$out" ] && [ "$out" -nt "$src" ] && return 0
    mkdir -p "$BUILD/host"
    # shellcheck disable=SC2046
    g++ -std=c++20 -O1 -fPIC -o "$out" "$src" $(pkg-config --cflags --libs Qt6Gui Qt6Svg)
}

# The lab for Windows: configured with Qt's toolchain file, built, installed into a stage
# folder (programs, DLLs, plugins, data) that the installer packs.
build_lab() {
    provide_header_libraries
    build_host_render_icon
    local launcher=()
    command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
    say "building the lab for Windows in $BUILD"
    # shellcheck disable=SC2046
    cmake -S "$ROOT" -B "$BUILD" -G Ninja $(qt_cmake_args) -DCMAKE_BUILD_TYPE=Release \
        -DCMAKE_INSTALL_PREFIX="$BUILD/stage" -DRIGIDLAB_BUILD_TREE_DATA=OFF \
        -DRIGIDLAB_RENDER_ICON="$BUILD/host/render-icon" \
        -DBoost_INCLUDE_DIR="$QT_PREFIX/include" -DBoost_NO_BOOST_CMAKE=ON \
        -DCMAKE_SKIP_INSTALL_ALL_DEPENDENCY=ON "${launcher[@]}" >/dev/null
    cmake --build "$BUILD" -j "$JOBS" --target rigidlab rigidlab-cli
    rm -rf "$BUILD/stage"
    cmake --install "$BUILD" --strip >/dev/null
    # The DLLs come from the Qt build as they are: stripped here (the programs by --strip).
    find "$BUILD/stage" -name '*.dll' -exec x86_64-w64-mingw32-strip --strip-unneeded {} +
}

# rigidlab-VERSION-windows-x64-setup.exe, VERSION from project() (version.nsh).
make_installer() {
    local generated=$BUILD/app/windows version
    version=$(sed -n 's/^!define VERSION "\(.*\)"$/\1/p' "$generated/version.nsh")
    SETUP=$BUILD/rigidlab-$version-windows-x64-setup.exe
    python3 "$ROOT/app/windows/nsis_file_lists.py" "$BUILD/stage" "$generated"
    makensis -V2 -DSTAGE="$BUILD/stage" -DGENERATED="$generated" -DOUTFILE="$SETUP" \
        "$ROOT/app/windows/rigidlab.nsi" >&2
    say "built $SETUP ($(du -m "$SETUP" | cut -f1) MB)"
}

main() {
    local check=0 qt_only=0 arg
    export CCACHE_BASEDIR=${CCACHE_BASEDIR:-$ROOT}
    for arg in "$@"; do
        case "$arg" in
            --check) check=1 ;;
            --qt-only) qt_only=1 ;;
            *) die "unknown option $arg (known: --check, --qt-only)" ;;
        esac
    done
    install_packages "${WINDOWS_PACKAGES[@]}"
    build_qt
    build_qcustomplot
    [ $qt_only -eq 1 ] && return 0
    build_lab
    make_installer
    if [ $check -eq 1 ]; then
        install_packages "${CHECK_PACKAGES[@]}"
        "$ROOT/tests/install/check_windows_installer.sh" "$SETUP"
    fi
}

main "$@"
