#!/usr/bin/env bash
# The main job: installs what is missing, builds Release, renders the built-in
# default scene and the real ship (../shared/scenes) with every method into out/ (EXR, PNG,
# stats JSON, graph dump), the real scenes with AGAA and its aggregates, and ends with the
# benchmark sweep (out/bench/report.html) and the results page written from it (out/results.md).
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
# What accuracy costs in time: every method at its main setting (n = 8, AGAA c = 2, SBAA S = 4,
# streaming S = 3; temporal AA and AGAA + TAA, issue 51) against the converged truth on the default
# scene, the ship, foliage, spikes and the chain-link fence (thin glossy metal before a wall, issue
# 49), still and along a 4-frame sideways truck of the camera (each frame against its own truth),
# each with and without geometric specular AA (--curvature-roughness),
# and AGAA's knob (--agaa-tolerance auto, never, 30 and 0, the reference) drawn as a curve:
# out/bench/report.html, and out/results.md written from the same run (docs/results.md is the
# committed copy: tools/results-page.py out/bench --write docs/results.md --readme README.md).
# The allocator thresholds keep lavapipe's large per-frame buffers mapped between frames; without
# them frame times on lavapipe swing up to 4x from job to job.
bench_scenes=default,foliage,spikes,chainlink
[ -f "$scenes/dutch_ship_medium/dutch_ship_medium_1k.gltf" ] && bench_scenes=default,ship,foliage,spikes,chainlink
MALLOC_TRIM_THRESHOLD_=1073741824 MALLOC_MMAP_THRESHOLD_=33554432 AGAA_SHARED_SCENES="$scenes" \
  tools/results-page.py --record out/bench -- "$build/tools/agaa_bench/agaa-bench" --out out/bench \
  --scenes "$bench_scenes" --methods noaa,fxaa,taa,reference,simple-complex,sbaa,streaming,agaa,agaa-taa \
  --samples 8 --aggregates 2 --tolerances auto,never,30,0 --size 160x90 --frames 5 --warmup 2 --temporal 4 \
  --temporal-path truck --specular-aa off,on
tools/results-page.py out/bench --write out/results.md
echo "report: $root/out/bench/report.html"
echo "results: $root/out/results.md"
