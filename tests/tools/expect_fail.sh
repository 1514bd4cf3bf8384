#!/usr/bin/env bash
# expect_fail.sh REGEX COMMAND [ARGS...] — a bad run must fail cleanly: COMMAND exits with a
# status from 1 to 125 (an error it reported, not a crash: no signal, no abort) and its output
# (stdout and stderr) matches the extended regular expression REGEX (the message names the
# file, the flag or the field). One CTest test checks both, running the command once.
set -u
regex="$1"
shift
out=$("$@" 2>&1)
status=$?
printf '%s\n' "$out"
if [ "$status" -eq 0 ]; then
  echo "expect_fail: exited 0, expected a failure" >&2
  exit 1
fi
if [ "$status" -gt 125 ]; then
  echo "expect_fail: exit status $status (a signal or abort), expected an error exit" >&2
  exit 1
fi
if ! grep -q -E -e "$regex" <<<"$out"; then
  echo "expect_fail: the output does not match: $regex" >&2
  exit 1
fi
