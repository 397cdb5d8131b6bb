#!/usr/bin/env bash
# clang-format check over src/, tests/, verification/ and bench/ with the repository's
# .clang-format (Google style, 100 columns): lists every file that differs and fails; changes
# nothing. To fix: the same file list through `clang-format -i`.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
mapfile -t files < <(git ls-files 'src/*.cpp' 'src/*.hpp' 'tests/*.cpp' 'tests/*.hpp' \
  'verification/*.cpp' 'verification/*.hpp' 'bench/*.cpp' 'bench/*.hpp')
if [ ${#files[@]} -eq 0 ]; then
  echo "ci/format.sh: no sources found (not a git checkout?)" >&2
  exit 1
fi
clang-format --version
if ! clang-format --dry-run --Werror "${files[@]}"; then
  echo "ci/format.sh: files above are not clang-formatted; run: clang-format -i <file>" >&2
  exit 1
fi
echo "ci/format.sh: ${#files[@]} files formatted"
