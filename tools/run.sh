#!/usr/bin/env bash
# The main job: installs what is missing, builds Release, renders the built-in
# default scene with every method into out/ (EXR, PNG, stats JSON, graph dump).
#   tools/run.sh [extra agaa-render flags]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
tools/deps.sh
build="${AGAA_BUILD_DIR:-build/release}"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DAGAA_BUILD_TESTS=OFF >/dev/null
cmake --build "$build" -j"$(nproc)"
render="$build/tools/agaa_render/agaa-render"
mkdir -p out
"$render" --builtin default --method reference --samples 8 --width 640 --height 360 \
  --out out/default_reference8 --stats out/default_reference8.json --graph out/default_reference8.dot "$@"
"$render" --builtin default --method noaa --width 640 --height 360 \
  --out out/default_noaa --stats out/default_noaa.json "$@"
echo
echo "out/ holds:"
ls -1 out | sed 's/^/  out\//'
