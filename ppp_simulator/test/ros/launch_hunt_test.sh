#!/usr/bin/env bash
# Hunts, shrinks and corpus checks as a user starts them through ROS (launch/hunt.launch, launch/shrink.launch,
# scripts/ppp-check-ros), each on a private master: a hunt and a shrink in continuous motion; launch/hunt.launch
# hunts a small set with only its panel's nodes, and launch/shrink.launch shrinks its failures as ppp shrink does;
# a planner checked against a corpus through ROS exits 1 naming the PPP it fails, 0 once fixed, 2 on bad input;
# a hunted set with a corpus through ROS has its planner's failures shrunk into it, which the planner then fails.
# Usage: launch_hunt_test.sh DEVEL_DIR
source "$(dirname "${BASH_SOURCE[0]}")/ros_harness.sh"

# A hunt and a shrink in continuous motion through ROS: the panel's local planners drive on simulated time over the
# candidates; the hunt finds a PPP one of them fails and gives the same set when launched again, and that failure
# shrinks through the planner's bridge, still failing the same way.
cat > "$work/driven_hunt.yaml" <<'EOF2'
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
  timeout 300 roslaunch -p "$port" "$root/launch/hunt.launch" output_dir:="$work/$run" set:=h \
    config:="$work/driven_hunt.yaml" > "$work/$run.log" 2>&1
done
failing=$(awk -F, 'NR > 1 && $4 > 0 { print $2; exit }' "$work/driven_hunt/set.csv")
[ -n "$failing" ] && same_sets "$work/driven_hunt" "$work/driven_hunt_again" && pass || \
  fail "the hunt in continuous motion: $(cut -d, -f1,4 "$work/driven_hunt/set.csv" | tr '\n' ' ') $(tail "$work/driven_hunt.log")"
shrunk=""
for agent in nd dwa; do
  timeout 300 roslaunch -p "$port" "$root/launch/shrink.launch" input:="$work/driven_hunt/$failing" agent:=$agent \
    output:="$work/driven_$agent.ppp" config:="$work/driven_hunt.yaml" args:="--runs 1" \
    > "$work/driven_shrink_$agent.log" 2>&1
  [ -s "$work/driven_$agent.ppp" ] && shrunk="$work/driven_$agent.ppp"
done
[ -n "$shrunk" ] && [ "$(sed -n 's/^meta shrink_failed //p' "$shrunk")" = "1 of 1" ] && \
  [ -n "$(sed -n 's/^meta shrink_kind //p' "$shrunk")" ] && pass || \
  fail "no failure of $failing shrunk in continuous motion: $(tail -3 "$work/driven_shrink_nd.log") $(tail -3 "$work/driven_shrink_dwa.log")"

# launch/hunt.launch on a small hunted set: only the hunter, the simulator and the panel's nodes start, and the
# set equals the one `ppp generate` makes in process with the options it stored.
cat > "$work/hunt.yaml" <<'EOF2'
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
timeout 300 roslaunch -p "$port" "$root/launch/hunt.launch" output_dir:="$work/hunt" set:=h \
  config:="$work/hunt.yaml" > "$work/hunt.log" 2>&1
[ "$(started "$work/hunt.log")" = "bumper gen_h hunt nodelet_manager rosout simulator wall_follower_left " ] && pass || \
  fail "the hunt started other processes: $(started "$work/hunt.log")"
"$devel/lib/ppp_simulator/ppp" generate --config "$work/hunt/generator.yaml" -o "$work/hunt_cli" > /dev/null 2>&1
same_sets "$work/hunt" "$work/hunt_cli" && pass || \
  fail "the hunt through ROS differs from ppp generate's: $(tail -20 "$work/hunt.log")"

# launch/shrink.launch: a built-in agent's failures of that set shrunk through ROS (only the shrink node, the
# simulator and that agent's node start) are `ppp shrink`'s byte for byte: the same seeds, the same diagnoses.
timeout 300 roslaunch -p "$port" "$root/launch/shrink.launch" input:="$work/hunt" agent:=bumper \
  output:="$work/shrunk" config:="$work/hunt.yaml" args:="--runs 2" > "$work/shrink.log" 2>&1
status=$?
[ "$(started "$work/shrink.log")" = "bumper nodelet_manager rosout shrink shrink_launch simulator " ] && pass || \
  fail "the shrink started other processes: $(started "$work/shrink.log")"
sed -n '/^agents:/,/^sets:/p' "$work/hunt.yaml" | grep -v '^sets:' > "$work/hunt_agents.yaml"
"$devel/lib/ppp_simulator/ppp" shrink "$work/hunt" --agents-file "$work/hunt_agents.yaml" --agent bumper \
  --runs 2 -o "$work/shrunk_cli" > "$work/shrink_cli.log" 2>&1
[ "$status" -eq 0 ] && [ -n "$(ls "$work/shrunk" 2>/dev/null)" ] && pass || \
  fail "the shrink through ROS exited $status: $(grep -v '^\s*$' "$work/shrink.log" | tail -20)"
diff -r "$work/shrunk" "$work/shrunk_cli" > /dev/null && pass || \
  fail "the shrink through ROS differs from ppp shrink's: $(diff -r "$work/shrunk" "$work/shrunk_cli" | head)"
# A shrink naming an agent the config lacks stops before any node of its graph starts.
timeout 120 roslaunch -p "$port" "$root/launch/shrink.launch" input:="$work/hunt" agent:=nobody \
  output:="$work/nobody" config:="$work/hunt.yaml" > "$work/nobody.log" 2>&1
grep -qF -- "--agent: the config has no agent 'nobody'; it has: wall_follower_left, bumper, astar" \
  "$work/nobody.log" && [ "$(started "$work/nobody.log")" = "rosout shrink_launch " ] && \
  [ ! -e "$work/nobody" ] && pass || fail "an unknown agent's shrink: $(tail "$work/nobody.log")"

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
finish
