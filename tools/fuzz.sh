#!/usr/bin/env bash
# The glTF/GLB loader under libFuzzer with ASan + UBSan (issue 19).
#   tools/fuzz.sh [SECONDS] [RUNS]     default 120 s and at most 2,000,000 executions
# Builds build/fuzz with clang (-DAGAA_FUZZ=ON: engine/scene and scenegen only), makes a seed
# corpus from every scene scenegen writes (built-in and hard kinds, .gltf and .glb) and the glTF
# files in ../shared/scenes (read in place, never copied into the repository), and runs the
# fuzzer with the glTF dictionary (tests/fuzz/gltf.dict) and a fixed seed, so a run is the same
# sequence of inputs on every machine (a slower one stops earlier in it). A finding is written to
# build/fuzz/findings/ and the script exits 1: copy it to tests/fuzz/regressions/ (every later run
# starts from those files too), fix the loader, and add a test in tests/scene for it.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
seconds="${1:-120}"
runs="${2:-2000000}"
tools/deps.sh --fuzz
build="${AGAA_FUZZ_BUILD_DIR:-build/fuzz}"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ -DAGAA_FUZZ=ON \
  -DAGAA_BUILD_TESTS=OFF >/dev/null
cmake --build "$build" -j"$(nproc)" --target gltf_loader_fuzzer scenegen
seeds="$build/seeds"
rm -rf "$seeds" "$build/corpus"
mkdir -p "$seeds" "$build/corpus" "$build/findings"
# The seed scenes at a small tessellation: the fuzzer mutates their JSON and chunks.
export ASAN_OPTIONS=detect_leaks=0 # scenegen is a tool here, not the target
gen="$build/tools/scenegen/scenegen"
"$gen" --all --out-dir "$seeds" --density 0.02 >/dev/null
for kind in $("$gen" --list | cut -d' ' -f1); do
  "$gen" --kind "$kind" --density 0.02 --out "$seeds/$kind.glb" >/dev/null
done
unset ASAN_OPTIONS
shared="$root/../shared/scenes"
if [ -d "$shared" ]; then
  find "$shared" -type f \( -name '*.gltf' -o -name '*.glb' \) -size -4M -print0 |
    while IFS= read -r -d '' f; do ln -sf "$f" "$seeds/shared_$(echo "$f" | md5sum | cut -c1-8)_$(basename "$f")"; done
fi
regressions=()
[ -d "$root/tests/fuzz/regressions" ] && regressions=("$root/tests/fuzz/regressions")
echo "fuzz: $(ls "$seeds" | wc -l) seed files, ${seconds} s or ${runs} runs"
log="$build/fuzz.log"
set +e
"$build/tests/fuzz/gltf_loader_fuzzer" "$build/corpus" "$seeds" "${regressions[@]}" \
  -dict=tests/fuzz/gltf.dict -seed=1 -max_len=131072 -timeout=20 -rss_limit_mb=4096 \
  -max_total_time="$seconds" -runs="$runs" -print_final_stats=1 \
  -artifact_prefix="$build/findings/" >"$log" 2>&1
rc=$?
set -e
grep -E "^stat::number_of_executed_units|^stat::peak_rss_mb|^#[0-9]+.*DONE|^Done" "$log" | sed 's/^/fuzz: /'
if [ "$rc" -ne 0 ]; then
  echo "fuzz: FINDING (exit $rc): the input is in $build/findings/; the fuzzer's report:"
  grep -E "ERROR|SUMMARY|finding|==[0-9]+==" "$log" | head -20
  exit 1
fi
echo "fuzz: no finding"
