#!/usr/bin/env bash
# The ROS experiment as a user starts it: roslaunch launch/experiment.launch, on a private master.
# First a small config (one set, two agents): exactly its nodes start (in one nodelet manager, or each in a process
# of its own), OUTPUT_DIR/sets holds only its set, results.csv equals `ppp experiment`'s byte for byte in both
# modes, a rerun resumes from the generator's stored set, the manager killed mid-run is started again and loses and
# changes no row, and configs naming an unknown agent type or an unreachable host stop before any node starts;
# astar in continuous motion gives `ppp experiment`'s rows in both modes too;
# launch/hunt.launch hunts a small set with only its panel's nodes, and launch/shrink.launch shrinks its failures as ppp shrink does;
# a planner checked against a corpus through ROS exits 1 naming the PPP it fails, 0 once fixed, 2 on bad input;
# a hunted set with a corpus through ROS has its planner's failures shrunk into it, which the planner then fails.
# Then the default config with 2 runs (three sets of 60 PPPs from three generator nodes, one of them hunting
# through the simulator for 2,000 matings; the ten agents with 2 runs each, the five grid planners with their own 3,
# ND and the DWA in continuous motion with their 1; the TP-space navigator is the path planners' section's):
# exactly sets x PPPs x agents x runs rows, the report and bag exist, MRPT's endless loop shrinks through ROS, the
# local planner's failures are diagnosed and never claimed endless, and rviz (headless) shows the recorded map.
# Usage: launch_experiment_test.sh DEVEL_DIR
source "$(dirname "${BASH_SOURCE[0]}")/ros_harness.sh"

# started LOG: the processes roslaunch started (both the entry's and the experiment graph's), sorted.
started() { sed -n 's/.*process\[\([A-Za-z0-9_]*\)-[0-9]*\]: started with pid.*/\1/p' "$1" | sort | tr '\n' ' '; }

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

# A hunt and a shrink in continuous motion through ROS: the panel's local planners drive on simulated time over the
# candidates; the hunt finds a PPP one of them fails and gives the same set when launched again, and that failure
# shrinks through the planner's bridge, still failing the same way.
cat > "$work/small/driven_hunt.yaml" <<'EOF2'
seed: 1
runs: 1
agents:
  - {name: nd, type: planner, motion: continuous, interface: cmd_vel, planner_node: ppp_agents/mrpt_reactive_node, planner_args: "_method:=ND"}
  - {name: dwa, type: planner, motion: continuous, interface: cmd_vel, planner_node: ppp_agents/dwa_planner_node}
sets:
  - name: h
    generator: {fitness: failure, agents: [nd, dwa], runs_per_eval: 1, population: 6, matings: 12, width: 10, height: 10}
EOF2
for run in driven_hunt driven_hunt_again; do
  timeout 300 roslaunch -p "$port" "$root/launch/hunt.launch" output_dir:="$work/small/$run" set:=h \
    config:="$work/small/driven_hunt.yaml" > "$work/small/$run.log" 2>&1
done
failing=$(awk -F, 'NR > 1 && $4 > 0 { print $2; exit }' "$work/small/driven_hunt/set.csv")
[ -n "$failing" ] && same_sets "$work/small/driven_hunt" "$work/small/driven_hunt_again" && pass || \
  fail "the hunt in continuous motion: $(cut -d, -f1,4 "$work/small/driven_hunt/set.csv" | tr '\n' ' ') $(tail "$work/small/driven_hunt.log")"
shrunk=""
for agent in nd dwa; do
  timeout 300 roslaunch -p "$port" "$root/launch/shrink.launch" input:="$work/small/driven_hunt/$failing" agent:=$agent \
    output:="$work/small/driven_$agent.ppp" config:="$work/small/driven_hunt.yaml" args:="--runs 1" \
    > "$work/small/driven_shrink_$agent.log" 2>&1
  [ -s "$work/small/driven_$agent.ppp" ] && shrunk="$work/small/driven_$agent.ppp"
done
[ -n "$shrunk" ] && [ "$(sed -n 's/^meta shrink_failed //p' "$shrunk")" = "1 of 1" ] && \
  [ -n "$(sed -n 's/^meta shrink_kind //p' "$shrunk")" ] && pass || \
  fail "no failure of $failing shrunk in continuous motion: $(tail -3 "$work/small/driven_shrink_nd.log") $(tail -3 "$work/small/driven_shrink_dwa.log")"

# launch/hunt.launch on a small hunted set: only the hunter, the simulator and the panel's nodes start, and the
# set equals the one `ppp generate` makes in process with the options it stored.
cat > "$work/small/hunt.yaml" <<'EOF2'
seed: 1
runs: 1
agents:
  - {name: wall_follower_left, type: wall_follower_left}
  - {name: bumper, type: bumper}
  - {name: astar, type: astar}
