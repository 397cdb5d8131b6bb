#!/usr/bin/env bash
# The fuzzing job: libFuzzer + AddressSanitizer + UndefinedBehaviorSanitizer on the network readers
# and the CLI grammar (tests/fuzz; "readers" below includes cli_arguments). Builds hmfnet_core and the harnesses with clang in build-fuzz/ (HMFNET_FUZZ=ON: no
# Trilinos), replays the kept crashes, then fuzzes each reader for FUZZ_SECONDS (default 60; as
# many readers at once as there are cores) on a copy of its seed corpus, so the corpus in git only changes by hand. A crash, leak, timeout or
# out-of-memory in hmfnet's code is copied to tests/fuzz/crashes/<reader>/ (replayed by the
# unit.fuzz_replay CTest once fixed) and fails the job; one inside Debian's libhdf5 is kept in
# tests/fuzz/libhdf5/ with a warning (not ours to fix; see tests/fuzz/README.md).
#   FUZZ_SECONDS=300 ci/fuzz.sh          longer run
#   FUZZ_READERS="edge_list" ci/fuzz.sh  one reader
#   FUZZ_SEED=0 ci/fuzz.sh               a random seed (default 1: the same run every time)
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
seconds="${FUZZ_SECONDS:-60}"
# A fixed seed makes a CI run repeat the same exploration (FUZZ_SEED=0: libFuzzer picks one).
seed="${FUZZ_SEED:-1}"
readers=(${FUZZ_READERS:-matrix_market edge_list network_hdf5 cli_arguments})

# clang, its runtimes (libFuzzer, sanitizers) and libomp, only when missing (ci/install-deps.sh
# installs everything else the library needs).
missing=()
for p in clang libclang-rt-dev libomp-dev; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y --no-install-recommends "${missing[@]}"
fi

# -O1, as OSS-Fuzz builds fuzzers: the build is most of this job's time, and -O2 -g made it 4-5 of
# CI's minutes on 2 cores (debug info: line tables, added by CMakeLists.txt's fuzz branch).
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHMFNET_FUZZ=ON \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -DNDEBUG" -DHMFNET_WERROR=ON > build-fuzz.log 2>&1 \
  || { cat build-fuzz.log; exit 1; }
cmake --build build-fuzz -j "$(nproc)" >> build-fuzz.log 2>&1 || { cat build-fuzz.log; exit 1; }

export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:strict_string_checks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
# The first stack frame of a sanitizer or libFuzzer report that is outside their runtimes and the
# allocator, from the first report on: an out-of-memory report may list libFuzzer's own live
# allocations before the stack of the allocation over the limit, and the RSS watchdog may add a
# second report with no stack at all. Prints nothing if there is no such frame. One awk program
# rather than a grep | grep | head pipeline: under `set -o pipefail` a grep with no match, or one
# killed by SIGPIPE when head exits, would end the whole job with no message.
first_frame_outside_runtimes() {
  awk '
    /ERROR:/ { seen = 1 }
    !seen || !/^ +#[0-9]+ / { next }
    / in (__interceptor_|__sanitizer|__asan|__lsan|__ubsan|fuzzer::|malloc|calloc|realloc|operator new|__mem|__str)/ { next }
    # The sanitizer interceptors under their plain C names (strdup, memcpy, ... as clang 14
    # prints them): a C function of the harness binary with no source location, i.e. linked in
    # without debug info. Our own code has line tables, so its frames carry file:line instead
    # of (binary+offset) (inlined frames may show unqualified names, never this form).
    / in [A-Za-z_][A-Za-z0-9_]* \(\/[^)]*\/fuzz_[a-z0-9_]+\+0x[0-9a-f]+\)/ { next }
    /\(\/lib\/x86_64-linux-gnu\/libc\.so/ { next }   # the signal trampoline of a timeout report
    { print; exit }
  ' "$1"
}

# The settings of one reader, as globals: fuzzer, asan, dict, limits, triage_limits.
reader_settings() {
  local reader=$1 max_len=4096 malloc_limit=512
  fuzzer="build-fuzz/bin/fuzz_$reader"
  # Limits: a text read of a few KiB that needs more than 512 MiB in one allocation, 2 GiB in all
  # or 10 s is itself the bug (an absurd allocation or a hang), not a reason to raise them.
  asan="$ASAN_OPTIONS"
  if [ "$reader" = network_hdf5 ]; then
    # HDF5 seeds are ~5 KiB files. Debian's libhdf5 (1.10) is outside our control and not
    # instrumented: it mallocs sizes read from a corrupted file and fails cleanly when malloc
    # returns NULL (as it does without ASan), so ASan returns NULL too instead of aborting, and
    # the per-allocation limit is the RSS limit. Our own `new` still aborts on an absurd size.
    # libhdf5 also keeps freed blocks on free lists and leaks on some of its own error paths:
    # libFuzzer would run a full leak scan after nearly every input (a few exec/s) and report
    # HDF5's leaks, so leak detection is off here (the text readers keep it); the harness checks
    # instead that no HDF5 handle stays open after a read.
    max_len=16384
    malloc_limit=2048
    asan="$ASAN_OPTIONS:allocator_may_return_null=1:detect_leaks=0"
  fi
  dict=()
  [ -f "tests/fuzz/$reader.dict" ] && dict=(-dict="tests/fuzz/$reader.dict")
  limits=(-rss_limit_mb=2048 -malloc_limit_mb=$malloc_limit -timeout=10 -max_len=$max_len)
  # Replaying one input to sort it: twice the RSS limit, so that one huge malloc is reported by
  # the malloc hook with its stack, not first by the RSS watchdog thread with none (a race when
  # both limits are equal).
  triage_limits=(-rss_limit_mb=$((2 * (malloc_limit > 1024 ? malloc_limit : 1024))) \
    -malloc_limit_mb=$malloc_limit -timeout=10 -max_len=$max_len)
}

