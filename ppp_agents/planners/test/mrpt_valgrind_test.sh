#!/usr/bin/env bash
# MRPT's PlannerSimple2D::computePath writes outside its grid for a goal just beyond the map's top edge: a heap
# write out of bounds that no unit test sees (it lands in the next heap chunk, and the call then returns
# notFound as documented). Run under valgrind (installed by scripts/install-deps.sh), and the upstream report
# shows exactly this program.
# Usage: mrpt_valgrind_test.sh PROGRAM SOURCE REPORT
set -uo pipefail
program="$1" source="$2" report="$3"
source "$(dirname "${BASH_SOURCE[0]}")/upstream_report_checks.sh"
command -v valgrind > /dev/null || { echo "FAIL: valgrind is not installed (scripts/install-deps.sh installs it)"; exit 1; }

log=$(mktemp)
trap 'rm -f "$log"' EXIT
output=$(valgrind --error-exitcode=99 "$program" 2> "$log")
status=$?
[ "$status" -eq 99 ] && grep -q "Invalid write of size 4" "$log" && \
  grep -q "12 bytes after a block of size 168 alloc'd" "$log" && [ "$output" = "notFound true, 0 path points" ] && \
  pass "MRPT writes 12 bytes past its 7x6 grid, then says notFound" || \
  fail "computePath under valgrind (exit $status, output '$output'): $(grep -A3 'Invalid\|ERROR SUMMARY' "$log" | head -12)"

report_shows_program "$report" "$source"

finish
