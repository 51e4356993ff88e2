# SPDX-License-Identifier: GPL-3.0-or-later
# Every dependency comes from a Debian 12 package; a missing one stops configuration
# with the package to install (scripts/install-deps.sh installs them all).
macro(hbm_require pkg debian)
  find_package(${pkg} ${ARGN} QUIET)
  if(NOT ${pkg}_FOUND)
    message(FATAL_ERROR "Missing dependency ${pkg}: install the Debian package '${debian}' "
                        "(sudo apt-get install ${debian}, or run scripts/install-deps.sh)")
  endif()
endmacro()

hbm_require(Eigen3 libeigen3-dev NO_MODULE)
hbm_require(OpenMP libgomp1)
hbm_require(GTest libgtest-dev)
hbm_require(CLI11 libcli11-dev CONFIG)
find_package(PkgConfig QUIET)
if(PkgConfig_FOUND)
  pkg_check_modules(TOMLPP QUIET IMPORTED_TARGET tomlplusplus)
endif()
if(NOT TOMLPP_FOUND)
  message(FATAL_ERROR "Missing dependency toml++: install the Debian package 'libtomlplusplus-dev'")
endif()
if(HBM_BUILD_DECKGEN)
  hbm_require(CGAL libcgal-dev)
  hbm_require(assimp libassimp-dev)
  hbm_require(urdfdom liburdfdom-dev)
endif()
