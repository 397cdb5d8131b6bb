#!/usr/bin/env bash
# `hmfnet convert` parses a text network in parallel (docs/scaling.md):
#   1. a Matrix Market file and an edge list converted on 1 and on 2 ranks give the datasets of
#      the HDF5 file `generate` writes for the same network, bit for bit;
#   2. `convert --partition 2` on 2 ranks writes the same network renumbered: original_index is
#      a permutation and maps the new file's edges onto the input's exactly;
#   3. a malformed line in the second rank's half of the file ends both ranks with one message
#      naming FILE:LINE, a non-zero exit and no output file (not even a temporary one).
# Usage: convert_ranks_agree.sh HMFNET PYTHON OUTDIR MPIEXEC [MPI FLAGS...]
set -euo pipefail
hmfnet=$1 python=$2 out=$3 mpiexec=$4
shift 4
dir="$out/convert_ranks"
rm -rf "$dir" && mkdir -p "$dir"
gen=("$hmfnet" generate er --n 3000 --mean-degree 20 --seed 8)
"${gen[@]}" -o "$dir/er.h5" 2>/dev/null
"${gen[@]}" -o "$dir/er.mtx" 2>/dev/null
"${gen[@]}" -o "$dir/er.txt" 2>/dev/null
for input in er.mtx er.txt; do
  "$hmfnet" convert "$dir/$input" -o "$dir/${input}_1.h5" 2>/dev/null
  OMP_NUM_THREADS=1 "$mpiexec" "$@" -np 2 "$hmfnet" convert "$dir/$input" \
    -o "$dir/${input}_2.h5" 2>/dev/null
done
OMP_NUM_THREADS=1 "$mpiexec" "$@" -np 2 "$hmfnet" convert "$dir/er.h5" --partition 2 \
  -o "$dir/er_part2.h5" 2>/dev/null
"$python" - "$dir" <<'PY'
import sys
import h5py
import numpy as np

d = sys.argv[1]
def datasets(path):
    out = {}
    with h5py.File(path, "r") as f:
        f.visititems(lambda name, obj: out.__setitem__(name, obj[()])
                     if isinstance(obj, h5py.Dataset) else None)
    return out

reference = datasets(f"{d}/er.h5")
assert reference, "no datasets in the generated file"
for name in ["er.mtx_1", "er.mtx_2", "er.txt_1", "er.txt_2"]:
    got = datasets(f"{d}/{name}.h5")
    assert got.keys() == reference.keys(), (name, sorted(got), sorted(reference))
    for key, value in reference.items():
        assert np.array_equal(got[key], value), (name, key)
print(f"converted files equal the generated one: {sorted(reference)}")

def edges(path):
    with h5py.File(path, "r") as f:
        row_ptr, col = f["network/row_ptr"][()], f["network/col"][()]
        original = f["network/original_index"][()] if "original_index" in f["network"] else None
    rows = np.repeat(np.arange(len(row_ptr) - 1), np.diff(row_ptr))
    return rows, col, original

rows, cols, _ = edges(f"{d}/er.h5")
new_rows, new_cols, original = edges(f"{d}/er_part2.h5")
assert original is not None, "no /network/original_index"
assert np.array_equal(np.sort(original), np.arange(len(original))), "not a permutation"
mapped = set(zip(original[new_rows].tolist(), original[new_cols].tolist()))
assert mapped == set(zip(rows.tolist(), cols.tolist())), "renumbered edges differ"
print(f"--partition 2: {len(mapped)} entries, the input's under original_index")
PY

# The first line starting at or after 3/4 of the file's bytes lies in the second rank's range
# (each rank parses an equal byte range of the body), however long the lines before it are.
size=$(stat -c %s "$dir/er.txt")
bad=$(LC_ALL=C awk -v from=$((size * 3 / 4)) \
  'at >= from { print NR; exit } { at += length($0) + 1 }' "$dir/er.txt")
sed "${bad}s/.*/17 x/" "$dir/er.txt" > "$dir/bad.txt"
if OMP_NUM_THREADS=1 "$mpiexec" "$@" -np 2 "$hmfnet" convert "$dir/bad.txt" -o "$dir/bad.h5" \
  > "$dir/bad.log" 2>&1; then
  echo "FAIL: convert of a corrupted file exited 0"; exit 1
fi
cat "$dir/bad.log"
grep -q "^hmfnet: error: $dir/bad.txt:$bad: node index 'x' is not an integer (on rank 1)$" \
  "$dir/bad.log" || { echo "FAIL: no FILE:LINE message from rank 1"; exit 1; }
[ "$(grep -c 'hmfnet: error' "$dir/bad.log")" -eq 1 ] || { echo "FAIL: not one message"; exit 1; }
if ls "$dir" | grep -q '^bad\.h5'; then echo "FAIL: output left behind: $(ls "$dir")"; exit 1; fi
echo "ok: corrupted line $bad refused on every rank, no output"
