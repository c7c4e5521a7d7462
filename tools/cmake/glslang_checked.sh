#!/bin/sh
# Runs glslangValidator (its command line in "$@") with SPIRV-Tools' validator, and fails the build
# step when the SPIR-V it wrote is invalid. glslang 11 prints the validator's errors but still exits
# 0, and invalid SPIR-V would otherwise reach the driver, where only the validation layer names it,
# and only for the variants a test creates: glslang can emit invalid SPIR-V from valid GLSL (`&&` of
# specialisation constants, docs/decisions/aggregate-cost.md "Eighth session").
out=$("$@" --spirv-val 2>&1)
rc=$?
[ -z "$out" ] || printf '%s\n' "$out"
[ "$rc" -eq 0 ] || exit "$rc"
case "$out" in
*"Validation Errors"*)
  # The output glslang wrote is invalid: remove it, so the next build compiles it again.
  previous=""
  for arg in "$@"; do
    [ "$previous" != "-o" ] || rm -f "$arg"
    previous="$arg"
  done
  echo "glslang_checked.sh: the SPIR-V above is invalid (SPIRV-Tools); fix the shader or work around glslang" >&2
  exit 1
  ;;
esac
