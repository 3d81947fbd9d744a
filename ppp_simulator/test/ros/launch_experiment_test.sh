#!/usr/bin/env bash
# The ROS experiment as a user starts it: roslaunch launch/experiment.launch, on a private master, on small configs.
# A small config (one set, two agents): exactly its nodes start (in one nodelet manager, or each in a process
# of its own), OUTPUT_DIR/sets holds only its set, results.csv equals `ppp experiment`'s byte for byte in both
# modes, a rerun resumes from the generator's stored set, the manager killed mid-run is started again and loses and
# changes no row, and configs naming an unknown agent type or an unreachable host stop before any node starts;
# astar in continuous motion gives `ppp experiment`'s rows in both modes too; a Python planner on simulated time,
# MRPT's ND, path planners and the TP-space navigator play reproducibly in continuous motion through ROS.
# The hunts, shrinks and checks through ROS are launch_hunt_test.sh's, the default config launch_default_config_test.sh's.
# Usage: launch_experiment_test.sh DEVEL_DIR
source "$(dirname "${BASH_SOURCE[0]}")/ros_harness.sh"

mkdir -p "$work/small"
cat > "$work/small/experiment.yaml" <<'EOF2'
seed: 5
runs: 3
agents:
  - {name: astar, type: astar}
  - {name: explorer, type: explorer}
sets:
  - name: mine
    generator: {fitness: advances, population: 6, matings: 50, seed: 4}
EOF2
cp "$root/config/generator.yaml" "$work/small/"
timeout 300 roslaunch -p "$port" "$root/launch/experiment.launch" output_dir:="$work/small/out" \
  config:="$work/small/experiment.yaml" > "$work/small/launch.log" 2>&1
[ "$(started "$work/small/launch.log")" = "astar experiment explorer gen_mine nodelet_manager rosout simulator " ] && pass || \
  fail "the small config started other processes: $(started "$work/small/launch.log")"
[ "$(ls "$work/small/out/sets")" = "mine" ] && pass || fail "sets/ holds $(ls "$work/small/out/sets")"
# Progress reaches the output as it happens: each phase's first and last lines at least.
grep -q "progress: set 'mine': 50/50 matings (100.0 %)" "$work/small/launch.log" &&
  grep -qE "progress: episodes: ([0-9]+)/\1 episodes \(100.0 %\)" "$work/small/launch.log" && pass ||
  fail "no progress lines for the set and the episodes: $(grep progress "$work/small/launch.log")"
"$devel/lib/ppp_simulator/ppp" experiment "$work/small/experiment.yaml" -o "$work/small/cli" --quiet > /dev/null 2>&1
cmp -s "$work/small/out/results.csv" "$work/small/cli/results.csv" && pass || \
  fail "roslaunch and ppp experiment differ on the small config: $(tail -20 "$work/small/launch.log")"
# A rerun publishes the stored set instead of evolving again, and changes nothing.
cp "$work/small/out/results.csv" "$work/small/first.csv"
timeout 300 roslaunch -p "$port" "$root/launch/experiment.launch" output_dir:="$work/small/out" \
  config:="$work/small/experiment.yaml" > "$work/small/rerun.log" 2>&1
grep -q "resuming: publishing the set already in" "$work/small/rerun.log" && pass || fail "the rerun evolved again"
cmp -s "$work/small/out/results.csv" "$work/small/first.csv" && pass || fail "the rerun changed results.csv"
# Every node in a process of its own (no manager): the same rows.
timeout 300 roslaunch -p "$port" "$root/launch/experiment.launch" output_dir:="$work/small/own" \
  config:="$work/small/experiment.yaml" args:="--processes own" > "$work/small/own.log" 2>&1
[ "$(started "$work/small/own.log")" = "astar experiment explorer gen_mine rosout simulator " ] && pass || \
  fail "--processes own started other processes: $(started "$work/small/own.log")"
cmp -s "$work/small/own/results.csv" "$work/small/first.csv" && pass || \
  fail "--processes own changed results.csv: $(tail -20 "$work/small/own.log")"

# The manager killed mid-run (SIGKILL: every nodelet in it dies at once): the launch starts the graph again, which
# resumes from results.csv, and the launch ends as if nothing had happened: no row lost or changed.
sed 's/^runs: 3/runs: 3000/' "$work/small/experiment.yaml" > "$work/small/long.yaml"
timeout 300 roslaunch -p "$port" "$root/launch/experiment.launch" output_dir:="$work/small/killed" \
  config:="$work/small/long.yaml" > "$work/small/killed.log" 2>&1 &
