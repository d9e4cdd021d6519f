# SPDX-License-Identifier: GPL-3.0-or-later
# The installed lab works where it is installed, and only from there: installs the build into a
# fresh prefix, moves that prefix elsewhere (so nothing can use a path compiled in at build or
# install time), then runs the installed programs and checks the desktop files.
#   cmake -DBUILD=<build folder> -DWORK=<scratch folder> -DVERSION=<x.y> -P check_install.cmake
cmake_minimum_required(VERSION 3.25)

function(fail what)
    message(FATAL_ERROR "install check: ${what}")
endfunction()

# Runs a program; fails with its output unless it exits 0. Sets OUT in the caller.
function(run_ok)
    execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out
        ERROR_VARIABLE err)
    if(NOT status EQUAL 0)
        fail("`${ARGN}` exited with ${status}:\n${out}${err}")
    endif()
    set(OUT "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORK})
run_ok(${CMAKE_COMMAND} --install ${BUILD} --prefix ${WORK}/prefix)
file(RENAME ${WORK}/prefix ${WORK}/moved)
set(root ${WORK}/moved)
set(ENV{RIGIDLAB_DATA_DIR} "")
set(ENV{QT_QPA_PLATFORM} offscreen)
# A fresh home: the user's own lessons are only the one put there below.
file(MAKE_DIRECTORY ${WORK}/home)
set(ENV{HOME} ${WORK}/home)
unset(ENV{XDG_DATA_HOME})

foreach(file
        bin/rigidlab bin/rigidlab-cli
        share/applications/io.github.rigidlab.RigidLab.desktop
        share/metainfo/io.github.rigidlab.RigidLab.metainfo.xml
        share/mime/packages/rigidlab.xml
        share/icons/hicolor/scalable/apps/io.github.rigidlab.RigidLab.svg
        share/icons/hicolor/48x48/apps/io.github.rigidlab.RigidLab.png
        share/icons/hicolor/256x256/apps/io.github.rigidlab.RigidLab.png
        share/man/man1/rigidlab.1.gz share/man/man1/rigidlab-cli.1.gz
        share/doc/rigidlab/README.md share/doc/rigidlab/LICENSE share/doc/rigidlab/copyright
        share/doc/rigidlab/SCENE_FORMAT.md share/doc/rigidlab/LESSON_FORMAT.md
        share/doc/rigidlab/RLESSON_FORMAT.md
        share/rigidlab/scenes/welcome.json
        share/rigidlab/measure/samples/ball_tracker.csv)
    if(NOT EXISTS ${root}/${file})
        fail("${file} is not installed")
    endif()
endforeach()

run_ok(${root}/bin/rigidlab-cli --version)
if(NOT OUT MATCHES "^rigidlab-cli ${VERSION}\n")
    fail("rigidlab-cli --version printed \"${OUT}\"")
endif()
run_ok(${root}/bin/rigidlab --version)
if(NOT OUT MATCHES "${VERSION}")
    fail("rigidlab --version printed \"${OUT}\"")
endif()

# The lessons the installed program finds are the installed ones, every one valid.
run_ok(${root}/bin/rigidlab-cli lessons)
string(REGEX MATCHALL "[^\n]+" listed "${OUT}")
file(GLOB installed_lessons ${root}/share/rigidlab/lessons/*.json)
list(LENGTH listed n_listed)
list(LENGTH installed_lessons n_installed)
if(n_installed LESS 1 OR NOT n_listed EQUAL n_installed)
    fail("rigidlab-cli lessons listed ${n_listed} of ${n_installed} installed lessons:\n${OUT}")
endif()
foreach(line IN LISTS listed)
    if(NOT line MATCHES "^${root}/share/rigidlab/lessons/")
        fail("a lesson found outside the installed folder: ${line}")
    endif()
endforeach()
file(GLOB installed_scenes ${root}/share/rigidlab/scenes/*.json)
run_ok(${root}/bin/rigidlab-cli validate ${installed_lessons} ${installed_scenes})

# A lesson of the user's own (~/.local/share/rigidlab/lessons) is listed after the shipped ones.
set(own ${WORK}/home/.local/share/rigidlab/lessons)
file(MAKE_DIRECTORY ${own}/scenes)
file(COPY_FILE ${root}/share/rigidlab/scenes/welcome.json ${own}/scenes/welcome.json)
file(WRITE ${own}/mine.json "{\"rigidlab-lesson\": 1, \"title\": \"Mine\",
  \"steps\": [{\"title\": \"s\", \"scene\": \"scenes/welcome.json\"}]}\n")
run_ok(${root}/bin/rigidlab-cli lessons)
string(REGEX MATCHALL "[^\n]+" listed_with_own "${OUT}")
list(POP_BACK listed_with_own last)
if(NOT listed_with_own STREQUAL listed OR NOT last STREQUAL "${own}/mine.json\tMine\tyour own")
    fail("rigidlab-cli lessons did not list the user's own lesson last:\n${OUT}")
endif()

# A lesson in one file: the installed program packs a shipped lesson, validates it and unpacks
# it; the installed MIME type and desktop file claim .rlesson for a double-click.
set(pack ${WORK}/restitution.rlesson)
run_ok(${root}/bin/rigidlab-cli lesson pack ${root}/share/rigidlab/lessons/restitution.json
    -o ${pack})
run_ok(${root}/bin/rigidlab-cli lesson ${pack} --validate)
run_ok(${root}/bin/rigidlab-cli lesson unpack ${pack} -o ${WORK}/unpacked)
if(NOT EXISTS ${WORK}/unpacked/restitution.json)
    fail("rigidlab-cli lesson unpack wrote no restitution.json:\n${OUT}")
endif()
file(READ ${root}/share/mime/packages/rigidlab.xml mime)
file(READ ${root}/share/applications/io.github.rigidlab.RigidLab.desktop desktop)
if(NOT mime MATCHES "glob pattern=\"\\*\\.rlesson\""
   OR NOT desktop MATCHES "application/x-rigidlab-lesson-file;")
    fail("the MIME type of .rlesson is not installed with the desktop file")
endif()

# The validators of the desktop files, where installed (./lab package installs them).
find_program(DESKTOP_FILE_VALIDATE desktop-file-validate)
if(DESKTOP_FILE_VALIDATE)
    run_ok(${DESKTOP_FILE_VALIDATE}
        ${root}/share/applications/io.github.rigidlab.RigidLab.desktop)
endif()
find_program(APPSTREAMCLI appstreamcli)
if(APPSTREAMCLI)
    run_ok(${APPSTREAMCLI} validate --no-net
        ${root}/share/metainfo/io.github.rigidlab.RigidLab.metainfo.xml)
endif()
file(REMOVE_RECURSE ${WORK})
message(STATUS "install check: ${n_installed} lessons found and valid where installed")
