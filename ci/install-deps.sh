#!/usr/bin/env bash
# Installs every Debian package hmfnet needs (idempotent). Debian's Trilinos -dev packages
# under-declare their dependencies: AnasaziConfig.cmake includes the configs of Belos, AztecOO,
# Xpetra, Thyra, EpetraExt, Triutils, Epetra, RTOp, KokkosKernels, Teuchos and Kokkos, so all are
# listed (../shared/TOOLCHAIN.md).
set -euo pipefail

packages=(
  cmake make g++ git ca-certificates
  libeigen3-dev libboost-math-dev libhdf5-dev catch2 libopenmpi-dev openmpi-bin
  libtrilinos-tpetra-dev libtrilinos-anasazi-dev libtrilinos-belos-dev libtrilinos-aztecoo-dev
  libtrilinos-xpetra-dev libtrilinos-thyra-dev libtrilinos-epetraext-dev libtrilinos-triutils-dev
  libtrilinos-epetra-dev libtrilinos-rtop-dev libtrilinos-kokkos-kernels-dev libtrilinos-teuchos-dev
  libtrilinos-kokkos-dev libtrilinos-zoltan2-dev libtrilinos-zoltan-dev
  libptscotch-dev  # Zoltan2's headers call PT-Scotch: linked though we use PHG (graph_partition.cpp)
  libcli11-dev nlohmann-json3-dev libbenchmark-dev
  python3 python3-numpy python3-h5py python3-matplotlib
  python3-dev pybind11-dev python3-pybind11 python3-pytest python3-scipy python3-networkx  # python/hmfnet
  python3-pip python3-venv python3-setuptools python3-wheel  # pip install . (tests/install/pip_install.sh)
  dpkg-dev  # cpack -G DEB: dpkg-shlibdeps (tests/install/debian_package.sh)
  clang libclang-rt-dev libomp-dev  # ci/fuzz.sh: libFuzzer and sanitizer runtimes, OpenMP for clang
  clang-format clang-tidy  # ci/format.sh, ci/tidy.sh
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "ci/install-deps.sh: all ${#packages[@]} packages present"
  exit 0
fi

SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
echo "ci/install-deps.sh: installing ${#missing[@]} packages: ${missing[*]}"
$SUDO apt-get update
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y --no-install-recommends "${packages[@]}"
