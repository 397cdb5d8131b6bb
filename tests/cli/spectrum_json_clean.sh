#!/usr/bin/env bash
# `hmfnet spectrum --json` prints exactly one JSON object even when Anasazi fails internally: on a
# star (three distinct eigenvalues) Krylov-Schur fails to find a second pair, and Anasazi used to
# print its exception to stdout, corrupting the JSON. lambda2 is then absent (unknown) and the
# star is reported as bipartite.
# Usage: spectrum_json_clean.sh HMFNET OUTDIR
set -euo pipefail
hmfnet=$1 out=$2
net="$out/star_2000.txt"
seq 2 2000 | awk '{print 1, $1}' > "$net"
"$hmfnet" spectrum "$net" --index-base 1 --json > "$out/star.json"
python3 - "$out/star.json" <<'PY'
import json, math, sys
text = open(sys.argv[1]).read()
assert text.count("\n") == 1, f"expected one line of JSON, got:\n{text}"
d = json.loads(text)
# The star's lambda is sqrt(N - 1) exactly. Tolerance: the eigensolver stops at a residual
# ||A u - lambda u|| <= 1e-10 lambda (spectral/perron.hpp), and for a symmetric A the Rayleigh
# quotient's error is at most residual^2 / gap (gap = lambda here: the other eigenvalues are 0 and
# -lambda), i.e. ~1e-20 relative; 1e-9 leaves room for the residual test being relative to a
# norm estimate, not for a different answer.
assert abs(d["lambda"] - math.sqrt(1999)) < 1e-9 * d["lambda"], d["lambda"]
assert "lambda2" not in d or d["lambda2"] < d["lambda"], d
assert any("bipartite" in w for w in d["warnings"]), d["warnings"]
print("spectrum --json on a star: one clean object; lambda2", d.get("lambda2", "not found"))
PY