launch=$!
total=$((6 * 2 * 3000))
for _ in $(seq 1 600); do
  rows=$(($(wc -l 2>/dev/null < "$work/small/killed/results.csv" || echo 1) - 1))
  [ "$rows" -gt 0 ] && break
  sleep 0.1
done
manager=$(sed -n 's/.*process\[nodelet_manager-[0-9]*\]: started with pid \[\([0-9]*\)\].*/\1/p' "$work/small/killed.log")
[ -n "$manager" ] && kill -KILL "$manager"
wait "$launch" && pass || fail "the launch whose manager was killed failed: $(tail -20 "$work/small/killed.log")"
grep -q "the nodelet manager died (signal 9); starting the graph again (restart 1 of 3)" "$work/small/killed.log" && \
  pass || fail "the killed manager was not started again: $(tail -20 "$work/small/killed.log")"
done_before=$(sed -n 's/.*running [0-9]* episodes (\([0-9]*\) already done.*/\1/p' "$work/small/killed.log" | tail -1)
[ "${done_before:-0}" -gt 0 ] && [ "$done_before" -lt "$total" ] && pass || \
  fail "the restarted graph did not resume mid-run: $(grep 'running' "$work/small/killed.log")"
"$devel/lib/ppp_simulator/ppp" experiment "$work/small/long.yaml" -o "$work/small/long_cli" --quiet > /dev/null 2>&1
cmp -s "$work/small/killed/results.csv" "$work/small/long_cli/results.csv" && pass || \
  fail "killed and restarted, results.csv differs from ppp experiment's: $(tail -20 "$work/small/killed.log")"
# Bad configs stop before any node of the experiment starts, naming the agent type or the host.
sed 's/type: explorer}/type: flier}/' "$work/small/experiment.yaml" > "$work/small/flier.yaml"
sed 's/type: explorer}/type: explorer, host: no-such-host.invalid}/' "$work/small/experiment.yaml" > "$work/small/host.yaml"
for bad in "flier.yaml:unknown agent type 'flier'" "host.yaml:host 'no-such-host.invalid' of agent(s) explorer does not resolve"; do
  timeout 120 roslaunch -p "$port" "$root/launch/experiment.launch" output_dir:="$work/small/bad" \
    config:="$work/small/${bad%%:*}" > "$work/small/bad.log" 2>&1
  grep -qF "${bad#*:}" "$work/small/bad.log" && pass || fail "${bad%%:*}: no error naming it: $(tail "$work/small/bad.log")"
  [ "$(started "$work/small/bad.log")" = "experiment rosout " ] && [ ! -e "$work/small/bad" ] && pass || \
    fail "${bad%%:*} started nodes or wrote output: $(started "$work/small/bad.log")"
done

# Continuous motion through ROS: astar drives a disc over /astar/sensing and /astar/commands beside an explorer on
# the grid, in one manager and with every node a process of its own; results.csv is `ppp experiment`'s byte for
# byte in both, and the bag holds astar's recorded trajectory; a planner on simulated time plays reproducibly. A disc
# that cannot stand at a start stops the simulator before any run, naming robot_radius.
sed 's/^runs: 3/runs: 3\nmotion: continuous\nrobot_radius: 0.3/; s/type: explorer}/type: explorer, motion: grid}/' \
  "$work/small/experiment.yaml" > "$work/small/continuous.yaml"
"$devel/lib/ppp_simulator/ppp" experiment "$work/small/continuous.yaml" -o "$work/small/continuous_cli" --quiet \
  > /dev/null 2>&1
for processes in manager own; do
  timeout 300 roslaunch -p "$port" "$root/launch/experiment.launch" output_dir:="$work/small/continuous_$processes" \
    config:="$work/small/continuous.yaml" args:="--processes $processes" > "$work/small/continuous_$processes.log" 2>&1
  cmp -s "$work/small/continuous_$processes/results.csv" "$work/small/continuous_cli/results.csv" && \
    [ "$(grep -c ',astar,.*,goal_reached,' "$work/small/continuous_cli/results.csv")" -eq 18 ] && pass || \
    fail "continuous motion through ROS ($processes) differs from ppp experiment: $(tail -20 "$work/small/continuous_$processes.log")"
done
# The bag holds a recorded continuous episode of astar: its path's poses turn with the robot's heading, stamped by
# its simulated time (a control period of 0.1 s).
/usr/bin/python3 - "$work/small/continuous_manager/experiment.bag" <<'EOF2' && pass || fail "the bag's continuous path"
import math, sys
import rosbag
path = None
for _, message, _ in rosbag.Bag(sys.argv[1]).read_messages(topics=["/astar/path"]):
    path = message
