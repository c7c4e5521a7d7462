#!/usr/bin/env bash
# Renders a tiny benchmark sweep, copies its output elsewhere (the report must not depend on where
# it was written), opens report.html in headless Chromium and checks the page's own verdict:
# document.body.dataset.rendered = "ok:<charts>:<images>" once every chart was built and every
# image loaded. Keeps a screenshot and the report in ARTEFACTS.
#   report_browser_test.sh AGAA_BENCH CHROMIUM ARTEFACTS
set -euo pipefail
bench="$1" chromium="$2" artefacts="$3"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
rm -rf "$artefacts"
mkdir -p "$artefacts"

# 2 scenes x reference at n = 4 and 8 (so the growth-with-n charts appear) + noaa + AGAA (8, 2)
# at two tolerances (its knob's curve): 8 jobs, 64x64.
"$bench" --out "$work/run" --scenes plane,railings --methods reference,noaa,agaa --samples 4,8 --aggregates 2 \
  --tolerances auto,never --size 64x64 --frames 1 --warmup 0 --temporal 2 >"$artefacts/bench.log" 2>&1 || {
  cat "$artefacts/bench.log"
  echo "FAIL: agaa-bench exited non-zero"
  exit 1
}
cp -r "$work/run" "$artefacts/report"
report="$artefacts/report/report.html"

chrome=("$chromium" --headless --no-sandbox --disable-gpu --disable-quic --no-first-run
  --disable-background-networking --disable-component-update --disable-sync
  --user-data-dir="$(mktemp -d -p "$work")" --virtual-time-budget=10000)
"${chrome[@]}" --dump-dom "file://$report" >"$artefacts/dom.html" 2>"$artefacts/chromium.log" || {
  tail -20 "$artefacts/chromium.log"
  echo "FAIL: chromium --dump-dom exited non-zero"
  exit 1
}
state="$(grep -o 'data-rendered="[^"]*"' "$artefacts/dom.html" | head -n1 | sed 's/^data-rendered="//; s/"$//')"
echo "report state: ${state:-<not set>}"
# Per scene: accuracy vs time, vs memory, per-pass bars, growth of time and of memory with n.
expected_charts=10
if [[ ! "$state" =~ ^ok:([0-9]+):([0-9]+)$ ]]; then
  echo "FAIL: the page did not report ok (charts or images failed, or the script did not run)"
  exit 1
fi
if ((BASH_REMATCH[1] != expected_charts)); then
  echo "FAIL: ${BASH_REMATCH[1]} charts built, expected $expected_charts"
  exit 1
fi
if ((BASH_REMATCH[2] < 6)); then
  echo "FAIL: only ${BASH_REMATCH[2]} images on the page; expected the crops of every job"
  exit 1
fi
# AGAA's knob: per scene, (4, 2) and (8, 2) at two tolerances each, on the time and memory charts.
knobs="$(grep -o 'data-knob-curves="[^"]*"' "$artefacts/dom.html" | head -n1 | sed 's/^data-knob-curves="//; s/"$//')"
if [ "$knobs" != 8 ]; then
  echo "FAIL: ${knobs:-no} knob curves drawn, expected 8 (2 scenes x 2 charts x 2 (n, c))"
  exit 1
fi
# Self-contained: nothing on the page is fetched from the network.
if grep -Eq '(src|href)="(https?:)?//' "$artefacts/dom.html"; then
  echo "FAIL: the page references a network resource:"
  grep -Eo '(src|href)="(https?:)?//[^"]*"' "$artefacts/dom.html" | head
  exit 1
fi

"${chrome[@]}" --screenshot="$artefacts/report.png" --window-size=1280,2000 "file://$report" \
  >>"$artefacts/chromium.log" 2>&1
if [ ! -s "$artefacts/report.png" ]; then
  echo "FAIL: no screenshot written"
  exit 1
fi
echo "PASS: $state; screenshot $artefacts/report.png"
