#!/usr/bin/env bash
# A GPU report in one command: installs what is missing, builds Release (only agaa-timings and
# agaa-render), finds the Vulkan device, runs a bounded timing sweep and rewrites docs/gpu.md with
# the device, driver, commit, date, the exact commands and the tables (frame and lighting ms per
# job, events/px, AGAA's lighting ms per shading event against the reference's, AGAA's frame
# against Simple/Complex's, bytes per pixel). Meant for a machine with a GPU: about 8 minutes at
# most on an H100, build included. CI never runs it (CI has no GPU).
#   tools/gpu-report.sh
# Environment (paths relative to the repository root):
#   AGAA_GPU_REPORT_SIZE       WxH (default 1280x720)
#   AGAA_GPU_REPORT_FRAMES     timed frames per job (default 15 on a GPU, 5 on a CPU device)
#   AGAA_GPU_REPORT_WARMUP     warm-up frames per job (default 5 on a GPU, 2 on a CPU device)
#   AGAA_GPU_REPORT_SCENES     built-in scenes, comma-separated (default foliage,furball,metal,chainlink)
#   AGAA_GPU_REPORT_OUT        the page to write (default docs/gpu.md)
#   AGAA_GPU_REPORT_BUILD_DIR  build folder (default build/gpu-report); one with a CMakeCache.txt is
#                              built as it is configured, never reconfigured
# A smoke test on lavapipe, at a size where it takes a minute:
#   AGAA_GPU_REPORT_SIZE=64x36 AGAA_GPU_REPORT_FRAMES=1 AGAA_GPU_REPORT_SCENES=foliage \
#     AGAA_GPU_REPORT_OUT=/tmp/gpu-report.md tools/gpu-report.sh
# The raw agaa-timings output (JSON and logs) stays in out/gpu-report/.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"

size="${AGAA_GPU_REPORT_SIZE:-1280x720}"
scenes="${AGAA_GPU_REPORT_SCENES:-foliage,furball,metal,chainlink}"
out="${AGAA_GPU_REPORT_OUT:-docs/gpu.md}"
build="${AGAA_GPU_REPORT_BUILD_DIR:-build/gpu-report}"
work=out/gpu-report
# The sweep, kept bounded so the whole script fits in 8 minutes on an H100: two sample counts, the
# paper's c = 2, and at n = 8 a second light count (64 generated point lights: lighting-bound).
extra_lights=64
# n = 8: the samples path pinned (the auto path's choice at n <= 16, named so a change of the auto
# rule cannot silently change the report); n = 32: the auto path (accumulate). Each AGAA job once
# at its default shading rate and once at `never` (no pixel shaded per sample).
jobs8="reference:8,simple-complex:8,agaa-samples:8:2,agaa-samples:8:2:agaa-tolerance=never"
jobs32="reference:32,simple-complex:32,agaa:32:2,agaa:32:2:agaa-tolerance=never"

die() {
  echo "gpu-report.sh: $*" >&2
  exit 1
}
# A bad setting (an environment value or scene name) exits 2, as every tool of the project does.
bad_input() {
  echo "gpu-report.sh: $*" >&2
  exit 2
}
# Every failure ends with one line that says so, how long it ran, and that the page is untouched
# (it is written only at the very end, from a temporary file).
tmp=
on_exit() {
  local rc=$?
  if ((rc)); then
    [ -z "$tmp" ] || rm -f "$tmp"
    echo "gpu-report.sh: FAILED (exit $rc) after $SECONDS s; $out was not written" >&2
  fi
}
trap on_exit EXIT

case "$size" in
  [1-9]*x[1-9]*) ;;
  *) bad_input "AGAA_GPU_REPORT_SIZE '$size' is not WxH, e.g. 1280x720" ;;
esac
[ -n "$scenes" ] || bad_input "AGAA_GPU_REPORT_SCENES is empty"
command -v python3 >/dev/null || die "python3 is needed to write the report (tools/deps.sh installs it)"

