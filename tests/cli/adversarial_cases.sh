#!/usr/bin/env bash
# Runs the rows of tests/cli/adversarial_cases.txt: after an optional set-up command (which must
# succeed), each command must be refused as expect_failure.sh defines, and every file the scratch
# folder held before the command (the input networks, their links, a checkpoint) must be byte for
# byte unchanged afterwards, with no file added beside them.
# Usage: adversarial_cases.sh HMFNET TABLE SCRATCH_DIR
set -u
hmfnet="$1"
table="$2"
out="$3/adversarial_cases"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
rm -rf "$out" && mkdir -p "$out"

fresh_inputs() {
  rm -rf "$out/files" && mkdir -p "$out/files"
  local d="$out/files"
  "$hmfnet" generate er --n 100 --mean-degree 6 --seed 1 -o "$d/net.h5" 2> /dev/null &&
    "$hmfnet" generate er --n 100 --mean-degree 6 --seed 1 -o "$d/net.mtx" 2> /dev/null &&
    "$hmfnet" generate regular --n 2000 --degree 10 --seed 1 -o "$d/rr1.h5" 2> /dev/null &&
    "$hmfnet" generate regular --n 2000 --degree 10 --seed 2 -o "$d/rr2.h5" 2> /dev/null ||
    { echo "adversarial_cases.sh: cannot generate the test networks" >&2; exit 1; }
  ln -s net.h5 "$d/link.h5"
  ln "$d/net.h5" "$d/hard.h5"
}

# Placeholders -> paths (longest names first, so RR1 is not read as RR followed by 1).
expand() {
  local d="$out/files" text="$1"
  text="${text//RUN/--K 0.05,0.1 --seed 1 --T 20 --transient 5 --quiet}"
  text="${text//CKPT/$d/ckpt.h5}"
  text="${text//LINK/$d/link.h5}"
  text="${text//HARD/$d/hard.h5}"
  text="${text//RR1/$d/rr1.h5}"
  text="${text//RR2/$d/rr2.h5}"
  text="${text//NET/$d/net.h5}"
  text="${text//MTX/$d/net.mtx}"
  text="${text//DIR/$d}"
  echo "$text"
}

snapshot() { (cd "$out/files" && find . -type f -o -type l | sort | xargs sha256sum); }

failures=0
cases=0
while IFS='|' read -r c_setup c_command c_text; do
  c_setup="$(echo "$c_setup" | sed -e 's/^ *//' -e 's/ *$//')"
  [[ -z "$c_setup" || "$c_setup" == \#* ]] && continue
  c_command="$(echo "$c_command" | sed -e 's/^ *//' -e 's/ *$//')"
  c_text="$(echo "$c_text" | sed -e 's/^ *//' -e 's/ *$//')"
  cases=$((cases + 1))
  fresh_inputs
  if [[ "$c_setup" != - ]]; then
    read -r -a setup <<< "$(expand "$c_setup")"
    if ! "$hmfnet" "${setup[@]}" > "$out/setup.log" 2>&1; then
      failures=$((failures + 1))
      echo "FAIL: set-up failed: $c_setup"
      sed 's/^/  /' "$out/setup.log"
      continue
    fi
  fi
  read -r -a command <<< "$(expand "$c_command")"
  text="$(expand "$c_text")"
  output=""
  for ((i = 0; i < ${#command[@]}; ++i)); do
    [[ "${command[$i]}" == -o ]] && output="${command[$((i + 1))]}"
  done
  # An output that existed before (an input it must not overwrite) is checked by the snapshot.
  [[ -e "$output" ]] && output=""
  before="$(snapshot)"
  if ! bash "$here/expect_failure.sh" ${output:+--output "$output"} --contains "hmfnet: error: " \
      --contains "$text" -- "$hmfnet" "${command[@]}" > "$out/case.log" 2>&1; then
    failures=$((failures + 1))
    echo "FAIL: $c_command"
    sed 's/^/  /' "$out/case.log"
  elif [[ "$(snapshot)" != "$before" ]]; then
    failures=$((failures + 1))
    echo "FAIL: $c_command changed or added files:"
    diff <(echo "$before") <(snapshot) | sed 's/^/  /'
  else
    echo "ok: $c_command -> $(grep -A1 '^stderr:' "$out/case.log" | tail -n 1)"
  fi
done < "$table"
echo "$cases cases, $failures failures"
[[ $cases -gt 0 && $failures -eq 0 ]]
