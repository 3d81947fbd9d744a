#!/usr/bin/env bash
# MRPT's CHolonomicND turns 35 to 45 degrees away from an open target within two sectors of its seam at -pi/+pi
# (mrpt_nd_seam.cpp, the program of docs/upstream/mrpt-nd-seam.md, which must show that very program and output).
# Usage: mrpt_seam_test.sh PROGRAM SOURCE REPORT
set -uo pipefail
program="$1" source="$2" report="$3"
failures=0
pass() { echo "ok: $1"; }
fail() { echo "FAIL: $1"; failures=$((failures + 1)); }

expected="target in sector 0 (-177.5 deg): ND heads -132.5 deg, 45.0 deg off
target in sector 1 (-172.5 deg): ND heads -132.5 deg, 40.0 deg off
target in sector 2 (-167.5 deg): ND heads -132.5 deg, 35.0 deg off
target in sector 70 (172.5 deg): ND heads 132.5 deg, -40.0 deg off
target in sector 71 (177.5 deg): ND heads 132.5 deg, -45.0 deg off
ND heads straight for 67 of 72 targets"
output=$("$program")
[ "$output" = "$expected" ] && pass "ND turns away from the five targets at its seam" || fail "mrpt_nd_seam printed:
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
