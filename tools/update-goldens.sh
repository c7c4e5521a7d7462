#!/usr/bin/env bash
# Regenerates the stored reference images in tests/golden/images (tests/README.md, "Golden
# images") and prints which changed and by how much. Run it after a change that is meant to
# change pixels (and only then); commit the new images with a commit message that says why
# each changed. Images whose pixels did not change are left untouched, byte for byte, so the
# diff holds exactly the goldens that moved.
#   tools/update-goldens.sh                 every scene
#   tools/update-goldens.sh 'gltf_*'        only the scenes matching a gtest filter (Every/Golden.*/NAME)
#   AGAA_GOLDEN_HOST_CASES=FILE tools/update-goldens.sh
#                                           a host's scenes instead: the goldens FILE lists, in
#                                           AGAA_GOLDEN_HOST_DIR (default: FILE's folder's goldens/;
#                                           tests/README.md, "A host's scenes")
# AGAA_BUILD_DIR (default build/release) is configured if needed and only test_golden is built.
set -euo pipefail
# A host's paths as the caller meant them, before the cd.
if [ -n "${AGAA_GOLDEN_HOST_CASES:-}" ]; then
  AGAA_GOLDEN_HOST_CASES="$(realpath "$AGAA_GOLDEN_HOST_CASES")"
  AGAA_GOLDEN_HOST_DIR="$(realpath -m "${AGAA_GOLDEN_HOST_DIR:-$(dirname "$AGAA_GOLDEN_HOST_CASES")/goldens}")"
  export AGAA_GOLDEN_HOST_CASES AGAA_GOLDEN_HOST_DIR
fi
[ -z "${AGAA_BUILD_DIR:-}" ] || AGAA_BUILD_DIR="$(realpath -m "$AGAA_BUILD_DIR")"
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
build="${AGAA_BUILD_DIR:-build/release}"
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DAGAA_BUILD_TESTS=ON >/dev/null
fi
if ! grep -q '^AGAA_TEST_PERTURB:STRING=none$' "$build/CMakeCache.txt"; then
  echo "update-goldens: $build is a perturbed build (AGAA_TEST_PERTURB); refusing to write goldens from it" >&2
  exit 2
fi
# Without a host's case file in the environment: the build's test discovery (gtest_discover_tests,
# after the link) lists test_golden's cases for ctest, and would list the host's instead.
env -u AGAA_GOLDEN_HOST_CASES -u AGAA_GOLDEN_HOST_DIR cmake --build "$build" --target test_golden -j2
lvp="$(ls /usr/share/vulkan/icd.d/lvp_icd.*.json 2>/dev/null | head -n1 || true)"
export VK_ICD_FILENAMES="${VK_ICD_FILENAMES:-$lvp}"
golden="${AGAA_GOLDEN_HOST_DIR:-$root/tests/golden/images}"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
filter="Every/Golden.*/${1:-*}"
# Two shards, one per core; every render must succeed (validation-clean) or nothing is written.
status=0
for shard in 0 1; do
  GTEST_TOTAL_SHARDS=2 GTEST_SHARD_INDEX=$shard AGAA_GOLDEN_WRITE="$tmp/images" \
    "$build/tests/golden/test_golden" --gtest_filter="$filter" >"$tmp/log$shard" 2>&1 &
done
for job in $(jobs -p); do
  wait "$job" || status=1
done
if [ "$status" != 0 ]; then
  cat "$tmp/log0" "$tmp/log1" >&2
  echo "update-goldens: rendering failed; tests/golden/images left as it was" >&2
  exit 1
fi
grep -h '^\[ golden \]' "$tmp/log0" "$tmp/log1" | sed 's/^\[ golden \] //' | LC_ALL=C sort >"$tmp/results"
grep -h 'SKIPPED\|loader refuses\|is missing' "$tmp/log0" "$tmp/log1" | grep -v '^\[  SKIPPED \] [0-9]' || true
unchanged=0 changed=0 added=0 removed=0
while IFS= read -r line; do
  stem="${line%%: *}"
  what="${line#*: }"
  case "$what" in
    unchanged) unchanged=$((unchanged + 1)); continue ;;
    new) added=$((added + 1)); echo "new      $stem" ;;
    *) changed=$((changed + 1)); echo "changed  $stem: ${what#changed, }" ;;
  esac
  mkdir -p "$golden/$(dirname "$stem")"
  cp "$tmp/images/$stem.exr" "$tmp/images/$stem.png" "$golden/$(dirname "$stem")/"
done <"$tmp/results"
# Goldens no case produces any more, in the scenes rendered this run (a scene that was not
# rendered, e.g. a missing asset, keeps its images).
for dir in "$tmp/images"/*/; do
  scene="$(basename "$dir")"
  [ -d "$golden/$scene" ] || continue
  for f in "$golden/$scene"/*.exr; do
    [ -e "$f" ] || continue
    stem="$scene/$(basename "$f" .exr)"
    if [ ! -e "$tmp/images/$stem.exr" ]; then
      rm -f "$golden/$stem.exr" "$golden/$stem.png"
      removed=$((removed + 1))
      echo "removed  $stem"
    fi
  done
done
echo "update-goldens: $unchanged unchanged, $changed changed, $added new, $removed removed ($(du -sh --apparent-size "$golden" | cut -f1) in $golden)"
if [ $((changed + added + removed)) -gt 0 ]; then
  echo "update-goldens: commit them with a message that says why each changed golden changed"
fi
