#!/usr/bin/env bash
# The device check, run on a machine with an NVIDIA GPU, nvcc, CMake and g++ (Trilinos, HDF5 and
# MPI are not needed): names the GPU, builds ci/device's standalone project (the CUDA backend and
# the gpu tests) and runs each check, writing logs under $OUT and printing a table last. Exits
# non-zero when the build or a check fails; a check that finds no device reports skip.
#
#   bash ci/device_prepare.sh   first, on a machine with nvcc and Catch2: fills build-device/ and
#                               prints the device call, which carries build-device
#   bash ci/device_check.sh     then, from the repository root on the GPU machine
#
# Environment: OUT (logs; ./device-out when unset), HMFNET_DEVICE_BUILD (scratch build folder,
# /tmp/hmfnet-device-build), HMFNET_DEVICE_BUDGET_S (seconds for the whole check, 450: each step's
# time limit is cut to what is left of it, so the table is printed inside an 8-minute call);
# the campaign's HMFNET_QSS_SIZES, HMFNET_QSS_LIVES (3), HMFNET_QSS_LIMIT_S (its share, 260 s),
# HMFNET_QSS_BATCH (rotors a thread loads together: 1, 4 or 8, the same bits), HMFNET_QSS_STATE
# (global or shared: where a launch keeps the state, the same bits) and
# HMFNET_QSS_RESUME (a qss_gpu_resume.bin to go on from: an earlier call's stays at
# $build/qss/ on a warm machine); HMFNET_DEVICE_CHECKS (the checks to run, space-separated
# names from the list `checks` below, all of them when unset: a second call on a warm machine
# that only goes on with the campaign names check_qss alone).
#
# A new check is one function that runs something from "$build" and calls `record` once per
# result, added to the list `checks` below. $OUT brings back at most 8 files, two folders deep:
# each check writes one log.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
OUT="${OUT:-$root/device-out}"
build="${HMFNET_DEVICE_BUILD:-/tmp/hmfnet-device-build}"
budget_s="${HMFNET_DEVICE_BUDGET_S:-450}"
prepared="$root/build-device"
mkdir -p "$OUT" || { echo "device_check: cannot create OUT=$OUT" >&2; exit 1; }
OUT="$(cd "$OUT" && pwd)"
t_start=$EPOCHREALTIME

rows=()
failed=0
device_name="none"

# record NAME RESULT SECONDS [NOTE]: one row of the table; RESULT is pass, fail or skip.
record() {
  rows+=("$(printf '%-34s %-5s %8s  %s' "$1" "$2" "$3" "${4:-}")")
  [ "$2" = fail ] && failed=1
  return 0
}
# exit_text RC: "exit RC", naming the time limit where timeout ended the command.
exit_text() { case $1 in 124|137) echo "exit $1 (time limit)" ;; *) echo "exit $1" ;; esac; }
elapsed_since() { awk -v a="$1" -v b="$EPOCHREALTIME" 'BEGIN { printf "%.1f", b - a }'; }
# Seconds a step may take: its own limit, cut to what the budget leaves after 20 s for the table.
limit_for() {
  local left
  left=$(awk -v a="$t_start" -v b="$EPOCHREALTIME" -v n="$budget_s" 'BEGIN { printf "%d", n - (b - a) - 20 }')
  if [ "$left" -lt "$1" ]; then echo "$left"; else echo "$1"; fi
}
# bounded LIMIT LOG COMMAND...: runs COMMAND under its time limit, appending its output to LOG.
bounded() {
  local limit=$1 log=$2
  shift 2
  [ "$limit" -gt 0 ] || { echo "device_check: no time left in the budget for: $*" >>"$log"; return 124; }
  timeout --kill-after=10 "$limit" "$@" >>"$log" 2>&1
}

