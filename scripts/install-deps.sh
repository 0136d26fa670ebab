#!/usr/bin/env bash
# Installs every dependency from Debian 12's packages (nothing is vendored). When every one is
# already installed it asks apt nothing (no package-list download), so a second run takes a moment.
set -euo pipefail
packages=(mesa-vulkan-drivers libvulkan-dev vulkan-tools vulkan-validationlayers glslang-tools
          glslang-dev spirv-tools libglm-dev libglfw3-dev libtinygltf-dev libstb-dev
          nlohmann-json3-dev libtinyexr-dev libimgui-dev libembree-dev pkg-config xvfb xauth
          libgtest-dev cmake g++ assimp-testmodels python3-matplotlib clang libclang-rt-14-dev
          clang-format)
missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages are installed"
  exit 0
fi
sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update
$sudo apt-get install -y "${packages[@]}"