# The commands the page lists are the ones run here, recorded as they run (an argument quoted only
# when a shell would need it), so the page can never drift from what produced its figures.
mkdir -p "$work"
commands="$work/commands.txt"
: >"$commands"
run() {
  local a line=""
  for a in "$@"; do
    if [[ $a =~ ^[A-Za-z0-9_./:=,+@%-]+$ ]]; then line+=" $a"; else line+=" $(printf '%q' "$a")"; fi
  done
  echo "${line# }" >>"$commands"
  "$@"
}

# Timings under the validation layer would measure the layer: it stays off whatever the caller's
# environment says.
unset AGAA_VALIDATE

echo "gpu-report.sh: packages"
run tools/deps.sh

# Configure only a new build folder: an existing one (e.g. build/test for a smoke test) keeps its
# own cache variables, and the page states the build type it really had.
echo "gpu-report.sh: building agaa-timings and agaa-render in $build"
build_start=$SECONDS
if [ ! -f "$build/CMakeCache.txt" ]; then
  run cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DAGAA_BUILD_TESTS=OFF >/dev/null ||
    die "cmake could not configure $build"
fi
build_type="$(sed -n 's/^CMAKE_BUILD_TYPE:[A-Z]*=//p' "$build/CMakeCache.txt")"
[ "$build_type" = Release ] ||
  echo "gpu-report.sh: warning: $build is a '${build_type:-no type}' build, not Release; the page says so" >&2
# Only the two tools: the library, its shaders and the harness come with them; tests never.
run cmake --build "$build" --target agaa-timings agaa-render -j"${CMAKE_BUILD_PARALLEL_LEVEL:-$(nproc)}" ||
  die "the build of agaa-timings and agaa-render in $build failed"
build_s=$((SECONDS - build_start))
render="$build/tools/agaa_render/agaa-render"
timings="$build/tools/agaa_timings/agaa-timings"
if [ ! -x "$render" ] || [ ! -x "$timings" ]; then die "the build left no $render or $timings"; fi

# The device: both tools pick the same one with no --device (the best-ranked Vulkan 1.3 device:
# discrete, integrated, virtual GPU, then CPU), so a GPU wins over lavapipe whenever there is one;
# agaa-timings has no --device flag. --caps names it, its type, driver and Vulkan version.
echo "gpu-report.sh: device"
run "$render" --caps >"$work/caps.txt" || die "no usable Vulkan device: $("$render" --caps 2>&1 | tail -n1)"
cat "$work/caps.txt"
device_line="$(sed -n 's/^device  *//p' "$work/caps.txt")"
[ -n "$device_line" ] || die "agaa-render --caps printed no device line"
device_name="${device_line% (*}"
cpu_device=0
case "$device_line" in
  *"(CPU)") cpu_device=1 ;;
esac
if ((cpu_device)); then
  # Still runs (a smoke test, or a machine whose GPU has no Vulkan 1.3 driver); the page says so.
  echo "gpu-report.sh: warning: the only Vulkan device is $device_name, a CPU implementation; the" \
    "page will say these are not GPU figures (at 1280x720 this takes hours: set AGAA_GPU_REPORT_SIZE)" >&2
fi
frames="${AGAA_GPU_REPORT_FRAMES:-$((cpu_device ? 5 : 15))}"
warmup="${AGAA_GPU_REPORT_WARMUP:-$((cpu_device ? 2 : 5))}"
case "$frames$warmup" in
  *[!0-9]*) bad_input "AGAA_GPU_REPORT_FRAMES '$frames' and AGAA_GPU_REPORT_WARMUP '$warmup' must be integers" ;;
esac
timing_env=()
if ((cpu_device)); then
  # As tools/run.sh: keeps lavapipe's large per-frame buffers mapped between frames; without it
  # frame times on lavapipe swing up to 4x from job to job.
  timing_env=(env MALLOC_TRIM_THRESHOLD_=1073741824 MALLOC_MMAP_THRESHOLD_=33554432)
fi

