#!/usr/bin/env bash
# clang-tidy over every src/, verification/ and bench/ *.cpp with the repository's .clang-tidy
# (which fails on any finding: WarningsAsErrors '*'; our own headers are checked through
# HeaderFilterRegex). Uses the
# compile database build/compile_commands.json that ci/build.sh configures, runs $(nproc) files
# at a time, prints each failing file's findings, a count per check and the slowest files, and
# exits non-zero on any finding or clang-tidy failure. Changes nothing.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
db=build/compile_commands.json
if [ ! -f "$db" ]; then
  echo "ci/tidy.sh: $db is missing; run ci/build.sh first (it configures build/)" >&2
  exit 1
fi
in_db() { grep -qF "\"file\": \"$root/$1\"" "$db"; }
mapfile -t files < <(git ls-files 'src/*.cpp')
if [ ${#files[@]} -eq 0 ]; then
  echo "ci/tidy.sh: no sources found (not a git checkout?)" >&2
  exit 1
fi
# A file without a compile command would be checked with guessed flags: refuse instead. Every
# src/ file is built by CMake; a few bench/ files are built by their own scripts
# (bench/sincos_table.sh builds bench/sincos_versions.cpp against an earlier commit and SLEEF)
# and are skipped, by name.
missing=()
for f in "${files[@]}"; do
  in_db "$f" || missing+=("$f")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "ci/tidy.sh: not in $db (re-run ci/build.sh?): ${missing[*]}" >&2
  exit 1
fi
while read -r f; do
  if in_db "$f"; then
    files+=("$f")
  else
    echo "ci/tidy.sh: skipped $f (not built by CMake)"
  fi
done < <(git ls-files 'verification/*.cpp' 'bench/*.cpp')

clang-tidy --version | grep -i version
logs="$(mktemp -d)"
trap 'rm -rf "$logs"' EXIT
start=$(date +%s)
# One clang-tidy per file; each writes <log>, <log>.rc (its exit code) and <log>.ms (its time).
tidy_one() {
  local f="$1" log="$2/${1//\//_}"
  local t0 rc=0
  t0=$(date +%s%N)
  clang-tidy -p build --quiet "$f" > "$log" 2>&1 || rc=$?
  echo "$rc" > "$log.rc"
  echo "$(( ($(date +%s%N) - t0) / 1000000 )) $f" > "$log.ms"
}
export -f tidy_one
printf '%s\n' "${files[@]}" | xargs -P "$(nproc)" -I{} bash -c 'tidy_one "$1" "$2"' _ {} "$logs"

failed=()
for f in "${files[@]}"; do
  log="$logs/${f//\//_}"
  if [ ! -f "$log.rc" ] || [ "$(cat "$log.rc")" != 0 ]; then
    failed+=("$f")
    echo "=== $f"
    grep -v ' warnings\? generated\.$' "$log" || true
  fi
done
echo "ci/tidy.sh: ${#files[@]} files in $(( $(date +%s) - start )) s on $(nproc) jobs; slowest:"
# awk reads the whole list (head would close the pipe early: sort's SIGPIPE fails the script
# under pipefail, depending on timing).
sort -rn "$logs"/*.ms | awk 'NR <= 5 {printf "  %6.1f s  %s\n", $1 / 1000, $2}'
if [ ${#failed[@]} -gt 0 ]; then
  echo "ci/tidy.sh: findings per check:"
  cat "$logs"/*.cpp | grep -E ': (warning|error): ' | sort -u \
    | grep -oE '\[[A-Za-z0-9.,-]+\]$' | sort | uniq -c | sort -rn || true
  echo "ci/tidy.sh: ${#failed[@]} files failed: ${failed[*]}" >&2
  exit 1
fi
echo "ci/tidy.sh: no findings"
