#!/usr/bin/env bash
# Installs every dependency from Debian 12's packages (nothing is vendored).
set -euo pipefail
packages=(mesa-vulkan-drivers libvulkan-dev vulkan-tools vulkan-validationlayers glslang-tools
          glslang-dev spirv-tools libglm-dev libglfw3-dev libtinygltf-dev libstb-dev
          nlohmann-json3-dev libtinyexr-dev libimgui-dev libembree-dev pkg-config xvfb xauth libgtest-dev cmake g++
          assimp-testmodels python3-matplotlib clang libclang-rt-14-dev clang-format)
sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update
$sudo apt-get install -y "${packages[@]}"
