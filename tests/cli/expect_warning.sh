#!/usr/bin/env bash
# Runs an hmfnet command that must succeed while warning about its input, and checks:
#   1. the exit code is 0;
#   2. stderr contains every --stderr-contains text (the warning names the file and the cause);
#   3. stdout contains every --stdout-contains text (the result was produced).
# Usage: expect_warning.sh [--stderr-contains TEXT]... [--stdout-contains TEXT]... -- COMMAND...
set -u

stderr_texts=()
stdout_texts=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --stderr-contains) stderr_texts+=("$2"); shift 2 ;;
    --stdout-contains) stdout_texts+=("$2"); shift 2 ;;
    --) shift; break ;;
    *) echo "expect_warning.sh: unknown option '$1'" >&2; exit 2 ;;
  esac
done
if [[ $# -eq 0 ]]; then
  echo "expect_warning.sh: no command after --" >&2
  exit 2
fi

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
"$@" >"$scratch/stdout" 2>"$scratch/stderr"
code=$?

failures=0
fail() {
  echo "expect_warning.sh: FAIL: $*" >&2
  failures=$((failures + 1))
}

[[ $code -ne 0 ]] && fail "exit code $code, expected 0"
for text in "${stderr_texts[@]}"; do
  grep -qF -- "$text" "$scratch/stderr" || fail "stderr does not contain '$text'"
done
for text in "${stdout_texts[@]}"; do
  grep -qF -- "$text" "$scratch/stdout" || fail "stdout does not contain '$text'"
done

echo "command: $*"
echo "exit code: $code"
echo "stderr:"
cat "$scratch/stderr"
echo "stdout:"
cat "$scratch/stdout"
[[ $failures -eq 0 ]]
