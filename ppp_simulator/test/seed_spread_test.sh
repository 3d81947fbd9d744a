#!/bin/bash
# scripts/seed_spread.py as a user runs it, on small experiments with a reference: astar passes every valid PPP,
# so its spread is known by hand; each seed's experiment is CONFIG's with only the seeds changed (every value as
# written, paths and generator defaults read beside CONFIG); bad usage and a CONFIG without a usable reference are
# refused with exit status 2 and a message naming the flag or key.
source "$(dirname "$0")/cli_harness.sh"
spread="$(dirname "$0")/../../scripts/seed_spread.py"
ppp="$(dirname "$0")/../../scripts/ppp"

# Inline agents whose values YAML 1.1 would retype if read and written back (1.10 as 1.1, on as true).
cat > "$work/experiment.yaml" <<'YAML'
seed: 9
runs: 3
agents:
  - {name: astar, type: astar}
  - {name: 1.10, type: random, goal_seeking: on}
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
if grep -q "^| turns | 1.10 |  | " "$work/out" && grep -q "^| turns | \*mean optimal turns\* |  | " "$work/out"
then pass
else fail "rows without a reference: $(grep "^| turns" "$work/out")"; fi
if grep -q "^Sets within 10 points of every reference: 3 of 3 (seeds 1, 2, 3)$" "$work/out"; then pass
else fail "sets within: $(grep "^Sets" "$work/out")"; fi
# One row per seed and agent of the referenced set (difficulty is left out).
rows=$(($(wc -l < "$work/spread/spread.csv") - 1))
if [ "$rows" -eq 6 ] && ! grep -q difficulty "$work/spread/spread.csv"; then pass
else fail "spread.csv: expected 6 rows of turns, got $rows: $(cat "$work/spread/spread.csv")"; fi
# Seed 2's experiment is CONFIG's with the experiment's and the set's seeds set to 2: the same 36 rows (6 PPPs x 2
# agents x 3 runs).
sed -e 's/^seed: 9/seed: 2/' -e 's/height: 14, seed: 3}/height: 14, seed: 2}/' "$work/experiment.yaml" \
  > "$work/seed2.yaml"
expect_ok "seed 2 directly" "$ppp" experiment "$work/seed2.yaml" -o "$work/direct" --quiet
grep "^turns," "$work/direct/results.csv" > "$work/direct_rows"
if [ "$(wc -l < "$work/direct_rows")" -eq 36 ] && grep -q ",1.10," "$work/direct_rows" &&
  cmp -s "$work/direct_rows" <(grep "^turns," "$work/spread/seed_2/results.csv"); then pass
else fail "seed 2's rows differ from ppp experiment's on the same options"; fi

# A reference out of reach: no set within 10 points, so no typical seed of them is named. The agents file and the
# generator defaults are beside the config, run from elsewhere.
mkdir "$work/config"
cat > "$work/config/agents.yaml" <<'YAML'
agents:
  - {name: astar, type: astar}
  - {name: random, type: random}
YAML
echo "max_obstacles: 3" > "$work/config/generator.yaml"
cat > "$work/config/experiment.yaml" <<'YAML'
agents: agents.yaml
runs: 2
sets:
  - name: turns
    generator: {fitness: turns, population: 6, matings: 200, width: 14, height: 14}
reference:
  turns: {astar: 80}
YAML
expect_ok "spread, none within" /usr/bin/python3 "$spread" "$work/config/experiment.yaml" --seeds 4,5 --runs 1 \
  --work "$work/none"
if grep -q "^Sets within 10 points of every reference: 0 of 2$" "$work/out" &&
  ! grep -q "most typical of them" "$work/out"; then pass
else fail "none within: $(tail -2 "$work/out")"; fi
if grep -q "^| turns | astar | 80.00 | 100.00 | 0.00 | 100.0 - 100.0 | 0 % |$" "$work/out"; then pass
else fail "astar's row at 80: $(grep astar "$work/out")"; fi
sed -e 's/^runs: 2/runs: 1\nseed: 5/' -e 's/height: 14}/height: 14, seed: 5}/' "$work/config/experiment.yaml" \
  > "$work/config/seed5.yaml"