show_device() {
  local log="$OUT/device.txt"
  : >"$log"
  if command -v nvidia-smi >/dev/null; then
    nvidia-smi -L | tee -a "$log" || true
    nvidia-smi --query-gpu=name,driver_version,memory.total,memory.used,compute_cap \
      --format=csv | tee -a "$log" || true
    device_name=$(nvidia-smi --query-gpu=name,driver_version,memory.total \
      --format=csv,noheader 2>/dev/null | head -n 1 || true)
    [ -n "$device_name" ] || device_name="unreadable (nvidia-smi failed)"
  else
    echo "nvidia-smi: not found (no NVIDIA driver on this machine)" | tee -a "$log"
    device_name="none (no nvidia-smi)"
  fi
  { echo; uname -srm; nvcc --version | tail -n 2; cmake --version | head -n 1
    "${CXX:-g++}" --version | head -n 1; } >>"$log" 2>&1 || true
}

# nvcc is put on the PATH where the toolkit sits in its usual place but the PATH lacks it.
find_tools() {
  if ! command -v nvcc >/dev/null && [ -x /usr/local/cuda/bin/nvcc ]; then
    export PATH="/usr/local/cuda/bin:$PATH"
  fi
  command -v nvcc >/dev/null || { echo "device_check: nvcc not found on the PATH" >&2; return 1; }
  command -v cmake >/dev/null || { echo "device_check: cmake not found on the PATH" >&2; return 1; }
  ctest_bin="$(dirname "$(command -v cmake)")/ctest"
  [ -x "$ctest_bin" ] || ctest_bin=$(command -v ctest) \
    || { echo "device_check: ctest not found beside cmake or on the PATH" >&2; return 1; }
  generator="Unix Makefiles"
  command -v ninja >/dev/null && generator="Ninja"
  return 0
}

# Configures and builds ci/device into $build; a build folder left by another source tree is
# started afresh.
build_standalone() {
  local log="$OUT/build.log" t0=$EPOCHREALTIME
  : >"$log"
  if [ -f "$build/CMakeCache.txt" ] &&
     ! grep -qx "CMAKE_HOME_DIRECTORY:INTERNAL=$root/ci/device" "$build/CMakeCache.txt"; then
    rm -rf "$build"
  fi
  if ! bounded "$(limit_for 90)" "$log" cmake -S ci/device -B "$build" -G "$generator" \
         -DCMAKE_CUDA_COMPILER="$(command -v nvcc)" \
         -DHMFNET_CATCH2_INCLUDE_DIR="$prepared/include"; then
    record "configure ($generator)" fail "$(elapsed_since "$t0")" "see build.log"
    return 1
  fi
  if ! bounded "$(limit_for 300)" "$log" cmake --build "$build" --parallel "$(nproc)"; then
    record "build ($generator)" fail "$(elapsed_since "$t0")" "see build.log"
    return 1
  fi
  # Which machine code and PTX the test program carries (sm_90 for the H100 and H200).
  if command -v cuobjdump >/dev/null; then
    cuobjdump --list-elf --list-ptx "$build/bin/hmfnet_gpu_tests" >>"$log" 2>&1 || true
  fi
  record "build ($generator)" pass "$(elapsed_since "$t0")" \
    "$(grep -m1 -o 'architectures .*' "$log" || true)"
}

# shellcheck disable=SC2317  # called through the list checks
# The CTest label gpu, one row per test, as CTest reports it (its skip code 77: no usable device).
check_gpu_label() {
  local log="$OUT/ctest-gpu.log" rc=0 t0=$EPOCHREALTIME line name time why n=0 n_failed=0
  : >"$log"
  (cd "$build" && bounded "$(limit_for 180)" "$log" "$ctest_bin" -L '^gpu$' -V) || rc=$?
  why=$(grep -m1 -o 'skipped: .*' "$log" | cut -c10- || true)
  while IFS= read -r line; do
    n=$((n + 1))
    name=$(awk '{ print $4 }' <<<"$line")
    time=$(grep -o '[0-9.]* sec$' <<<"$line" | cut -d' ' -f1)
    case "$line" in
      *Passed*) record "$name" pass "$time" ;;
      *Skipped*) record "$name" skip "$time" "$why" ;;
      *) n_failed=$((n_failed + 1))
         record "$name" fail "$time" "$(sed -E 's/.*\*\*\*([A-Za-z :]+[A-Za-z]).*/\1/' <<<"$line"), see ctest-gpu.log" ;;
    esac
  done < <(grep -E '^ *[0-9]+/[0-9]+ Test +#[0-9]+: ' "$log" || true)
  if [ "$n" -eq 0 ]; then
    record "ctest -L gpu" fail "$(elapsed_since "$t0")" "no test result, ctest $(exit_text "$rc")"
  elif [ "$rc" -ne 0 ] && [ "$n_failed" -eq 0 ]; then
    record "ctest -L gpu" fail "$(elapsed_since "$t0")" "ctest $(exit_text "$rc")"
  fi
}

