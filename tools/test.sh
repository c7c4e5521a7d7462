#!/usr/bin/env bash
# The whole test suite: installs what is missing, builds, and runs every CTest test. GPU tests
# run on lavapipe with the Khronos validation layer; a validation message fails them.
#   tools/test.sh                the whole suite: the GPU comparisons, goldens (label golden) and
#                                quality measurements in a -O2 build; the perturbation proof that
#                                every golden can fail (tools/perturb-test.sh); the CPU tests and
#                                the host-facing GPU tests (command line, hard cases, package,
#                                viewer, embedding, faults) with the module under ASan + UBSan; a
#                                60 s libFuzzer run of the glTF loader
#                                (AGAA_PERTURB=0, AGAA_SANITIZE=0 and AGAA_FUZZ_SECONDS=0 skip those
#                                three stages; with AGAA_SANITIZE=0 the -O2 build runs every test)
#   tools/test.sh [ctest args]   only the -O2 build and the chosen tests, e.g. -L cpu
#   tools/test.sh --sanitize [ctest args]   only the ASan + UBSan build and its tests
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
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
# Software Vulkan only: a machine with a GPU still tests the same driver CI uses. Looked up after
# deps, which installs lavapipe on a fresh machine.
lvp="$(ls /usr/share/vulkan/icd.d/lvp_icd.*.json 2>/dev/null | head -n1 || true)"
[ -n "$lvp" ] || { echo "test.sh: no lavapipe ICD in /usr/share/vulkan/icd.d after tools/deps.sh" >&2; exit 1; }
export VK_ICD_FILENAMES="${VK_ICD_FILENAMES:-$lvp}"

# The module built with AddressSanitizer and UndefinedBehaviorSanitizer (GCC, -O1, assertions on;
# the tests' own code is not instrumented: AGAA_SANITIZE in the top-level CMakeLists.txt).
# Leak detection is on for the CPU tests. The others run with it off: the Vulkan driver and
# the validation layer are unloaded at vkDestroyInstance and leave allocations LeakSanitizer
# can only attribute to "<unknown module>"; our own GPU objects are checked for leaks by the
# validation layer at vkDestroyDevice (every GPU test) and by the soak test.
# Which tests run here: every CPU test, and the GPU tests of the module's host-facing code, where
# inputs and lifetimes go wrong (labels below): every command-line case, every hard scene, the
# installed package, the viewer, the embedding API and fault injection (label `sanitize`). The
# other GPU tests compare images and buffers against CPU references, goldens and the truth; they
# run the same host code on other data and run once, in the -O2 build. Under ASan they took 2.2x
# as long, because ASan's allocator also serves lavapipe's LLVM: 858 s of test time against 388 s
# for the same 100 tests on this project's 2-core machine, with a cold shader cache, as in CI.
# Debug info is line tables only (-g1): the sanitizers' reports and a debugger's backtrace need
# no more, and full -g made this build 21 % slower per file (574 s of a 1796 s CI run).
sanitized="cli|hard|package|viewer|sanitize" # the GPU tests the sanitizer stage runs (and every CPU test)
# The test executables of which the sanitizer stage runs no test (the GPU comparisons), read from
# the -O2 build's discovered tests ($1) with the labels ctest selects by, as a CMake list: the
# sanitizer build leaves them out (AGAA_SANITIZE_SKIP_TESTS, tests/CMakeLists.txt), some 20
# executables of a 653 s build. Empty where the -O2 build has listed no tests yet.
unsanitized_executables() {
  [ -f "$1/CTestTestfile.cmake" ] || return 0
  ctest --test-dir "$1" -N --show-only=json-v1 | python3 -c '
import json, os, re, sys
run, other = set(), set()
for test in json.load(sys.stdin)["tests"]:
    command = test.get("command") or []
    if not command or "/tests/" not in command[0] or not os.path.basename(command[0]).startswith("test_"):
        continue
    labels = next((p["value"] for p in test.get("properties", []) if p["name"] == "LABELS"), [])
    selected = any(re.search(sys.argv[1], label) for label in labels)
    (run if selected else other).add(os.path.basename(command[0]))
print(";".join(sorted(other - run)))
' "cpu|$sanitized"
}
sanitize() {
  local build="${AGAA_SANITIZE_BUILD_DIR:-build/sanitize}" skip=""
  # Only the whole suite's stage, whose tests are those labels; `--sanitize [ctest args]` builds all.
  [ "$#" -gt 0 ] || skip="$(unsanitized_executables "${AGAA_BUILD_DIR:-build/test}")"
  stage sanitize-configure cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Debug -DAGAA_BUILD_TESTS=ON \
    -DCMAKE_CXX_FLAGS_DEBUG=-g1 -DCMAKE_CXX_FLAGS=-O1 -DCMAKE_EXE_LINKER_FLAGS= \
    -DAGAA_SANITIZE=address,undefined "-DAGAA_SANITIZE_SKIP_TESTS=$skip" >/dev/null
  [ -z "$skip" ] || echo "sanitize: not built (no test of theirs runs here): ${skip//;/ }"
  stage sanitize-build cmake --build "$build" -j"$(nproc)"
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  if [ "$#" -gt 0 ]; then
    ASAN_OPTIONS=detect_leaks=0 stage sanitize-ctest ctest --test-dir "$build" --output-on-failure -j2 "$@"
    return
  fi
  echo "sanitize: CPU tests, leak detection on"
  ASAN_OPTIONS=detect_leaks=1 stage sanitize-ctest-cpu ctest --test-dir "$build" --output-on-failure -j2 -L cpu
  echo "sanitize: command-line, hard-case, package, viewer, embedding and fault-injection tests"
  ASAN_OPTIONS=detect_leaks=0 stage sanitize-ctest-gpu \
    ctest --test-dir "$build" --output-on-failure -j2 -L "$sanitized" -LE cpu
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
# In the whole suite every test runs once: the CPU tests and the host-facing GPU tests in the
# sanitizer stage below (its -O1 build with assertions on checks more than this one), the rest
# here: the GPU comparisons, goldens, quality measurements, soak, browser and glTF-Validator
# tests. AGAA_SANITIZE=0 runs everything here.
plain=()
[ "$#" -gt 0 ] || [ "${AGAA_SANITIZE:-1}" = 0 ] || plain=(-LE "cpu|$sanitized")
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