headings = {round(2 * math.atan2(p.pose.orientation.z, p.pose.orientation.w), 2) for p in path.poses}
steps = [(b.header.stamp - a.header.stamp).to_sec() for a, b in zip(path.poses, path.poses[1:])]
sys.exit(0 if len(headings) > 4 and all(abs(s - 0.1) < 1e-6 for s in steps) else 1)
EOF2
# A planner in Python on simulated time (rospy.Rate, /use_sim_time): every run ends on the robot's own account
# (reached, collided, out of time), never on the link's, and a second launch with both cores kept busy gives the
# same rows (the clock moves only when the planner has answered).
cat > "$work/small/steer.yaml" <<'EOF2'
seed: 3
runs: 2
motion: continuous
robot_radius: 0.2
agents:
  - {name: astar, type: astar}
  - {name: steer, type: planner, interface: cmd_vel, planner_node: ppp_agents/steering_planner.py}
sets:
  - name: small
    generator: {fitness: turns, population: 6, matings: 60, width: 12, height: 12, seed: 2}
EOF2
timeout 300 roslaunch -p "$port" "$root/launch/experiment.launch" output_dir:="$work/small/steer" \
  config:="$work/small/steer.yaml" > "$work/small/steer.log" 2>&1
steer_rows=$(grep -c ',steer,' "$work/small/steer/results.csv")
[ "$steer_rows" -eq 12 ] && ! grep ',steer,' "$work/small/steer/results.csv" | \
  grep -q -e planner_timeout -e planner_lost -e agent_lost -e ',timeout,' && pass || \
  fail "the steering planner's runs: $(cut -d, -f3,11 "$work/small/steer/results.csv" | sort | uniq -c) $(tail "$work/small/steer.log")"
busy=()
for _ in 1 2; do timeout 120 sh -c 'while :; do :; done' & busy+=($!); done
timeout 300 roslaunch -p "$port" "$root/launch/experiment.launch" output_dir:="$work/small/steer_loaded" \
  config:="$work/small/steer.yaml" > "$work/small/steer_loaded.log" 2>&1
kill "${busy[@]}" 2> /dev/null
cmp -s "$work/small/steer/results.csv" "$work/small/steer_loaded/results.csv" && pass || \
  fail "the steering planner's rows differ under load: $(diff "$work/small/steer/results.csv" "$work/small/steer_loaded/results.csv" | head -5)"
# MRPT's ND through its node, on the grid and in continuous motion in one experiment: the grid's rows are those of
# the experiment without the continuous entry (/use_sim_time, set for the graph, leaves them alone), and a second
# launch with every node a process of its own (the driven planner on its bridge's clock instead of a nodelet beside
# its bridge, every message through TCPROS) gives the same rows.
cat > "$work/small/nd.yaml" <<'EOF2'
seed: 3
runs: 2
robot_radius: 0.2
agents:
  - {name: mrpt_nd, type: planner, interface: cmd_vel, endless_proof: false, planner_node: ppp_agents/mrpt_reactive_node, planner_args: "_method:=ND"}
  - {name: mrpt_nd_driven, type: planner, motion: continuous, interface: cmd_vel, planner_node: ppp_agents/mrpt_reactive_node, planner_args: "_method:=ND"}
sets:
  - name: small
    generator: {fitness: turns, population: 10, matings: 100, width: 12, height: 12, seed: 2}
EOF2
grep -v mrpt_nd_driven "$work/small/nd.yaml" > "$work/small/nd_grid.yaml"
for run in nd nd_own nd_grid; do
  processes=manager
  [ "$run" = nd_own ] && processes=own
  timeout 300 roslaunch -p "$port" "$root/launch/experiment.launch" output_dir:="$work/small/$run" \
    config:="$work/small/${run%_own}.yaml" args:="--processes $processes" > "$work/small/$run.log" 2>&1
done
[ "$(grep -c ',mrpt_nd_driven,' "$work/small/nd/results.csv")" -eq 20 ] && \
  ! grep ',mrpt_nd_driven,' "$work/small/nd/results.csv" | grep -q -e planner_ -e agent_lost -e ',timeout,' && pass || \
  fail "ND in continuous motion: $(cut -d, -f3,11 "$work/small/nd/results.csv" | sort | uniq -c) $(tail "$work/small/nd.log")"
grep -q "Loading nodelet /mrpt_nd_driven/instance_1/robot/planner" "$work/small/nd.log" && \
  grep -q "process\[mrpt_nd_driven/instance_1/robot/planner-[0-9]*\]: started" "$work/small/nd_own.log" && pass || \
  fail "ND's driven planner: not a nodelet in one launch and a process in the other"
