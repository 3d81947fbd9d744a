#!/usr/bin/env bash
# A timer-driven planner in continuous motion (the steering example: a rospy.Rate on the robot's clock) started by
# hand after the bridge waits for it, once at once and once with its timer started three seconds late, when the
# bridge has already asked the first period and the clock stands at that period's time: the timer would wait a
# whole period on a clock that moves only when the planner answers. The bridge asks that first period again a
# control period later, so both launches give the same rows and no run times out.
# Usage: timer_planner_start_test.sh DEVEL_DIR
source "$(dirname "${BASH_SOURCE[0]}")/ros_harness.sh"

cat > "$work/steer.yaml" <<'YAML'
seed: 3
runs: 1
motion: continuous
robot_radius: 0.2
agents:
  - {name: mine, type: planner, interface: cmd_vel}
sets:
  - name: small
    generator: {fitness: turns, population: 4, matings: 40, width: 10, height: 10, seed: 2}
YAML
planner="$root/ppp_agents/scripts/steering_planner.py"
sed 's|^    rate = rospy.Rate(10)|    import time; time.sleep(3)\n&|' "$planner" > "$work/late_steering.py"
grep -q 'time.sleep(3)' "$work/late_steering.py" && pass || fail "the late copy of the planner was not made"

# play NAME PLANNER: the experiment with PLANNER started by hand in the robot's namespace, as the tutorial does.
play() {
  timeout 300 roslaunch -p "$port" "$root/launch/experiment.launch" output_dir:="$work/$1" \
    config:="$work/steer.yaml" > "$work/$1.log" 2>&1 &
  local launch=$!
  for _ in $(seq 1 600); do grep -q "bridge 'mine': waiting for a planner" "$work/$1.log" && break; sleep 0.1; done
  /usr/bin/python3 "$2" __ns:=/mine/robot /clock:=/mine/robot/clock > "$work/$1.planner.log" 2>&1 &
  local started=$!
  wait "$launch"
  kill "$started" 2> /dev/null
  wait "$started" 2> /dev/null
}
play at_once "$planner"
play late "$work/late_steering.py"

rows=$(grep -c ',mine,' "$work/at_once/results.csv")
[ "$rows" -eq 4 ] && pass || fail "expected 4 rows of mine, got $rows: $(tail "$work/at_once.log")"
! grep -q -e planner_timeout -e planner_lost "$work/at_once/results.csv" "$work/late/results.csv" && pass || \
  fail "a run timed out or lost its planner: $(grep -h ",mine," "$work"/*/results.csv | cut -d, -f11 | sort | uniq -c)"
cmp -s "$work/at_once/results.csv" "$work/late/results.csv" && pass || \
  fail "the late timer's rows differ: $(diff "$work/at_once/results.csv" "$work/late/results.csv" | head -5)"
finish
