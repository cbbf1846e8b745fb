#!/usr/bin/env bash
# The whole test suite under AddressSanitizer (with LeakSanitizer) and UndefinedBehaviorSanitizer:
# builds rockfall with ROCKFALL_SANITIZE=ON in build-asan/ (its own directory: every object is
# compiled differently) and runs ctest there. Any finding fails the test that made it. Slow: the
# build is a full second build, and the tests run about 3 times slower (docs/sanitizers.md).
# Arguments go to ctest, e.g. `bash scripts/sanitize.sh -R test_db`. JOBS sets the parallelism.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=${JOBS:-$(nproc)}
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DROCKFALL_SANITIZE=ON \
    -DROCKFALL_BUILD_BENCH=OFF >/dev/null
cmake --build build-asan -j "$jobs"
# halt_on_error: the first finding ends the process with a non-zero exit, so the test fails.
# detect_leaks: LeakSanitizer checks at exit (the default on Linux x86-64, stated here).
export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:detect_stack_use_after_return=1:strict_string_checks=1:check_initialization_order=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
# The suppressions cover libassimp alone (scripts/lsan-suppressions.txt says why); another file
# can be given in ROCKFALL_LSAN_SUPPRESSIONS.
suppressions=${ROCKFALL_LSAN_SUPPRESSIONS:-$PWD/scripts/lsan-suppressions.txt}
export LSAN_OPTIONS="print_suppressions=0:suppressions=$suppressions"
cd build-asan
ctest --output-on-failure -j "$jobs" "$@"
