#!/usr/bin/env bash
# Proof that the golden suite can fail (issues 17 and 37): builds test_golden with a deliberate
# shader error (AGAA_TEST_PERTURB, top-level CMakeLists.txt), runs every golden against the stored
# images and asserts what each variant must catch:
#   brdf     every BRDF 1 % darker: every golden it renders whose pixels the change reaches fails;
#   methods  one error in each method family's own logic (AGAA: sample 0's aggregate-id bit
#            flipped; FXAA: the end-of-edge blend lost; SBAA and streaming: no merge;
#            Simple/Complex: every pixel simple): every FXAA, SBAA, streaming and Simple/Complex
#            golden of the built-in scenes but plane (flat: nothing to merge, classify or blend)
#            fails, and every AGAA c = 2 and 4 golden at n = 4 and 8 of the built-in scenes; every
#            golden no error can reach (reference, no-AA, AGAA c = 1) is still bit for bit its own.
#            (At n = 32 a flat pixel may already hold two aggregates of one plane, lit alike:
#            moving sample 0 between them changes plane's image by rounding only.)
#   scene    every vertex 1/16 pixel right, the constant sky 1 % darker and a tone-map black
#            level of 1e-3, run on the goldens neither brdf nor methods failed
#            (the emissive strands on black, the sky seen alone, the unlit scene's black images):
#            every golden it runs fails.
# With all three run, every golden must have failed under one of them. The variants run in the
# order given (by default methods, brdf, scene): methods renders every golden (its check reads
# them all); each other variant renders only the goldens no earlier variant failed
# (AGAA_GOLDEN_ONLY, tests/golden/test_golden.cpp) instead of every golden again.
# Each variant rebuilds test_golden in the plain build folder of tools/test.sh ($AGAA_BUILD_DIR,
# default build/test; configured as tools/test.sh does when it does not exist yet): only the
# shaders and the sources that embed a shader whose SPIR-V changed recompile. On exit (also on
# failure) the folder is reconfigured with AGAA_TEST_PERTURB=none and test_golden rebuilt.
# Exit status 0 when everything is caught; each variant's per-golden numbers are kept in
# <build>/perturb-results-<variant>.txt.
#   tools/perturb-test.sh [brdf|methods|scene]...
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
lvp="$(ls /usr/share/vulkan/icd.d/lvp_icd.*.json 2>/dev/null | head -n1 || true)"
export VK_ICD_FILENAMES="${VK_ICD_FILENAMES:-$lvp}"
variants=("$@")
[ ${#variants[@]} -gt 0 ] || variants=(methods brdf scene)
builtins="furball metal foliage bamboo railings default spikes glints" # plane apart (above)
build="${AGAA_BUILD_DIR:-build/test}"
case "$build" in /*) ;; *) build="$root/$build" ;; esac
tmp="$(mktemp -d)"
restore() {
  echo "perturb-test: restoring $build (AGAA_TEST_PERTURB=none)"
  cmake -S . -B "$build" -DAGAA_TEST_PERTURB=none >/dev/null
  cmake --build "$build" --target test_golden -j"$(nproc)" >/dev/null
}
trap 'status=$?; rm -rf "$tmp"; restore || status=1; exit $status' EXIT
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DAGAA_BUILD_TESTS=ON -DAGAA_WERROR=ON >/dev/null
fi
fail=0
check() { # check DESCRIPTION COUNT: COUNT must be 0
  if [ "$2" != 0 ]; then
    echo "perturb-test: FAILED: $1 ($2)" >&2
    fail=1
  fi
}
count() { grep -cE "$1" "$2" || true; }
# The goldens (scene/case stems) that no variant so far failed, of those the first full run
# rendered ($tmp/all).
uncaught() {
  cat "$tmp"/*.result 2>/dev/null | sed -n 's/^\([^:]*\):.* FAIL$/\1/p' | LC_ALL=C sort -u >"$tmp/caught"
  LC_ALL=C comm -23 "$tmp/all" "$tmp/caught"
}
# The scenes of the stems in file $1, as a gtest filter.
scene_filter() { cut -d/ -f1 "$1" | uniq | sed 's/-/_/g; s|^|Every/Golden.*/|' | paste -sd: -; }
for variant in "${variants[@]}"; do
  case "$variant" in brdf | methods | scene) ;; *)
    echo "perturb-test: unknown variant '$variant': allowed values are brdf, methods, scene" >&2
    exit 2 ;;
  esac
  filter="*"
  unset AGAA_GOLDEN_ONLY
  if [ "$variant" != methods ] && [ -f "$tmp/all" ]; then
    uncaught >"$tmp/only"
    if [ ! -s "$tmp/only" ]; then
      echo "perturb-test: $variant: every golden already failed; not run"
      continue
    fi
    filter="$(scene_filter "$tmp/only")"
    export AGAA_GOLDEN_ONLY="$tmp/only"
    echo "perturb-test: $variant: the $(wc -l <"$tmp/only") goldens no variant failed yet"
  fi
  start=$SECONDS
  cmake -S . -B "$build" -DAGAA_TEST_PERTURB="$variant" >/dev/null
  cmake --build "$build" --target test_golden -j"$(nproc)" >/dev/null
  echo "perturb-test: $variant: rebuilt test_golden in $((SECONDS - start)) s"
  start=$SECONDS
  for shard in 0 1; do
    GTEST_TOTAL_SHARDS=2 GTEST_SHARD_INDEX=$shard "$build/tests/golden/test_golden" --gtest_filter="$filter" \
      >"$tmp/$variant.$shard" 2>&1 &
  done
  status=0
  for job in $(jobs -p); do
    wait "$job" || status=1
  done
  result="$tmp/$variant.result"
  grep -h '^\[ golden \]' "$tmp/$variant.0" "$tmp/$variant.1" | sed 's/^\[ golden \] //' | LC_ALL=C sort >"$result"
  cp "$result" "$build/perturb-results-$variant.txt" # every golden's numbers, for the record
  total=$(wc -l <"$result")
  [ -f "$tmp/all" ] || [ "$filter" != "*" ] || cut -d: -f1 "$result" | LC_ALL=C sort -u >"$tmp/all"
  echo "perturb-test: $variant: $(count ' FAIL$' "$result") of $total goldens fail ($((SECONDS - start)) s)"
  check "$variant: the golden test did not fail" "$((1 - status))"
  check "$variant: no golden ran" "$((total == 0))"
  # test_golden skips what AGAA_GOLDEN_ONLY does not name, so a stem it never rendered would
  # otherwise go unnoticed: every listed golden must have run.
  if [ -n "${AGAA_GOLDEN_ONLY:-}" ]; then
    check "$variant: listed goldens that did not run" \
      "$(cut -d: -f1 "$result" | LC_ALL=C sort -u | LC_ALL=C comm -13 - "$AGAA_GOLDEN_ONLY" | wc -l)"
  fi
  case "$variant" in
    brdf)
      check "brdf: goldens the 1 % BRDF change reached that still pass" \
        "$(grep ' PASS$' "$result" | grep -vc ' 0 pixels differ' || true)" ;;
    scene)
      check "scene: goldens that still pass" "$(count ' PASS$' "$result")" ;;
    methods)
      check "methods: reference, no-AA or AGAA c = 1 goldens changed" \
        "$(grep -E '^[^/]+/(reference|noaa)-|^[^/]+/agaa-[a-z]+-n[0-9]+-c1:' "$result" | grep -vc ' 0 pixels differ' || true)"
      for scene in $builtins plane; do
        check "methods: $scene AGAA c >= 2 goldens at n = 4, 8 that still pass" \
          "$(count "^$scene/agaa-[a-z]+-n[48]-c[24]:.* PASS$" "$result")"
      done
      for scene in $builtins; do
        check "methods: $scene FXAA, SBAA, streaming or Simple/Complex goldens that still pass" \
          "$(count "^$scene/(fxaa|sbaa|streaming|simple-complex)-.* PASS$" "$result")"
      done ;;
  esac
  echo "perturb-test: $variant: still passing, per scene:"
  grep ' PASS$' "$result" | cut -d/ -f1 | uniq -c | sed 's/^/  /' || true
done
if [ -f "$tmp/brdf.result" ] && [ -f "$tmp/methods.result" ]; then
  # Every golden failed under some variant.
  missed="$(uncaught)"
  [ -z "$missed" ] || echo "$missed" | sed 's/^/  no variant failed: /' >&2
  check "goldens no variant failed" "$(echo "$missed" | sed '/^$/d' | wc -l)"
  [ -n "$missed" ] || echo "perturb-test: every one of $(wc -l <"$tmp/all") goldens failed under a variant"
fi
exit "$fail"
