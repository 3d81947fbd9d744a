#!/bin/bash
# scripts/calibrate.py as a user runs it: a quick search writes a row per candidate and ranks them; bad usage is
# refused with exit status 2 and a message naming the flag.
source "$(dirname "$0")/cli_harness.sh"
calibrate="$(dirname "$0")/../../scripts/calibrate.py"

expect_ok "quick search" /usr/bin/python3 "$calibrate" --quick --runs 1 --seeds 1 --work "$work/search"
# --quick keeps the agent options at their defaults (goal range 0, which the random agent's 4.4 % +- 1 admits with
# free bumps only): 2 shape mixes x 3 obstacle budgets x 3 bar lengths.
rows=$(($(wc -l < "$work/search/calibration.csv") - 1))
if [ "$rows" -eq 18 ]; then pass; else fail "calibration.csv: expected 18 candidates, got $rows"; fi
if head -1 "$work/search/calibration.csv" | grep -q "worst_gap,rms_gap,random,wall_follower_left"; then pass
else fail "calibration.csv header: $(head -1 "$work/search/calibration.csv")"; fi
if grep -q "^Best candidates" "$work/out" && grep -q "facts: turns" "$work/out"; then pass
else fail "no ranking printed: $(tail -3 "$work/out")"; fi
expect_error "bad seeds" "--seeds: expected FIRST-LAST or distinct integers separated by commas" \
  /usr/bin/python3 "$calibrate" --seeds one --work "$work/bad"
if grep -qF "at most 10000, got 'one'" "$work/err"; then pass; else fail "bad seeds: $(cat "$work/err")"; fi
if [ ! -e "$work/bad" ]; then pass; else fail "bad usage created $work/bad"; fi
expect_error "no runs" "--runs: expected at least 1, got 0" /usr/bin/python3 "$calibrate" --runs 0 --work "$work/bad"
finish
