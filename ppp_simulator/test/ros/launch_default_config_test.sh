#!/usr/bin/env bash
# The default config as a user launches it (roslaunch launch/experiment.launch, on a private master), with 2 runs:
# three sets of 60 PPPs from three generator nodes, one of them hunting through the simulator for 2,000 matings; the
# ten agents with 2 runs each, the five grid planners with their own 3, ND and the DWA in continuous motion with
# their 1 (the TP-space navigator is launch_experiment_test.sh's): exactly sets x PPPs x agents x runs rows, the
# report and bag exist, MRPT's endless loop shrinks through ROS, the local planner's failures are diagnosed and never
# claimed endless, the in-process experiment gives the same rows, and rviz (headless) shows the recorded map.
# Usage: launch_default_config_test.sh DEVEL_DIR
source "$(dirname "${BASH_SOURCE[0]}")/ros_harness.sh"

# The default config with 2 runs; its hunted set evolved for 2,000 matings instead of 10,000, and without the
# TP-space navigator, whose runs through ROS launch_experiment_test.sh's path planners' launches prove (two instances sharing them,
# the same rows twice): its 180 runs alone were half of this launch.
sed -e 's/^runs: 1000 .*/runs: 2/' -e '/fitness: failure/s/matings: 10000/matings: 2000/' \
  "$root/config/experiment.yaml" > "$work/experiment.yaml"
grep -q 'runs_per_eval: 20, matings: 2000,' "$work/experiment.yaml" || fail "the hunted set's matings were not cut"
grep -v '{name: mrpt_tpspace,' "$root/config/agents.yaml" > "$work/agents.yaml"
cp "$root/config/generator.yaml" "$work/"
timeout 900 roslaunch -p "$port" "$root/launch/experiment.launch" output_dir:="$work/out" config:="$work/experiment.yaml" \
  > "$work/launch.log" 2>&1
rows=$(($(wc -l < "$work/out/results.csv") - 1))
expected=$((3 * 60 * (10 * 2 + 5 * 3 + 2 * 1)))
[ "$rows" -eq "$expected" ] && pass || fail "results.csv has $rows rows, expected $expected: $(tail -20 "$work/launch.log")"
for f in summary.csv report.html report.md experiment.bag sets/turns/tree.html sets/difficulty/set.csv sets/hunted/set.csv; do
  [ -s "$work/out/$f" ] && pass || fail "the launched experiment did not write $f"
done
grep -q "experiment done" "$work/launch.log" && pass || fail "the simulator did not report the end"
# reasons AGENT...: "agent reason count" lines of results.csv for those agents.
reasons() {
  awk -F, -v agents=" $* " 'NR > 1 && index(agents, " " $3 " ") { n[$3 " " $11]++ } END { for (k in n) print k, n[k] }' \
    "$work/out/results.csv" | sort
}
! grep -q ",agent_lost,[01],\|,timeout,[01],\|,planner_lost,[01],\|,planner_timeout,[01],\|,invalid_path,[01],\|,invalid_action,[01]," \
  "$work/out/results.csv" && pass || fail "healthy agents lost runs: $(grep "lost,[01],\|timeout,[01],\|invalid" "$work/out/results.csv" | head)
$(grep "fails as" "$work/launch.log" | head)"
# Measured: the planners pass all 540 runs. OMPL plans on the true map, so only its time limit (1 s per plan,
# on a loaded machine) could make it miss a path; the optimistic and MRPT planners' re-plans race the robot.
for planner in ompl optimistic mrpt; do
  passes=$(grep -c ",$planner,.*,goal_reached,[01]," "$work/out/results.csv")
  [ "$passes" -ge 531 ] && pass || fail "$planner passed $passes of 540 runs: $(reasons "$planner")"
done

# Every failed run has a diagnosis. MRPT's planner shuttles between two cells on turns/ppp_011 in all three of its
# runs: a loop of period 2 that the bridge's state digests prove endless (docs/reference/diagnoses.md).
undiagnosed=$(awk -F, 'NR > 1 && $6 == 0 && $13 == ""' "$work/out/results.csv" | wc -l)
[ "$undiagnosed" -eq 0 ] && pass || fail "$undiagnosed failed runs without a diagnosis"
mrpt_loops=$(awk -F, '$1 == "turns" && $2 == "ppp_011" && $3 == "mrpt" && $13 == "loop" && $15 == 2 && $16 != ""' \
  "$work/out/results.csv" | wc -l)
[ "$mrpt_loops" -eq 3 ] && pass || fail "mrpt on turns/ppp_011 is not an endless loop of period 2 in 3 runs: \
$(grep ',ppp_011,mrpt,' "$work/out/results.csv")"