# Where the build here failed: the test program that ci/device_prepare.sh built on the CPU
# machine, run directly (exit 0 pass, 77 skip). The build's own failure still fails the check.
check_prebuilt_gpu_tests() {
  local exe="$prepared/bin/hmfnet_gpu_tests" log="$OUT/ctest-gpu.log" rc=0 t0=$EPOCHREALTIME
  [ -x "$exe" ] || { record "gpu tests (prebuilt)" skip 0 "none in build-device/bin"; return 0; }
  bounded "$(limit_for 180)" "$log" "$exe" || rc=$?
  case $rc in
    0) record "gpu tests (prebuilt)" pass "$(elapsed_since "$t0")" "$(head -n 1 "$prepared/PREPARED" 2>/dev/null)" ;;
    77) record "gpu tests (prebuilt)" skip "$(elapsed_since "$t0")" "$(grep -m1 -o 'skipped: .*' "$log" | cut -c10-)" ;;
    *) record "gpu tests (prebuilt)" fail "$(elapsed_since "$t0")" "$(exit_text "$rc"), see ctest-gpu.log" ;;
  esac
}

# shellcheck disable=SC2317  # called through the list checks
# The benchmark table (bench/gpu/ensemble_rates.cpp): rates beside the bounds measured in the
# same run; its table is printed again before the summary.
check_bench() {
  local log="$OUT/runs.log" rc=0 t0=$EPOCHREALTIME
  echo "== hmfnet_gpu_ensemble_rates" >>"$log"
  bounded "$(limit_for 120)" "$log" "$bin_dir/hmfnet_gpu_ensemble_rates" || rc=$?
  case $rc in
    0) record "benchmark table" pass "$(elapsed_since "$t0")" "runs.log" ;;
    77) record "benchmark table" skip "$(elapsed_since "$t0")" "no device" ;;
    *) record "benchmark table" fail "$(elapsed_since "$t0")" "$(exit_text "$rc"), see runs.log" ;;
  esac
}

# shellcheck disable=SC2317  # called through the list checks
# The QSS campaign on K_N (verification/gpu/qss_lifetime_gpu.cpp): its data come back as
# qss_gpu.json and qss_gpu.f64 for paper/scripts/qss_lifetime_gpu.py. Its own wall budget is
# what the check's budget leaves, less 30 s for writing and the table.
check_qss() {
  local log="$OUT/runs.log" rc=0 t0=$EPOCHREALTIME limit budget dir="$build/qss" f
  local resume=()
  limit=$(limit_for "${HMFNET_QSS_LIMIT_S:-260}")
  budget=$((limit - 30))
  [ "$budget" -gt 10 ] || { record "QSS campaign" skip 0 "no time left in the budget"; return 0; }
  # HMFNET_QSS_RESUME: a resume file of an earlier campaign (its --replicas and --lives).
  [ -z "${HMFNET_QSS_RESUME:-}" ] || resume=(--resume "$HMFNET_QSS_RESUME")
  echo "== hmfnet_gpu_qss_lifetime (budget $budget s) ${resume[*]}" >>"$log"
  # The run's folder stays in the build folder: its resume file (up to 10 MB a size) for a later
  # call on the same machine; the records come back through $OUT.
  mkdir -p "$dir"
  rm -f "$dir"/qss_gpu.json "$dir"/qss_gpu.f64
  bounded "$limit" "$log" "$bin_dir/hmfnet_gpu_qss_lifetime" \
    --sizes "${HMFNET_QSS_SIZES:-20000,10000,5000,2000,1600,1000}" --replicas 32 \
    --lives "${HMFNET_QSS_LIVES:-3}" --batch "${HMFNET_QSS_BATCH:-4}" \
    --state "${HMFNET_QSS_STATE:-global}" \
    --budget-s "$budget" --out "$dir" "${resume[@]}" || rc=$?
  for f in qss_gpu.json qss_gpu.f64; do [ ! -f "$dir/$f" ] || cp "$dir/$f" "$OUT/"; done
  [ ! -f "$dir/qss_gpu_resume.bin" ] || echo "resume file: $dir/qss_gpu_resume.bin" >>"$log"
  case $rc in
    0) record "QSS campaign" pass "$(elapsed_since "$t0")" "qss_gpu.json, qss_gpu.f64" ;;
    77) record "QSS campaign" skip "$(elapsed_since "$t0")" "no device" ;;
    *) record "QSS campaign" fail "$(elapsed_since "$t0")" "$(exit_text "$rc"), see runs.log" ;;
  esac
}

