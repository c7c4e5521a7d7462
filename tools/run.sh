#!/usr/bin/env bash
# The main job: installs what is missing, builds Release, renders the built-in
# default scene and the real ship (../shared/scenes) with every method into out/ (EXR, PNG,
# stats JSON, graph dump), the real scenes with AGAA and its aggregates, and ends with the
# benchmark sweep on the default scene and the ship: out/bench/report.html.
#   tools/run.sh            (AGAA_RENDER_FLAGS adds agaa-render flags, e.g. "--device NAME")
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
tools/deps.sh
build="${AGAA_BUILD_DIR:-build/release}"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DAGAA_BUILD_TESTS=OFF >/dev/null
cmake --build "$build" -j"$(nproc)"
render="$build/tools/agaa_render/agaa-render"
mkdir -p out
# Every method at its paper setting (n = 8; AGAA c = 2), validation layer on.
for job in "reference 8 1" "noaa 1 1" "simple-complex 8 1" "fxaa 1 1" "sbaa 8 1" "streaming 8 1" "agaa 8 2"; do
  set -- $job
  name="default_$1"
  "$render" --builtin default --method "$1" --samples "$2" --aggregates "$3" --width 640 --height 360 \
    --validate --out "out/$name" --stats "out/$name.json" --graph "out/$name.dot" ${AGAA_RENDER_FLAGS:-}
done
# The clustering made visible: aggregate count per pixel (hue) and split (brightness).
"$render" --builtin default --method agaa --samples 8 --aggregates 2 --debug aggregates --width 640 --height 360 \
  --validate --out out/default_agaa_aggregates
# The real scenes of ../shared/scenes (used in place, never copied), with the lighting and exposure a
# user gets without flags: the ship (no lights: the default sun and sky), the chair (one sun: a fill
# sky), the cubes (one lamp: a fill sky). Each with AGAA and its aggregates, and the ship with
# every method.
scenes="${AGAA_SHARED_SCENES:-$root/../shared/scenes}"
if [ -f "$scenes/dutch_ship_medium/dutch_ship_medium_1k.gltf" ]; then
  for job in "reference 8 1" "noaa 1 1" "simple-complex 8 1" "fxaa 1 1" "sbaa 8 1" "streaming 8 1" "agaa 8 2"; do
    set -- $job
    "$render" --scene "$scenes/dutch_ship_medium/dutch_ship_medium_1k.gltf" --method "$1" --samples "$2" \
      --aggregates "$3" --width 640 --height 360 --validate --out "out/ship_$1" --stats "out/ship_$1.json" \
      ${AGAA_RENDER_FLAGS:-}
  done
  for pair in "ship dutch_ship_medium/dutch_ship_medium_1k.gltf" "chair MixedLightingExample/MixedLightingExample.gltf" \
    "cubes Cubes/Cubes.glb"; do
    set -- $pair
    "$render" --scene "$scenes/$2" --method agaa --width 640 --height 360 --validate --out "out/$1_agaa"
    "$render" --scene "$scenes/$2" --method agaa --width 640 --height 360 --validate --debug aggregates \
      --out "out/$1_agaa_aggregates"
  done
else
  echo "run.sh: $scenes holds no shared scenes (AGAA_SHARED_SCENES); the real-scene renders are skipped"
fi
echo
echo "out/ holds:"
ls -1 out | sed 's/^/  out\//'
# What accuracy costs in time, on the default scene: every method and setting, and the report.
bench_scenes=default
[ -f "$scenes/dutch_ship_medium/dutch_ship_medium_1k.gltf" ] && bench_scenes=default,ship
AGAA_SHARED_SCENES="$scenes" "$build/tools/agaa_bench/agaa-bench" --out out/bench --scenes "$bench_scenes" \
  --size 160x90 --frames 3 --warmup 1
echo "report: $root/out/bench/report.html"
