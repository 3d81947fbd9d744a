#!/usr/bin/env bash
# Failure signatures tell the zoo's faults apart: the optimistic planner and each of the eight zoo faults alone
# (their limits scaled to 10x10 maps) played through roslaunch on seven hand-made maps (fault_maps/), one made for
# each fault: a route that must step west into the left column (west), an obstacle diagonal to the goal
# (goal_clear), a goal with three blocked sides (dead_end), a corridor that ends where the robot must turn back
# (back), a wall the robot follows down into a bag (bag: the search horizon and the expansion budget), an empty map
# (open: the open list's front), two walls whose gaps lie on opposite sides (zigzag: re-planning). The planner
# without a fault passes every map; each fault fails its own map; the signatures of those failures are different
# for every pair of faults the benchmark says signatures separate (all but search_horizon / expansion_budget and
# goal_clearance / dead_end_filter, which give up at the same moment for the same reason); and on each fault's map,
# no other fault of such a pair fails the way it does.
# Usage: fault_signatures_test.sh DEVEL_DIR
source "$(dirname "${BASH_SOURCE[0]}")/ros_harness.sh"

zoo() {  # zoo FAULT LIMIT: the agent entry of the zoo planner with FAULT planted
  printf '  - {name: %s, type: planner, planner_node: ppp_agents/zoo_planner_node, planner_args: "_fault:=%s%s"}\n' \
    "$1" "$1" "${2:+ _limit:=$2}"
}
{
  printf 'seed: 1\nruns: 1\nbudget: 300\nsensor_range: 2\nagents:\n'
  printf '  - {name: none, type: planner, planner_node: ppp_agents/optimistic_planner_node}\n'
  zoo search_horizon 20; zoo expansion_budget 40; zoo west_edge; zoo goal_clearance; zoo dead_end_filter
  zoo open_list_cap 14; zoo no_backtrack; zoo replan_limit 7
  printf 'sets:\n  - name: hand\n    directory: %s\n' "$root/ppp_simulator/test/ros/fault_maps"
} > "$work/faults.yaml"

if timeout 300 roslaunch -p "$port" "$root/launch/experiment.launch" output_dir:="$work/out" \
  config:="$work/faults.yaml" > "$work/launch.log" 2>&1; then pass; else fail "the experiment failed: $(tail -5 "$work/launch.log")"; fi

/usr/bin/python3 - "$work/out/results.csv" > "$work/verdicts" <<'PY'
import csv, itertools, sys
own = {"search_horizon": "bag", "expansion_budget": "bag", "west_edge": "west", "goal_clearance": "goal_clear",
       "dead_end_filter": "dead_end", "open_list_cap": "open", "no_backtrack": "back", "replan_limit": "zigzag"}
apart = [p for p in itertools.combinations(own, 2)
         if set(p) not in ({"search_horizon", "expansion_budget"}, {"goal_clearance", "dead_end_filter"})]
ran = {(r["agent"], r["problem"]): r for r in csv.DictReader(open(sys.argv[1]))}
def signature(agent, problem):
    r = ran[(agent, problem)]
    return None if r["pass"] == "1" else r["signature"]
for problem in sorted(set(own.values())):
    print("ok" if signature("none", problem) is None else "FAIL none fails %s" % problem)
for fault, problem in own.items():
    print("ok" if signature(fault, problem) else "FAIL %s passes its map %s" % (fault, problem))
for a, b in apart:
    sa, sb = signature(a, own[a]), signature(b, own[b])
    print("ok" if sa != sb else "FAIL %s on %s and %s on %s both %s" % (a, own[a], b, own[b], sa))
    for fault, other in ((a, b), (b, a)):
        mine, theirs = signature(fault, own[fault]), signature(other, own[fault])
        print("ok" if mine != theirs else "FAIL %s fails %s as %s does: %s" % (other, own[fault], fault, mine))
PY
[ "$(grep -c '^ok$' "$work/verdicts")" -eq $((7 + 8 + 3 * 26)) ] && pass || fail "$(grep -v '^ok$' "$work/verdicts")"
finish