sets:
  - name: h
    generator: {fitness: failure, agents: [bumper, wall_follower_left], runs_per_eval: 5, population: 8, matings: 40}
EOF2
timeout 300 roslaunch -p "$port" "$root/launch/hunt.launch" output_dir:="$work/small/hunt" set:=h \
  config:="$work/small/hunt.yaml" > "$work/small/hunt.log" 2>&1
[ "$(started "$work/small/hunt.log")" = "bumper gen_h hunt nodelet_manager rosout simulator wall_follower_left " ] && pass || \
  fail "the hunt started other processes: $(started "$work/small/hunt.log")"
"$devel/lib/ppp_simulator/ppp" generate --config "$work/small/hunt/generator.yaml" -o "$work/small/hunt_cli" > /dev/null 2>&1
same_sets "$work/small/hunt" "$work/small/hunt_cli" && pass || \
  fail "the hunt through ROS differs from ppp generate's: $(tail -20 "$work/small/hunt.log")"

# launch/shrink.launch: a built-in agent's failures of that set shrunk through ROS (only the shrink node, the
# simulator and that agent's node start) are `ppp shrink`'s byte for byte: the same seeds, the same diagnoses.
timeout 300 roslaunch -p "$port" "$root/launch/shrink.launch" input:="$work/small/hunt" agent:=bumper \
  output:="$work/small/shrunk" config:="$work/small/hunt.yaml" args:="--runs 2" > "$work/small/shrink.log" 2>&1
status=$?
[ "$(started "$work/small/shrink.log")" = "bumper nodelet_manager rosout shrink shrink_launch simulator " ] && pass || \
  fail "the shrink started other processes: $(started "$work/small/shrink.log")"
sed -n '/^agents:/,/^sets:/p' "$work/small/hunt.yaml" | grep -v '^sets:' > "$work/small/hunt_agents.yaml"
"$devel/lib/ppp_simulator/ppp" shrink "$work/small/hunt" --agents-file "$work/small/hunt_agents.yaml" --agent bumper \
  --runs 2 -o "$work/small/shrunk_cli" > "$work/small/shrink_cli.log" 2>&1
[ "$status" -eq 0 ] && [ -n "$(ls "$work/small/shrunk" 2>/dev/null)" ] && pass || \
  fail "the shrink through ROS exited $status: $(grep -v '^\s*$' "$work/small/shrink.log" | tail -20)"
diff -r "$work/small/shrunk" "$work/small/shrunk_cli" > /dev/null && pass || \
  fail "the shrink through ROS differs from ppp shrink's: $(diff -r "$work/small/shrunk" "$work/small/shrunk_cli" | head)"
# A shrink naming an agent the config lacks stops before any node of its graph starts.
timeout 120 roslaunch -p "$port" "$root/launch/shrink.launch" input:="$work/small/hunt" agent:=nobody \
  output:="$work/small/nobody" config:="$work/small/hunt.yaml" > "$work/small/nobody.log" 2>&1
grep -qF -- "--agent: the config has no agent 'nobody'; it has: wall_follower_left, bumper, astar" \
  "$work/small/nobody.log" && [ "$(started "$work/small/nobody.log")" = "rosout shrink_launch " ] && \
  [ ! -e "$work/small/nobody" ] && pass || fail "an unknown agent's shrink: $(tail "$work/small/nobody.log")"

# A planner checked against a corpus through ROS (scripts/ppp-check-ros, launch/check.launch's graph): the
# tutorial's horizon planner fails the one PPP of three it was shrunk on (a pocket whose way out is longer than its
# 45-cell horizon; recorded seed 1), so the check exits 1 and the JUnit XML names that one; without the horizon
# (simple_planner.py) it exits 0; an agent the config lacks exits 2 before any node starts.
mkdir -p "$work/corpus"
cp "$root/ppp_simulator/test/ros/planner_maps/open.ppp" "$root/ppp_simulator/test/ros/planner_maps/wall.ppp" \
  "$root/ppp_simulator/test/ros/horizon_pocket.ppp" "$work/corpus/"
check_ros() {  # PLANNER JUNIT [AGENT]: scripts/ppp-check-ros on the corpus; sets $status
  PPP_BUILD_DIR="$(dirname "$devel")" timeout 300 "$root/scripts/ppp-check-ros" "$work/corpus" --agent "${3:-mine}" \
    --config "$root/config/planner_hunt.yaml" --planner "mine=ppp_agents/$1" --junit "$2" > "$2.log" 2>&1
  status=$?
}
check_ros horizon_planner.py "$work/horizon.xml"
[ "$status" -eq 1 ] && grep -q "^mine fails 1 of 3 PPPs of $work/corpus: horizon_pocket" "$work/horizon.xml.log" && \
  pass || fail "the horizon planner's check exited $status: $(grep -v '^\s*$' "$work/horizon.xml.log" | tail -20)"
