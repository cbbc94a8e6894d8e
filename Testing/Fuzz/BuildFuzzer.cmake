# cmake -DSOURCE_DIR=<source> -DBINARY_DIR=<build/fuzz> -DMAIN_BINARY_DIR=<build>
#       -DSCENE_SOURCE_DIR=<dir> -DSCENE_HEADER_DIR=<dir>
#       -DCLANGXX=<clang++> -DGENERATOR=<generator> [-DLAUNCHER=ccache] -P BuildFuzzer.cmake
#
# Run by the target RiemannFuzzers (./run.sh fuzz): configure build/fuzz (Clang,
# Testing/Fuzz/Standalone), then build it; Ninja rebuilds only what changed.
# The folders are passed on each run (a re-configure of a configured tree
# takes a second or two), so a moved scene parser is picked up.
foreach (var SOURCE_DIR BINARY_DIR MAIN_BINARY_DIR SCENE_SOURCE_DIR
             SCENE_HEADER_DIR CLANGXX GENERATOR)
  if (NOT DEFINED ${var})
    message(FATAL_ERROR "BuildFuzzer.cmake: pass -D${var}=...")
  endif ()
endforeach ()

set(configure_arguments
  -S "${SOURCE_DIR}/Testing/Fuzz/Standalone"
  -B "${BINARY_DIR}"
  "-DRIEMANN_SOURCE_DIR=${SOURCE_DIR}"
  "-DRIEMANN_SCENE_SOURCE_DIR=${SCENE_SOURCE_DIR}"
  "-DRIEMANN_SCENE_HEADER_DIR=${SCENE_HEADER_DIR}"
  "-DRIEMANN_BINARY_DIR=${MAIN_BINARY_DIR}")
if (NOT EXISTS "${BINARY_DIR}/CMakeCache.txt")
  list(APPEND configure_arguments -G "${GENERATOR}" "-DCMAKE_CXX_COMPILER=${CLANGXX}")
  if (LAUNCHER)
    list(APPEND configure_arguments "-DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER}")
  endif ()
endif ()
execute_process(
  COMMAND "${CMAKE_COMMAND}" ${configure_arguments}
  RESULT_VARIABLE status)
if (NOT status EQUAL 0)
  file(REMOVE "${BINARY_DIR}/CMakeCache.txt")
  message(FATAL_ERROR "Configuring the fuzzer build in ${BINARY_DIR} failed")
endif ()

execute_process(
  COMMAND "${CMAKE_COMMAND}" --build "${BINARY_DIR}"
  RESULT_VARIABLE status)
if (NOT status EQUAL 0)
  message(FATAL_ERROR "Building the fuzzer in ${BINARY_DIR} failed")
endif ()
