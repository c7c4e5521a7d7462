#!/usr/bin/env bash
# The whole test suite: installs what is missing, builds, and runs every CTest test. GPU tests
# run on lavapipe with the Khronos validation layer; a validation message fails them.
#   tools/test.sh                the whole suite: the CPU tests, goldens (label golden) and quality
#                                measurements in a -O2 build; the perturbation proof that every
#                                golden can fail (tools/perturb-test.sh); every GPU, hard-case and
#                                command-line test (and the CPU tests again) with the module under
#                                ASan + UBSan; a 60 s libFuzzer run of the glTF loader
#                                (AGAA_PERTURB=0, AGAA_SANITIZE=0 and AGAA_FUZZ_SECONDS=0 skip those
#                                three stages; with AGAA_SANITIZE=0 the -O2 build runs every test)
#   tools/test.sh [ctest args]   only the -O2 build and the chosen tests, e.g. -L cpu
#   tools/test.sh --sanitize [ctest args]   only the ASan + UBSan build and its tests
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
# Software Vulkan only: a machine with a GPU still tests the same driver CI uses.
lvp="$(ls /usr/share/vulkan/icd.d/lvp_icd.*.json 2>/dev/null | head -n1)"
export VK_ICD_FILENAMES="${VK_ICD_FILENAMES:-$lvp}"

