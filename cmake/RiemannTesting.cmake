# Test helpers shared by the module folders and Testing/.
#
# Globs use CONFIGURE_DEPENDS: adding a Test*.cxx / Test*.py re-runs CMake on
# the next build, so a new test needs no CMake edit. Folders without sources
# are skipped, so the tree configures before the tests are written.

# Environment every test gets (Python and CLI tests alike):
#   PYTHONPATH        the build tree's folder holding the `riemann` package
#   LD_LIBRARY_PATH   build/lib (RPATH covers it too; this helps ctypes/dlopen)
#   RIEMANN_DATA_DIR  <source>/Data (metric/scene JSON, meshes, baselines)
#   RIEMANN_BIN_DIR   build/bin (the `riemann` CLI, for CLI tests)
#   RIEMANN_TEST_OUTPUT_DIR  build/Testing/Temporary (scratch output)
set(RIEMANN_TEST_OUTPUT_DIR "${CMAKE_BINARY_DIR}/Testing/Temporary")
file(MAKE_DIRECTORY "${RIEMANN_TEST_OUTPUT_DIR}")
set(RIEMANN_TEST_ENVIRONMENT
  "PYTHONPATH=${RIEMANN_PYTHONPATH}"
  "LD_LIBRARY_PATH=${CMAKE_LIBRARY_OUTPUT_DIRECTORY}"
  "RIEMANN_DATA_DIR=${CMAKE_SOURCE_DIR}/Data"
  "RIEMANN_BIN_DIR=${CMAKE_RUNTIME_OUTPUT_DIRECTORY}"
  "RIEMANN_TEST_OUTPUT_DIR=${RIEMANN_TEST_OUTPUT_DIR}")

# riemann_add_gtest_dir(<dir> <executable> LIBRARIES <lib>...)
#
# One GoogleTest executable from <dir>/Test*.cxx (relative to the top source
# folder), linked to GTest::gtest_main, each TEST registered as its own ctest
# test by gtest_discover_tests.
function (riemann_add_gtest_dir dir name)
  cmake_parse_arguments(PARSE_ARGV 2 arg "" "" "LIBRARIES")
  if (NOT IS_ABSOLUTE "${dir}")
    set(dir "${CMAKE_SOURCE_DIR}/${dir}")
  endif ()
  file(GLOB sources CONFIGURE_DEPENDS "${dir}/Test*.cxx")
  if (NOT sources)
    return ()
  endif ()
  list(SORT sources)

  add_executable(${name} ${sources})
  target_link_libraries(${name} PRIVATE ${arg_LIBRARIES} GTest::gtest_main)
  # Tests may include helpers that sit next to them, or the cross-module
  # ones of Testing/Cxx (RenderingTestUtilities.h).
  target_include_directories(${name} PRIVATE "${dir}" "${CMAKE_SOURCE_DIR}/Testing/Cxx")
  # Where the shipped data is when RIEMANN_DATA_DIR is not set (a test run
  # by hand): an absolute path, unlike __FILE__ under ccache or a moved test.
  target_compile_definitions(${name} PRIVATE "RIEMANN_TEST_DATA_DIR=\"${CMAKE_SOURCE_DIR}/Data\"")
  # ctest names are <Module>.<Suite>.<Test> (e.g. CommonMetric.Metric.Norm):
  # the same suite name in two executables must not clash, and
  # `ctest -R '^CommonMetric\.'` selects one module.
  string(REGEX REPLACE "^Riemann(.*)Tests$" "\\1" prefix "${name}")
  gtest_discover_tests(${name}
    TEST_PREFIX "${prefix}."
    DISCOVERY_TIMEOUT 60
    WORKING_DIRECTORY "${RIEMANN_TEST_OUTPUT_DIR}"
    PROPERTIES
      LABELS      "Cxx")
  # The environment, set here rather than in PROPERTIES above: CMake 3.25's
  # gtest_discover_tests flattens PROPERTIES into one list, so ENVIRONMENT
  # kept only its first variable (the tests then fell back to __FILE__ for
  # their data, a relative path under ccache's base_dir). This file runs in
  # ctest after gtest's own, which lists the tests in ${name}_TESTS.
  set(environment_file "${CMAKE_CURRENT_BINARY_DIR}/${name}_environment.cmake")
  file(WRITE "${environment_file}"
    "foreach (test IN LISTS ${name}_TESTS)\n"
    "  set_tests_properties(\"\${test}\" PROPERTIES ENVIRONMENT [==[${RIEMANN_TEST_ENVIRONMENT}]==])\n"
    "endforeach ()\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES "${environment_file}")
endfunction ()

# riemann_add_python_tests(<dir>)
#
# `Python.<name>` for each <dir>/Test<name>.py, run by /usr/bin/python3 (the
# interpreter Debian's vtkmodules are built for; VTK 9.1 on Debian has no
# vtkpython target) with the environment above. None without RIEMANN_WRAP_PYTHON.
function (riemann_add_python_tests dir)
  if (NOT RIEMANN_WRAP_PYTHON)
    return () # they import the package `riemann`, which is not built
  endif ()
  if (NOT IS_ABSOLUTE "${dir}")
    set(dir "${CMAKE_SOURCE_DIR}/${dir}")
  endif ()
  file(GLOB scripts CONFIGURE_DEPENDS "${dir}/Test*.py")
  list(SORT scripts)
  foreach (script IN LISTS scripts)
    get_filename_component(test_name "${script}" NAME_WE)
    add_test(
      NAME    "Python.${test_name}"
      COMMAND "${Python3_EXECUTABLE}" "${script}"
      WORKING_DIRECTORY "${RIEMANN_TEST_OUTPUT_DIR}")
    set_tests_properties("Python.${test_name}" PROPERTIES
      ENVIRONMENT "${RIEMANN_TEST_ENVIRONMENT}"
      LABELS      "Python")
  endforeach ()
endfunction ()
