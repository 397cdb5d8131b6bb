#!/usr/bin/env bash
# Packs the `hmfnet` CLI built here for the GPU machine, which has no Trilinos, HDF5 or Open MPI:
# the executable, the shared libraries it loads (ldd, less glibc's and the NVIDIA driver's, which
# the GPU machine has), and Open MPI's plugins and help files under a relocated prefix
# (OPAL_PREFIX), so that `hmfnet simulate --device cuda` runs there as one MPI singleton, and
# Open MPI's launcher (orterun, orted) for runs of several ranks on that one machine.
#
#   bash ci/device_pack_cli.sh BUILD/bin/hmfnet OUT.tar.xz
#
# Unpacked into D, it runs as `D/run hmfnet ARGS...` (one rank) or `D/mpirun NP hmfnet ARGS...`
# (NP ranks on this machine); the wrappers set the environment.
set -euo pipefail
exe=$1 pack=$2
die() { echo "device_pack_cli: $*" >&2; exit 1; }
[ -x "$exe" ] || die "no executable $exe"
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
mkdir -p "$stage/bin" "$stage/lib"
cp "$exe" "$stage/bin/"

# The C library, its loader and the driver's libraries stay the GPU machine's own.
system_lib='^(libc|libm|libdl|librt|libpthread|libresolv|libutil|ld-linux-x86-64|linux-vdso|libcuda|libnvidia)[.-]'
copy_deps() {
  ldd "$1" | awk '$2 == "=>" && $3 ~ /^\// { print $3 }' | while read -r lib; do
    name=$(basename "$lib")
    [[ "$name" =~ $system_lib ]] && continue
    [ -e "$stage/lib/$name" ] || cp -L "$lib" "$stage/lib/$name"
  done
}
copy_deps "$exe"

# Open MPI (Debian: prefix /usr, libdir lib/x86_64-linux-gnu/openmpi/lib): its plugins are
# opened at run time from the prefix, which OPAL_PREFIX relocates. Plugins whose own libraries
# are absent there (InfiniBand, UCX) fail to load quietly; a singleton needs none of them.
libmpi=$(ldd "$exe" | awk '$1 == "libmpi.so.40" { print $3 }')
[ -n "$libmpi" ] || die "$exe does not link libmpi.so.40 (Open MPI 4): nothing else is packed"
ompi_lib=$(dirname "$(readlink -f "$libmpi")")
multiarch=$(basename "$ompi_lib")                         # x86_64-linux-gnu
plugins=/usr/lib/$multiarch/openmpi/lib/openmpi3
[ -d "$plugins" ] || die "no Open MPI plugin folder $plugins"
prefix="$stage/prefix"
mkdir -p "$prefix/lib/$multiarch/openmpi/lib" "$prefix/share" "$prefix/etc"
cp -a "$plugins" "$prefix/lib/$multiarch/openmpi/lib/"
# The launcher opens its own plugins (ess, plm, odls, pmix, oob, rmaps, ...): every plugin's
# libraries are packed, so that none the launcher needs fails to load for want of one.
for p in "$plugins"/mca_*.so; do copy_deps "$p"; done
[ -d /usr/share/openmpi ] && cp -a /usr/share/openmpi "$prefix/share/"
launcher=$(readlink -f "$(command -v mpirun)")
[ "$(basename "$launcher")" = orterun ] || die "mpirun is $launcher, not Open MPI's orterun"
cp "$launcher" "$stage/bin/mpirun"
cp "$(dirname "$launcher")/orted" "$stage/bin/orted"
copy_deps "$stage/bin/mpirun"
copy_deps "$stage/bin/orted"

cat >"$stage/run" <<'SH'
#!/usr/bin/env bash
# D/run PROGRAM ARGS...: runs D/bin/PROGRAM with D's libraries and D's relocated Open MPI, as an
# isolated singleton (no mpirun, no daemon, messages only to itself).
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
program=$1
shift
export LD_LIBRARY_PATH="$here/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export OPAL_PREFIX="$here/prefix"
export OMPI_MCA_ess_singleton_isolated=1
export OMPI_MCA_mca_base_component_show_load_errors=0
export OMPI_MCA_pml=ob1 OMPI_MCA_btl=self
export OMPI_MCA_rmaps_base_oversubscribe=1
exec "$here/bin/$program" "$@"
SH
chmod +x "$stage/run"

cat >"$stage/mpirun" <<'SH'
#!/usr/bin/env bash
# D/mpirun NP PROGRAM ARGS...: NP ranks of D/bin/PROGRAM on this machine, launched by D's own
# orterun with D's libraries and relocated Open MPI; shared memory between the ranks (vader),
# TCP where that is refused, as root too.
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ranks=$1 program=$2
shift 2
export LD_LIBRARY_PATH="$here/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export OPAL_PREFIX="$here/prefix"
export PATH="$here/bin:$PATH"
export OMPI_MCA_mca_base_component_show_load_errors=0
export OMPI_MCA_pml=ob1 OMPI_MCA_btl=self,vader,tcp
export OMPI_MCA_rmaps_base_oversubscribe=1
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
exec "$here/bin/mpirun" -np "$ranks" -x LD_LIBRARY_PATH -x OPAL_PREFIX "$here/bin/$program" "$@"
SH
chmod +x "$stage/mpirun"

# Every library the executable loads must resolve into the pack or to the system's own C library.
unresolved=$(for b in hmfnet mpirun orted; do LD_LIBRARY_PATH="$stage/lib" ldd "$stage/bin/$b"; done |
  awk -v lib="$stage/lib/" '$2 == "=>" && index($3, lib) != 1 { print $1 " -> " $3 }' |
  grep -Ev "$system_lib" | sort -u || true)
[ -z "$unresolved" ] || die "libraries that resolve outside the pack: $unresolved"
# The newest glibc symbol version any packed binary needs: the GPU machine's glibc must have it.
glibc=$(find "$stage/bin" "$stage/lib" -type f -exec objdump -T {} + 2>/dev/null |
  grep -o 'GLIBC_[0-9.]*' | sort -uV | tail -n 1)
echo "$glibc" >"$stage/GLIBC_REQUIRED"
tar -C "$stage" -cJf "$pack" .
echo "packed $(du -sh "$pack" | cut -f1): $(find "$stage/lib" -type f | wc -l) libraries, $(find "$prefix" -name 'mca_*.so' | wc -l) Open MPI plugins -> $pack"
