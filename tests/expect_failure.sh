#!/bin/sh
# expect_failure.sh PATTERN COMMAND...: passes when COMMAND exits non-zero and
# its output contains PATTERN (a grep -E pattern). An exit by a signal (a
# crash or an abort, status 128 and above) is a failure whatever it printed.
pattern="$1"
shift
output=$("$@" 2>&1)
status=$?
printf '%s\n' "$output"
if [ "$status" -eq 0 ]; then
  echo "expect_failure: the command succeeded but should have failed" >&2
  exit 1
fi
if [ "$status" -ge 128 ]; then
  echo "expect_failure: the command crashed (exit $status) instead of refusing the input" >&2
  exit 1
fi
if ! printf '%s\n' "$output" | grep -Eq -- "$pattern"; then
  echo "expect_failure: exit $status, but the output lacks /$pattern/" >&2
  exit 1
fi
exit 0
