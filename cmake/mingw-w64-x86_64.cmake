# SPDX-License-Identifier: GPL-3.0-or-later
# Cross-compiling for 64-bit Windows with Debian's MinGW-w64 (g++-mingw-w64-x86-64-posix):
# ./lab package-windows builds Qt and the lab with it. The posix-thread compilers, because
# Qt's and the lab's std::thread and std::mutex need them (the win32 ones have none in GCC 12).
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(RIGIDLAB_MINGW_TRIPLE x86_64-w64-mingw32)
set(CMAKE_C_COMPILER ${RIGIDLAB_MINGW_TRIPLE}-gcc-posix)
set(CMAKE_CXX_COMPILER ${RIGIDLAB_MINGW_TRIPLE}-g++-posix)
set(CMAKE_RC_COMPILER ${RIGIDLAB_MINGW_TRIPLE}-windres)
set(CMAKE_FIND_ROOT_PATH /usr/${RIGIDLAB_MINGW_TRIPLE})
# Programs (moc, rcc, lupdate) from the build machine; libraries and headers from the
# target's root or from what CMAKE_PREFIX_PATH adds (the Qt and QCustomPlot built for it).
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