# MRPT's ND, a local planner steering by velocity commands, fails most PPPs (a reactive method has no route to
# follow out of a pocket); every failure is diagnosed, none is claimed endless (ND remembers its last choice), and
# the report shows its worst PPP shrunk.
nd_undiagnosed=$(awk -F, '$3 == "mrpt_nd" && $6 == 0 && ($13 == "" || $16 != "")' "$work/out/results.csv" | wc -l)
nd_failed=$(awk -F, '$3 == "mrpt_nd" && $6 == 0' "$work/out/results.csv" | wc -l)
[ "$nd_failed" -gt 0 ] && [ "$nd_undiagnosed" -eq 0 ] && pass || \
  fail "mrpt_nd: $nd_failed failed runs, $nd_undiagnosed without a diagnosis or claimed endless: $(reasons mrpt_nd)"
grep -q '^- shrunk: .*(`ppps/[a-z]*_ppp_[0-9]*_mrpt_nd_shrunk.ppp`' "$work/out/report.md" && pass || \
  fail "the report does not show mrpt_nd's worst PPP shrunk"

# MRPT's endless loop shrunk through ROS (launch/shrink.launch, the planner judged through its bridge) on the seed
# of its first failed run there: still a loop proven endless, on fewer obstacle cells.
timeout 600 roslaunch -p "$port" "$root/launch/shrink.launch" input:="$work/out/sets/turns/ppp_011.ppp" agent:=mrpt \
  output:="$work/mrpt_011.ppp" config:="$work/experiment.yaml" results:="$work/out/results.csv" args:="--runs 1" \
  > "$work/shrink_mrpt.log" 2>&1
meta() { sed -n "s/^meta $1 //p" "$work/mrpt_011.ppp"; }
[ "$(meta shrink_kind) $(meta shrink_endless) $(meta shrink_failed)" = "loop true 1 of 1" ] && \
  [ "$(meta obstacle_cells_after)" -lt "$(meta obstacle_cells_before)" ] && pass || \
  fail "mrpt's loop on turns/ppp_011 did not shrink to an endless loop: $(grep -v '^\s*$' "$work/shrink_mrpt.log" | tail)"

# The report shows MRPT's worst PPP shrunk through its bridge for the pictured run's seed: still an endless loop.
grep -q '^- shrunk: .* obstacle cells, still endless loop in 1 of 1 run (`ppps/turns_ppp_011_mrpt_shrunk.ppp`' \
  "$work/out/report.md" && [ -s "$work/out/pictures/turns_ppp_011_mrpt_shrunk.png" ] && pass || \
  fail "the report does not show mrpt's loop shrunk: $(grep -A8 'ppp_011. .* .mrpt' "$work/out/report.md")"

# Every planner run that moved has its moves recorded, one action per step (the report draws planner runs from
# them); a report entry of a planner says so.
unmatched=$(awk -F, 'NR == FNR { if (FNR > 1) moves[$1 "," $2 "," $3 "," $4] = length($5); next }
  FNR > 1 && ($3 == "ompl" || $3 == "optimistic" || $3 == "mrpt" || $3 == "mrpt_nd" || $3 == "dwa") && $7 > 0 && moves[$1 "," $2 "," $3 "," $4] != $7' \
  "$work/out/planner_moves.csv" "$work/out/results.csv" | wc -l)
[ "$unmatched" -eq 0 ] && pass || fail "$unmatched planner runs without their moves in planner_moves.csv"

# The same experiment in process gives the same rows (it runs no planner agents).
"$devel/lib/ppp_simulator/ppp" experiment "$work/experiment.yaml" -o "$work/cli" --quiet > /dev/null 2>&1
grep -v ",ompl,\|,optimistic,\|,mrpt,\|,mrpt_nd,\|,dwa,\|,mrpt_nd_continuous,\|,dwa_continuous," "$work/out/results.csv" > "$work/ros_built_in.csv"
cmp -s "$work/ros_built_in.csv" "$work/cli/results.csv" && pass || fail "roslaunch and ppp experiment results differ"

# rviz, headless, on the recorded bag: the picture must show the map (pixels checked, not just a file).
if "$root/scripts/rviz-screenshot.sh" "$work/out/experiment.bag" "$work/rviz.png" 5 > "$work/rviz.log" 2>&1; then
  pass
  /usr/bin/python3 "$root/scripts/check_screenshot.py" "$work/rviz.png" > "$work/check.log" 2>&1 && pass || \
    fail "the rviz picture does not show the map: $(cat "$work/check.log")"
  [ -n "${PPP_KEEP_SCREENSHOT:-}" ] && cp "$work/rviz.png" "$PPP_KEEP_SCREENSHOT"
else
  fail "rviz-screenshot failed: $(tail -20 "$work/rviz.log")"
fi
finish