grep -q '<testsuite name="corpus" tests="3" failures="1"' "$work/horizon.xml" && \
  [ "$(grep -c '<failure type="missed_route" message="mine fails horizon_pocket: 1 of 1 runs failed' "$work/horizon.xml")" -eq 1 ] && \
  pass || fail "the JUnit XML does not name horizon_pocket alone: $(cat "$work/horizon.xml")"
check_ros simple_planner.py "$work/simple.xml"
[ "$status" -eq 0 ] && grep -q '<testsuite name="corpus" tests="3" failures="0"' "$work/simple.xml" && pass || \
  fail "the fixed planner's check exited $status: $(grep -v '^\s*$' "$work/simple.xml.log" | tail -20)"
check_ros simple_planner.py "$work/nobody.xml" nobody
[ "$status" -eq 2 ] && grep -qF -- "--agent: the config has no agent 'nobody'" "$work/nobody.xml.log" && \
  [ ! -e "$work/nobody.xml" ] && pass || fail "an unknown agent's check exited $status: $(tail -5 "$work/nobody.xml.log")"

# A hunted set with a corpus, through ROS: once the runs are played, each PPP of the set a planner of the panel failed
# (a zoo planner that refuses a goal without clearance) is shrunk through its node and added to the corpus once per
# trap; corpus.csv lists exactly the PPPs results.csv shows it failing; the corpus fails the planner under
# scripts/ppp-check-ros (exit 1 naming every trap) and the planner without the fault passes it (exit 0).
mkdir -p "$work/hunt_corpus"
cat > "$work/hunt_corpus/experiment.yaml" <<'EOF2'
seed: 1
runs: 1
sensor_range: 2
agents:
  - {name: mine, type: planner, planner_node: ppp_agents/zoo_planner_node, planner_args: "_fault:=goal_clearance"}
sets:
  - name: hunted
    generator: {fitness: failure, agents: [mine], runs_per_eval: 1, population: 8, matings: 200, seed: 1}
    corpus: corpus
EOF2
cp "$root/config/generator.yaml" "$work/hunt_corpus/"
timeout 300 roslaunch -p "$port" "$root/launch/experiment.launch" output_dir:="$work/hunt_corpus/out" \
  config:="$work/hunt_corpus/experiment.yaml" > "$work/hunt_corpus/launch.log" 2>&1
failing_ppps=$(awk -F, '$3 == "mine" && $6 == "0" && $11 !~ /^(timeout|agent_lost|planner_lost)$/ {print $2}' \
  "$work/hunt_corpus/out/results.csv" | sort -u | tr '\n' ' ')
listed=$(awk -F, 'NR > 1 && $3 == "mine" && $10 == "" {print $2}' "$work/hunt_corpus/out/corpus.csv" | sort -u | tr '\n' ' ')
[ -n "$failing_ppps" ] && [ "$listed" = "$failing_ppps" ] && pass || \
  fail "corpus.csv lists '$listed', results.csv has mine failing '$failing_ppps': $(tail -5 "$work/hunt_corpus/launch.log")"
traps=$(awk -F, 'NR > 1 && $(NF-1) == "true" {print $(NF-2)}' "$work/hunt_corpus/out/corpus.csv" | sort | tr '\n' ' ')
[ -n "$traps" ] && [ "$(ls "$work/hunt_corpus/corpus" | sort | tr '\n' ' ')" = "$traps" ] && pass || \
  fail "the corpus holds $(ls "$work/hunt_corpus/corpus") where corpus.csv added '$traps'"
check_corpus() {  # PLANNER: scripts/ppp-check-ros on the hunt's corpus; sets $status
  PPP_BUILD_DIR="$(dirname "$devel")" timeout 300 "$root/scripts/ppp-check-ros" "$work/hunt_corpus/corpus" \
    --agent mine --config "$work/hunt_corpus/experiment.yaml" --planner "mine=ppp_agents/$1" \
    > "$work/hunt_corpus/check_$1.log" 2>&1
  status=$?
}
check_corpus zoo_planner_node
count=$(ls "$work/hunt_corpus/corpus" | wc -l)
[ "$status" -eq 1 ] && grep -q "^mine fails $count of $count PPPs of $work/hunt_corpus/corpus" \
  "$work/hunt_corpus/check_zoo_planner_node.log" && pass || \
  fail "the faulty planner's check of its corpus exited $status: $(tail -5 "$work/hunt_corpus/check_zoo_planner_node.log")"
check_corpus optimistic_planner_node
[ "$status" -eq 0 ] && pass || \
  fail "the planner without the fault exited $status: $(tail -5 "$work/hunt_corpus/check_optimistic_planner_node.log")"

# The default config with 2 runs; its hunted set evolved for 2,000 matings instead of 10,000, and without the
# TP-space navigator, whose runs through ROS the path planners' launches above prove (two instances sharing them,
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
