#!/usr/bin/env bash
# Installs the Debian packages the project needs, only when missing.
# Idempotent: `apt-get update` runs only when something must be installed.
#   tools/deps.sh            build + test dependencies
#   tools/deps.sh --viewer   also GLFW for samples/viewer
#   tools/deps.sh --browser  also Chromium and Chart.js for the report's browser test
#   tools/deps.sh --fuzz     also clang and its runtime libraries (libFuzzer, sanitizers)
set -euo pipefail

packages=(
  build-essential cmake pkg-config clang-format
  mesa-vulkan-drivers libvulkan-dev vulkan-validationlayers
  glslang-tools glslang-dev
  libglm-dev libtinygltf-dev nlohmann-json3-dev libstb-dev libopenexr-dev
  libgtest-dev
  libjs-chart.js
)
for arg in "$@"; do
  case "$arg" in
    --viewer) packages+=(libglfw3-dev) ;;
    --browser) packages+=(chromium) ;;
    --fuzz) packages+=(clang libclang-rt-14-dev) ;;
    -h|--help) sed -n '2,8p' "$0"; exit 0 ;;
    *) echo "deps.sh: unknown option '$arg' (allowed: --viewer, --browser, --fuzz)" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${packages[@]}"; do
  # dpkg-query prints "install ok installed" only for a fully installed package.
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if ((${#missing[@]} == 0)); then
  exit 0
fi

echo "deps.sh: installing ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
