# One helper per CTest category (Nalu-Wind style): every test gets a label and a TIMEOUT.
#   unit          fast Catch2 tests, run by CI
#   verification  one driver per claim of the paper, CI scale (CI runs them)
#   regression    comparison against stored reference HDF5 in reference/ (CI runs them)
#   mpi           tests run under mpirun with 2 ranks (CI runs them)
#   paper         paper-figure pipeline steps
set(HMFNET_MPIEXEC ${MPIEXEC_EXECUTABLE})
set(HMFNET_MPI_FLAGS --allow-run-as-root --oversubscribe)

# CTest runs tests side by side (-j2 on 2 cores): OpenMP threads that spin while waiting would
# then fight over the cores and slow small parallel regions down by 10-50x, so tests wait
# passively. Tests that need a thread count set it themselves.
set(HMFNET_TEST_ENVIRONMENT "OMP_WAIT_POLICY=PASSIVE")

# A TIMEOUT guards against hangs, and the unit tests' guards (which ci/sanitize.sh runs) are
# multiplied by this factor. Under the sanitizers the same code runs 10-20x slower: the dense
# dispersion test (tests/theory/test_dispersion_relation.cpp, N = 250) takes 6.4 s in Release and
# 117 s (AMD EPYC) to over 120 s (Intel Xeon) under ASan + UBSan at -O1 beside another test on 2
# cores (ci/sanitize.sh now leaves it to the main job), and cli.instruction_sets_agree 136 s of
# its 180 (AMD EPYC): a guard met by chance.
set(HMFNET_TIMEOUT_FACTOR 1)
if(HMFNET_SANITIZE)
  set(HMFNET_TIMEOUT_FACTOR 3)
endif()

# CTest starts tests in descending COST (ties in the order declared); a test without one takes
# the time a previous run stored, and a fresh build (CI's) has none. Without it the verification
# drivers, declared last and the longest (15-130 s each), started last, and a fresh `ctest -j2`
# ended with one driver running alone. A COST always decides: the drivers start first, the CLI
# scripts next, and the short Catch2 tests (by their stored times, when there are any) fill the
# end. Measured in CI's clean clone (AMD EPYC, 2 cores): 831 s against 841 s before, near the
# floor of ~818 s (763 s of tests a core, and the MPI tests hold both cores).
set(HMFNET_COST_VERIFICATION 100)
set(HMFNET_COST_CLI 10)

# Links a test binary to Catch2 and to its implementation, which tests/support/catch_session.cpp
# compiles once for all of them, at -O0: at -O3 that one file took 33 s of a 2-core build (AMD
# EPYC), three times over, and at -O0 15 s once. Every CHECK goes through this code, yet
# hmfnet_unit_tests (2 million assertions) ran in 16.1 s with it at -O0 and 15.8-16.9 s at -O1.
# The binary's main() calls run_catch_session (support/catch_session.hpp).
function(hmfnet_link_catch target)
  if(NOT TARGET hmfnet_catch_session)
    get_filename_component(tests_dir "${CMAKE_CURRENT_FUNCTION_LIST_DIR}/../tests" ABSOLUTE)
    add_library(hmfnet_catch_session STATIC ${tests_dir}/support/catch_session.cpp)
    target_include_directories(hmfnet_catch_session PUBLIC ${tests_dir})
    target_link_libraries(hmfnet_catch_session PUBLIC Catch2::Catch2)
    target_compile_options(hmfnet_catch_session PRIVATE -O0)
  endif()
  target_link_libraries(${target} PRIVATE hmfnet_catch_session)
  # Every test file includes Catch2 (1.3 s to parse on the AMD EPYC) and most of these; parsed
  # once per binary instead of once per file (the 87 test files: 325 s of compile, 244 s with
  # it). The price: a test file that forgets one of these includes still compiles here.
  target_precompile_headers(${target} PRIVATE <catch2/catch.hpp> <algorithm> <cmath> <cstdint>
                            <limits> <random> <string> <vector>)
endfunction()

# LEAK_CHECKED: in an AddressSanitizer build, each of the target's tests runs with LeakSanitizer
# on (ci/sanitize.sh turns it off for the rest: Open MPI's components leak at exit where no
# suppression can name them), so the binary need not run a second time, whole, for leaks.
function(hmfnet_catch_tests target label timeout)
  math(EXPR timeout "${timeout} * ${HMFNET_TIMEOUT_FACTOR}")
  set(leaks)
  if("LEAK_CHECKED" IN_LIST ARGN AND HMFNET_SANITIZE MATCHES "address")
    if(CMAKE_VERSION VERSION_LESS 3.22)  # older CMake ignores the property: no leak check at all
      message(FATAL_ERROR "The leak checks of ${target} need CMake 3.22 (ENVIRONMENT_MODIFICATION)")
    endif()
    set(leaks ENVIRONMENT_MODIFICATION
        "ASAN_OPTIONS=set:detect_leaks=1:strict_string_checks=1:check_initialization_order=1")
  endif()
  # --warn NoTests: a test whose name CTest cannot carry (a ';' splits it, an unclosed '[' joins
  # the names after it into one) runs no test case, and Catch2 then exits 0 unless told to fail.
  catch_discover_tests(${target} EXTRA_ARGS --warn NoTests
                       PROPERTIES LABELS ${label} TIMEOUT ${timeout}
                       ENVIRONMENT "${HMFNET_TEST_ENVIRONMENT}" ${leaks})
endfunction()

function(hmfnet_add_verification name timeout)
  add_test(NAME verification.${name} COMMAND ${ARGN})
  set_tests_properties(verification.${name} PROPERTIES LABELS verification TIMEOUT ${timeout}
                       ENVIRONMENT "${HMFNET_TEST_ENVIRONMENT}" COST ${HMFNET_COST_VERIFICATION})
endfunction()

function(hmfnet_add_verification_full name timeout)
  add_test(NAME verification-full.${name} COMMAND ${ARGN})
  set_tests_properties(verification-full.${name} PROPERTIES LABELS verification-full TIMEOUT ${timeout})
endfunction()

function(hmfnet_add_mpi_test name nranks timeout)
  add_test(NAME mpi.${name}
           COMMAND ${HMFNET_MPIEXEC} ${HMFNET_MPI_FLAGS} ${MPIEXEC_NUMPROC_FLAG} ${nranks} ${ARGN})
  # One OpenMP thread per rank: the ranks already use the cores.
  set_tests_properties(mpi.${name} PROPERTIES LABELS mpi TIMEOUT ${timeout} PROCESSORS ${nranks}
                       ENVIRONMENT "OMP_NUM_THREADS=1;${HMFNET_TEST_ENVIRONMENT}")
endfunction()

function(hmfnet_add_cli_test name label timeout)
  math(EXPR timeout "${timeout} * ${HMFNET_TIMEOUT_FACTOR}")
  add_test(NAME ${label}.${name} COMMAND ${ARGN})
  set_tests_properties(${label}.${name} PROPERTIES LABELS ${label} TIMEOUT ${timeout}
                       ENVIRONMENT "${HMFNET_TEST_ENVIRONMENT}" COST ${HMFNET_COST_CLI})
endfunction()
