#!/usr/bin/env bash
# MRPT's PlannerSimple2D::computePath from two threads, each with a planner and a map of its own
# (mrpt_planner_race.cpp, the program of docs/upstream/mrpt-planner-thread-race.md). Whether two traces meet is
# the scheduler's, so this test asserts what is deterministic: the program runs, one thread alone answers the same
# every time, and it reports its counts; it prints them for the log. By hand, `mrpt_planner_race 20000
# --expect-race` fails when it catches nothing; the report's deterministic demonstration, the program built with
# -fsanitize=thread and MRPT 2.x's PlannerSimple2D.cpp (-DMRPT_SOURCE), is run by hand too.
# Usage: mrpt_race_test.sh PROGRAM SOURCE REPORT
set -uo pipefail
program="$1" source="$2" report="$3"
source "$(dirname "${BASH_SOURCE[0]}")/upstream_report_checks.sh"

output=$("$program" 3000)
status=$?
echo "$output"
[ "$status" -eq 0 ] && [[ "$output" =~ ^6000\ plans\ in\ two\ threads:\ [0-9]+\ wrong\ paths,\ [0-9]+\ runaway\ traces,\ [0-9]+\ failed\ assertions$ ]] && \
  pass "the race program ran and counted" || fail "mrpt_planner_race (exit $status): $output"

report_shows_program "$report" "$source"

finish
