#!/usr/bin/env bash
# Continuous motion from the command line as a user runs it: an experiment where astar drives in continuous motion
# beside an agent on the grid (whose rows stay exactly those of the grid-only experiment), `ppp simulate` and
# `ppp replay` in continuous motion, and the bad inputs each refused with the option named, before any run.
# Usage: continuous_cli_test.sh PATH_TO_PPP
set -u
ppp="$1"
source "$(dirname "${BASH_SOURCE[0]}")/cli_harness.sh"

write_experiment() {  # write_experiment FILE EXTRA_TOP_LEVEL_YAML ASTAR_EXTRA
  cat > "$1" <<YAML
seed: 5
runs: 3
threads: 2
$2
agents:
  - {name: astar, type: astar$3}
  - {name: explorer, type: explorer, motion: grid}
sets:
  - name: turns
    generator: {fitness: turns, population: 6, matings: 100, width: 14, height: 14, seed: 3}
YAML
}

write_experiment "$work/grid.yaml" "" ""
write_experiment "$work/continuous.yaml" "motion: continuous
robot_radius: 0.3" ""
expect_ok "grid experiment" "$ppp" experiment "$work/grid.yaml" -o "$work/grid" --quiet
expect_ok "continuous experiment" "$ppp" experiment "$work/continuous.yaml" -o "$work/continuous" --quiet

# astar drives a disc of 0.3 cells in continuous motion and reaches every goal; its rows count control periods.
rows=$(awk -F, '$3 == "astar"' "$work/continuous/results.csv" | wc -l)
passes=$(awk -F, '$3 == "astar" && $6 == 1 && $8 == 0 && $11 == "goal_reached"' "$work/continuous/results.csv" | wc -l)
if [ "$rows" -eq 18 ] && [ "$passes" -eq 18 ]; then pass; else fail "astar continuous: $passes of $rows rows passed"; fi
grid_steps=$(awk -F, '$3 == "astar" && $4 == 0 { print $7; exit }' "$work/grid/results.csv")
continuous_steps=$(awk -F, '$3 == "astar" && $4 == 0 { print $7; exit }' "$work/continuous/results.csv")
if [ "$continuous_steps" -gt $((5 * grid_steps)) ]; then pass; else
  fail "astar continuous took $continuous_steps control periods for $grid_steps grid moves (0.1 s periods at 0.5 m/s)"
fi
# The explorer plays on the grid in both: its rows are byte for byte those of the grid-only experiment.
if diff <(grep ',explorer,' "$work/grid/results.csv") <(grep ',explorer,' "$work/continuous/results.csv") \
  > /dev/null; then pass; else fail "the explorer's grid rows changed beside a continuous astar"; fi
# A directory of the grid experiment refuses the same experiment in continuous motion (their rows would mix).
write_experiment "$work/motion_only.yaml" "motion: continuous" ""
expect_error "resume under another motion" "holds a different experiment ($work/grid/experiment.yaml against this configuration: motion: 'grid' there, 'continuous' here)" \
  "$ppp" experiment "$work/motion_only.yaml" -o "$work/grid" --quiet

# One agent's own motion overrides the experiment's.
write_experiment "$work/override.yaml" "robot_radius: 0.3" ", motion: continuous"
expect_ok "per-agent motion" "$ppp" experiment "$work/override.yaml" -o "$work/override" --quiet
if diff <(grep ',astar,' "$work/continuous/results.csv") <(grep ',astar,' "$work/override/results.csv") \
  > /dev/null; then pass; else fail "astar's own motion: continuous did not play as the experiment's"; fi

# simulate and replay
expect_ok "simulate continuous" "$ppp" simulate --agent astar --problem empty:8x6 --motion continuous \
  --kinematics holonomic --robot-radius 0.4 --runs 2 --json
grep -q '"passes":2' "$work/out" && pass || fail "simulate continuous: $(cat "$work/out")"
expect_ok "replay continuous" "$ppp" replay empty:8x6 --agent astar --motion continuous --seed 1 -o "$work/run.png"
grep -q 'control periods' "$work/out" && [ -s "$work/run.png" ] && pass || fail "replay continuous: $(cat "$work/out")"
# A run too slow for its budget (time_factor 1 at top speed, slow turns) is diagnosed from its cells.
expect_ok "replay continuous failure" "$ppp" replay empty:8x6 --agent astar --motion continuous --time-factor 1 \
  --max-angular-speed 0.3 --seed 1 -o "$work/fail.png"
grep -q 'failed (budget_exhausted) after 240 control periods' "$work/out" && grep -q '^diagnosis: wandering' "$work/out" \
  && pass || fail "replay continuous failure: $(cat "$work/out")"