# Every scene is checked before the sweep, so a scene this build lacks fails in seconds with its
# name, not minutes later inside agaa-timings. The help's list is free; a name not in it (e.g. an
# adversarial hard-* scene) gets one tiny render.
known="$("$render" --help | sed -n 's/^built-in scenes: *//p')"
IFS=, read -r -a scene_list <<<"$scenes"
for s in "${scene_list[@]}"; do
  case " $known " in
    *" $s "*) continue ;;
  esac
  "$render" --builtin "$s" --method noaa --samples 1 --aggregates 1 --width 8 --height 8 \
    --out "$work/probe_$s" >/dev/null 2>"$work/probe_$s.log" ||
    bad_input "scene '$s' is not a built-in scene of this build ($(tail -n1 "$work/probe_$s.log")); built-in: $known"
done

# The sweep: one agaa-timings process per sample count, every scene in it; its --json output is
# what the tables are made of (the text goes to the terminal and to a log).
sweep_start=$SECONDS
common=(--scenes "$scenes" --size "$size" --frames "$frames" --warmup "$warmup")
rm -f "$work"/n8.json "$work"/n32.json
echo "gpu-report.sh: sweep n = 8 (and $extra_lights extra lights)"
run "${timing_env[@]}" "$timings" "${common[@]}" --extra-lights "0,$extra_lights" --jobs "$jobs8" \
  --json "$work/n8.json" 2>&1 | tee "$work/n8.log" || die "agaa-timings failed at n = 8 (log: $work/n8.log)"
echo "gpu-report.sh: sweep n = 32"
run "${timing_env[@]}" "$timings" "${common[@]}" --jobs "$jobs32" --json "$work/n32.json" 2>&1 |
  tee "$work/n32.log" || die "agaa-timings failed at n = 32 (log: $work/n32.log)"
if [ ! -s "$work/n8.json" ] || [ ! -s "$work/n32.json" ]; then die "agaa-timings wrote no JSON into $work"; fi
sweep_s=$((SECONDS - sweep_start))

# The commit measured: a tree with uncommitted changes to tracked files is marked -dirty (git diff
# reads the index without rewriting it, unlike git status). A copy without .git says so.
if commit="$(git rev-parse --short HEAD 2>/dev/null)"; then
  git diff --quiet HEAD -- 2>/dev/null || commit="$commit-dirty"
else
  commit="unknown (no git checkout)"
fi

# The page, written to a temporary file and moved into place only when complete.
echo "gpu-report.sh: writing $out"
mkdir -p "$(dirname "$out")"
tmp="$(mktemp "$out.XXXXXX")"
GR_COMMIT="$commit" GR_DATE="$(date -u '+%Y-%m-%d %H:%M UTC')" GR_BUILD="$build" GR_BUILD_TYPE="$build_type" \
  GR_CPU_DEVICE="$cpu_device" GR_SWEEP_S="$sweep_s" GR_BUILD_S="$build_s" GR_SCENES="$scenes" \
  GR_ICD="${VK_ICD_FILENAMES:-${VK_DRIVER_FILES:-}}" \
  python3 - "$tmp" "$work/caps.txt" "$commands" "8:$work/n8.json" "32:$work/n32.json" <<'PY' ||
import json, os, re, sys

tmp, caps_path, commands_path, *runs = sys.argv[1:]
env = os.environ

# agaa-render --caps: "key<two or more spaces>value" lines.
caps = {}
for line in open(caps_path):
    m = re.match(r"^(\S+(?: \S+)*?)\s{2,}(.*)$", line.rstrip("\n"))
    if m:
        caps[m.group(1)] = m.group(2)
device_line = caps.get("device", "?")
device_name = re.sub(r" \([^)]*\)$", "", device_line)
commands = [c for c in open(commands_path).read().splitlines() if c]
scene_order = [s for s in env["GR_SCENES"].split(",") if s]


def num(v, digits=2):
    if v is None:
        return "–"
    if digits == 2 and 0 < abs(v) < 0.1:
        return f"{v:.3f}"
    return f"{v:.{digits}f}"


def ratio(a, b):
    return f"{a / b:.2f}x" if a is not None and b else "–"


def lighting(job):
    # The method's lighting pass and its sub-passes (AGAA's agaa.lighting.perSample: the pixels its
    # shading rate shades per sample); agaa-timings' shading_ms is the first pass alone.
    ms = [v for k, v in (job.get("passes") or {}).items() if re.search(r"\.lighting(\.|$)", k)]
    return sum(ms) if ms else job.get("shading_ms")


