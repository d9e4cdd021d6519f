# SPDX-License-Identifier: GPL-3.0-or-later
# ./lab package: a Debian package of what cmake --install puts in place, by CPack's DEB
# generator. Its dependencies are computed from the programs' libraries (dpkg-shlibdeps),
# its version is project()'s.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME rigidlab)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "The RigidLab developers")
set(CPACK_PACKAGE_CONTACT "The RigidLab developers <rigidlab@users.noreply.github.com>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "lab for teaching 2D rigid-body mechanics")
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
    "A desktop lab for a physics class: polygons and balls collide in a scene beside live\n\
energy and momentum plots; guided lessons on the energy drift of Euler, Verlet and\n\
Runge-Kutta integrators, the separating axis theorem and the coefficient of restitution;\n\
plots export for handouts. rigidlab-cli runs, checks and exports without a window.")
set(CPACK_PACKAGE_HOMEPAGE_URL https://github.com/rigidlab/rigidlab)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT) # rigidlab_VERSION_ARCH.deb
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# What dpkg-shlibdeps cannot see: Qt loads its platform plugins (xcb, wayland, offscreen) at run
# time, from a package of their own.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "qt6-qpa-plugins")
# Qt's own Czech for its standard dialogs (qtbase_cs.qm); RigidLab's texts are built in.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "qt6-translations-l10n")
set(CPACK_DEBIAN_PACKAGE_RELEASE 1)
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_STRIP_FILES ON)
include(CPack)
