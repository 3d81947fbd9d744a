#!/usr/bin/env bash
# MRPT's PlannerSimple2D::computePath from two threads, each with a planner and a map of its own
# (mrpt_planner_race.cpp, the program of docs/upstream/mrpt-planner-thread-race.md). Whether two traces meet is
# the scheduler's, so this test asserts what is deterministic: the program runs, one thread alone answers the same
# every time, and it reports its counts; it prints them for the log. By hand, `mrpt_planner_race 20000
# --expect-race` fails when it catches nothing.
# Usage: mrpt_race_test.sh PROGRAM SOURCE REPORT
set -uo pipefail
program="$1" source="$2" report="$3"
failures=0
pass() { echo "ok: $1"; }
fail() { echo "FAIL: $1"; failures=$((failures + 1)); }

output=$("$program" 3000)
status=$?
echo "$output"
[ "$status" -eq 0 ] && [[ "$output" =~ ^6000\ plans\ in\ two\ threads:\ [0-9]+\ wrong\ paths,\ [0-9]+\ runaway\ traces,\ [0-9]+\ failed\ assertions$ ]] && \
  pass "the race program ran and counted" || fail "mrpt_planner_race (exit $status): $output"

# The report's program is this one, line for line.
sed -n '/^```cpp$/,/^```$/p' "$report" | sed '1d;$d' | diff -q - "$source" > /dev/null && \
  pass "the report shows the program tested" || fail "$report's program differs from $source"

echo "$((2 - failures)) passed, $failures failed"
[ "$failures" -eq 0 ]