cmp -s "$work/small/nd/results.csv" "$work/small/nd_own/results.csv" && pass || \
  fail "ND's rows differ between its nodelet and its process: $(diff "$work/small/nd/results.csv" "$work/small/nd_own/results.csv" | head -5)"
diff <(grep ',mrpt_nd,' "$work/small/nd/results.csv") <(grep ',mrpt_nd,' "$work/small/nd_grid/results.csv") > /dev/null && \
  pass || fail "ND's grid rows changed beside its continuous entry"
# Path planners in continuous motion: the robot follows their paths by pure pursuit, re-planning as plan_requests
# says. An optimistic A* on the map the robot's laser builds passes wherever astar does; OMPL planning for a point
# on the true map shortcuts past corners the disc of 0.2 m hits, and passes once its map is inflated by the body.
# Beside them MRPT's TP-space navigator, two instances sharing its runs: each run ends as the navigator drove it
# (reached, collided, or given up: planner_aborted), none lost or timed out. A second launch gives the same rows
# (the TP-space navigator is new at each episode, on the robot's clock).
cat > "$work/small/paths.yaml" <<'EOF2'
seed: 3
runs: 1
motion: continuous
robot_radius: 0.2
agents:
  - {name: astar, type: astar}
  - {name: optimistic, type: planner, plan_requests: on_change, planner_node: ppp_agents/optimistic_planner_node}
  - {name: ompl, type: planner, prior_map: true, plan_requests: on_blocked, planner_node: ppp_agents/ompl_planner_node}
  - {name: ompl_inflated, type: planner, prior_map: true, plan_requests: on_blocked, cells_per_ppp_cell: 4, planner_node: ppp_agents/ompl_planner_node, planner_args: "_inflation:=1"}
  - {name: tpspace, type: planner, interface: cmd_vel, planner_node: ppp_agents/mrpt_tpspace_node, instances: 2}
sets:
  - name: small
    generator: {fitness: turns, population: 10, matings: 100, width: 12, height: 12, seed: 2}
EOF2
for run in paths paths_again; do
  timeout 300 roslaunch -p "$port" "$root/launch/experiment.launch" output_dir:="$work/small/$run" \
    config:="$work/small/paths.yaml" > "$work/small/$run.log" 2>&1
done
reasons() { grep ",$1," "$work/small/paths/results.csv" | cut -d, -f11 | sort | uniq -c | tr -s ' ' | tr '\n' ' '; }
[ "$(reasons astar)" = " 10 goal_reached " ] && [ "$(reasons optimistic)" = " 10 goal_reached " ] && \
  [ "$(reasons ompl_inflated)" = " 10 goal_reached " ] && reasons ompl | grep -q collision && \
  [ "$(grep -c ',tpspace,' "$work/small/paths/results.csv")" -eq 10 ] && reasons tpspace | grep -q planner_aborted && \
  ! grep -q -e planner_timeout -e planner_lost -e agent_lost "$work/small/paths/results.csv" && pass || \
  fail "path planners in continuous motion: $(cut -d, -f3,11 "$work/small/paths/results.csv" | sort | uniq -c) $(tail "$work/small/paths.log")"
cmp -s "$work/small/paths/results.csv" "$work/small/paths_again/results.csv" && pass || \
  fail "path planners' and the TP-space navigator's continuous rows differ between two launches"
# The report draws OMPL's worst run, played again through its bridge, as a trajectory with its animation, and
# shrinks its PPP through ROS: OMPL still collides on the shrunk one.
ls "$work/small/paths/pictures/"*_ompl.png "$work/small/paths/pictures/"*_ompl.gif \
  "$work/small/paths/pictures/"*_ompl_shrunk.png > /dev/null 2>&1 && \
  grep -q "control periods, .* m driven" "$work/small/paths/report.md" && \
  grep -q "still reported in 1 of 1 run (\`ppps/small_ppp_[0-9]*_ompl_shrunk.ppp" "$work/small/paths/report.md" && pass || \
  fail "the report's continuous runs: $(ls "$work/small/paths/pictures/") $(grep -n 'path \|shrunk' "$work/small/paths/report.md")"
sed 's/^robot_radius: 0.3/robot_radius: 0.5/' "$work/small/continuous.yaml" > "$work/small/fat.yaml"
timeout 120 roslaunch -p "$port" "$root/launch/experiment.launch" output_dir:="$work/small/fat" \
  config:="$work/small/fat.yaml" > "$work/small/fat.log" 2>&1
grep -qF "robot_radius: set 'mine', PPP ppp_000: a disc of 0.5" "$work/small/fat.log" && \
  [ ! -s "$work/small/fat/results.csv" ] && pass || fail "a disc too wide for its start: $(tail "$work/small/fat.log")"
finish
