#!/usr/bin/env bash
# Measures how AGAA's seed threshold t (Equation 1 units) trades shading events for error:
# for each scene and t, the mean aggregates lit per pixel and the error against the
# per-sample reference at the same n (display RMSE from imgdiff). Used to choose the default t
# (agaa/aggregate/README.md). Needs a build: AGAA_BUILD_DIR (default build/release).
#   tools/measure_seed_threshold.sh [WIDTHxHEIGHT] [n] [c]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${AGAA_BUILD_DIR:-$root/build/release}"
size="${1:-320x180}"; n="${2:-8}"; c="${3:-2}"
w="${size%x*}"; h="${size#*x}"
render="$build/tools/agaa_render/agaa-render"; diff="$build/tools/imgdiff/imgdiff"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
printf "%-9s %8s %10s %12s\n" scene t "agg/pixel" "display-RMSE"
for scene in plane railings foliage furball metal; do
  "$render" --builtin "$scene" --method reference --samples "$n" --width "$w" --height "$h" --out "$tmp/ref" >/dev/null
  for t in 0.005 0.02 0.05 0.2 1.0; do
    "$render" --builtin "$scene" --method agaa --samples "$n" --aggregates "$c" --seed-threshold "$t" \
      --width "$w" --height "$h" --out "$tmp/agaa" --stats "$tmp/agaa.json" >/dev/null
    mean=$(python3 -c "import json;print('%.3f'%json.load(open('$tmp/agaa.json'))['shading_events_per_pixel']['mean'])")
    rmse=$("$diff" "$tmp/agaa.exr" "$tmp/ref.exr" | sed -E 's/display RMSE ([0-9.]+).*/\1/')
    printf "%-9s %8s %10s %12s\n" "$scene" "$t" "$mean" "$rmse"
  done
done
