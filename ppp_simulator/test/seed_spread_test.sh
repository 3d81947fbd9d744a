#!/bin/bash
# scripts/seed_spread.py as a user runs it, on a small experiment with a reference: astar passes every valid PPP,
# so its spread is known by hand; each seed's experiment is CONFIG's with only the seeds changed; bad usage and a
# CONFIG without a usable reference are refused with exit status 2 and a message naming the flag or key.
source "$(dirname "$0")/cli_harness.sh"
spread="$(dirname "$0")/../../scripts/seed_spread.py"
ppp="$(dirname "$0")/../../scripts/ppp"

# Inline agents, one with a word YAML 1.1 would read as a boolean (goal_seeking: on).
cat > "$work/experiment.yaml" <<'YAML'
seed: 9
runs: 3
agents:
  - {name: astar, type: astar}
  - {name: random, type: random, goal_seeking: on}
sets:
  - name: turns
    generator: {fitness: turns, population: 6, matings: 200, width: 14, height: 14, seed: 3}
  - name: difficulty
    generator: {fitness: difficulty, population: 6, matings: 200, width: 14, height: 14, seed: 4}
reference:
  turns: {astar: 95}
YAML

expect_ok "spread" /usr/bin/python3 "$spread" "$work/experiment.yaml" --seeds 1-3 --runs 3 --work "$work/spread"
# astar passes 100 % of every set: within 10 points of 95 on all three seeds, none of its sets below 95.
if grep -q "^| turns | astar | 95.00 | 100.00 | 0.00 | 100.0 - 100.0 | 0 % |$" "$work/out"; then pass
else fail "astar's row: $(grep astar "$work/out")"; fi
if grep -q "^Sets within 10 points of every reference: 3 of 3 (seeds 1, 2, 3)$" "$work/out"; then pass
else fail "sets within: $(grep "^Sets" "$work/out")"; fi
# Every seed's astar rate is the mean, so each is as typical as the others: the first is named.
if grep -q "^The most typical set: seed 1 (its rates 0.0 points from the mean" "$work/out" &&
  grep -q "^The most typical of them: seed 1 (0.0 points from the mean)$" "$work/out"; then pass
else fail "typical seed: $(tail -3 "$work/out")"; fi
# One row per seed and agent of the referenced set (difficulty is left out).
rows=$(($(wc -l < "$work/spread/spread.csv") - 1))
if [ "$rows" -eq 6 ] && ! grep -q difficulty "$work/spread/spread.csv"; then pass
else fail "spread.csv: expected 6 rows of turns, got $rows: $(cat "$work/spread/spread.csv")"; fi
# Seed 2's experiment is CONFIG's with the experiment's and the set's seeds set to 2: the same rows.
sed -e 's/^seed: 9/seed: 2/' -e 's/height: 14, seed: 3}/height: 14, seed: 2}/' "$work/experiment.yaml" \
  > "$work/seed2.yaml"
expect_ok "seed 2 directly" "$ppp" experiment "$work/seed2.yaml" -o "$work/direct" --quiet
if cmp -s <(grep "^turns," "$work/direct/results.csv") <(grep "^turns," "$work/spread/seed_2/results.csv"); then pass
else fail "seed 2's rows differ from ppp experiment's on the same options"; fi

# A reference out of reach: no set within 10 points, so no typical seed is named. The agents are a file beside
# the config, run from elsewhere.
mkdir "$work/config"
cat > "$work/config/agents.yaml" <<'YAML'
agents:
  - {name: astar, type: astar}
YAML
cat > "$work/config/experiment.yaml" <<'YAML'
agents: agents.yaml
sets:
  - name: turns
    generator: {fitness: turns, population: 6, matings: 200, width: 14, height: 14}
reference:
  turns: {astar: 80}
YAML
expect_ok "spread, none within" /usr/bin/python3 "$spread" "$work/config/experiment.yaml" --seeds 4,5 --runs 1 \
  --work "$work/none"
if grep -q "^Sets within 10 points of every reference: 0 of 2$" "$work/out" && ! grep -q "most typical of them" "$work/out"
then pass; else fail "none within: $(tail -2 "$work/out")"; fi
if grep -q "^| turns | astar | 80.00 | 100.00 | 0.00 | 100.0 - 100.0 | 0 % |$" "$work/out"; then pass
else fail "astar's row at 80: $(grep astar "$work/out")"; fi

refused() {  # NAME TEXT CONFIG_TEXT: the config is refused naming TEXT
  printf '%s\n' "$3" > "$work/bad.yaml"
  expect_error "$1" "$2" /usr/bin/python3 "$spread" "$work/bad.yaml" --seeds 1 --runs 1 --work "$work/bad"
}
sets='sets: [{name: turns, generator: {fitness: turns, population: 6, matings: 10, width: 8, height: 8}}]'
refused "no reference" "bad.yaml: no reference to compare with" "seed: 1
$sets"
refused "unknown set" "bad.yaml: reference.hunted: no set of that name in sets" "$sets
reference: {hunted: {astar: 90}}"
refused "set from a directory" "reference.mine: the set is read from a directory" \
  "sets: [{name: mine, directory: /nowhere}]
reference: {mine: {astar: 90}}"
refused "bad percent" "reference.turns.astar: expected a pass rate in percent (0 to 100), got 'high'" "$sets
reference: {turns: {astar: high}}"
refused "unknown agent" "reference.turns.nobody: no agent of that name in the experiment" "agents: [{name: astar, type: astar}]
$sets
reference: {turns: {nobody: 90}}"
printf '%s\n' "$sets" 'reference: {turns: {astar: 90}}' 'budget: 0' > "$work/bad.yaml"
expect_error "experiment refused" "ppp experiment failed on $work/bad/seed_1.yaml" \
  /usr/bin/python3 "$spread" "$work/bad.yaml" --seeds 1 --runs 1 --work "$work/bad"
expect_error "bad seeds" "--seeds: expected FIRST-LAST or distinct non-negative integers" \
  /usr/bin/python3 "$spread" "$work/experiment.yaml" --seeds 5-1 --work "$work/bad"
expect_error "no runs" "--runs: expected at least 1, got 0" \
  /usr/bin/python3 "$spread" "$work/experiment.yaml" --runs 0 --work "$work/bad"
expect_error "negative tolerance" "--tolerance: expected points >= 0, got -1" \
  /usr/bin/python3 "$spread" "$work/experiment.yaml" --tolerance -1 --work "$work/bad"
expect_error "missing config" "cannot read it" /usr/bin/python3 "$spread" "$work/nothing.yaml" --work "$work/bad"
finish
