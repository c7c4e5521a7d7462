#!/usr/bin/env bash
# Issue 16: the Khronos glTF-Validator (tools/gltf-validate.sh) against the scene files the tests
# use, and the loader against files the validator calls invalid.
#   1. valid: every built-in and adversarial scene as tools/scenegen writes it, and the shared
#      real scenes (../shared/scenes) when present: the validator reports no error;
#   2. invalid: each file of tests/scene/invalid_gltf/ is invalid to the validator (so the corpus
#      tests what it claims; so is the adversarial hard-degenerate), and agaa-render either refuses it (exit 2, a message naming the file)
#      or repairs it with a warning naming the file (exit 0); it never crashes, never exits with an
#      internal error, and never renders an invalid file without a word.
#   validator_test.sh ROOT SCENEGEN AGAA_RENDER SHARED_SCENES_DIR WORK_DIR
set -uo pipefail
root="$1" scenegen="$2" render="$3" shared="$4" work="$5"
validate="$root/tools/gltf-validate.sh"
fail=0
rm -rf "$work" && mkdir -p "$work/scenes"
for kind in $("$scenegen" --list | cut -d" " -f1); do
  "$scenegen" --kind "$kind" --out "$work/scenes/$kind.gltf" >/dev/null || { echo "FAIL: scenegen $kind"; fail=1; }
done
# hard-degenerate is invalid by design (zero-area and repeated-index triangles the loader drops
# with a warning): it joins the invalid files below.
mv "$work/scenes/hard-degenerate.gltf" "$work/hard-degenerate.gltf"
files=("$work"/scenes/*.gltf)
for f in dutch_ship_medium/dutch_ship_medium_1k.gltf MixedLightingExample/MixedLightingExample.gltf Cubes/Cubes.glb; do
  if [ -f "$shared/$f" ]; then files+=("$shared/$f"); else echo "note: $shared/$f is missing; not validated"; fi
done
"$validate" "${files[@]}"
rc=$?
if [ "$rc" -eq 2 ]; then echo "FAIL: the validator did not run (tools/deps.sh --validator)"; exit 1; fi
if [ "$rc" -ne 0 ]; then echo "FAIL: a scene file the tests use is invalid (above)"; fail=1; fi
echo "valid: ${#files[@]} files"

for f in "$root"/tests/scene/invalid_gltf/*.gltf "$work/hard-degenerate.gltf"; do
  name="$(basename "$f")"
  "$validate" "$f" >"$work/validator.txt" 2>&1
  if [ $? -ne 1 ]; then
    echo "FAIL: $name: the validator does not call it invalid:"; cat "$work/validator.txt"; fail=1; continue
  fi
  "$render" --scene "$f" --width 8 --height 8 --out "$work/render" >"$work/out.txt" 2>"$work/err.txt"
  code=$?
  first="$(grep -m1 . "$work/err.txt")"
  if [ "$code" -eq 2 ] && grep -q "$name" "$work/err.txt" && ! grep -q "internal error" "$work/err.txt"; then
    echo "refused  $name: $first"
  elif [ "$code" -eq 0 ] && grep -q "^warning: .*$name" "$work/err.txt"; then
    echo "repaired $name: $first"
  else
    echo "FAIL: $name: exit $code (expected 2 naming the file, or 0 with a warning naming it)"
    cat "$work/err.txt"; fail=1
  fi
done
exit "$fail"
