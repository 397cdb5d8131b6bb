# Shared by the reproduction scripts beside it (source it after `set -euo pipefail`): the binary
# argument, the temporary folder and the Python that has h5py.

# script_binary USAGE ARG: sets HMF to ARG's absolute path, or prints USAGE and exits 2.
script_binary() {
  if [[ -z "${2:-}" || ! -x "$2" ]]; then
    echo "usage: $1" >&2
    exit 2
  fi
  HMF=$(realpath "$2")
}

# script_tmp NAME: sets TMP to a new folder, removed on exit unless KEEP=1.
script_tmp() {
  TMP=$(mktemp -d "${TMPDIR:-/tmp}/$1.XXXXXX")
  if [[ "${KEEP:-0}" == 1 ]]; then
    echo "# runs kept in $TMP" >&2
  else
    trap 'rm -rf "$TMP"' EXIT
  fi
}

# Debian's python3 has h5py and numpy (ci/install-deps.sh); a virtual environment may not.
PY=/usr/bin/python3
[[ -x $PY ]] || PY=python3
