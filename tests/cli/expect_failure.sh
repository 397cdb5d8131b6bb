#!/usr/bin/env bash
# Runs an hmfnet command that must refuse its input, and checks how it refuses:
#   1. the exit code is non-zero and below 128 (a signal, i.e. a crash, is not a clean refusal);
#   2. stderr is exactly N lines (default 1: "hmfnet: error: FILE:LINE: cause");
#   3. the first stderr line contains every --contains text (file name, line number, cause);
#   4. the --output file (the command's -o) does not exist afterwards, nor any temporary of it
#      (AtomicFile names them OUTPUT.tmp.PID).
# Usage: expect_failure.sh [--output FILE] [--stderr-lines N] [--contains TEXT]... -- COMMAND...
set -u

output=""
stderr_lines=1
contains=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --output) output="$2"; shift 2 ;;
    --stderr-lines) stderr_lines="$2"; shift 2 ;;
    --contains) contains+=("$2"); shift 2 ;;
    --) shift; break ;;
    *) echo "expect_failure.sh: unknown option '$1'" >&2; exit 2 ;;
  esac
done
if [[ $# -eq 0 ]]; then
  echo "expect_failure.sh: no command after --" >&2
  exit 2
fi

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
if [[ -n "$output" ]]; then
  # A stale output from an earlier run must not fake a fresh one.
  rm -f "$output" "$output".tmp.*
fi

"$@" >"$scratch/stdout" 2>"$scratch/stderr"
code=$?

failures=0
fail() {
  echo "expect_failure.sh: FAIL: $*" >&2
  failures=$((failures + 1))
}

if [[ $code -eq 0 ]]; then
  fail "exit code 0, expected a refusal"
elif [[ $code -ge 128 ]]; then
  fail "exit code $code: killed by signal $((code - 128)), not a clean refusal"
fi
lines=$(wc -l <"$scratch/stderr")
if [[ $lines -ne $stderr_lines ]]; then
  fail "stderr has $lines lines, expected $stderr_lines"
fi
first=$(head -n 1 "$scratch/stderr")
for text in "${contains[@]}"; do
  if [[ "$first" != *"$text"* ]]; then
    fail "first stderr line does not contain '$text'"
  fi
done
if [[ -n "$output" ]]; then
  [[ -e "$output" ]] && fail "output file '$output' exists"
  for temp in "$output".tmp.*; do
    [[ -e "$temp" ]] && fail "temporary output '$temp' was left behind"
  done
fi

echo "command: $*"
echo "exit code: $code"
echo "stderr:"
cat "$scratch/stderr"
if [[ $failures -gt 0 ]]; then
  echo "stdout:"
  cat "$scratch/stdout"
  exit 1
fi
exit 0
