#!/usr/bin/env bash
# MRPT's PlannerSimple2D::computePath sends two neighbours of a target each through the other and reports notFound
# for a path that exists; the change proposed in the upstream report answers each with the one step
# (mrpt_planner_paths.cpp, the program of docs/upstream/mrpt-planner-paths.md, which must show that very program).
# Usage: mrpt_paths_test.sh PROGRAM SOURCE REPORT
set -uo pipefail
program="$1" source="$2" report="$3"
failures=0
pass() { echo "ok: $1"; }
fail() { echo "FAIL: $1"; failures=$((failures + 1)); }

expected="free map, cell (2, 2) to (3, 3): MRPT (3, 2) (3, 3) | proposed (3, 3) 
free map, cell (3, 2) to (3, 3): MRPT (2, 2) (3, 3) | proposed (3, 3) 
wall below, cell (3, 2) to (3, 3): MRPT notFound | proposed (3, 3) "
output=$("$program")
[ "$output" = "$expected" ] && pass "MRPT's answers and the proposal's" || fail "mrpt_planner_paths printed:
$output"
python3 -c '
import re, sys
blocks = re.findall(r"^```text\n(.*?)^```$", open(sys.argv[1]).read(), re.S | re.M)
sys.exit(0 if any(b.rstrip("\n") == sys.argv[2] for b in blocks) else 1)' "$report" "$expected" && \
  pass "the report shows that output" || fail "$report does not show that output as a text block"
sed -n '/^```cpp$/,/^```$/p' "$report" | sed '1d;$d' | diff -q - "$source" > /dev/null && \
  pass "the report shows the program tested" || fail "$report's program differs from $source"

echo "$((3 - failures)) passed, $failures failed"
[ "$failures" -eq 0 ]
