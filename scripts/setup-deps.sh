#!/usr/bin/env bash
# Installs the Debian packages ffvk needs, only when one is missing.
# Usage: scripts/setup-deps.sh [--test]   (--test adds what the test suite needs)
set -euo pipefail

pkgs=(
  mesa-vulkan-drivers   # lavapipe, the CPU Vulkan driver
  libvulkan1            # the Vulkan loader
  glslc                 # shaderc's GLSL compiler (glslang), run by build.rs
)
if [[ "${1:-}" == "--test" ]]; then
  pkgs+=(
    vulkan-validationlayers  # VK_LAYER_KHRONOS_validation, on in every test
    # Mesa's OpenGL through EGL, the conformance oracle, opened at run time (nothing links it):
    libegl1                  # libEGL.so.1, glvnd's EGL dispatcher
    libegl-mesa0             # Mesa's EGL vendor library (EGL_EXT_platform_device, surfaceless)
    libgl1-mesa-dri          # Mesa's GL drivers, llvmpipe (swrast_dri.so) among them
    libxml2-utils            # xmllint: the JUnit files checked against the JUnit schemas
    chromium                 # headless Chromium: the HTML report opened, clicked and screenshot
    # The C API (ffvk-c): its header and C example compiled with the system C and C++ compilers.
    libvulkan-dev            # <vulkan/vulkan.h> and libvulkan.so for the C example
    libgl-dev                # <GL/gl.h>: the header test includes it beside ffvk.h
    pkg-config               # the installed library's ffvk.pc, read as a C program's build reads it
    # The shader library as GLSL ES 3.00 on Mesa's OpenGL ES 3 (the layer example's C program).
    libgles2                 # libGLESv2.so.2, glvnd's OpenGL ES dispatcher
    libgles-dev              # <GLES3/gl3.h> and libGLESv2.so to link against
    libegl-dev               # <EGL/egl.h> and libEGL.so to link against
  )
fi

missing=()
for p in "${pkgs[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if ((${#missing[@]} == 0)); then
  exit 0
fi

echo "ffvk: installing missing Debian packages: ${missing[*]}" >&2
if [[ $(id -u) -ne 0 ]]; then
  if command -v sudo >/dev/null 2>&1; then
    SUDO=sudo
  else
    echo "ffvk: not root and no sudo; please install: ${missing[*]}" >&2
    exit 1
  fi
else
  SUDO=
fi
export DEBIAN_FRONTEND=noninteractive
if ! $SUDO apt-get update -qq || ! $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"; then
  echo "ffvk: could not install: ${missing[*]}; install them by hand (apt-get install ${missing[*]})" >&2
  exit 1
fi
