#!/usr/bin/env bash
# The Khronos glTF-Validator over glTF / GLB files (tools/gltf_validator/validate.js): one line
# per file with its error, warning and info counts. Exit 0 when every file is valid, 1 when one
# is not, 2 when the validator is missing or a file cannot be read.
#   tools/gltf-validate.sh FILE...       (tools/deps.sh --validator installs the validator)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
node_dir="${AGAA_NODE_DIR:-$root/build/node}"
if ! command -v node >/dev/null; then
  echo "gltf-validate: node is not installed (tools/deps.sh --validator)" >&2
  exit 2
fi
NODE_PATH="$node_dir/node_modules" exec node "$root/tools/gltf_validator/validate.js" "$@"
