#!/usr/bin/env bash
# Headless rendering needs Mesa's EGL and its software rasteriser (llvmpipe), which wgpu's
# GL backend uses when there is no GPU, and Mesa's Vulkan driver (lavapipe), which many
# users' machines have too: CI renders on both (WGPU_BACKEND in .ci/run). The studio's
# tests need an X server (Xvfb) and xdotool to drive its window.
# Installs them from Debian's packages if missing.
set -euo pipefail
packages=(libegl1 libegl-mesa0 libgl1-mesa-dri mesa-vulkan-drivers xvfb xauth xdotool)
if dpkg -s "${packages[@]}" >/dev/null 2>&1; then
    echo "graphics: Mesa and Xvfb present"
    exit 0
fi
SUDO=""
if [ "$(id -u)" != 0 ]; then SUDO=sudo; fi
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${packages[@]}"
