#!/usr/bin/env bash
# One-command set-up on Debian 12: install missing Debian packages, build (Release, ccache), then
#   run   -> run the default case on 2 MPI ranks
#   test  -> run the whole CTest suite
#   build -> stop after the build
#   peers -> also install the peer codes for cases/benchmarks (FEniCSx, CalculiX), then build
set -euo pipefail
mode=${1:-run}
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$root/build}

packages=(cmake g++ make ccache pkg-config libdeal.ii-dev gmsh libgmsh-dev openmpi-bin libopenmpi-dev
          python3-matplotlib python3-h5py python3-numpy python3-scipy python3-pil numdiff googletest libgtest-dev
          libopenblas0-serial)
# libopenblas0-serial: without it Debian's alternatives give MUMPS (and every peer using it) the
# reference BLAS, whose dgemm makes a 63k-DoF 3D factorization 3.6 times slower (5.3 s against 1.5 s).
# Serial, so two MPI ranks do not each start BLAS threads on a 2-core machine.
# Tests only: case.report_page opens report.html in a real (headless) browser.
if [ "$mode" = test ]; then packages+=(chromium); fi
# Benchmarks only, never the tests: the same problems in FEniCSx (dolfinx) and CalculiX.
if [ "$mode" = peers ]; then packages+=(calculix-ccx python3-dolfinx); fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "Installing Debian packages: ${missing[*]}"
  sudo_cmd=""; [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
  $sudo_cmd apt-get update -q
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

# Open MPI refuses root without these; harmless otherwise.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
export CCACHE_DIR=${CCACHE_DIR:-$root/.ccache}

jobs=$(nproc)
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" -j "$jobs"

case "$mode" in
  build|peers) ;;
  run)
    cd "$root"
    mpirun -np 2 "$build/solver/fe/compliant" cases/flexure_hinge.prm ;;
  test)
    cd "$build"
    ctest --output-on-failure -j "$jobs" ;;
  *) echo "usage: scripts/setup.sh [run|test|build|peers]" >&2; exit 2 ;;
esac
