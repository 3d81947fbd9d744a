#!/usr/bin/env bash
# MRPT's PlannerSimple2D::computePath, on a free map, sends two neighbours of a target each through the other: its
# paths are not the shortest its header promises (mrpt_planner_paths.cpp, the program of
# docs/upstream/mrpt-planner-paths.md, which must show that very program and output).
# Usage: mrpt_paths_test.sh PROGRAM SOURCE REPORT
set -uo pipefail
program="$1" source="$2" report="$3"
source "$(dirname "${BASH_SOURCE[0]}")/upstream_report_checks.sh"

expected="free map, cell (2, 2) to (3, 3): path (3, 2) (3, 3)
free map, cell (3, 2) to (3, 3): path (2, 2) (3, 3)"
output=$("$program")
[ "$output" = "$expected" ] && pass "MRPT sends each neighbour through the other" || fail "mrpt_planner_paths printed:
$output"
report_shows_output "$report" "$expected"
report_shows_program "$report" "$source"

finish
