#!/usr/bin/env bash
# The sanitizer job (run by .ci/run after the tests): AddressSanitizer + UndefinedBehaviorSanitizer
# build of the library, the CLI and the unit tests in build-asan/, then `ctest -L unit` there.
# Leak detection: on for the binary without MPI (see below); ci/sanitizers/lsan.supp names the
# MPI and hwloc libraries in case one is ever linked in.
# Warnings are not errors here: the sanitizers change inlining, and GCC 12 then reports
# -Wmaybe-uninitialized inside libstdc++ and Catch2 (the main build keeps -Werror).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
bash ci/install-deps.sh
# -O1 -g1 (line tables): the optimisation level the sanitizers' authors recommend, and stack
# traces with file:line; measured on two heavy files (Tpetra, Catch2), it compiles in 0.50-0.62
# of the time of RelWithDebInfo's -O2 -g, which made this job's build ~13 of CI's 45 minutes.
# No Python module (HMFNET_PYTHON_MODULE=OFF): an instrumented extension cannot load into Debian's
# uninstrumented interpreter, and its tests run in the main job. No CUDA backend
# (HMFNET_CUDA=OFF): nvcc's device code is not instrumented, the main job compiles and links it,
# and this build then checks the other branch, `--device cuda` refused as "built without CUDA"
# (tests/cli/simulate_outputs.sh).
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
  -DHMFNET_SANITIZE=address,undefined -DHMFNET_PYTHON_MODULE=OFF -DHMFNET_CUDA=OFF \
  -DHMFNET_BUILD_BENCH=OFF -DHMFNET_WERROR=OFF > build-asan.log 2>&1 || { cat build-asan.log; exit 1; }
# The build runs the test binaries to list their Catch2 tests: no leak reports from MPI there.
export ASAN_OPTIONS="detect_leaks=0"
cmake --build build-asan -j "$(nproc)" --target hmfnet hmfnet_unit_tests hmfnet_parallel_tests \
  hmfnet_fuzz_replay
# Leaks: Open MPI's dlopen'ed components leak at exit and are unloaded before LeakSanitizer
# reports, so their frames show as "<unknown module>" (or a wrong library) and no suppression by
# name can match them. So leak detection runs on the tests of the binary that never starts MPI
# (hmfnet_unit_tests: core, I/O, networks, theory), each with its own ASAN_OPTIONS
# (LEAK_CHECKED in cmake/HmfnetTesting.cmake); everything else, the CLI and the MPI tests, runs
# under ASan + UBSan with leak detection off.
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$root/ci/sanitizers/lsan.supp:print_suppressions=0"
export ASAN_OPTIONS="detect_leaks=0:strict_string_checks=1:check_initialization_order=1"
cd build-asan
# Two unit tests are left to the main job (ci/test.sh runs them):
# - the dense dispersion relation on 8 ER networks (tests/theory/test_dispersion_relation.cpp),
#   128 test-seconds here when measured (6 s in Release), nearly all in Eigen's complex LU.
#   solve_dispersion, with that LU, still runs under the sanitizers in the complete-graph test
#   beside it (N = 300, 23 s);
# - unit.cli.instruction_sets_agree, 94 of this job's 519 test-seconds (14 s in Release): its
#   property is bits across instruction sets, which the main job checks; the kernels it reaches
#   run here in the unit tests of each set: the rank-one force at 1, 2, 3, 11 and 16 replicas
#   (whole and partial groups, [rank_one]) in the widest set and in unit.avx2_rank_one_loops, its
#   fused pass and the sparse row loops ([rank_one_fused], [network_force], [column_segments]) in
#   the widest set and in unit.baseline_row_loops.
ctest -L '^unit$' \
  -E '^(On finite ER networks the full dispersion relation |unit\.cli\.instruction_sets_agree$)' \
  -j "$(nproc)" --output-on-failure --timeout 900
