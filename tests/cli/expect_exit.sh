#!/usr/bin/env bash
# expect_exit.sh CODE PATTERN -- COMMAND...: runs COMMAND and fails unless it exits with CODE
# and its standard error contains PATTERN (a fixed string; empty matches anything).
set -u
code="$1"; pattern="$2"; shift 3
err="$(mktemp)"
"$@" >/dev/null 2>"$err"
got=$?
if [ "$got" -ne "$code" ]; then
  echo "expected exit code $code, got $got from: $*"; cat "$err"; rm -f "$err"; exit 1
fi
if [ -n "$pattern" ] && ! grep -qF -- "$pattern" "$err"; then
  echo "stderr of '$*' does not mention '$pattern':"; cat "$err"; rm -f "$err"; exit 1
fi
rm -f "$err"
