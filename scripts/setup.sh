#!/usr/bin/env bash
# Installs every Debian package isphdem needs. Idempotent: when all are present it does nothing.
set -euo pipefail

PACKAGES=(
  build-essential cmake
  liggghts libliggghts-dev          # LIGGGHTS 3.8.0 (pulls ParaView as a recommended package: keep it)
  libeigen3-dev
  libopenmpi-dev openmpi-bin
  libhdf5-openmpi-dev               # the HDF5 PETSc links (never mix it with the serial one)
  petsc-dev                         # PETSc 3.18 with hypre: solver.preconditioner = "amg"
  pkg-config
  libgtest-dev libgmock-dev
  libtomlplusplus-dev
  nlohmann-json3-dev                # result.json and isphdem study
  python3-h5py python3-matplotlib python3-pil   # plots (PIL: GIFs), run with /usr/bin/python3
  python3-numpy                     # scripts/cylinder_lbm_reference.py
  paraview                          # pvpython opens our XDMF in a test
  time                              # /usr/bin/time: memory per rank in bench/mpi/run_ranks.sh
)
# Reference solvers outside the build and the tests, on request only (large):
# ISPHDEM_REFERENCE=1 adds OpenFOAM for scripts/dam_break_vof_reference.py.
if [ "${ISPHDEM_REFERENCE:-0}" = 1 ]; then PACKAGES+=(openfoam); fi

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "setup: installing missing Debian packages: ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
    echo "setup: need root (or sudo) to install: ${missing[*]}" >&2
    exit 1
  fi
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq "${missing[@]}"
