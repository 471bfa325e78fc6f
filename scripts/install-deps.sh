#!/usr/bin/env bash
# Installs halfspace's build and test dependencies from Debian 12 packages.
# Idempotent: only packages that are missing are installed. Needs root (or sudo).
set -euo pipefail

packages=(
  build-essential cmake pkg-config git clang-format
  libeigen3-dev
  libfftw3-dev
  libhdf5-dev
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
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ "${#missing[@]}" -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages already installed"
  exit 0
fi

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  sudo_cmd=(sudo)
fi

echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
