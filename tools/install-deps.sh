#!/usr/bin/env bash
# Installs the Debian 12 packages ispm builds and tests with, only those missing.
# Uses sudo when not root. Usage: tools/install-deps.sh [--test]  (--test adds the test-only ones)
set -euo pipefail

packages=(cmake g++ make pkg-config python3-glad libglfw3-dev libglm-dev libimgui-dev libegl-dev
          libegl1-mesa-dev libgl1-mesa-dri libosmesa6-dev libstb-dev libtinyobjloader-dev
          nlohmann-json3-dev libcli11-dev libgtest-dev libtinyexr-dev libtinygltf-dev)
if [[ "${1:-}" == "--test" ]]; then
    packages+=(xvfb xauth python3-matplotlib clang-format)
fi

missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
    exit 0
fi
echo "installing: ${missing[*]}"
sudo=""
if [[ $(id -u) -ne 0 ]]; then sudo="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
