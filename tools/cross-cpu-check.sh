#!/usr/bin/env bash
# Renders golden scenes as another x86-64 CPU would (qemu-user, TCG) and prints, per golden, the
# golden metric against the stored image and PASS/FAIL at the golden test's thresholds
# (tests/golden/golden_compare.h: display RMSE <= 1e-4 and p99 <= 1/255). docs/cross-cpu.md.
#
#   tools/cross-cpu-check.sh [-c CPU] [-b TEST_BINARY] [-o OUT_DIR] SCENE...
#
#   -c CPU   a `qemu-x86_64 -cpu help` model (default Haswell), with optional feature edits
#            (`Haswell,-fma`), or `native` for no emulation
#            (then e.g. GALLIUM_OVERRIDE_CPU_CAPS=sse4.1 in the environment narrows llvmpipe).
#   -b PATH  the golden test binary (default build/test/tests/golden/test_golden). It is copied
#            first, so a rebuild during the run does not change what runs.
#   -o DIR   where the rendered images go (default: a new directory under /tmp). Nothing is
#            written to the source tree or the build tree (AGAA_GOLDEN_WRITE mode of the test).
#   SCENE    a golden scene: metal, foliage, gltf-cubes, ... (`ctest -N -L golden` lists them).
#
# Exit status: 0 when every golden passes, 1 when one fails or a scene run crashes, 2 on usage.
# Under qemu a built-in scene (20 goldens at 64x64) takes 6 to 7 min on 2 shared cores; native,
# about 15 s.
set -euo pipefail

cpu=Haswell
binary=$(cd "$(dirname "$0")/.." && pwd)/build/test/tests/golden/test_golden
out=""
usage() { sed -n '6,17p' "$0" | sed 's/^# \{0,1\}//' >&2; exit "${1:-2}"; }
while getopts "c:b:o:h" opt; do
    case "$opt" in
        c) cpu=$OPTARG ;;
        b) binary=$OPTARG ;;
        o) out=$OPTARG ;;
        h) usage 0 ;;
        *) usage ;;
    esac
done
shift $((OPTIND - 1))
[[ $# -ge 1 ]] || usage
[[ -x "$binary" ]] || { echo "cross-cpu-check: $binary is not an executable (build the tests first)" >&2; exit 2; }
if [[ "$cpu" != native ]]; then
    command -v qemu-x86_64 > /dev/null || { echo "cross-cpu-check: qemu-x86_64 missing (apt-get install qemu-user)" >&2; exit 2; }
    models=$(qemu-x86_64 -cpu help | awk '{print $2}' || true) # `-cpu help` exits with 1
    grep -qx -- "${cpu%%,*}" <<< "$models" ||
        { echo "cross-cpu-check: '$cpu' is not a qemu-x86_64 CPU model (qemu-x86_64 -cpu help)" >&2; exit 2; }
fi
if [[ -z "${VK_ICD_FILENAMES:-}" ]]; then
    VK_ICD_FILENAMES=$(ls /usr/share/vulkan/icd.d/lvp_icd.*.json | head -1)
    export VK_ICD_FILENAMES
fi
[[ -n "$out" ]] || out=$(mktemp -d /tmp/cross-cpu-XXXXXX)
mkdir -p "$out/$cpu"
work=$(mktemp -d /tmp/cross-cpu-bin-XXXXXX)
trap 'rm -rf "$work"' EXIT
cp "$binary" "$work/test_golden"

status=0
printf '%-12s %-40s %10s %10s %10s %8s  %s\n' cpu golden rmse p99 max pixels result
for scene in "$@"; do
    filter="Every/Golden.MatchesStoredImages/${scene//-/_}"
    log="$out/$cpu/${scene//\//_}.log"
    # Line-buffered stdout (stdbuf; qemu-user passes LD_PRELOAD on to the guest): a run that
    # crashes part-way keeps the lines of the goldens it finished.
    runner=(stdbuf -oL)
    [[ "$cpu" != native ]] && runner+=(qemu-x86_64 -cpu "$cpu")
    rc=0
    # In a subshell, so that bash's "Illegal instruction" report lands in the log too.
    (AGAA_GOLDEN_WRITE="$out/$cpu/images" "${runner[@]}" "$work/test_golden" --gtest_filter="$filter"
     exit $?) > "$log" 2>&1 || rc=$?
    if ! grep -q '^\[ RUN      \]' "$log"; then
        echo "cross-cpu-check: no golden test matches '$scene' (log: $log)" >&2
        status=1
        continue
    fi
    # Update mode prints one line per golden:
    #   [ golden ] metal/fxaa-n1: unchanged
    #   [ golden ] metal/fxaa-n1: changed (within threshold), display RMSE 2e-05, p99 0, max 0.01, 3 pixels differ
    #   [ golden ] metal/fxaa-n1: changed, display RMSE 0.00188, p99 0.0118, max 0.159, 114 pixels differ
    #   [ golden ] metal/new-case: new
    awk -v cpu="$cpu" '
        /^\[ golden \] / {
            stem = $4; sub(/:$/, "", stem)
            if ($5 == "unchanged") { printf "%-12s %-40s %10s %10s %10s %8s  %s\n", cpu, stem, 0, 0, 0, 0, "PASS (bit-identical)"; next }
            if ($5 == "new") { printf "%-12s %-40s %10s %10s %10s %8s  %s\n", cpu, stem, "-", "-", "-", "-", "NO GOLDEN"; bad = 1; next }
            line = $0
            match(line, /RMSE [^,]*/); rmse = substr(line, RSTART + 5, RLENGTH - 5)
            match(line, /p99 [^,]*/);  p99 = substr(line, RSTART + 4, RLENGTH - 4)
            match(line, /max [^,]*/);  mx = substr(line, RSTART + 4, RLENGTH - 4)
            match(line, /[0-9]+ pixels differ/); px = substr(line, RSTART, RLENGTH); sub(/ pixels differ/, "", px)
            result = (line ~ /within threshold/) ? "PASS" : "FAIL"
            if (result == "FAIL") bad = 1
            printf "%-12s %-40s %10s %10s %10s %8s  %s\n", cpu, stem, rmse, p99, mx, px, result
        }
        END { exit bad }' "$log" || status=1
    if [[ $rc -ne 0 ]]; then
        status=1
        case $rc in
            132) why="SIGILL (llvmpipe without F16C: docs/cross-cpu.md)" ;;
            139) why="SIGSEGV" ;;
            *) why="exit status $rc" ;;
        esac
        printf '%-12s %-40s %10s %10s %10s %8s  %s\n' "$cpu" "${scene//_/-}/(rest)" - - - - "CRASH: $why"
        grep -E '^(.*Failure|.*validation|Expected|  Actual)' "$log" | head -5 >&2 || true
    fi
done
echo "images and logs: $out/$cpu" >&2
exit "$status"