expect_ok "seed 5 directly" "$ppp" experiment "$work/config/seed5.yaml" -o "$work/direct5" --quiet
if cmp -s <(grep "^turns," "$work/direct5/results.csv") <(grep "^turns," "$work/none/seed_5/results.csv") &&
  grep -q "max_obstacles: 3" "$work/none/seed_5/sets/turns/generator.yaml"; then pass
else fail "seed 5's rows differ from ppp experiment's beside the config"; fi
# Run again without the generator defaults: the copy the first run left in the work directory goes too.
rm "$work/config/generator.yaml"
expect_ok "spread, no defaults" /usr/bin/python3 "$spread" "$work/config/experiment.yaml" --seeds 5 --runs 1 \
  --work "$work/none"
if grep -q "max_obstacles: 10" "$work/none/seed_5/sets/turns/generator.yaml"; then pass
else fail "an earlier config's generator defaults were used"; fi

# A set that starts from another set's pool: both are played, the first with the seed, the second with seed + 1.
cat > "$work/pool.yaml" <<'YAML'
agents: [{name: astar, type: astar}]
sets:
  - name: base
    generator: {fitness: turns, population: 6, matings: 50, width: 10, height: 10}
  - name: unused
    generator: {fitness: turns, population: 6, matings: 50, width: 10, height: 10}
  - name: derived
    generator: {fitness: turns, population: 6, matings: 50, width: 10, height: 10, initial_pool: base}
reference:
  derived: {astar: 100}
YAML
expect_ok "spread from a pool" /usr/bin/python3 "$spread" "$work/pool.yaml" --seeds 7 --runs 1 --work "$work/pool"
if [ "$(ls "$work/pool/seed_7/sets")" = "$(printf 'base\nderived')" ] &&
  grep -q "seed: 7" "$work/pool/seed_7/sets/base/generator.yaml" &&
  grep -q "seed: 8" "$work/pool/seed_7/sets/derived/generator.yaml"; then pass
else fail "pool sets: $(ls "$work/pool/seed_7/sets")"; fi

refused() {  # NAME TEXT CONFIG_TEXT: the config is refused naming TEXT, with exit status 2
  printf '%s\n' "$3" > "$work/bad.yaml"
  /usr/bin/python3 "$spread" "$work/bad.yaml" --seeds 1 --runs 1 --work "$work/bad" > "$work/out" 2> "$work/err"
  local status=$?
  if [ "$status" -eq 2 ] && grep -qF -- "$2" "$work/err"; then pass
  else fail "$1: exit $status, expected 2 and '$2': $(cat "$work/err")"; fi
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
refused "unknown agent" "reference.turns.nobody: no agent of that name in agents" \
  "agents: [{name: astar, type: astar}]
$sets
reference: {turns: {nobody: 90}}"
refused "two sets of a name" "sets[1].name: 'turns' names two sets" \
  "sets: [{name: turns, directory: /a}, {name: turns, directory: /b}]
reference: {turns: {astar: 90}}"
refused "generator not a mapping" "sets[0].generator: expected a mapping of generator options" \
  "sets: [{name: turns, generator: 3}]
reference: {turns: {astar: 90}}"
# (the flags' own checks, after the config is fine)
printf '%s\n' "$sets" 'reference: {turns: {astar: 90}}' 'budget: 0' > "$work/bad.yaml"
expect_error "experiment refused" "ppp experiment failed on $work/bad/seed_1.yaml" \
  /usr/bin/python3 "$spread" "$work/bad.yaml" --seeds 1 --runs 1 --work "$work/bad"
for flags in "--seeds 5-1" "--seeds 0-99999999999" "--seeds 1,1" "--runs 0" "--tolerance -1" "--tolerance nan" \
  "--work $work"; do
  # shellcheck disable=SC2086
  /usr/bin/python3 "$spread" "$work/bad.yaml" $flags > "$work/out" 2> "$work/err"
  status=$?
  flag="${flags%% *}"
  if [ "$status" -eq 2 ] && grep -qF -- "$flag: " "$work/err"; then pass
  else fail "$flags: exit $status, expected 2 naming $flag: $(cat "$work/err")"; fi
done
expect_error "missing config" "cannot read it" /usr/bin/python3 "$spread" "$work/nothing.yaml" --work "$work/bad"
finish
