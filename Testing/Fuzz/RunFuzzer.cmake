# cmake -DFUZZER=<FuzzExpression> -DCORPUS=<committed seeds> -DWORK=<scratch dir>
#       -DDICTIONARY=<dict> -DSECONDS=<n> [-DEXTRA_CORPUS=<more seeds>]
#       [-DMAX_LEN=<bytes, default 256>] -P RunFuzzer.cmake
#
# Run by the ctest tests Fuzz.Expressions and Fuzz.Scenes: fuzz for SECONDS
# seconds, starting from the committed seed corpus (read only; new inputs go
# to WORK/corpus).
# A crash, a timeout (one input running over 10 s), a leak or a sanitizer
# report stops libFuzzer with a non-zero status and leaves the input in
# WORK/crash-*, timeout-*, leak-*: the test fails and prints how to replay it.
foreach (var FUZZER CORPUS WORK DICTIONARY SECONDS)
  if (NOT DEFINED ${var})
    message(FATAL_ERROR "RunFuzzer.cmake: pass -D${var}=...")
  endif ()
endforeach ()

if (NOT EXISTS "${FUZZER}")
  message(FATAL_ERROR "no fuzzer ${FUZZER}: the fuzzers are built apart from the test suite; "
    "run ./run.sh fuzz (or cmake --build build --target RiemannFuzzers, then ctest -L Fuzz)")
endif ()

if (NOT DEFINED MAX_LEN)
  set(MAX_LEN 256)
endif ()
set(seeds "${CORPUS}")
if (DEFINED EXTRA_CORPUS)
  list(APPEND seeds "${EXTRA_CORPUS}")
endif ()

file(MAKE_DIRECTORY "${WORK}/corpus")
execute_process(
  COMMAND "${FUZZER}"
          "-max_total_time=${SECONDS}"
          "-max_len=${MAX_LEN}"
          -timeout=10
          -rss_limit_mb=2048
          -print_final_stats=1
          "-dict=${DICTIONARY}"
          "-artifact_prefix=${WORK}/"
          "${WORK}/corpus"
          ${seeds}
  RESULT_VARIABLE status)
if (NOT status EQUAL 0)
  file(GLOB artifacts "${WORK}/crash-*" "${WORK}/timeout-*" "${WORK}/leak-*" "${WORK}/oom-*"
                      "${WORK}/slow-unit-*")
  message(FATAL_ERROR
    "The fuzzer found a failing input (status ${status}): ${artifacts}\n"
    "Replay it with: ${FUZZER} <file>")
endif ()
