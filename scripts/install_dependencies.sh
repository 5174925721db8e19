#!/usr/bin/env bash
# Installs the Debian 12 packages wetbed needs, only those that are missing.
set -euo pipefail
packages=(build-essential cmake libdeal.ii-dev libfftw3-dev gmsh openmpi-bin numdiff python3 python3-matplotlib python3-h5py clang-format)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "wetbed: installing ${missing[*]}"
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO=sudo
  $SUDO apt-get update
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y --no-install-recommends "${missing[@]}"
fi