def per_event(job):
    if not job or not job.get("events_per_pixel") or lighting(job) is None:
        return None
    return lighting(job) / job["events_per_pixel"]


# Rows: (n, scene key) in the order n = 8, n = 8 with extra lights, n = 32; scenes as asked.
blocks = []
meta = None
for spec in runs:
    n, path = spec.split(":", 1)
    data = json.load(open(path))
    if data.get("device") != device_name:
        sys.exit(f"gpu-report.sh: {path} was measured on '{data.get('device')}', not '{device_name}'")
    meta = meta or data
    keys = []
    for key in data.get("scenes", {}):
        m = re.match(r"^(.*?)(?:\+l(\d+))?$", key)
        base, lights = m.group(1), int(m.group(2) or 0)
        order = scene_order.index(base) if base in scene_order else len(scene_order)
        keys.append((lights, order, key))
    for lights, _, key in sorted(keys):
        base = re.sub(r"\+l\d+$", "", key)
        label = base + (f" + {lights} lights" if lights else "")
        blocks.append((int(n), label, data["scenes"][key]))
for n, label, jobs in blocks:
    missing = [s for s in ("reference", "simple-complex") if not any(k.startswith(s + " ") for k in jobs)]
    if missing:
        sys.exit(f"gpu-report.sh: {label}, n = {n} has no {' or '.join(missing)} job")


def role(key):
    if key.startswith("reference "):
        return 0
    if key.startswith("simple-complex "):
        return 1
    return 2 if key.startswith("agaa") else 3


def job_rows(n, jobs):
    keys = sorted((k for k in jobs if k != "ratios"), key=lambda k: (role(k), k))
    return [(k, k.replace(f" n={n}", ""), jobs[k]) for k in keys]


w, h = meta["size"]
cpu = env["GR_CPU_DEVICE"] == "1"
lines = []
add = lines.append
if cpu:
    add(f"# GPU report without a GPU: {device_name}, commit {env['GR_COMMIT']}")
else:
    add(f"# On a GPU: {device_name}, commit {env['GR_COMMIT']}")
add("")
add("The GPU measurement: per-pass GPU times of the per-sample reference, Simple/Complex and AGAA on "
    "real hardware, at n = 8 and 32, with their shading events and memory per pixel. CI and the "
    "rest of the docs run on lavapipe (software Vulkan); the GPU figures are kept here. Every figure "
    "and command on this page comes from one run of `tools/gpu-report.sh`, which wrote the page; "
    "run it again on a machine with a GPU to measure today's code (it replaces this file, so change "
    "the script, not the page).")
add("")
if cpu:
    add(f"> **Not a GPU.** The only Vulkan device found was {device_name}, a CPU implementation "
        "(lavapipe): these are software-rendering figures, a test of the script, not GPU timings.")
    add("")
add("| | |")
add("|---|---|")
add(f"| device | {device_line} |")
if "driver" in caps:
    add(f"| driver | {caps['driver']} |")
if "api" in caps:
    add(f"| Vulkan | {caps['api']} |")
if env.get("GR_ICD"):
    add(f"| Vulkan drivers offered | `{env['GR_ICD']}` (VK_ICD_FILENAMES / VK_DRIVER_FILES) |")
add(f"| commit | {env['GR_COMMIT']} |")
add(f"| date | {env['GR_DATE']} |")
add(f"| build | {env['GR_BUILD_TYPE'] or 'no build type'} (`{env['GR_BUILD']}`) |")
add(f"| frames | {w}x{h}, median of {meta['frames']} timed frames after {meta['warmup']} warm-up frames |")
add(f"| time | build {env['GR_BUILD_S']} s, sweep {env['GR_SWEEP_S']} s |")
add("")
add("## The commands")
add("")
add("Run from the repository root, in this order, by `tools/gpu-report.sh` (the raw output, JSON "
    "and logs, is in `out/gpu-report/`):")
