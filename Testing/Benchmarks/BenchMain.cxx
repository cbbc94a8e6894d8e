/**
 * @file BenchMain.cxx
 * @brief The one main() of build/bin/RiemannBenchmarks.
 *
 * Every Testing/Benchmarks/Bench*.cxx is compiled into the same executable
 * (see Testing/CMakeLists.txt), so main() lives here, on its own, and the
 * Bench*.cxx files only register benchmarks: adding one never clashes.
 */
#include <benchmark/benchmark.h>

BENCHMARK_MAIN();
