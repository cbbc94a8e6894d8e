# RIEMANN_SANITIZE: build the project's own code with AddressSanitizer (and
# LeakSanitizer) and UndefinedBehaviorSanitizer. Clang only; system libraries
# (VTK, Mesa, GiNaC, Embree, ...) stay the uninstrumented Debian builds.
#
#   ./run.sh sanitize        configures build-asan/ with this on, builds, and
#                            runs the C++ and CLI tests (see run.sh)
#
# By hand (the same as run.sh sanitize does):
#
#   cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Release \
#     -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
#     -DRIEMANN_SANITIZE=ON -DRIEMANN_WRAP_PYTHON=OFF -DRIEMANN_BUILD_BENCHMARKS=OFF
#
# UBSan does not recover: the first report ends the process with a non-zero
# status, so a test with undefined behaviour fails instead of printing.
# Speed: the integrators and the CPU tracer are Eigen code, slow under the
# sanitizers. A 160x120 CPU render of paper-one-bump took 37 s at -O1,
# 29 s at -O2, 10 s at -O2 with Eigen's EIGEN_STRONG_INLINE forced (below),
# against 2.4 s in the GCC Release build; the CLI tests allow 60 s per run.
# Debug line tables give file:line stacks.
option(RIEMANN_SANITIZE
  "Build with -fsanitize=address,undefined (Clang; for the C++ and CLI tests)" OFF)

if (RIEMANN_SANITIZE)
  if (NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR
      "RIEMANN_SANITIZE needs Clang (-DCMAKE_CXX_COMPILER=clang++), not ${CMAKE_CXX_COMPILER_ID}")
  endif ()
  set(RIEMANN_SANITIZE_FLAGS
    -fsanitize=address,undefined
    -fno-sanitize-recover=undefined
    -fno-omit-frame-pointer
    -gline-tables-only
    -O2)
  # Every target of this directory tree (libraries, tests, the CLI). After
  # CMAKE_CXX_FLAGS_<CONFIG> on the command line, so -O2 wins over -O3.
  add_compile_options("$<$<COMPILE_LANGUAGE:CXX>:${RIEMANN_SANITIZE_FLAGS}>")
  # Eigen's small fixed-size expressions must be inlined to be fast; with the
  # sanitizers' instrumentation the inliner gives up on many of them and the
  # numerical code ran ~12 times slower than the GCC build (4-5 times with
  # this). Force what Eigen marks EIGEN_STRONG_INLINE, as Eigen itself does
  # for MSVC (__forceinline).
  add_compile_definitions(
    "$<$<COMPILE_LANGUAGE:CXX>:EIGEN_STRONG_INLINE=inline __attribute__((always_inline))>")
  # Executables get the runtimes; shared libraries leave the symbols to them.
  add_link_options(-fsanitize=address,undefined)
  # Executables keep the libraries they load at run time (Mesa's GL driver)
  # until exit: see RiemannSanitizeSupport.cxx. The definition in the
  # executable must be in its dynamic symbol table to win over libc's.
  add_library(RiemannSanitizeSupport OBJECT
    "${CMAKE_CURRENT_LIST_DIR}/RiemannSanitizeSupport.cxx")
  link_libraries(
    "$<$<STREQUAL:$<TARGET_PROPERTY:TYPE>,EXECUTABLE>:RiemannSanitizeSupport>")
  add_link_options(
    "$<$<STREQUAL:$<TARGET_PROPERTY:TYPE>,EXECUTABLE>:LINKER:--export-dynamic-symbol=dlclose>")
  # gtest_discover_tests lists each test executable's tests when ctest runs,
  # not right after linking: listing runs the instrumented program, which
  # needs the sanitizer options (LSAN_OPTIONS=suppressions=...) that
  # ./run.sh sanitize gives ctest, not the build.
  set(CMAKE_GTEST_DISCOVER_TESTS_DISCOVERY_MODE PRE_TEST)
  message(STATUS "RIEMANN_SANITIZE: ${RIEMANN_SANITIZE_FLAGS}")
endif ()
