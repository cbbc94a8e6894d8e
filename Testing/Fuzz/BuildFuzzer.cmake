# cmake -DSOURCE_DIR=<source> -DBINARY_DIR=<build/fuzz> -DEXPORT_HEADER_DIR=<dir>
#       -DCLANGXX=<clang++> -DGENERATOR=<generator> -P BuildFuzzer.cmake
#
# Run by the ctest test Fuzz.Build: configure build/fuzz once (Clang,
# Testing/Fuzz/Standalone), then build it; Ninja rebuilds only what changed.
foreach (var SOURCE_DIR BINARY_DIR EXPORT_HEADER_DIR CLANGXX GENERATOR)
  if (NOT DEFINED ${var})
    message(FATAL_ERROR "BuildFuzzer.cmake: pass -D${var}=...")
  endif ()
endforeach ()

if (NOT EXISTS "${BINARY_DIR}/CMakeCache.txt")
  execute_process(
    COMMAND "${CMAKE_COMMAND}"
            -S "${SOURCE_DIR}/Testing/Fuzz/Standalone"
            -B "${BINARY_DIR}"
            -G "${GENERATOR}"
            "-DCMAKE_CXX_COMPILER=${CLANGXX}"
            "-DRIEMANN_SOURCE_DIR=${SOURCE_DIR}"
            "-DRIEMANN_EXPORT_HEADER_DIR=${EXPORT_HEADER_DIR}"
    RESULT_VARIABLE status)
  if (NOT status EQUAL 0)
    file(REMOVE "${BINARY_DIR}/CMakeCache.txt")
    message(FATAL_ERROR "Configuring the fuzzer build in ${BINARY_DIR} failed")
  endif ()
endif ()

execute_process(
  COMMAND "${CMAKE_COMMAND}" --build "${BINARY_DIR}"
  RESULT_VARIABLE status)
if (NOT status EQUAL 0)
  message(FATAL_ERROR "Building the fuzzer in ${BINARY_DIR} failed")
endif ()
