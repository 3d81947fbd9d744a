#!/usr/bin/env bash
# MRPT's PlannerSimple2D::computePath answers notFound for paths that exist: between neighbouring cells with a
# wall below the origin or in a corridor one cell wide, and from a corridor's dead end (mrpt_planner_not_found.cpp,
# the program of docs/upstream/mrpt-planner-not-found.md, which must show that very program and output).
# Usage: mrpt_not_found_test.sh PROGRAM SOURCE REPORT
set -uo pipefail
program="$1" source="$2" report="$3"
source "$(dirname "${BASH_SOURCE[0]}")/upstream_report_checks.sh"

# The three calls with notFound have a path (the free room's answer and the last corridor call show it).
expected="free room, cell (3, 2) to (3, 3): path (2, 2) (3, 3)
wall below, cell (3, 2) to (3, 3): notFound
corridor, cell (3, 1) to (4, 1): notFound
corridor, cell (1, 1) to (3, 1): notFound
corridor, cell (2, 1) to (4, 1): path (3, 1) (4, 1)"
output=$("$program")
[ "$output" = "$expected" ] && pass "MRPT answers notFound where the waves meet at once" || \
  fail "mrpt_planner_not_found printed:
$output"
report_shows_output "$report" "$expected"
report_shows_program "$report" "$source"

finish
