#!/usr/bin/env bash
# The ROS experiment as a user starts it: roslaunch launch/experiment.launch on a small config (three sets of 60
# PPPs: two evolved by generator nodes, one hunted by the simulator; the ten agents with 2 runs each and the two example planners with their own 3), on a private
# master. Checks the experiment finishes with exactly sets x PPPs x agents x runs rows, the report and bag
# exist, and rviz (headless) shows the recorded map.
# Usage: launch_experiment_test.sh DEVEL_DIR
devel="$1"
source "$devel/setup.bash"  # before set -u: setup.bash reads unset variables
set -u
source "$(dirname "${BASH_SOURCE[0]}")/../cli_harness.sh"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)"
export PATH="/usr/bin:$PATH"
port="$(/usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')"
export ROS_MASTER_URI="http://127.0.0.1:$port" ROS_IP=127.0.0.1 ROS_HOME="$work/ros"

sed 's/^runs: 1000 .*/runs: 2/' "$root/config/experiment.yaml" > "$work/experiment.yaml"
cp "$root/config/agents.yaml" "$root/config/generator.yaml" "$work/"
timeout 600 roslaunch -p "$port" "$root/launch/experiment.launch" output_dir:="$work/out" config:="$work/experiment.yaml" \
  > "$work/launch.log" 2>&1
rows=$(($(wc -l < "$work/out/results.csv") - 1))
expected=$((3 * 60 * (10 * 2 + 2 * 3)))
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
! grep -q ",agent_lost$\|,timeout$\|,planner_lost$\|,planner_timeout$\|,invalid_path$\|,invalid_action$" \
  "$work/out/results.csv" && pass || fail "healthy agents lost runs: $(grep "lost$\|timeout$\|invalid" "$work/out/results.csv" | head)
$(grep "fails as" "$work/launch.log" | head)"
# Measured: both planners pass all 540 runs. OMPL plans on the true map, so only its time limit (1 s per plan,
# on a loaded machine) could make it miss a path; the optimistic planner's re-plans race the robot.
for planner in ompl optimistic; do
  passes=$(grep -c ",$planner,.*,goal_reached$" "$work/out/results.csv")
  [ "$passes" -ge 531 ] && pass || fail "$planner passed $passes of 540 runs: $(reasons "$planner")"
done

# The same experiment in process gives the same rows (it runs no planner agents).
"$devel/lib/ppp_simulator/ppp" experiment "$work/experiment.yaml" -o "$work/cli" --quiet > /dev/null 2>&1
grep -v ",ompl,\|,optimistic," "$work/out/results.csv" > "$work/ros_built_in.csv"
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
