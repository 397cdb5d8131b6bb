#!/usr/bin/env bash
# Installs the build into a fresh prefix and uses it as a user would: a C++ project that calls
# find_package(hmfnet) and links hmfnet::hmfnet, the installed CLI, and the installed Python
# module. The consumer's lambda and K_c must equal the installed CLI's for the same network.
#   install_and_consume.sh BUILD_DIR WORK_DIR
set -euo pipefail
build="$1"
work="$2"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
rm -rf "$work" && mkdir -p "$work"
prefix="$work/prefix"
cmake --install "$build" --prefix "$prefix" > "$work/install.log"
test -x "$prefix/bin/hmfnet" && test -f "$prefix/lib/cmake/hmfnet/hmfnetConfig.cmake"

cmake -S "$here/consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_BUILD_TYPE=Release > "$work/consumer.log" 2>&1 || { cat "$work/consumer.log"; exit 1; }
cmake --build "$work/consumer" >> "$work/consumer.log" 2>&1 || { cat "$work/consumer.log"; exit 1; }
read -r lambda kc < <("$work/consumer/consumer")

# The installed CLI runs from anywhere (its RPATH finds the installed provenance library).
(cd "$work" && "$prefix/bin/hmfnet" generate er --n 500 --mean-degree 10 --seed 3 -o er.h5 2> /dev/null)
cli_json="$(cd "$work" && "$prefix/bin/hmfnet" spectrum er.h5 --json --sigma0 0.35)"

# The installed Python module, not the build tree's: its path must be under the prefix.
PYTHONPATH="$prefix/lib/python3/dist-packages" /usr/bin/python3 - "$prefix" "$lambda" "$kc" "$cli_json" <<'PY'
import json, sys
prefix, lam, kc, cli = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), json.loads(sys.argv[4])
import hmfnet
assert hmfnet.__file__.startswith(prefix), hmfnet.__file__
py = hmfnet.spectrum(hmfnet.generate.er(500, mean_degree=10, seed=3), sigma0=0.35)
# Anasazi converges to a relative residual of 1e-10 on every side (spectrum's extra lambda_2
# request changes the Krylov run), so lambda agrees to ~1e-10, not to the last bit.
for name, a, b in [("consumer lambda", lam, cli["lambda"]), ("consumer Kc", kc, cli["Kc"]),
                   ("python lambda", py["lambda"], cli["lambda"])]:
    assert abs(a - b) <= 1e-9 * abs(b), (name, a, b)
print(f"consumer lambda {lam:.12g}, CLI {cli['lambda']:.12g}, Python {py['lambda']:.12g}: agree")
PY
