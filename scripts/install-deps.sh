#!/usr/bin/env bash
# Installs the Debian packages bemcontact builds with, when any is missing.
#   install-deps.sh          what the build and `make test` need (Python module, figures,
#                            VTK read-back, Gmsh)
#   install-deps.sh --core   only the library and the command (`make demo`)
#   install-deps.sh --fuzz   plus clang, libFuzzer and clang's OpenMP (`make fuzz`)
#   install-deps.sh --mpi    plus OpenMPI and PETSc (`make test-mpi`, distributed runs)
set -euo pipefail
cd "$(dirname "$0")/.."
packages=(g++ cmake make ninja-build pkg-config libeigen3-dev libopenblas-dev libhmat-oss-dev
  libtomlplusplus-dev libcli11-dev nlohmann-json3-dev)
if [ "${1:-}" != "--core" ]; then
  packages+=(libgtest-dev libbenchmark-dev
    python3 python3-dev pybind11-dev python3-numpy python3-pytest python3-matplotlib python3-vtk9
    libgmsh-dev)
fi
if [ "${1:-}" = "--fuzz" ]; then
  packages+=(clang libclang-rt-14-dev libomp-14-dev)
fi
if [ "${1:-}" = "--mpi" ]; then
  packages+=(libopenmpi-dev openmpi-bin petsc-dev)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
if [ "$(id -u)" -ne 0 ]; then
  echo "install-deps: missing packages and not root; run as root or install: ${missing[*]}" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}" > /dev/null
