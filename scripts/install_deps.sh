#!/usr/bin/env bash
# Installs every Debian package Cairn needs to build, test and benchmark.
#   scripts/install_deps.sh [--training-tools]
# --training-tools also installs what scripts/train_material_net.py needs (PyTorch, ONNX, Pillow: large, and
# needed by no build or test). Non-interactive and idempotent: packages already present are not touched, and
# `apt-get update` runs at most once, only when something is missing.
set -euo pipefail

with_training_tools=0
for arg in "$@"; do
  case "$arg" in
    --training-tools) with_training_tools=1 ;;
    *) echo "install_deps.sh: unknown option '$arg' (known: --training-tools)" >&2; exit 2 ;;
  esac
done

# Libraries linked into Cairn, the build toolchain, and the test/benchmark frameworks.
CORE_PACKAGES=(
  build-essential cmake pkg-config git ninja-build ccache
  libeigen3-dev coinor-libipopt-dev libnlopt-cxx-dev libsuitesparse-dev libfcl-dev libccd-dev
  liburdfdom-dev libtinyxml-dev libopencv-dev libopencv-contrib-dev libbullet-dev libbullet-extras-dev
  pybind11-dev python3-dev python3-numpy libgtest-dev libgmock-dev libbenchmark-dev libyaml-cpp-dev
  libcli11-dev nlohmann-json3-dev python3-pytest python3-matplotlib libopenmpi-dev openmpi-bin
  libjs-three chromium  # three.js inlined by the HTML viewers (visualization/); the viewer test's headless browser
)
# Peers and reference data: used by cross-check tests and benchmarks only, never linked into Cairn's libraries.
PEER_PACKAGES=(
  libdart-dev libdart-utils-urdf-dev dart-doc liboctomap-dev libpcl-dev
)
# Tool scripts only (scripts/train_material_net.py); no test or library needs them.
SCRIPT_PACKAGES=()
if [ "$with_training_tools" -eq 1 ]; then
  SCRIPT_PACKAGES=(python3-torch python3-onnx python3-pil)
fi

missing=()
for pkg in "${CORE_PACKAGES[@]}" "${PEER_PACKAGES[@]}" ${SCRIPT_PACKAGES[@]+"${SCRIPT_PACKAGES[@]}"}; do
  if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$pkg")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install_deps: all ${#CORE_PACKAGES[@]} core, ${#PEER_PACKAGES[@]} peer and ${#SCRIPT_PACKAGES[@]} script packages are installed."
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