# Every stage's wall time, printed when it ends and again as a summary when the script exits
# (also on failure), so CI time can be attributed: stage NAME COMMAND...
stage_times=()
stage() {
  local name="$1" start=$SECONDS
  shift
  "$@"
  stage_times+=("$(printf '%-22s %5d s' "$name" $((SECONDS - start)))")
  echo "test.sh: stage $name took $((SECONDS - start)) s"
}
stage_summary() {
  [ ${#stage_times[@]} -gt 0 ] || return 0
  echo "test.sh: stage times (total ${SECONDS} s):"
  printf '  %s\n' "${stage_times[@]}"
}
trap stage_summary EXIT

# --browser: Chromium for the report's browser test (label `browser`), part of the whole suite;
# --fuzz: clang and its runtime for the loader's fuzz stage.
stage deps tools/deps.sh --browser --fuzz --validator

# The module built with AddressSanitizer and UndefinedBehaviorSanitizer (GCC, -O1, assertions on;
# the tests' own code is not instrumented: AGAA_SANITIZE in the top-level CMakeLists.txt).
# Leak detection is on for the CPU tests. The GPU tests run with it off: the Vulkan driver and
# the validation layer are unloaded at vkDestroyInstance and leave allocations LeakSanitizer
# can only attribute to "<unknown module>"; our own GPU objects are checked for leaks by the
# validation layer at vkDestroyDevice (every GPU test) and by the soak test. Left to the plain
# build: the soak test (a minute-long loop), the browser test (Chromium, not our code), the
# glTF-Validator test (Khronos's JavaScript tool) and the golden images (they compare pixels; the
# code they run is every method on every scene, which HardRealScenes, the hard suite and the GPU
# tests run under the sanitizers too: the stage took 302 s in CI instead of 364), and the
# quality measurements (label measure: the per-scene quality table and goal P8; they render the
# built-in and hard scenes with every AGAA setting, which the GPU tests cover under the
# sanitizers, and their value is the numbers: 129 s of the stage's test time in CI).
# Debug info is line tables only (-g1): the sanitizers' reports and a debugger's backtrace need
# no more, and full -g made this build 21 % slower per file (574 s of a 1796 s CI run).
unsanitized="cpu|soak|browser|golden|validator|measure" # the labels the sanitizer GPU stage leaves out
sanitize() {
  local build="${AGAA_SANITIZE_BUILD_DIR:-build/sanitize}"
  stage sanitize-configure cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Debug -DAGAA_BUILD_TESTS=ON \
    -DCMAKE_CXX_FLAGS_DEBUG=-g1 -DCMAKE_CXX_FLAGS=-O1 -DCMAKE_EXE_LINKER_FLAGS= \
    -DAGAA_SANITIZE=address,undefined >/dev/null
  stage sanitize-build cmake --build "$build" -j"$(nproc)"
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  if [ "$#" -gt 0 ]; then
    ASAN_OPTIONS=detect_leaks=0 stage sanitize-ctest ctest --test-dir "$build" --output-on-failure -j2 "$@"
    return
  fi
  echo "sanitize: CPU tests, leak detection on"
  ASAN_OPTIONS=detect_leaks=1 stage sanitize-ctest-cpu ctest --test-dir "$build" --output-on-failure -j2 -L cpu
  echo "sanitize: GPU, hard-case and command-line tests"
  ASAN_OPTIONS=detect_leaks=0 stage sanitize-ctest-gpu \
    ctest --test-dir "$build" --output-on-failure -j2 -LE "$unsanitized"
}

if [ "${1:-}" = "--sanitize" ]; then
  shift
  sanitize "$@"
  exit 0
fi

build="${AGAA_BUILD_DIR:-build/test}"
# AGAA_TEST_PERTURB=none: a perturbation run (tools/perturb-test.sh reconfigures this folder)
# that was killed before it restored the folder must not leave a perturbed build behind. Line
# tables only (-g1), as in the sanitizer build: the code is the same -O2, the build is shorter.
stage configure cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DAGAA_BUILD_TESTS=ON -DAGAA_WERROR=ON \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG" \
  -DAGAA_TEST_PERTURB=none >/dev/null
stage build cmake --build "$build" -j"$(nproc)"
# What ran (issue 37: goldens are compared on whatever CPU runs the suite): the CPU, the vector
# extensions llvmpipe's JIT can use, and the device lavapipe reports (its vector width in bits).
echo "test.sh: CPU: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//'), $(nproc) cores;" \
  "extensions: $(grep -m1 '^flags' /proc/cpuinfo | tr ' ' '\n' | grep -xE 'sse4_2|avx|avx2|fma|avx512f' | tr '\n' ' ')"
echo "test.sh: llvmpipe: $("$build/tools/agaa_render/agaa-render" --caps 2>/dev/null | sed -n 's/^device *//p');" \
  "LP_NATIVE_VECTOR_WIDTH=${LP_NATIVE_VECTOR_WIDTH:-unset} LP_NUM_THREADS=${LP_NUM_THREADS:-unset (one per core)}"
# In the whole suite every GPU, hard-case and command-line test runs once, in the sanitizer stage
# below (its -O1 build with assertions on checks more than this one); this -O2 build runs the CPU
# tests and what the sanitizer stage leaves out: the goldens, the quality measurements, the soak,
# browser and glTF-Validator tests. AGAA_SANITIZE=0 runs everything here.
plain=()
[ "$#" -gt 0 ] || [ "${AGAA_SANITIZE:-1}" = 0 ] || plain=(-L "$unsanitized")
stage ctest ctest --test-dir "$build" --output-on-failure -j2 "${plain[@]}" "$@"
if [ "$#" -eq 0 ]; then
  # The same build folder with a deliberate shader error, one variant after the other: only the
  # shaders and the sources that embed a changed one rebuild; the golden suite must fail on both.
  if [ "${AGAA_PERTURB:-1}" != 0 ]; then
    AGAA_BUILD_DIR="$build" stage perturb tools/perturb-test.sh
  fi
  if [ "${AGAA_SANITIZE:-1}" != 0 ]; then
    sanitize
  fi
  # A bounded libFuzzer run of the glTF loader under ASan + UBSan (tools/fuzz.sh).
  if [ "${AGAA_FUZZ_SECONDS:-60}" != 0 ]; then
    stage fuzz tools/fuzz.sh "${AGAA_FUZZ_SECONDS:-60}"
  fi
fi