# With a progress timeout the same slow-turning run ends once it has stayed within half a cell of one point for
# 2 s (it dithers at step 133 on): no_progress, earlier than its budget, diagnosed from its cells as before.
expect_ok "replay continuous no progress" "$ppp" replay empty:8x6 --agent astar --motion continuous --time-factor 1 \
  --max-angular-speed 0.3 --progress-timeout 2 --seed 1 -o "$work/stalled.png"
grep -q 'failed (no_progress) after 162 control periods' "$work/out" && grep -q 'the progress timeout, not a trap' "$work/out" \
  && pass || fail "replay continuous no progress: $(cat "$work/out")"
# The run animated: the start, every control period (258 of them), and the last frame; read back by Pillow.
expect_ok "replay continuous gif" "$ppp" replay empty:8x6 --agent astar --motion continuous --seed 1 -o "$work/run.gif"
grep -q 'animated in .* (259 frames)' "$work/out" && pass || fail "replay continuous gif: $(cat "$work/out")"
frames=$(/usr/bin/python3 -c 'import sys; from PIL import Image; print(Image.open(sys.argv[1]).n_frames)' "$work/run.gif")
[ "$frames" = 259 ] && pass || fail "replay continuous gif: Pillow reads $frames frames"
expect_error "replay continuous as jpg" "--output: expected a .png (the trajectory drawn) or .gif (the run animated)" \
  "$ppp" replay empty:8x6 --agent astar --motion continuous --seed 1 -o "$work/run.jpg"

# Bad input, each refused naming what is wrong.
expect_error "unknown motion" "--motion: unknown motion 'teleport'; valid: grid, continuous" \
  "$ppp" simulate --agent astar --problem empty:8x6 --motion teleport
expect_error "zero control period" "--control-period: expected a number in" \
  "$ppp" simulate --agent astar --problem empty:8x6 --motion continuous --control-period 0
expect_error "negative speed" "--max-linear-speed: expected a number in" \
  "$ppp" simulate --agent astar --problem empty:8x6 --motion continuous --max-linear-speed -1
expect_error "a progress timeout that is no duration" "--progress-timeout: expected a number, got '2s'" \
  "$ppp" simulate --agent astar --problem empty:8x6 --motion continuous --progress-timeout 2s
expect_error "a negative progress timeout" "--progress-timeout: expected a number in [0, 1000000], got -1" \
  "$ppp" simulate --agent astar --problem empty:8x6 --motion continuous --progress-timeout -1
expect_error "grid-only agent" "motion: agent 'explorer' (explorer) moves only on the grid" \
  "$ppp" simulate --agent explorer --problem empty:8x6 --motion continuous
write_experiment "$work/explorer.yaml" "motion: continuous" ""
sed -i 's/type: explorer, motion: grid/type: explorer/' "$work/explorer.yaml"
expect_error "grid-only agent in an experiment" "motion: agent 'explorer' (explorer) moves only on the grid" \
  "$ppp" experiment "$work/explorer.yaml" -o "$work/explorer" --quiet
write_experiment "$work/wide.yaml" "motion: continuous
robot_radius: 0.5" ""
expect_error "a disc that cannot stand at the start" "robot_radius: set 'turns', PPP ppp_000: a disc of 0.5" \
  "$ppp" experiment "$work/wide.yaml" -o "$work/wide" --quiet
[ ! -e "$work/wide/results.csv" ] && pass || fail "runs were played before refusing the disc"
"$ppp" random --size 8x6 --obstacles 3 --seed 2 -o "$work/small.ppp" > /dev/null
expect_error "continuous shrink" "motion: agent 'astar' plays in continuous motion" \
  "$ppp" shrink "$work/small.ppp" --agent astar --motion continuous --runs 2 -o "$work/shrunk.ppp"
expect_error "continuous hunt" "motion: agent 'astar' plays in continuous motion" \
  "$ppp" generate --fitness failure --agents astar --motion continuous --matings 4 --population 4 -o "$work/hunt"
# Through ROS, astar's node is given its continuous topics; a planner that sends paths is followed in lockstep
# only.
expect_ok "continuous through ROS" "$ppp" launch-file "$work/continuous.yaml" -o "$work/ros"
grep -q '<remap from="sensing" to="~sensing"/>' "$work/out" && pass || fail "astar's node has no sensing topic"
write_experiment "$work/planner.yaml" "motion: continuous" ""
sed -i 's/  - {name: astar, type: astar}/  - {name: ompl, type: planner, lockstep: false, planner_node: ppp_agents\/ompl_planner_node}/' \
  "$work/planner.yaml"
expect_error "a free-running continuous planner" "lockstep: planner agent 'ompl' plays in continuous motion, which its bridge plays in lockstep only" \
  "$ppp" launch-file "$work/planner.yaml" -o "$work/planner"

finish
