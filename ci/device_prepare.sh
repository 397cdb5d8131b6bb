#!/usr/bin/env bash
# Prepares the device check on a machine with nvcc and Catch2 (no GPU needed), so that a session
# with a GPU machine spends its time only running ci/device_check.sh there:
#   1. fills build-device/ (ignored by git) with what the GPU machine lacks: Catch2's single
#      header, and the gpu test program built here, which the check runs only if its own build
#      there fails;
#   2. runs ci/device_check.sh here: the standalone project ci/device must configure and build
#      with nvcc, and the gpu tests must report skip (exit 77) where there is no device;
#   3. packs the CLI of the main build (build/bin/hmfnet, built with the CUDA backend) with its
#      shared libraries into build-device/hmfnet-cli.tar.xz (ci/device_pack_cli.sh) for the
#      check's end-to-end `simulate --device cuda`, and tries the pack here (it must load and
#      refuse --device cuda for want of a device);
#   4. prints the size of what travels (the working tree and build-device/, 64 MiB at most) and
#      the device tool's call.
# Rerun it after changing the CUDA sources, the gpu tests, their Catch2 runner (tests/support/
# catch_session.*) or ci/device.
#
#   bash ci/device_prepare.sh     (where several builds share the cores: under flock, as any build)
#
# Environment: HMFNET_CATCH2_HEADER (Catch2 2.x's single header, /usr/include/catch2/catch.hpp),
# HMFNET_DEVICE_BUILD (scratch build folder, /tmp/hmfnet-device-prepare; its logs go beside it),
# HMFNET_CLI_BUILD (the main build whose bin/hmfnet is packed, ./build).
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
die() { echo "device_prepare: $*" >&2; exit 1; }

header="${HMFNET_CATCH2_HEADER:-/usr/include/catch2/catch.hpp}"
scratch="${HMFNET_DEVICE_BUILD:-/tmp/hmfnet-device-prepare}"
logs="$scratch-out"
travel_limit=$((64 * 1024 * 1024))

# 1. build-device/: the header now, the program once it is built and has skipped.
[ -f "$header" ] || die "no Catch2 header at $header (Debian: apt-get install catch2, or set HMFNET_CATCH2_HEADER)"
grep -q 'Catch v2\.' "$header" || die "$header is not Catch2 2.x's single header, which tests/gpu includes as <catch2/catch.hpp>"
git check-ignore -q build-device/ || die "build-device/ is not ignored by git (.gitignore): it would travel twice"
rm -rf build-device
mkdir -p build-device/include/catch2 build-device/bin
cp "$header" build-device/include/catch2/catch.hpp

# 2. The device check itself, here.
rm -rf "$logs"
rc=0
OUT="$logs" HMFNET_DEVICE_BUILD="$scratch" bash ci/device_check.sh || rc=$?
[ "$rc" -eq 0 ] || die "ci/device_check.sh failed here (exit $rc): its logs are in $logs"
exe="$scratch/bin/hmfnet_gpu_tests"
expected=77
if command -v nvidia-smi >/dev/null && nvidia-smi -L >/dev/null 2>&1; then expected=0; fi
rc=0
"$exe" >"$logs/gpu-tests-direct.log" 2>&1 || rc=$?
[ "$rc" -eq "$expected" ] || die "$exe exited $rc here, expected $expected (see $logs/gpu-tests-direct.log)"
cp "$exe" "$scratch/bin/hmfnet_gpu_ensemble_rates" "$scratch/bin/hmfnet_gpu_qss_lifetime" build-device/bin/
changed=""
[ -z "$(git status --porcelain -- src tests/gpu tests/support ci/device cmake)" ] || changed=" with uncommitted changes"
printf 'built on %s from %s%s (nvcc %s; %s)\n' "$(date -u +%F)" "$(git rev-parse --short HEAD)" \
  "$changed" "$(nvcc --version | grep -o 'V[0-9.]*' | tail -n 1)" "$(c++ --version | head -n 1)" \
  >build-device/PREPARED

# 3. The CLI, packed and tried.
cli_build="${HMFNET_CLI_BUILD:-$root/build}"
if [ -x "$cli_build/bin/hmfnet" ] && grep -q '^HMFNET_CUDA:BOOL=ON' "$cli_build/CMakeCache.txt"; then
  bash ci/device_pack_cli.sh "$cli_build/bin/hmfnet" build-device/hmfnet-cli.tar.xz
  try="$scratch/cli-try"
  rm -rf "$try" && mkdir -p "$try" && tar -xJf build-device/hmfnet-cli.tar.xz -C "$try"
  "$try/run" hmfnet generate er --n 200 --q 0.1 --seed 1 --output "$try/net.h5" >/dev/null
  refusal=$("$try/run" hmfnet simulate "$try/net.h5" --K 1 --seed 1 --T 2 --transient 1 \
    --device cuda 2>&1 || true)
  if [ "$expected" -eq 77 ]; then
    grep -q -- '--device cuda: .*run it with --device cpu' <<<"$refusal" \
      || die "the packed CLI did not refuse --device cuda here as expected: $refusal"
  fi
  # The check's end-to-end script with the CPU in the device's place, on small networks, under a
  # Python with h5py (the device's has it; here it may be Debian's beside another on the PATH).
  python=python3
  python3 -c 'import h5py' 2>/dev/null || python=/usr/bin/python3
  HMFNET_SIMULATE_DEVICE=cpu HMFNET_SIMULATE_SMALL=1 "$python" ci/device_simulate.py "$try" \
    "$try/work" >"$logs/simulate-try.log" 2>&1 \
    || die "ci/device_simulate.py failed here with the CPU in the device's place: $logs/simulate-try.log"
  echo "packed CLI tried: $(tail -n 1 "$logs/simulate-try.log"); needs $(cat "$try/GLIBC_REQUIRED")"
else
  echo "device_prepare: no $cli_build/bin/hmfnet built with HMFNET_CUDA=ON: the check's simulate --device cuda will skip" >&2
fi

# 4. What travels: tracked and untracked files that git does not ignore, and build-device.
tree_bytes=$(git ls-files -co --exclude-standard -z | python3 -c '
import os, sys
names = [n for n in sys.stdin.buffer.read().split(b"\0") if n]
print(sum(os.lstat(n).st_size for n in names if os.path.lexists(n)))')
carry_bytes=$(du -sb build-device | cut -f1)
total=$((tree_bytes + carry_bytes))
mib() { awk -v b="$1" 'BEGIN { printf "%.1f MiB", b / 1048576 }'; }
echo
echo "What travels: working tree $(mib "$tree_bytes") + build-device $(mib "$carry_bytes") = $(mib "$total") (limit 64 MiB)"
[ "$total" -le "$travel_limit" ] || die "what travels is over 64 MiB: ignore or remove large untracked files first"
cat <<'EOF'
The device call (the device tool's run; the check keeps to 450 s and prints its table last):
  {"command": "bash ci/device_check.sh", "carry": ["build-device"], "timeout_s": 480}
EOF
