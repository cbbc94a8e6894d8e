# The ParaView plugin RiemannVTK (ParaView/, Documentation/ParaView.md).
#
# ParaView 5.11 brings its own VTK (9.2), which exports the same target names
# and unversioned symbols as Debian's VTK 9.1 that this tree builds on. So the
# plugin is a CMake tree of its own (an external project built by this one):
# it compiles our VTK modules (their vtk.module files, unchanged) a second
# time against ParaView's VTK, with library names of their own (suffix
# "pv5.11"), and links the VTK-free libraries built here, which it imports
# from RiemannCoreTargets.cmake. The two VTKs never meet in one process.
#
# Built when ParaView's development files and python3-paraview's unpacked
# hierarchy files are there (run.sh installs and unpacks them); otherwise
# skipped with a message, and the plugin's tests with it.
include(RiemannParaViewPackage)

set(RIEMANN_PARAVIEW_SYSTEM_CONFIG "/usr/lib/x86_64-linux-gnu/cmake/paraview-5.11/paraview-config.cmake")
set(RIEMANN_PARAVIEW_DEB_DIR "${CMAKE_BINARY_DIR}/paraview-deb" CACHE PATH
  "python3-paraview's .deb unpacked (dpkg-deb -x; run.sh does it): the wrapping hierarchy files")
set(_riemann_paraview_hierarchy "${RIEMANN_PARAVIEW_DEB_DIR}/usr/lib/x86_64-linux-gnu/vtk/hierarchy/ParaView")

set(_riemann_paraview_default OFF)
if (EXISTS "${RIEMANN_PARAVIEW_SYSTEM_CONFIG}" AND EXISTS "${_riemann_paraview_hierarchy}"
    AND NOT RIEMANN_SANITIZE)
  set(_riemann_paraview_default ON)
endif ()
option(RIEMANN_BUILD_PARAVIEW_PLUGIN "Build the ParaView plugin RiemannVTK (ParaView/)"
  ${_riemann_paraview_default})

if (NOT RIEMANN_BUILD_PARAVIEW_PLUGIN)
  if (RIEMANN_SANITIZE)
    message(STATUS "ParaView plugin: not built in the sanitizer build (ParaView is not instrumented)")
  else ()
    message(STATUS "ParaView plugin: not built (needs paraview-dev and python3-paraview's hierarchy "
      "files in ${_riemann_paraview_hierarchy}; ./run.sh build provides both)")
  endif ()
  return ()
endif ()
if (NOT EXISTS "${RIEMANN_PARAVIEW_SYSTEM_CONFIG}")
  message(FATAL_ERROR "RIEMANN_BUILD_PARAVIEW_PLUGIN: ${RIEMANN_PARAVIEW_SYSTEM_CONFIG} is missing "
    "(apt-get install --no-install-recommends paraview paraview-dev libqt5svg5-dev qtxmlpatterns5-dev-tools)")
endif ()
if (NOT EXISTS "${_riemann_paraview_hierarchy}")
  message(FATAL_ERROR "RIEMANN_BUILD_PARAVIEW_PLUGIN: no ${_riemann_paraview_hierarchy} "
    "(apt-get download python3-paraview; dpkg-deb -x python3-paraview_*.deb ${RIEMANN_PARAVIEW_DEB_DIR})")
endif ()

set(RIEMANN_PARAVIEW_PACKAGE_DIR "${CMAKE_BINARY_DIR}/paraview-cmake")
riemann_prepare_paraview_package("${RIEMANN_PARAVIEW_PACKAGE_DIR}" "${_riemann_paraview_hierarchy}")

# The VTK-free libraries, for the plugin's tree to import as built here.
get_property(_riemann_plain_libraries GLOBAL PROPERTY RIEMANN_PLAIN_LIBRARIES)
export(TARGETS ${_riemann_plain_libraries} NAMESPACE Riemann::
  FILE "${CMAKE_BINARY_DIR}/RiemannCoreTargets.cmake")

set(RIEMANN_PARAVIEW_BUILD_DIR "${CMAKE_BINARY_DIR}/paraview")
# Where the plugin lands (paraview --plugin-search-paths, PV_PLUGIN_PATH).
set(RIEMANN_PARAVIEW_PLUGIN_DIR "${RIEMANN_PARAVIEW_BUILD_DIR}/lib/paraview-5.11/plugins")

set(_riemann_paraview_args
  "-DParaView_DIR=${RIEMANN_PARAVIEW_PACKAGE_DIR}"
  "-DRIEMANN_BUILD_DIR=${CMAKE_BINARY_DIR}"
  "-DRIEMANN_SOURCE_DIR=${CMAKE_SOURCE_DIR}"
  "-DCMAKE_BUILD_TYPE=${CMAKE_BUILD_TYPE}"
  "-DCMAKE_C_COMPILER=${CMAKE_C_COMPILER}"
  "-DCMAKE_CXX_COMPILER=${CMAKE_CXX_COMPILER}"
  )
if (CMAKE_CXX_COMPILER_LAUNCHER)
  list(APPEND _riemann_paraview_args "-DCMAKE_CXX_COMPILER_LAUNCHER=${CMAKE_CXX_COMPILER_LAUNCHER}")
endif ()

include(ExternalProject)
ExternalProject_Add(RiemannParaViewPlugin
  SOURCE_DIR    "${CMAKE_SOURCE_DIR}/ParaView"
  BINARY_DIR    "${RIEMANN_PARAVIEW_BUILD_DIR}"
  CMAKE_ARGS    ${_riemann_paraview_args}
  # Its own build decides what is out of date (our sources, the generated XML).
  BUILD_ALWAYS  ON
  INSTALL_COMMAND ""
  DEPENDS       ${_riemann_plain_libraries})

if (BUILD_TESTING)
  add_subdirectory(ParaView/Testing "${CMAKE_BINARY_DIR}/ParaViewTesting")
endif ()
