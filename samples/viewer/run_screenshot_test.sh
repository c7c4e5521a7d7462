#!/usr/bin/env bash
# viewer.screenshots: agaa-viewer under Xvfb, every method in turn and then the split and
# difference views (--script cycle-methods), with
# the validation layer and synchronisation validation on. Fails on a non-zero exit, a blank
# scene in any presented frame (the viewer's own check, per method), a missing screenshot, or
# any VUID-/UNASSIGNED-/SYNC- message in the output. Skips (exit 77) only when no X server can
# be started and CI is not set; under CI it fails instead.
#   run_screenshot_test.sh VIEWER OUT_DIR
set -uo pipefail
viewer="$1"
out="$2"
rm -rf "$out"
mkdir -p "$out"
log="$out/viewer.log"

no_x() {
  if [ -n "${CI:-}" ] && [ "${CI}" != "false" ]; then
    echo "viewer.screenshots: FAILED: $1, and CI is set (tools/deps.sh installs xvfb)" >&2
    exit 1
  fi
  echo "viewer.screenshots: SKIPPED: $1 (install xvfb: tools/deps.sh)"
  exit 77
}
command -v xvfb-run >/dev/null || no_x "xvfb-run not found"
# Can an X server start at all? (xvfb-run exits non-zero when Xvfb fails.)
xvfb-run -a -s "-screen 0 1024x768x24" true >/dev/null 2>&1 || no_x "Xvfb cannot start"

AGAA_VALIDATE=1 xvfb-run -a -s "-screen 0 1024x768x24" \
  "$viewer" --builtin railings --width 640 --height 360 --validate \
  --script cycle-methods --frames 2 --screenshot-dir "$out" >"$log" 2>&1
rc=$?
cat "$log"
fail=0
if [ $rc -ne 0 ]; then echo "viewer.screenshots: FAILED: agaa-viewer exited $rc" >&2; fail=1; fi
if grep -Eq 'VUID-|UNASSIGNED-|SYNC-' "$log"; then
  echo "viewer.screenshots: FAILED: validation messages in the output:" >&2
  grep -E 'VUID-|UNASSIGNED-|SYNC-' "$log" | head -20 >&2
  fail=1
fi
grep -q "validation on" "$log" || { echo "viewer.screenshots: FAILED: validation was not on" >&2; fail=1; }
methods=$(grep -c '^script: .*not blank.*, 0 validation errors$' "$log")
shots=$(ls "$out"/*.png 2>/dev/null | wc -l)
# Every method alone, then agaa split against the reference and agaa's difference from it.
expected=$(($("$viewer" --help | sed -n 's/^methods://p' | wc -w) + 2))
if [ "$methods" -ne "$expected" ] || [ "$shots" -ne "$expected" ]; then
  echo "viewer.screenshots: FAILED: $methods methods passed the checks and $shots screenshots were written; expected $expected" >&2
  fail=1
fi
if [ $fail -eq 0 ]; then echo "viewer.screenshots: $methods steps, every frame non-blank and validation-clean"; fi
exit $fail
