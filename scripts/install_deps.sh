#!/usr/bin/env bash
# Installs every Debian 12 package pcl_flowseg needs to build, test and run.
# Idempotent: packages already present are not reinstalled; apt is only
# consulted when something is missing.
set -euo pipefail

PACKAGES=(
  build-essential cmake make pkg-config python3
  libpcl-dev libcgal-dev libflann-dev libeigen3-dev libboost-dev
  libgtest-dev libtbb-dev libpng-dev
  python3-dev pybind11-dev python3-numpy python3-pytest python3-distributed
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install_deps: all ${#PACKAGES[@]} packages present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO="sudo"; else
    echo "install_deps: need root (or sudo) to install: ${missing[*]}" >&2
    exit 1
  fi
fi

echo "install_deps: installing ${missing[*]}"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