# shellcheck disable=SC2317  # called through the list checks
# The campaign's resume (qss_resume_file.hpp): N = 1000 stopped after 3 launches and resumed
# from its qss_gpu_resume.bin must write the records of the same run uninterrupted, bit for bit;
# resumed with the state in shared memory (--state shared) too.
check_qss_resume() {
  local log="$OUT/runs.log" rc=0 t0=$EPOCHREALTIME dir="$build/qss-resume"
  local run=("$bin_dir/hmfnet_gpu_qss_lifetime" --sizes 1000 --replicas 8 --lives 0.3 --chunk 2000)
  rm -rf "$dir" && mkdir -p "$dir/whole" "$dir/first" "$dir/rest" "$dir/shared"
  echo "== QSS resume: N = 1000, 8 replicas, stopped after 3 launches, resumed" >>"$log"
  bounded "$(limit_for 30)" "$log" "${run[@]}" --out "$dir/whole" || rc=$?
  [ "$rc" -ne 0 ] || bounded "$(limit_for 30)" "$log" "${run[@]}" --chunks 3 --out "$dir/first" || rc=$?
  [ "$rc" -ne 0 ] || bounded "$(limit_for 30)" "$log" "${run[@]}" \
    --resume "$dir/first/qss_gpu_resume.bin" --out "$dir/rest" || rc=$?
  [ "$rc" -ne 0 ] || bounded "$(limit_for 30)" "$log" "${run[@]}" --state shared \
    --resume "$dir/first/qss_gpu_resume.bin" --out "$dir/shared" || rc=$?
  if [ "$rc" -eq 77 ]; then
    record "QSS resume" skip "$(elapsed_since "$t0")" "no device"
  elif [ "$rc" -ne 0 ]; then
    record "QSS resume" fail "$(elapsed_since "$t0")" "$(exit_text "$rc"), see runs.log"
  elif [ -f "$dir/rest/qss_gpu_resume.bin" ] || [ ! -f "$dir/first/qss_gpu_resume.bin" ]; then
    record "QSS resume" fail "$(elapsed_since "$t0")" "resume file where none belongs, or none where one does"
  elif ! cmp "$dir/whole/qss_gpu.f64" "$dir/shared/qss_gpu.f64" >>"$log" 2>&1; then
    record "QSS resume" fail "$(elapsed_since "$t0")" "records resumed in shared memory differ from the uninterrupted run's"
  elif cmp "$dir/whole/qss_gpu.f64" "$dir/rest/qss_gpu.f64" >>"$log" 2>&1; then
    record "QSS resume" pass "$(elapsed_since "$t0")" "records equal to the uninterrupted run's (global and shared)"
  else
    record "QSS resume" fail "$(elapsed_since "$t0")" "records differ from the uninterrupted run's"
  fi
}

