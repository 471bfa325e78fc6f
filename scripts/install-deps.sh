#!/usr/bin/env bash
# Installs halfspace's build and test dependencies from Debian 12 packages.
# Idempotent: only packages that are missing are installed. Needs root (or sudo).
set -euo pipefail

packages=(
  build-essential cmake pkg-config git clang-format
  libeigen3-dev
  libfftw3-dev  # double and single precision (fftw3, fftw3f) with their OpenMP libraries
  libhdf5-dev
  zlib1g-dev  # result fields deflated on the threads (src/io/hdf5_chunk_compression.cpp)
  libgtest-dev libgmock-dev
  libbenchmark-dev
  libcli11-dev
  libtomlplusplus-dev
  libfmt-dev
  libsiconos-numerics-dev
  libalglib-dev
  libzip-dev libpugixml-dev
  clang-14 libclang-rt-14-dev
  time
  python3 python3-numpy python3-h5py python3-matplotlib python3-scipy
  # `python3 -m venv` for the Python package's tests (scripts/test-python.sh).
  python3-venv
  # The MPI build (-DHALFSPACE_MPI=ON, docs/usage.md#running-on-a-cluster):
  # Open MPI, FFTW's MPI interface and the parallel HDF5, which installs
  # beside the serial libhdf5-dev (hdf5/openmpi next to hdf5/serial).
  libopenmpi-dev openmpi-bin libfftw3-mpi-dev libhdf5-openmpi-dev
)

# Installing libhdf5-openmpi-dev makes Debian's hdf5.pc alternative point to
# the parallel HDF5 (it has the higher priority); keep the serial one the
# system default, so that only the MPI build (which asks for it) uses MPI.
keep_serial_hdf5_default() {
  local serial=/usr/lib/x86_64-linux-gnu/pkgconfig/hdf5-serial.pc
  if [ -e "$serial" ] && update-alternatives --query hdf5.pc 2>/dev/null | grep -q "^Status: auto"; then
    "${sudo_cmd[@]}" update-alternatives --set hdf5.pc "$serial" >/dev/null
  fi
}

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  sudo_cmd=(sudo)
fi

if [ "${#missing[@]}" -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages already installed"
  keep_serial_hdf5_default
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
keep_serial_hdf5_default
