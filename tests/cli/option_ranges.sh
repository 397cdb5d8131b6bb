#!/usr/bin/env bash
# Runs the rows of tests/cli/option_ranges.txt for one subcommand: each bad option value must be
# refused as expect_failure.sh defines (non-zero exit below 128, one stderr line naming the
# option and the allowed range, no output file left). Then checks coverage: every option that
# `hmfnet SUBCOMMAND --help` lists with a value (and the positional input) has at least one row.
# Usage: option_ranges.sh HMFNET TABLE SCRATCH_DIR SUBCOMMAND...
#   e.g. option_ranges.sh build/bin/hmfnet tests/cli/option_ranges.txt /tmp/x generate er
set -u
hmfnet="$1"
table="$2"
scratch="$3"
shift 3
sub="$*"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
out="$scratch/option_ranges_${sub// /_}"
rm -rf "$out"
mkdir -p "$out"

# A valid network for the commands that read one (N = 200: --rotor-node 200 is out of range).
net="$out/net.mtx"
"$hmfnet" generate er --n 200 --q 0.1 --seed 1 --output "$net" 2> "$out/generate.log" ||
  { cat "$out/generate.log"; echo "option_ranges.sh: cannot generate the test network" >&2; exit 1; }

# The valid arguments each case starts from ("input" is the positional file), and the groups of
# options that exclude each other: a case on one member drops the others from the base.
declare -A base=(
  ["generate er"]="--n 50 --q 0.1 --seed 1 --output $out/er.mtx"
  ["generate sf"]="--n 100 --alpha 2.5 --dmin 3 --seed 1 --output $out/sf.mtx"
  ["generate sbm"]="--half 30 --p-in 0.2 --p-out 0.05 --seed 1 --output $out/sbm.mtx"
  ["generate complete"]="--n 50 --output $out/k.h5"
  ["generate regular"]="--n 51 --degree 4 --seed 1 --output $out/rr.mtx"
  ["rewire"]="input $net --target-rho 1.1 --seed 1 --output $out/rewired.mtx"
  ["convert"]="input $net --output $out/converted.h5"
  ["spectrum"]="input $net"
  ["theory"]="input $net --sigma0 0.35 --K-over-Kc 2"
  ["simulate"]="input $net --K 1 --seed 1 --T 10 --transient 1 --node-data --integrator rk4 --output $out/sim.h5"
  ["demo"]=""
)
declare -A group=(
  ["generate er"]="--q --mean-degree"
  ["generate sf"]="--dmin --mean-degree"
  ["theory"]="--K --K-over-Kc"
  ["simulate"]="--K --K-over-Kc --K-sweep"
)
if [[ -z "${base[$sub]+set}" ]]; then
  echo "option_ranges.sh: no base arguments for subcommand '$sub'" >&2
  exit 2
fi

# The arguments of one case: the base with OPTION set to VALUE (replacing the base's value, or
# added), the other members of OPTION's exclusion group dropped. Flags (no value) are kept.
case_args() {
  local option="$1" value="$2"
  local -a tokens=(${base[$sub]})
  local drop=" "
  local g=" ${group[$sub]:-} "
  [[ "$g" == *" $option "* ]] && drop="$g"
  args=()
  local found=0 i=0
  while [[ $i -lt ${#tokens[@]} ]]; do
    local t="${tokens[$i]}"
    local next="${tokens[$((i + 1))]:-}"
    if [[ "$t" == input ]]; then
      if [[ "$option" == input ]]; then args+=("$value"); found=1; else args+=("$next"); fi
      i=$((i + 2))
    elif [[ "$t" == --* && -n "$next" && "$next" != --* ]]; then
      if [[ "$t" == "$option" ]]; then
        args+=("$t" "$value"); found=1
      elif [[ "$drop" != *" $t "* ]]; then
        args+=("$t" "$next")
      fi
      i=$((i + 2))
    else
      args+=("$t")
      i=$((i + 1))
    fi
  done
  [[ $found -eq 1 ]] || args+=("$option" "$value")
}

failures=0
cases=0
declare -A covered=()
while IFS='|' read -r c_sub c_option c_value c_text; do
  c_sub="$(echo "$c_sub" | xargs)"
  [[ -z "$c_sub" || "$c_sub" == \#* || "$c_sub" != "$sub" ]] && continue
  c_option="$(echo "$c_option" | xargs)"
  c_value="$(echo "$c_value" | xargs)"
  c_text="$(echo "$c_text" | sed -e 's/^ *//' -e 's/ *$//')"
  c_value="${c_value//OUT/$out/bad}"
  c_value="${c_value//DIR/$out/no_such_dir}"
  c_value="${c_value//MISSING/$out/missing.mtx}"
  c_text="${c_text//MISSING/$out/missing.mtx}"
  covered["$c_option"]=1
  case_args "$c_option" "$c_value"
  # The file the command would write: it must not exist after the refusal.
  output=""
  for ((i = 0; i < ${#args[@]}; ++i)); do
    [[ "${args[$i]}" == --output ]] && output="${args[$((i + 1))]}"
  done
  cases=$((cases + 1))
  if ! bash "$here/expect_failure.sh" ${output:+--output "$output"} --contains "hmfnet: error: " \
      --contains "$c_text" -- "$hmfnet" $sub "${args[@]}" > "$out/case.log" 2>&1; then
    failures=$((failures + 1))
    echo "FAIL: $sub $c_option $c_value"
    sed 's/^/  /' "$out/case.log"
  else
    echo "ok: $sub $c_option $c_value -> $(grep -A1 '^stderr:' "$out/case.log" | tail -n 1)"
  fi
done < "$table"

# Coverage: the options --help lists with a value type, long names; plus the positional input.
mapfile -t listed < <("$hmfnet" $sub --help |
  sed -n -E 's/^ +(-[A-Za-z],)?(--[A-Za-z0-9-]+) (TEXT|FLOAT|INT|UINT).*/\2/p; s/^ +input TEXT.*/input/p')
if [[ ${#listed[@]} -eq 0 ]]; then
  echo "FAIL: could not read the options of '$sub --help'"
  failures=$((failures + 1))
fi
for option in "${listed[@]}"; do
  if [[ -z "${covered[$option]+set}" ]]; then
    echo "FAIL: '$sub $option' has no row in $table"
    failures=$((failures + 1))
  fi
done
echo "$sub: $cases cases, ${#listed[@]} options listed by --help, $failures failures"
[[ $failures -eq 0 ]]
