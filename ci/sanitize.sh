#!/usr/bin/env bash
# The sanitizer job (run by .ci/run after the tests): AddressSanitizer + UndefinedBehaviorSanitizer
# build of the library, the CLI and the unit tests in build-asan/, then `ctest -L unit` there.
# Leak reports from Open MPI's and hwloc's own start-up allocations are suppressed by name
# (ci/sanitizers/lsan.supp); everything in hmfnet's code is reported and fails the job.
# Warnings are not errors here: the sanitizers change inlining, and GCC 12 then reports
# -Wmaybe-uninitialized inside libstdc++ and Catch2 (the main build keeps -Werror).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
bash ci/install-deps.sh
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHMFNET_SANITIZE=address,undefined \
  -DHMFNET_BUILD_BENCH=OFF -DHMFNET_WERROR=OFF > build-asan.log 2>&1 || { cat build-asan.log; exit 1; }
cmake --build build-asan -j "$(nproc)" --target hmfnet hmfnet_unit_tests hmfnet_parallel_tests
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:strict_string_checks=1:check_initialization_order=1"
export LSAN_OPTIONS="suppressions=$root/ci/sanitizers/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
cd build-asan
ctest -L '^unit$' -j "$(nproc)" --output-on-failure --timeout 900
