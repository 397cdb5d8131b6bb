#!/usr/bin/env bash
# Reproduce the numbers in docs/chung_lu_table2.md: which Chung-Lu link-probability variant
# comes closest to the paper's Table II (scale-free networks, N = 10^4, target mean degree 100).
#
# Usage: docs/scripts/chung_lu_table2.sh HMFNET_BINARY [NSEEDS (default 5)] [JOBS (default 2)]
#   KEEP=1 keeps the temporary folder with the JSON lines (runs.jsonl, rewire.jsonl).
# Needs bash, xargs, python3 (standard library only). About 4 minutes on 2 cores.
set -euo pipefail

source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
script_binary "$0 HMFNET_BINARY [NSEEDS] [JOBS]" "${1:-}"
NSEEDS=${2:-5}
JOBS=${3:-2}
N=10000
MEAN=100
export HMF N MEAN

script_tmp chung_lu_table2
export TMP
mkdir -p "$TMP/runs" "$TMP/nets" "$TMP/rewire"

# Generate one network and append its spectrum as a JSON line. d is the continuum d_min for mean
# 100 without cutoff, D (alpha-2)/(alpha-1): 33.3, 44.4, 52.4, 60, 64.3 -- the paper's Table II
# values. The cutoff variants keep these d_min (as the paper's table does);
# "capped_cut1000_resolved" instead re-solves d_min for mean 100 under the cutoff.
run_one() {
  local variant=$1 alpha=$2 seed=$3
  local d; d=$(python3 -c "import sys; a=float(sys.argv[1]); print(repr($MEAN*(a-2)/(a-1)))" "$alpha")
  local flags
  case $variant in
    capped)                  flags="--link capped  --mean-degree $MEAN" ;;
    poisson)                 flags="--link poisson --mean-degree $MEAN" ;;
    odds)                    flags="--link odds    --mean-degree $MEAN" ;;
    capped_cut1000)          flags="--link capped  --dmin $d --cutoff 1000" ;;
    capped_cutN-1)           flags="--link capped  --dmin $d --cutoff $((N - 1))" ;;
    capped_cut1000_resolved) flags="--link capped  --mean-degree $MEAN --cutoff 1000" ;;
    *) echo "unknown variant $variant" >&2; return 1 ;;
  esac
  local net="$TMP/nets/${variant}_${alpha}_${seed}.h5"
  # shellcheck disable=SC2086
  "$HMF" generate sf --n "$N" --alpha "$alpha" $flags --seed "$seed" -o "$net" 2>/dev/null
  local spec; spec=$("$HMF" spectrum "$net" --json)
  printf '{"variant":"%s","alpha":%s,"seed":%s,"flags":"%s","spectrum":%s}\n' \
    "$variant" "$alpha" "$seed" "$flags" "$spec" > "$TMP/runs/${variant}_${alpha}_${seed}.json"
  # Keep the alpha = 2.5 networks of the rewiring bases (capped, capped_cutN-1, capped_cut1000).
  case "$variant/$alpha" in capped/2.5|capped_cutN-1/2.5|capped_cut1000/2.5) ;; *) rm -f "$net" ;; esac
}
export -f run_one

# Rewire the alpha = 2.5 network of variant $1 and seed $2 to target rho $3 with
# max attempts $4 (0: the default 200 x edges; rewiring seed always 1). On failure the CLI writes no file, so the
# network at (just below) the plateau is produced by a second run to a target 0.002 below the
# rho reached, to measure lambda there.
rewire_one() {
  local base=$1 seed=$2 target=$3 attempts=$4
  local tag="${base}_${seed}_${target}_${attempts}"
  local in="$TMP/nets/${base}_2.5_${seed}.h5" out="$TMP/rewire/r_${tag}.h5"
  local log="$TMP/rewire/r_${tag}.log" rc=0
  "$HMF" rewire "$in" --target-rho "$target" --seed 1 --max-attempts "$attempts" -o "$out" \
    2> "$log" || rc=$?
  local reached_file="$out" plateau_target=null
  if [[ $rc -ne 0 ]]; then
    local reached
    reached=$(python3 -c "import re,sys; m=re.search(r'reached rho = ([0-9.eE+-]+)', open(sys.argv[1]).read()); print(m.group(1) if m else '')" "$log")
    if [[ -n $reached ]]; then
      plateau_target=$(python3 -c "import sys; print(round(float(sys.argv[1]) - 0.002, 4))" "$reached")
      reached_file="$TMP/rewire/p_${tag}.h5"
      "$HMF" rewire "$in" --target-rho "$plateau_target" --seed 1 -o "$reached_file" 2>/dev/null
    fi
  fi
  local spec=null
  [[ -f $reached_file ]] && spec=$("$HMF" spectrum "$reached_file" --json)
  local msg; msg=$(python3 -c "import json,sys; print(json.dumps(open(sys.argv[1]).read().strip()))" "$log")
  printf '{"base":"%s","seed":%s,"target":%s,"max_attempts":%s,"rc":%s,"plateau_target":%s,"message":%s,"spectrum":%s}\n' \
    "$base" "$seed" "$target" "$attempts" "$rc" "$plateau_target" "$msg" "$spec" > "${log%.log}.json"
  rm -f "$out" "$reached_file"
}
export -f rewire_one

