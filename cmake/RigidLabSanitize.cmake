# SPDX-License-Identifier: GPL-3.0-or-later
# Robustness builds.
#
# RIGIDLAB_SANITIZE: everything (the engine, the lessons, the window, the programs and every
# test) built with AddressSanitizer and UndefinedBehaviorSanitizer; `./lab test-sanitize` runs
# the whole suite so, in build-sanitize/. Any report fails the test that made it.
#
# RIGIDLAB_FUZZ: the libFuzzer targets of tests/fuzz (clang only), and only what they need:
# the engine and the lessons library, instrumented for coverage, ASan and UBSan. The window is
# not built. `./lab fuzz [SECONDS]` builds and runs them in build-fuzz/.

option(RIGIDLAB_SANITIZE "Build everything with AddressSanitizer and UBSan" OFF)
option(RIGIDLAB_FUZZ "Build only the libFuzzer targets (needs clang)" OFF)

if(RIGIDLAB_SANITIZE AND RIGIDLAB_FUZZ)
    message(FATAL_ERROR "RIGIDLAB_SANITIZE and RIGIDLAB_FUZZ are separate builds: choose one")
endif()

if(RIGIDLAB_SANITIZE)
    # Frame pointers give whole stacks in every report; no recovery, so that the first
    # undefined behaviour stops the test instead of scrolling past.
    add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer
                        -fno-sanitize-recover=all)
    add_link_options(-fsanitize=address,undefined)
endif()

if(RIGIDLAB_FUZZ)
    if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
        message(FATAL_ERROR "RIGIDLAB_FUZZ needs clang (libFuzzer): configure with "
                            "-DCMAKE_CXX_COMPILER=clang++-14")
    endif()
    # Libraries get the coverage hooks; each fuzz target links libFuzzer's main itself.
    add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer
                        -fno-sanitize-recover=undefined)
    add_link_options(-fsanitize=address,undefined)
endif()
