#!/usr/bin/env bash
# Installs every Debian package Cairn needs to build, test and benchmark.
# Non-interactive and idempotent: packages already present are not touched, and
# `apt-get update` runs at most once, only when something is missing.
set -euo pipefail

# Libraries linked into Cairn, the build toolchain, and the test/benchmark frameworks.
CORE_PACKAGES=(
  build-essential cmake pkg-config git ninja-build ccache
  libeigen3-dev coinor-libipopt-dev libnlopt-cxx-dev libsuitesparse-dev libfcl-dev libccd-dev
  liburdfdom-dev libopencv-dev libopencv-contrib-dev libbullet-dev libbullet-extras-dev
  pybind11-dev python3-dev python3-numpy libgtest-dev libgmock-dev libbenchmark-dev libyaml-cpp-dev
  libcli11-dev
)
# Peers and reference data: used by cross-check tests and benchmarks only, never linked into Cairn's libraries.
PEER_PACKAGES=(
  libdart-dev libdart-utils-urdf-dev dart-doc liboctomap-dev
)

missing=()
for pkg in "${CORE_PACKAGES[@]}" "${PEER_PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$pkg")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install_deps: all ${#CORE_PACKAGES[@]} core and ${#PEER_PACKAGES[@]} peer packages are installed."
  exit 0
fi

SUDO=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then
    SUDO=(sudo)
  else
    echo "install_deps: missing packages (${missing[*]}) and not root; run as root or install sudo." >&2
    exit 1
  fi
fi

echo "install_deps: installing ${#missing[@]} package(s): ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${SUDO[@]}" apt-get update -qq
"${SUDO[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