# shellcheck disable=SC2317  # called through the list checks
# `hmfnet simulate --device cuda` end to end (ci/device_simulate.py): the CLI built on the CPU
# machine, packed with its libraries by ci/device_pack_cli.sh, against `--device cpu` here.
check_simulate() {
  local log="$OUT/simulate.log" rc=0 t0=$EPOCHREALTIME pack="$prepared/hmfnet-cli.tar.xz"
  local dir="$build/cli"
  [ -f "$pack" ] || { record "simulate --device cuda" skip 0 "no $pack (ci/device_prepare.sh)"; return 0; }
  rm -rf "$dir" && mkdir -p "$dir"
  tar -xJf "$pack" -C "$dir" || { record "simulate --device cuda" fail "$(elapsed_since "$t0")" "cannot unpack $pack"; return 0; }
  # The pack's newest glibc symbol against this machine's glibc.
  { echo "pack needs $(cat "$dir/GLIBC_REQUIRED" 2>/dev/null); this machine: $(ldd --version 2>&1 | head -n 1)"; } >>"$log"
  bounded "$(limit_for 150)" "$log" python3 "$root/ci/device_simulate.py" "$dir" "$build/cli-work" || rc=$?
  case $rc in
    0) record "simulate --device cuda" pass "$(elapsed_since "$t0")" "$(tail -n 1 "$log")" ;;
    *) record "simulate --device cuda" fail "$(elapsed_since "$t0")" "$(exit_text "$rc"): $(tail -n 1 "$log")" ;;
  esac
}

# Whether the word $1 is one of the space-separated words $2.
one_of() { [[ " $2 " == *" $1 "* ]]; }

all_checks="check_gpu_label check_simulate check_bench check_qss_resume check_qss"
read -r -a checks <<<"${HMFNET_DEVICE_CHECKS:-$all_checks}"
for c in "${checks[@]}"; do
  one_of "$c" "$all_checks" || { echo "device_check: unknown check '$c' in HMFNET_DEVICE_CHECKS (known: $all_checks)" >&2; exit 2; }
done

echo "== device"
show_device
echo "== build ($build)"
bin_dir="$build/bin"
if find_tools && build_standalone; then
  for c in "${checks[@]}"; do
    echo "== $c"
    "$c" || record "$c" fail - "the check stopped with exit $?"
  done
else
  [ "${#rows[@]}" -gt 0 ] || record "tools (nvcc, cmake, ctest)" fail 0 "see the line above"
  echo "== build failed: see $OUT/build.log"
  tail -n 30 "$OUT/build.log" 2>/dev/null || true
  # The checks asked for, with what was prepared on the CPU machine, where it was built.
  wanted() { one_of "$1" "${checks[*]}"; }
  ! wanted check_gpu_label || check_prebuilt_gpu_tests
  ! wanted check_simulate || check_simulate || record check_simulate fail - "exit $?"
  bin_dir="$prepared/bin"
  if [ -x "$bin_dir/hmfnet_gpu_ensemble_rates" ] && wanted check_bench; then
    check_bench || record check_bench fail - "exit $?"
  fi
  if [ -x "$bin_dir/hmfnet_gpu_qss_lifetime" ]; then
    ! wanted check_qss_resume || check_qss_resume || record check_qss_resume fail - "exit $?"
    ! wanted check_qss || check_qss || record check_qss fail - "exit $?"
  fi
fi

[ -f "$OUT/simulate.log" ] && { echo; grep -E '^(pass|FAIL) ' "$OUT/simulate.log" || true; }
if [ -f "$OUT/runs.log" ]; then
  echo
  grep -A 20 -E '^kind +prec' "$OUT/runs.log" | grep -v '^==' || true
  grep -E '^(N = |wall )' "$OUT/runs.log" || true
fi
{
  echo
  echo "== device check on: $device_name"
  printf '%-34s %-5s %8s  %s\n' check result "wall s" note
  printf '%s\n' "${rows[@]}"
  printf '%-34s %-5s %8s\n' total "" "$(elapsed_since "$t_start")"
  echo "logs: $OUT"
} | tee "$OUT/summary.txt"
exit "$failed"
