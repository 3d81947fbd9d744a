#!/usr/bin/env bash
# MRPT's CHolonomicND turns 35 to 45 degrees away from an open target within two sectors of its seam at -pi/+pi
# (mrpt_nd_seam.cpp, the program of docs/upstream/mrpt-nd-seam.md, which must show that very program and output, and
# the same program for MRPT 3's API).
# Usage: mrpt_seam_test.sh PROGRAM SOURCE REPORT
set -uo pipefail
program="$1" source="$2" report="$3"
source "$(dirname "${BASH_SOURCE[0]}")/upstream_report_checks.sh"

expected="target in sector 0 (-177.5 deg): ND heads -132.5 deg, 45.0 deg off
target in sector 1 (-172.5 deg): ND heads -132.5 deg, 40.0 deg off
target in sector 2 (-167.5 deg): ND heads -132.5 deg, 35.0 deg off
target in sector 70 (172.5 deg): ND heads 132.5 deg, -40.0 deg off
target in sector 71 (177.5 deg): ND heads 132.5 deg, -45.0 deg off
ND heads straight for 67 of 72 targets"
output=$("$program")
[ "$output" = "$expected" ] && pass "ND turns away from the five targets at its seam" || fail "mrpt_nd_seam printed:
$output"
report_shows_output "$report" "$expected"
# The report shows two programs: the one tested here (MRPT 2's API) and the same for MRPT 3's (the development
# branch), which differs from it in the API's lines only.
python3 - "$report" "$source" <<'PY'
import re, sys
blocks = re.findall(r"^```cpp\n(.*?)^```$", open(sys.argv[1]).read(), re.S | re.M)
source = open(sys.argv[2]).read()
mrpt3 = source
for old, new in [
    ("it does not.\n#include", "it does not. MRPT 3's API.\n#include"),
    ("<mrpt/math/TPoint2D.h>", "<mrpt/math/TPose2D.h>"),
    ("mrpt::math::TPoint2D(0.5 * std::cos(target), 0.5 * std::sin(target))",
     "mrpt::math::TPose2D(0.5 * std::cos(target), 0.5 * std::sin(target), 0)"),
    ("    mrpt::nav::CAbstractHolonomicReactiveMethod::NavOutput out;\n    nd.navigate(in, out);\n",
     "    const auto out = nd.navigate(in);\n"),
]:
    if mrpt3.count(old) != 1:
        print("FAIL: the tested program has no single '%s' to translate to MRPT 3's API" % old)
        sys.exit(2)
    mrpt3 = mrpt3.replace(old, new)
failed = 0
if source not in blocks:
    print("FAIL: %s's programs differ from %s" % (sys.argv[1], sys.argv[2])); failed += 1
else:
    print("ok: the report shows the program tested")
if mrpt3 not in blocks:
    print("FAIL: %s shows no MRPT 3 program that differs from %s in the API's lines only" % (sys.argv[1], sys.argv[2]))
    failed += 1
else:
    print("ok: the report's MRPT 3 program is the same program")
sys.exit(failed)
PY
status=$?
checks=$((checks + 2)) failures=$((failures + status))  # its two checks, each printed above

finish