start=$(date +%s)
# 1. Generation grid: 6 variants x 5 alphas x NSEEDS seeds.
for v in capped poisson odds capped_cut1000 capped_cutN-1 capped_cut1000_resolved; do
  for a in 2.5 2.8 3.1 3.5 3.8; do
    for s in $(seq 1 "$NSEEDS"); do echo "$v $a $s"; done
  done
done | xargs -P "$JOBS" -n 3 bash -c 'run_one "$@"' _
cat "$TMP"/runs/*.json > "$TMP/runs.jsonl"

# 2. Rewiring from the alpha = 2.5 networks (d_min 33.3) of the capped variant (the one asked
#    for) and, for comparison, of capped_cutN-1 and capped_cut1000: targets 0.97 and 1.09 with the
#    default budget (200 x edges attempts); plus one capped run with 10x that budget to check that
#    the stall is a plateau and not a budget limit.
{
  echo "capped 1 0.97 $((200 * 10 * 451644))"   # 10 x 200 x edges of capped seed 1; longest job first
  for b in capped capped_cutN-1 capped_cut1000; do
    for s in $(seq 1 "$NSEEDS"); do for t in 0.97 1.09; do echo "$b $s $t 0"; done; done
  done
} | xargs -P "$JOBS" -n 4 bash -c 'rewire_one "$@"' _
cat "$TMP"/rewire/*.json > "$TMP/rewire.jsonl"
echo "# elapsed $(( $(date +%s) - start )) s" >&2

# 3. Summary (Markdown) on stdout.
python3 - "$TMP/runs.jsonl" "$TMP/rewire.jsonl" <<'PY'
import json, statistics, sys
from collections import defaultdict

PAPER = {2.5: (33, 299, 0.52), 2.8: (44, 243, 0.81), 3.1: (52, 201, 0.84),
         3.5: (60, 162, 0.93), 3.8: (64, 140, 0.99)}
VARIANTS = ["capped", "poisson", "odds", "capped_cut1000", "capped_cutN-1",
            "capped_cut1000_resolved"]

def ms(xs):
    m = statistics.fmean(xs)
    s = statistics.stdev(xs) if len(xs) > 1 else 0.0
    return m, s

def dmin_for_mean(alpha, mean, cutoff=float("inf")):
    def pl_mean(d):
        x = 0.0 if cutoff == float("inf") else d / cutoff
        return d * (alpha - 1) / (alpha - 2) * (1 - x ** (alpha - 2)) / (1 - x ** (alpha - 1))
    lo, hi = 1e-9, mean
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if pl_mean(mid) < mean else (lo, mid)
    return 0.5 * (lo + hi)

runs = defaultdict(list)
for line in open(sys.argv[1]):
    r = json.loads(line)
    runs[(r["variant"], r["alpha"])].append(r["spectrum"])

print("## Generated networks (mean +- sd over %d seeds)\n" % len(next(iter(runs.values()))))
print("dlambda, drho: (mean - paper) / paper. z: (mean - paper) / sd, i.e. how many seed-to-seed\n"
      "standard deviations the paper's single network lies from our mean.\n")
print("| variant | alpha | d_min | mean degree | max degree | lambda | rho | "
      "dlambda | z lambda | drho | z rho |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
score = {}
for v in VARIANTS:
    errs_l, errs_r, zs_l, zs_r = [], [], [], []
    for a in sorted(PAPER):
        rs = runs[(v, a)]
        d_paper, l_paper, r_paper = PAPER[a]
        md = ms([r["mean_degree"] for r in rs])
        mx = ms([r["max_degree"] for r in rs])
        lam = ms([r["lambda"] for r in rs])
        rho = ms([r["rho"] for r in rs])
        dl = (lam[0] - l_paper) / l_paper
        dr = (rho[0] - r_paper) / r_paper
        zl = (lam[0] - l_paper) / lam[1] if lam[1] > 0 else float("nan")
        zr = (rho[0] - r_paper) / rho[1] if rho[1] > 0 else float("nan")
        errs_l.append(abs(dl)); errs_r.append(abs(dr)); zs_l.append(abs(zl)); zs_r.append(abs(zr))
        dm = dmin_for_mean(a, 100, 1000) if v == "capped_cut1000_resolved" else dmin_for_mean(a, 100)
        print(f"| {v} | {a} | {dm:.1f} | {md[0]:.1f} ± {md[1]:.1f} | {mx[0]:.0f} ± {mx[1]:.0f} | "
              f"{lam[0]:.1f} ± {lam[1]:.1f} | {rho[0]:.3f} ± {rho[1]:.3f} | "
              f"{100*dl:+.1f}% | {zl:+.1f} | {100*dr:+.1f}% | {zr:+.1f} |")
    score[v] = (statistics.fmean(errs_l), max(errs_l), max(zs_l),
                statistics.fmean(errs_r), max(errs_r), max(zs_r))

print("\n## Distance from the paper per variant (over the 5 alphas, using seed means)\n")
print("| variant | mean abs dlambda | max abs dlambda | max abs z lambda | "
      "mean abs drho | max abs drho | max abs z rho |")
print("|---|---|---|---|---|---|---|")
for v in sorted(VARIANTS, key=lambda v: score[v][0]):
    s = score[v]
    print(f"| {v} | {100*s[0]:.1f}% | {100*s[1]:.1f}% | {s[2]:.1f} | "
          f"{100*s[3]:.1f}% | {100*s[4]:.1f}% | {s[5]:.1f} |")

print("\n## Rewiring from the alpha = 2.5 networks (d_min 33.3); paper: start rho 0.78 "
      "(lambda 282), then rho 0.97 -> lambda 364, rho 1.09 -> lambda 459\n")
print("| base variant | seed | start rho | start lambda | target rho | max attempts | reached? | "
      "rho reached | attempts | swaps | lambda at end (rho of that network) |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
import re
start = {}
for line in open(sys.argv[1]):
    r = json.loads(line)
    if r["alpha"] == 2.5:
        start[(r["variant"], r["seed"])] = r["spectrum"]
rows = [json.loads(l) for l in open(sys.argv[2])]
order = {"capped": 0, "capped_cutN-1": 1, "capped_cut1000": 2}
rows.sort(key=lambda r: (order[r["base"]], r["max_attempts"], r["seed"], r["target"]))
for r in rows:
    msg = r["message"]
    ok = r["rc"] == 0
    m_ok = re.search(r"-> ([0-9.eE+-]+) \((\d+) swaps in (\d+) attempts", msg)
    m_no = re.search(r"reached rho = ([0-9.eE+-]+) after (\d+) attempts \((\d+) swaps\)", msg)
    if ok and m_ok:
        rho_r, swaps, att = m_ok.group(1), m_ok.group(2), m_ok.group(3)
    elif m_no:
        rho_r, att, swaps = m_no.group(1), m_no.group(2), m_no.group(3)
    else:
        rho_r = att = swaps = "?"
    sp = r["spectrum"]
    lam = "n/a" if sp is None else f"{sp['lambda']:.1f} ({sp['rho']:.3f})"
    if not ok and sp is not None:
        lam += " [rerun to %s]" % r["plateau_target"]
    st = start[(r["base"], r["seed"])]
    budget = "200 x edges" if r["max_attempts"] == 0 else f"{r['max_attempts']:.3g}"
    print(f"| {r['base']} | {r['seed']} | {st['rho']:.3f} | {st['lambda']:.1f} | {r['target']} | "
          f"{budget} | {'yes' if ok else 'no'} | {float(rho_r):.4f} | {att} | {swaps} | {lam} |")
PY