status=0
declare -A replay_failed=()
for reader in "${readers[@]}"; do
  reader_settings "$reader"
  # 1. The kept crashes must no longer crash (the gcc build replays them too, without sanitizers).
  if compgen -G "tests/fuzz/crashes/$reader/*" > /dev/null; then
    ASAN_OPTIONS="$asan" "$fuzzer" "${limits[@]}" tests/fuzz/crashes/"$reader"/* > "$work/$reader-replay.log" 2>&1 ||
      { cat "$work/$reader-replay.log"; echo "ci/fuzz.sh: a kept crash of $reader crashes again"; status=1; replay_failed[$reader]=1; continue; }
  fi

  # 2. Fuzz a copy of the corpus for a bounded time. HDF5 runs in fork mode and goes on after a
  #    crash: corrupted files also crash Debian's libhdf5 1.10 itself, within minutes, and those
  #    must not end the run or fail the job (step 3 sorts them out).
  mkdir -p "$work/corpus-$reader" "$work/artifacts-$reader"
  cp tests/fuzz/corpus/"$reader"/* "$work/corpus-$reader"/
  mode=()
  [ "$reader" = network_hdf5 ] && mode=(-fork=1 -ignore_crashes=1 -ignore_ooms=1 -ignore_timeouts=1)
  #    The readers fuzz side by side, one a core (each fuzzer is one process; the HDF5 one forks
  #    one child), so the job takes FUZZ_SECONDS per core's share of readers, not per reader.
  while [ "$(jobs -rp | wc -l)" -ge "$(nproc)" ]; do wait -n || true; done
  echo "ci/fuzz.sh: fuzzing $reader for ${seconds} s"
  (ASAN_OPTIONS="$asan" "$fuzzer" "$work/corpus-$reader" "${dict[@]}" "${limits[@]}" "${mode[@]}" \
    -seed="$seed" -max_total_time="$seconds" -print_final_stats=1 \
    -artifact_prefix="$work/artifacts-$reader/" \
    > "$work/$reader.log" 2>&1 || true) &
done
wait

for reader in "${readers[@]}"; do
  [ -z "${replay_failed[$reader]:-}" ] || continue
  reader_settings "$reader"
  grep -E '^(stat::number_of_executed_units|stat::average_exec_per_sec|stat::peak_rss_mb)' \
    "$work/$reader.log" | sed "s/^/  $reader /" || true
  grep -E '^#[0-9]+: cov:' "$work/$reader.log" | tail -n 1 | sed "s/^/  $reader /" || true

  # 3. Sort each crashing input by the first stack frame outside the sanitizer and libFuzzer
  #    runtimes: inside libhdf5 it is HDF5's bug (kept in tests/fuzz/libhdf5/, reported, not
  #    replayed); anywhere else it is ours (kept in tests/fuzz/crashes/<reader>/, fails the job).
  for input in "$work/artifacts-$reader"/*; do
    [ -e "$input" ] || continue
    if ASAN_OPTIONS="$asan" "$fuzzer" "${triage_limits[@]}" "$input" > "$work/triage.log" 2>&1; then
      echo "ci/fuzz.sh: warning: $(basename "$input") did not crash again when replayed alone"
      continue
    fi
    first_frame="$(first_frame_outside_runtimes "$work/triage.log")"
    if [[ "$first_frame" == *libhdf5* ]]; then
      mkdir -p tests/fuzz/libhdf5
      cp "$input" tests/fuzz/libhdf5/
      echo "ci/fuzz.sh: warning: $(basename "$input") crashes inside libhdf5, not hmfnet" \
        "(kept in tests/fuzz/libhdf5/):"
      grep -m1 -E 'ERROR|SUMMARY' "$work/triage.log" || true
    elif [ -z "$first_frame" ]; then
      # No stack to blame: libFuzzer's RSS watchdog thread can win the race against the malloc
      # hook and report "out-of-memory (used: ...)" with no allocation stack. Such an input is
      # kept for a person to look at, and does not fail the job: it names no code.
      mkdir -p tests/fuzz/unattributed
      cp "$input" tests/fuzz/unattributed/
      echo "ci/fuzz.sh: warning: $(basename "$input") fails without a stack to attribute it" \
        "(kept in tests/fuzz/unattributed/):"
      grep -m1 -E 'ERROR|SUMMARY' "$work/triage.log" || true
    else
      mkdir -p "tests/fuzz/crashes/$reader"
      cp "$input" "tests/fuzz/crashes/$reader/"
      tail -n 60 "$work/triage.log"
      echo "ci/fuzz.sh: $reader crashed in $first_frame"
      echo "ci/fuzz.sh: input kept as tests/fuzz/crashes/$reader/$(basename "$input")"
      status=1
    fi
  done
done
exit $status