add("")
add("```sh")
lines.extend(commands)
add("```")
add("")
add("## Every job")
add("")
add("Medians in milliseconds. frame: every pass of the method; lighting: its `*.lighting` pass, and AGAA's `agaa.lighting.perSample` (the pixels its "
    "shading rate shades per sample). "
    "events/px: shading events per pixel (the reference: covered samples; Simple/Complex: sample 0 "
    "and the samples of complex pixels; AGAA: its aggregates, and every sample of a pixel it shades "
    "per sample). lighting per event: lighting ms / events per pixel, the cost of one shading event "
    "in every pixel. bytes/px: the allocation sizes of the method's images and buffers per pixel. "
    "At n = 8 the AGAA jobs are the samples path (`agaa-samples`), at n = 32 the accumulate path "
    "(`agaa`, auto), whose default shading rate is `never` already.")
add("")
add("| scene | n | job | frame ms | lighting ms | events/px | lighting per event | bytes/px |")
add("|---|---|---|---|---|---|---|---|")
for n, label, jobs in blocks:
    for key, name, j in job_rows(n, jobs):
        add(f"| {label} | {n} | {name} | {num(j.get('frame_ms'))} | {num(lighting(j))} | "
            f"{num(j.get('events_per_pixel'))} | {num(per_event(j), 3)} | {num(j.get('bytes_per_pixel'), 1)} |")
add("")
add("## AGAA against the reference and Simple/Complex")
add("")
add("frame: AGAA's frame ms / Simple/Complex's at the same n (below 1: AGAA is faster). lighting per "
    "event: AGAA's lighting ms per event/px / the reference's (what one aggregate's shading costs "
    "against one sample's). bytes/px: AGAA's / the peer's.")
add("")
add("| scene | n | AGAA job | frame / Simple-Complex | lighting / Simple-Complex | lighting per event / reference | "
    "bytes/px / reference | bytes/px / Simple-Complex |")
add("|---|---|---|---|---|---|---|---|")
for n, label, jobs in blocks:
    ref = next((j for k, _, j in job_rows(n, jobs) if role(k) == 0), None)
    sc = next((j for k, _, j in job_rows(n, jobs) if role(k) == 1), None)
    for key, name, a in job_rows(n, jobs):
        if role(key) != 2:
            continue
        ref_event = per_event(ref)
        add(f"| {label} | {n} | {name} | {ratio(a.get('frame_ms'), sc.get('frame_ms'))} | "
            f"{ratio(lighting(a), lighting(sc))} | {ratio(per_event(a), ref_event)} | "
            f"{ratio(a.get('bytes_per_pixel'), ref.get('bytes_per_pixel'))} | "
            f"{ratio(a.get('bytes_per_pixel'), sc.get('bytes_per_pixel'))} |")
add("")
add("## AGAA's passes")
add("")
add("Each AGAA job's passes, ms, by name.")
add("")
add("| scene | n | AGAA job | passes, ms |")
add("|---|---|---|---|")
chosen = {}  # (n, job) -> [(variants, [scenes])]: what each effect chose, once per distinct choice
for n, label, jobs in blocks:
    for key, name, a in job_rows(n, jobs):
        if role(key) != 2:
            continue
        passes = ", ".join(f"{p} {num(ms)}" for p, ms in a.get("passes", {}).items())
        add(f"| {label} | {n} | {name} | {passes} |")
        variants = "; ".join(f"{e}: {v}" for e, v in a.get("variants", {}).items()) or "–"
        groups = chosen.setdefault((n, name), [])
        for v, where in groups:
            if v == variants:
                where.append(label)
                break
        else:
            groups.append((variants, [label]))
add("")
add("## AGAA's variants")
add("")
add("What each effect of each AGAA job chose on this device, with the scenes that chose it.")
add("")
for (n, name), groups in chosen.items():
    for variants, where in groups:
        add(f"- n = {n}, {name} ({', '.join(where)}): {variants}")
add("")
with open(tmp, "w") as f:
    f.write("\n".join(lines))
PY
  die "could not write the page from $work/n8.json and $work/n32.json"
mv "$tmp" "$out"
tmp=
echo "gpu-report.sh: wrote $out ($device_name, commit $commit)"
echo "gpu-report.sh: total wall time $((SECONDS / 60)) min $((SECONDS % 60)) s (build $build_s s, sweep $sweep_s s)"
