#!/usr/bin/env bash
# The whole test suite: installs what is missing, builds (Release with
# assertions), and runs every CTest test. GPU tests run on lavapipe with the
# Khronos validation layer; a validation message fails them.
#   tools/test.sh [ctest args, e.g. -L cpu]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
# --browser: Chromium for the report's browser test (label `browser`), part of the whole suite.
tools/deps.sh --browser --fuzz
build="${AGAA_BUILD_DIR:-build/test}"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DAGAA_BUILD_TESTS=ON -DAGAA_WERROR=ON >/dev/null
cmake --build "$build" -j"$(nproc)"
# Software Vulkan only: a machine with a GPU still tests the same driver CI uses.
lvp="$(ls /usr/share/vulkan/icd.d/lvp_icd.*.json 2>/dev/null | head -n1)"
export VK_ICD_FILENAMES="${VK_ICD_FILENAMES:-$lvp}"
ctest --test-dir "$build" --output-on-failure -j2 "$@"
# The whole suite (no ctest arguments) ends with a bounded libFuzzer run of the glTF loader under
# ASan + UBSan (tools/fuzz.sh; AGAA_FUZZ_SECONDS=0 skips it).
if [ "$#" -eq 0 ] && [ "${AGAA_FUZZ_SECONDS:-120}" != 0 ]; then
  tools/fuzz.sh "${AGAA_FUZZ_SECONDS:-120}"
fi
