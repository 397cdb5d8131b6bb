#!/usr/bin/env bash
# `cpack -G DEB` on the build: the package must hold the CLI, the library, its CMake package and
# the Python module, and declare its Debian runtime dependencies (dpkg-shlibdeps).
#   debian_package.sh BUILD_DIR WORK_DIR
set -euo pipefail
build="$1"
work="$2"
rm -rf "$work" && mkdir -p "$work"
(cd "$build" && cpack -G DEB -B "$work" > "$work/cpack.log" 2>&1) || { cat "$work/cpack.log"; exit 1; }
deb="$(ls "$work"/*.deb)"
dpkg-deb -c "$deb" > "$work/files.txt"
for path in ./usr/bin/hmfnet ./usr/lib/cmake/hmfnet/hmfnetConfig.cmake \
            ./usr/include/hmfnet/network/network.hpp ./usr/lib/python3/dist-packages/hmfnet/__init__.py; do
  grep -q " $path\$" "$work/files.txt" || { echo "debian_package.sh: $path missing from $deb"; exit 1; }
done
grep -q "_hmfnet.cpython" "$work/files.txt" || { echo "debian_package.sh: no Python extension"; exit 1; }
depends="$(dpkg-deb -f "$deb" Depends)"
echo "$(basename "$deb"): Depends: $depends"
for lib in libc6 libhdf5 libtrilinos-tpetra libopenmpi python3-numpy; do
  [[ "$depends" == *"$lib"* ]] || { echo "debian_package.sh: Depends lacks $lib"; exit 1; }
done
