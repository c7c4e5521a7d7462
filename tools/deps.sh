#!/usr/bin/env bash
# Installs the Debian packages the project needs, only when missing.
# Idempotent: `apt-get update` runs only when something must be installed.
#   tools/deps.sh            build + test dependencies, including the sample viewer's (GLFW, Dear
#                            ImGui) and Xvfb for its screenshot test
#   tools/deps.sh --viewer   accepted for old scripts; the viewer's packages are always installed
#   tools/deps.sh --browser  also Chromium and Chart.js for the report's browser test
#   tools/deps.sh --fuzz     also clang and its runtime libraries (libFuzzer, sanitizers)
#   tools/deps.sh --validator  also node and the Khronos glTF-Validator (npm gltf-validator, into
#                            build/node, or $AGAA_NODE_DIR)
set -euo pipefail

packages=(
  build-essential cmake pkg-config clang-format python3
  mesa-vulkan-drivers libvulkan-dev vulkan-validationlayers
  glslang-tools glslang-dev
  libglm-dev libtinygltf-dev nlohmann-json3-dev libstb-dev libopenexr-dev
  libgtest-dev
  libjs-chart.js
  libglfw3-dev libimgui-dev xvfb xauth
)
validator=0
# The npm package's version is pinned: a new validator may report new issues.
validator_version=2.0.0-dev.3.10
root="$(cd "$(dirname "$0")/.." && pwd)"
node_dir="${AGAA_NODE_DIR:-$root/build/node}"
install_validator() {
  if [ -f "$node_dir/node_modules/gltf-validator/package.json" ] &&
     grep -q "\"version\": \"$validator_version\"" "$node_dir/node_modules/gltf-validator/package.json"; then
    return
  fi
  echo "deps.sh: installing gltf-validator@$validator_version into $node_dir"
  mkdir -p "$node_dir"
  npm install --silent --no-audit --no-fund --prefix "$node_dir" "gltf-validator@$validator_version"
}
for arg in "$@"; do
  case "$arg" in
    --viewer) ;; # in the default list since the viewer test (xvfb) runs in CI
    --browser) packages+=(chromium) ;;
    --fuzz) packages+=(clang libclang-rt-14-dev) ;;
    --validator)
      packages+=(nodejs)
      # Debian's nodejs needs its npm package; NodeSource's nodejs bundles npm (and conflicts with it).
      command -v npm >/dev/null || packages+=(npm)
      validator=1 ;;
    -h|--help) sed -n '2,10p' "$0"; exit 0 ;;
    *) echo "deps.sh: unknown option '$arg' (allowed: --viewer, --browser, --fuzz, --validator)" >&2; exit 2 ;;
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
  if ((validator)); then install_validator; fi
  exit 0
fi

echo "deps.sh: installing ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
if ((validator)); then install_validator; fi
