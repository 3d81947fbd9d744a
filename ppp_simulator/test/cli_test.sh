#!/usr/bin/env bash
# Behaviour of the `ppp` command line, run as a user would. Usage: cli_test.sh PATH_TO_PPP
set -u
ppp="$1"
config_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../config" && pwd)"
source "$(dirname "${BASH_SOURCE[0]}")/cli_harness.sh"

for sub in random evaluate convert generate tree select export scenarios; do
  expect_ok "help $sub" "$ppp" "$sub" --help
  grep -q "Usage" "$work/out" && pass || fail "help $sub has no usage"
done

# The wrapper passes the user's arguments to the binary untouched (catkin's setup script must not see them).
wrapper="$(dirname "${BASH_SOURCE[0]}")/../../scripts/ppp"
if PPP_BUILD_DIR="$(cd "$(dirname "$ppp")/../../.." && pwd)" "$wrapper" generate --help > "$work/wrapper.out" 2> "$work/wrapper.err" \
  && [ ! -s "$work/wrapper.err" ] && grep -q "Usage" "$work/wrapper.out"; then
  pass
else
  fail "scripts/ppp generate --help: $(head -3 "$work/wrapper.err")"
fi

# docs/reference/options.md is kept equal to `ppp options` by docs_reference_test (scripts/docs_reference.sh).
expect_ok "options" "$ppp" options

expect_ok "random" "$ppp" random --size 12x9 --obstacles 6 --seed 7 -o "$work/a.ppp"
expect_ok "random again" "$ppp" random --size 12x9 --obstacles 6 --seed 7 -o "$work/b.ppp"
cmp -s "$work/a.ppp" "$work/b.ppp" && pass || fail "same seed gave different files"
expect_ok "random other seed" "$ppp" random --size 12x9 --obstacles 6 --seed 8 -o "$work/c.ppp"
cmp -s "$work/a.ppp" "$work/c.ppp" && fail "different seeds gave the same file" || pass
grep -q "^size 12 9$" "$work/a.ppp" && pass || fail "size line"

expect_ok "evaluate json" "$ppp" evaluate "$work/a.ppp" --json
for key in width height valid turns advances turns_plus_advances obstacle_use visibility start goal centre \
  top_right bottom_left horizontal_openness vertical_openness difficulty; do
  grep -q "\"$key\":" "$work/out" && pass || fail "evaluate --json lacks $key"
done
/usr/bin/python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); assert d["width"]==12 and d["valid"] is True' \
  "$work/out" && pass || fail "evaluate --json is not the expected JSON"
expect_ok "evaluate text" "$ppp" evaluate "$work/a.ppp"
grep -q "difficulty" "$work/out" && pass || fail "evaluate text lacks difficulty"
expect_ok "evaluate csv" "$ppp" evaluate "$work/a.ppp" "$work/c.ppp" --csv "$work/m.csv"
[ "$(wc -l < "$work/m.csv")" -eq 3 ] && pass || fail "evaluate --csv rows"
expect_ok "evaluate weight" "$ppp" evaluate "$work/a.ppp" --json --weight goal=0 --weight one_turn_penalty=5

expect_ok "to yaml" "$ppp" convert "$work/a.ppp" "$work/a.yaml" --resolution 0.5
[ -s "$work/a.pgm" ] && pass || fail "no pgm next to the yaml"
expect_ok "from yaml" "$ppp" convert "$work/a.yaml" "$work/a2.ppp"
cmp -s "$work/a.ppp" "$work/a2.ppp" && pass || fail ".ppp -> .yaml -> .ppp is not identical"
expect_ok "to png" "$ppp" convert "$work/a.ppp" "$work/a.png" --route
head -c 8 "$work/a.png" | od -An -c | grep -q "P   N   G" && pass || fail "png signature"
expect_ok "to bt" "$ppp" convert "$work/a.ppp" "$work/a.bt" --height 2
[ -s "$work/a.bt" ] && pass || fail "empty .bt"

expect_error "missing file" "$work/none.ppp" "$ppp" evaluate "$work/none.ppp"
printf 'ppp 1\nsize 4 x\n' > "$work/bad.ppp"
expect_error "bad file" "bad.ppp:2: size: height must be an integer" "$ppp" evaluate "$work/bad.ppp"
expect_error "bad size" "--size: expected WIDTHxHEIGHT" "$ppp" random --size 20 --obstacles 1 --seed 1 -o "$work/x.ppp"
expect_error "huge size" "--size: expected width and height in [2, 4096]" \
  "$ppp" random --size 5000x5000 --obstacles 1 --seed 1 -o "$work/x.ppp"
expect_error "negative obstacles" "--obstacles" "$ppp" random --obstacles -2 --seed 1 -o "$work/x.ppp"
expect_error "start outside" "start: cell (30, 0) is outside" \
  "$ppp" random --obstacles 1 --seed 1 --start 30,0 -o "$work/x.ppp"
expect_error "start is goal" "goal: must differ from start" \
  "$ppp" random --obstacles 1 --seed 1 --start 19,19 -o "$work/x.ppp"
expect_error "unknown weight" "unknown weight 'gaol'; valid: start" "$ppp" evaluate "$work/a.ppp" --weight gaol=1
expect_error "bad extension" "cannot write '.txt' files" "$ppp" convert "$work/a.ppp" "$work/a.txt"
expect_error "bad height" "height" "$ppp" convert "$work/a.ppp" "$work/z.bt" --height -1
[ ! -e "$work/x.ppp" ] && pass || fail "a failed command left an output file"
expect_error "no subcommand" "A subcommand is required" "$ppp"

# --- generate, tree, select
gen=(generate --population 12 --matings 300 --width 14 --height 10 --max-obstacles 6 --quiet)
expect_ok "generate" "$ppp" "${gen[@]}" --seed 5 -o "$work/set_a"
expect_ok "generate same seed" "$ppp" "${gen[@]}" --seed 5 -o "$work/set_b"
diff -r "$work/set_a" "$work/set_b" > /dev/null && pass || fail "same seed gave different set directories"
expect_ok "generate --size" "$ppp" generate --population 12 --matings 300 --size 14x10 --max-obstacles 6 --quiet --seed 5 \
  -o "$work/set_size"
diff -r "$work/set_a" "$work/set_size" > /dev/null && pass || fail "--size 14x10 and --width 14 --height 10 differ"
expect_ok "generate help" "$ppp" generate --help
grep -q -- "--population INT in \[2, 100000\]" "$work/out" && pass || fail "generate --help hides the population's kind and range"
grep -q -- "--connectivity 4|8" "$work/out" && pass || fail "generate --help lacks --connectivity"
expect_ok "generate other seed" "$ppp" "${gen[@]}" --seed 6 -o "$work/set_c"
diff -r "$work/set_a" "$work/set_c" > /dev/null && fail "different seeds gave the same set" || pass
[ "$(ls "$work/set_a"/*.ppp | wc -l)" -eq 12 ] && pass || fail "generate did not write 12 .ppp files"
for f in set.csv generator.yaml tree.nwk tree.json tree.html; do
  [ -s "$work/set_a/$f" ] && pass || fail "generate did not write $f"
done
[ "$(wc -l < "$work/set_a/set.csv")" -eq 13 ] && pass || fail "set.csv rows"
grep -q "^meta fitness turns$" "$work/set_a/ppp_000.ppp" && pass || fail "PPP lacks its fitness metadata"
expect_ok "generate over an old set" "$ppp" "${gen[@]}" --seed 6 -o "$work/set_a"
diff -r "$work/set_a" "$work/set_c" > /dev/null && pass || fail "regenerating into a set directory did not replace it"
expect_ok "generate difficulty" "$ppp" "${gen[@]}" --fitness difficulty --weights-goal 3 --seed 1 -o "$work/set_d"
grep -q "^  goal: 3$" "$work/set_d/generator.yaml" && pass || fail "weight override not recorded"

expect_ok "tree wei" "$ppp" tree "$work/set_a" --characters wei
grep -q ";$" "$work/out" && pass || fail "tree printed no Newick"
expect_ok "tree barn" "$ppp" tree "$work/set_a" --characters barn
grep -q "barn characters" "$work/set_a/tree.html" && pass || fail "tree --characters barn did not title its tree"
expect_ok "select" "$ppp" select "$work/set_a" -k 4
[ "$(sort -u "$work/out" | wc -l)" -eq 4 ] && pass || fail "select -k 4 did not print 4 distinct PPPs"
expect_ok "select hardest" "$ppp" select "$work/set_a" -k 3 --prefer hardest --copy-to "$work/picked"
[ "$(ls "$work/picked" | wc -l)" -eq 3 ] && pass || fail "select --copy-to did not copy 3 files"

# --- export: a set as MovingAI maps with a scenario list, each map converting back to its PPP's grid
expect_ok "export map" "$ppp" export "$work/set_a" "$work/exported"
[ "$(ls "$work/exported"/*.map | wc -l)" -eq 12 ] && pass || fail "export did not write 12 .map files"
[ "$(head -1 "$work/exported/set_a.scen")" = "version 1" ] && [ "$(wc -l < "$work/exported/set_a.scen")" -eq 13 ] \
  && pass || fail "set_a.scen is not a version 1 list of 12 scenarios"
read -r _ map _ _ sx sy gx gy _ < <(sed -n 2p "$work/exported/set_a.scen")
expect_ok "export map back" "$ppp" convert "$work/exported/$map" "$work/back.ppp" --start "$sx,$sy" --goal "$gx,$gy"
expect_ok "export map back to .map" "$ppp" convert "$work/back.ppp" "$work/back.map"
expect_ok "original to .map" "$ppp" convert "$work/set_a/ppp_000.ppp" "$work/orig.map"
cmp -s "$work/back.map" "$work/orig.map" && pass || fail "exported ppp_000.map is not ppp_000's grid"
expect_ok "export yaml" "$ppp" export "$work/set_a" "$work/exported_yaml" --format yaml
[ "$(ls "$work/exported_yaml"/*.pgm | wc -l)" -eq 12 ] && pass || fail "export --format yaml did not write 12 maps"
expect_error "export unknown format" "--format: cannot export to '.gif'" "$ppp" export "$work/set_a" "$work/x" --format gif
expect_error "export no set" "nothing: is not a directory of PPP files" "$ppp" export "$work/nothing" "$work/x"

# --- scenarios: the exported set's own .scen, then MovingAI's arena map
expect_ok "scenarios on an export" "$ppp" scenarios "$work/exported/set_a.scen" --agent astar
grep -q "^astar on .*: 12 of 12 scenarios passed" "$work/out" && pass || fail "astar did not pass every exported PPP"
arena="$(dirname "${BASH_SOURCE[0]}")/../../src/test/data/movingai/arena.map.scen"
expect_ok "scenarios json" "$ppp" scenarios "$arena" --agent astar --json
python3 -c "
import json, sys
j = json.load(open(sys.argv[1]))
s = j['scenarios']
assert len(s) == 130 and j['totals']['passed'] == 130, j['totals']
assert s[0] == {'bucket': 0, 'start': [19, 26], 'goal': [19, 29], 'optimal_length': 3.0, 'path_length': 3,
                'passed': True, 'steps': 3, 'seed': s[0]['seed']}, s[0]
assert all(x['path_length'] >= x['optimal_length'] - 1e-9 for x in s)
" "$work/out" && pass || fail "scenarios --json: $(head -c 300 "$work/out")"
expect_ok "scenarios connectivity 8" "$ppp" scenarios "$arena" --agent astar --connectivity 8 --json
python3 -c "
import json, sys
j = json.load(open(sys.argv[1]))
assert j['connectivity'] == 8 and j['totals']['passed'] == 130, j['totals']
assert all(abs(x['path_length'] - x['optimal_length']) < 1e-3 for x in j['scenarios'])
" "$work/out" && pass || fail "astar --connectivity 8 did not reproduce the published lengths"
# Without --budget a scenario may take as many moves as its map has free cells: a serpentine 41 x 41 map whose
# only route is 880 moves long (21 rows of 40 and 40 steps down) passes by default and fails with --budget 300.
python3 -c "
rows = []
for y in range(41):
    if y % 2 == 0:
        rows.append('.' * 41)
    else:
        rows.append(('@' * 40 + '.') if y % 4 == 1 else ('.' + '@' * 40))
open('$work/snake.map', 'w').write('type octile\\nheight 41\\nwidth 41\\nmap\\n' + '\\n'.join(rows) + '\\n')
open('$work/snake.map.scen', 'w').write('version 1\\n215\\tsnake.map\\t41\\t41\\t0\\t0\\t40\\t40\\t880\\n')
"
expect_ok "scenarios default budget" "$ppp" scenarios "$work/snake.map.scen" --agent astar --json
grep -q '"passed":true,"path_length":880.0' "$work/out" && pass || fail "the 880-move route did not fit the default budget: $(cat "$work/out")"
expect_ok "scenarios --budget" "$ppp" scenarios "$work/snake.map.scen" --agent astar --budget 300 --json
grep -q '"passed":false,"path_length":300.0,.*"steps":300' "$work/out" && pass || fail "--budget 300 was not applied: $(cat "$work/out")"
expect_ok "scenarios --budget-factor 1" "$ppp" scenarios "$work/snake.map.scen" --agent astar --budget-factor 1 --json
grep -q '"passed":true,.*"steps":880' "$work/out" && pass || fail "factor 1 did not give astar its 880 moves: $(cat "$work/out")"
expect_ok "scenarios --budget-factor 0.99" "$ppp" scenarios "$work/snake.map.scen" --agent astar --budget-factor 0.99 --json
grep -q '"passed":false,.*"steps":872' "$work/out" && pass || fail "ceil(0.99 x 880) is not 872 moves: $(cat "$work/out")"
expect_error "budget and budget factor" "--budget-factor: give either --budget or --budget-factor, not both" \
  "$ppp" scenarios "$work/snake.map.scen" --agent astar --budget 300 --budget-factor 2
expect_error "scenarios connectivity 6" "--connectivity: unknown connectivity '6'; valid: 4, 8" "$ppp" scenarios "$arena" --agent astar --connectivity 6
cp "$arena" "$work/lonely.scen"
expect_error "scenarios map missing" "map 'arena.map' not found" "$ppp" scenarios "$work/lonely.scen" --agent astar
expect_ok "scenarios --map-dir" "$ppp" scenarios "$work/lonely.scen" --agent astar --map-dir "$(dirname "$arena")"
expect_error "scenarios no file" "cannot open" "$ppp" scenarios "$work/none.scen" --agent astar

# Bad options fail validation before any work, so these runs use the shipped defaults otherwise.
expect_error "unknown fitness" "fitness: unknown fitness 'hardness'; valid: turns, advances" \
  "$ppp" generate --quiet --fitness hardness -o "$work/bad1"
expect_error "population 1" "--population: expected an integer in [2, 100000], got 1" "$ppp" generate --quiet --population 1 -o "$work/bad1"
expect_error "negative matings" "--matings: expected an integer in [0, 1000000000], got -1" "$ppp" generate --quiet --matings -1 -o "$work/bad1"
expect_error "tiny size" "width: expected an integer in [2, 4096], got 1" \
  "$ppp" generate --quiet --width 1 -o "$work/bad1"
expect_error "huge size" "height: expected an integer in [2, 4096], got 9000" "$ppp" generate --quiet --height 9000 -o "$work/bad1"
expect_error "not a number" "--height: expected an integer, got 'tall'" "$ppp" generate --quiet --height tall -o "$work/bad1"
expect_error "negative budget" "--max-obstacles: expected an integer in [0, 1048576], got -1" "$ppp" generate --quiet --max-obstacles -1 -o "$work/bad1"
expect_error "goal outside" "goal: cell (14, 0) is outside the 14x10 grid" "$ppp" generate --quiet --width 14 --height 10 --goal 14,0 -o "$work/bad1"
expect_error "start is goal" "goal: must differ from start" "$ppp" generate --quiet --width 14 --height 10 --start 13,9 -o "$work/bad1"
expect_error "size and width" "--size: give either --size or --width, not both" \
  "$ppp" generate --quiet --size 14x10 --width 12 -o "$work/bad1"
expect_error "size and height" "--size: give either --size or --height, not both" \
  "$ppp" generate --quiet --size 14x10 --height 12 -o "$work/bad1"
expect_error "bad size" "--size: expected" "$ppp" generate --quiet --size 14by10 -o "$work/bad1"
expect_error "episode flag without failure" "--fitness: the episode flags (--budget, --sensor-range, ...) and --threads are for the panel fitnesses" \
  "$ppp" generate --quiet --fitness turns --connectivity 8 -o "$work/bad1"
expect_error "connectivity 6" "--connectivity: unknown connectivity '6'; valid: 4, 8" \
  "$ppp" generate --quiet --fitness failure --agents bumper --connectivity 6 -o "$work/bad1"
expect_error "unknown characters" "characters: unknown character set 'all'" \
  "$ppp" generate --quiet --characters all -o "$work/bad1"
expect_error "bad config key" "generator.yaml:1: populaton: unknown key" \
  "$ppp" generate --quiet --config "$(printf 'populaton: 3\n' > "$work/generator.yaml"; echo "$work/generator.yaml")" -o "$work/bad1"
[ ! -e "$work/bad1" ] && pass || fail "a failed generate left an output directory"
mkdir -p "$work/not_a_set" && touch "$work/not_a_set/notes.txt"
expect_error "foreign directory" "holds files but no set.csv" "$ppp" "${gen[@]}" -o "$work/not_a_set"
[ -e "$work/not_a_set/notes.txt" ] && pass || fail "generate touched a directory that was not a set"
expect_error "unwritable output" "/proc/ppp_set" "$ppp" "${gen[@]}" -o /proc/ppp_set
expect_error "k too large" "k: " "$ppp" select "$work/set_a" -k 13
expect_error "k zero" "k: " "$ppp" select "$work/set_a" -k 0
expect_error "select bad characters" "characters: unknown character set" "$ppp" select "$work/set_a" -k 2 --characters x
expect_error "tree of a non-set" "not_a_set: holds no PPP" "$ppp" tree "$work/not_a_set"

# --- hunting: the failure fitness and the MAP-Elites archive
hunt=(generate --population 12 --matings 200 --quiet --fitness failure --runs-per-eval 3)
expect_ok "hunt" "$ppp" "${hunt[@]}" --agents wall_follower_left,bumper --seed 3 -o "$work/hunt_a"
expect_ok "hunt again" "$ppp" "${hunt[@]}" --agents wall_follower_left,bumper --seed 3 --threads 1 -o "$work/hunt_b"
same_sets "$work/hunt_a" "$work/hunt_b" && pass || fail "same hunt seed gave different sets"
grep -q "^meta fitness failure$" "$work/hunt_a/ppp_000.ppp" && pass || fail "hunted PPP lacks its fitness"
grep -q "diversity" "$work/out" && pass || fail "generate did not print the diversity"
head -1 "$work/hunt_a/set.csv" | grep -q ",nearest_difference$" && pass || fail "set.csv lacks nearest_difference"
expect_ok "hunt map_elites" "$ppp" "${hunt[@]}" --agents explorer_memory_5x5 --agents-file "$config_dir/agents.yaml" \
  --archive map_elites --features turns,visibility_goal --bins 5 --seed 3 -o "$work/hunt_m"
for f in archive.csv archive.svg; do
  [ -s "$work/hunt_m/$f" ] && pass || fail "map_elites did not write $f"
done
head -1 "$work/hunt_m/archive.csv" | grep -q "^cell,turns_bin,visibility_goal_bin," && pass || fail "archive.csv header"
regret=(generate --population 12 --matings 100 --quiet --fitness regret --runs-per-eval 3 --agents explorer,long_term_explorer)
expect_ok "regret hunt" "$ppp" "${regret[@]}" --budget-factor 3 --archive map_elites --seed 4 -o "$work/regret_a"
expect_ok "regret hunt again" "$ppp" "${regret[@]}" --budget-factor 3 --archive map_elites --seed 4 --threads 1 \
  -o "$work/regret_b"
same_sets "$work/regret_a" "$work/regret_b" && pass || fail "same regret hunt seed gave different sets"
grep -q "^meta fitness regret$" "$work/regret_a/ppp_000.ppp" && pass || fail "a regret PPP lacks its fitness"
grep -h "^meta fitness_value " "$work"/regret_a/ppp_*.ppp | awk '$3 < 0 || $3 > 2 { bad = 1 } END { exit bad }' && pass \
  || fail "a regret outside [0, 2] with budgets of 3 x the optimum"
expect_error "regret without panel" "agents: empty panel: the regret fitness" "$ppp" generate --quiet --fitness regret -o "$work/bad2"
expect_error "empty panel" "agents: empty panel" "$ppp" "${hunt[@]}" -o "$work/bad2"
expect_error "unknown panel agent" "agents: unknown agent 'nobody'" "$ppp" "${hunt[@]}" --agents nobody -o "$work/bad2"
expect_error "planner in process" "agents: 'optimistic' is a ROS planner agent" \
  "$ppp" "${hunt[@]}" --agents optimistic --agents-file "$config_dir/agents.yaml" -o "$work/bad2"
expect_error "runs_per_eval 0" "--runs-per-eval: expected an integer in [1, 10000], got 0" \
  "$ppp" generate --quiet --fitness failure --agents bumper --runs-per-eval 0 -o "$work/bad2"
expect_error "unknown feature" "features: unknown character 'width'" \
  "$ppp" "${hunt[@]}" --agents bumper --archive map_elites --features turns,width -o "$work/bad2"
expect_error "bins 1" "--bins: expected an integer in [2, 100], got 1" \
  "$ppp" "${hunt[@]}" --agents bumper --archive map_elites --bins 1 -o "$work/bad2"
expect_error "panel without failure" "agents: only the panel fitnesses (failure, regret) use an agent panel" \
  "$ppp" generate --quiet --agents bumper -o "$work/bad2"
[ ! -e "$work/bad2" ] && pass || fail "a failed hunt left an output directory"


# --- shrink: the smallest PPP that still fails the same way
expect_ok "shrink one" "$ppp" shrink "$work/hunt_a/ppp_000.ppp" --agent wall_follower_left --runs 3 -o "$work/small.ppp"
grep -q "still loop in 3 of 3 runs" "$work/out" && pass || fail "shrink did not say what it kept: $(cat "$work/out")"
grep -q "^meta shrunk_from ppp_000.ppp$" "$work/small.ppp" && pass || fail "the shrunk PPP does not say where it came from"
expect_ok "shrink again" "$ppp" shrink "$work/hunt_a/ppp_000.ppp" --agent wall_follower_left --runs 3 -o "$work/small2.ppp"
cmp -s "$work/small.ppp" "$work/small2.ppp" && pass || fail "the same shrink gave different bytes"
seed=$(sed -n 's/^meta shrink_seeds \([0-9]*\),.*/\1/p' "$work/small.ppp")
expect_ok "replay the shrunk PPP" "$ppp" replay "$work/small.ppp" --agent wall_follower_left --seed "$seed" -o "$work/small.png"
grep -q "^diagnosis: loop" "$work/out" && pass || fail "the shrunk PPP's run is not a loop: $(cat "$work/out")"
expect_ok "shrink a set" "$ppp" shrink "$work/hunt_a" --agent bumper --runs 2 -o "$work/small_set"
[ "$(ls "$work/small_set" | grep -c '\.ppp$')" -eq "$(grep -c "obstacle cells, still" "$work/out")" ] && pass || \
  fail "the shrunk set's files do not match what shrink printed"
# The shrunk PPPs are a set an experiment can play (set.csv, tree), each with the failure fitness it kept.
[ "$(($(wc -l < "$work/small_set/set.csv") - 1))" -eq "$(grep -c "obstacle cells, still" "$work/out")" ] && \
  [ -s "$work/small_set/tree.nwk" ] && [ ! -e "$work/small_set/generator.yaml" ] && pass || \
  fail "the shrunk set has no set.csv and tree: $(ls "$work/small_set")"
# The shrunk PPPs grouped by trap: the lines count every shrunk PPP once, there are as many as a corpus keeps
# obstacle shapes, and the most common trap's replay command plays the failure it kept.
traps=$(sed -n 's/^\([0-9]*\) distinct traps\{0,1\} (one obstacle shape each):$/\1/p' "$work/out")
[ -n "$traps" ] && [ "$(grep -c '^  [0-9]* PPPs\{0,1\}: trap_' "$work/out")" -eq "$traps" ] && \
  [ "$(sed -n 's/^  \([0-9]*\) PPPs\{0,1\}: trap_.*/\1/p' "$work/out" | awk '{n += $1} END {print n}')" -eq \
    "$(grep -c "obstacle cells, still" "$work/out")" ] && pass || fail "the traps do not count the shrunk PPPs: $(cat "$work/out")"
expect_ok "shrink a set into a corpus" "$ppp" shrink "$work/hunt_a" --agent bumper --runs 2 --corpus "$work/small_corpus"
[ "$(ls "$work/small_corpus" | grep -c '\.ppp$')" -eq "$traps" ] && pass || \
  fail "$traps distinct traps said, but the corpus kept $(ls "$work/small_corpus")"
first=$(grep -m1 '^  [0-9]* PPPs\{0,1\}: trap_' "$work/out")
kept=$(printf '%s\n' "$first" | sed -n 's/^  [0-9]* PPPs\{0,1\}: trap_[0-9a-f]* (\([a-z_ ]*\));.*/\1/p')
replay=$(printf '%s\n' "$first" | sed -n 's/.*; replay: ppp replay \(.*\) -o path\.png$/\1/p')
# shellcheck disable=SC2086  # the replay command's words, as a user pastes them
expect_ok "replay the most common trap" "$ppp" replay $replay -o "$work/trap.png"
grep -q "^diagnosis: $kept" "$work/out" && pass || fail "the trap's replay is not a $kept run: $(cat "$work/out")"
printf 'runs: 2\nagents: [{name: bumper, type: bumper}]\nsets: [{name: small, directory: %s}]\n' "$work/small_set" \
  > "$work/small_set.yaml"
expect_ok "an experiment on the shrunk set" "$ppp" experiment "$work/small_set.yaml" -o "$work/small_run" --quiet
expect_ok "shrink with an agents file" "$ppp" shrink "$work/hunt_a/ppp_000.ppp" --agents-file "$config_dir/agents.yaml" \
  --agent explorer_memory_5x5 --runs 2 --any-kind -o "$work/small_m.ppp"
printf 'ppp 1\nsize 6 6\nstart 0 0\ngoal 5 5\nmax_obstacles 1\nobstacles 0\ngrid\nS.....\n......\n......\n......\n......\n.....G\nend\n' \
  > "$work/open.ppp"
expect_error "shrink a passing PPP" "astar passes open.ppp in all 3 runs judged: nothing to shrink" \
  "$ppp" shrink "$work/open.ppp" --agent astar --runs 3 -o "$work/none.ppp"
[ ! -e "$work/none.ppp" ] && pass || fail "shrinking a passing PPP wrote a file"
expect_error "shrink unknown agent" "--agent" "$ppp" shrink "$work/open.ppp" --agent nobody -o "$work/none.ppp"
expect_error "shrink missing file" "input: '$work/missing.ppp' does not exist" \
  "$ppp" shrink "$work/missing.ppp" --agent bumper -o "$work/none.ppp"
expect_error "shrink a planner in process" "planner agents play through ROS" \
  "$ppp" shrink "$work/open.ppp" --agent planner -o "$work/none.ppp"
expect_error "shrink a planner of an agents file" "'optimistic' is a planner agent" \
  "$ppp" shrink "$work/open.ppp" --agents-file "$config_dir/agents.yaml" --agent optimistic -o "$work/none.ppp"
expect_error "shrink runs 0" "--runs: expected a number of runs in [1, 100000], got 0" \
  "$ppp" shrink "$work/open.ppp" --agent bumper --runs 0 -o "$work/none.ppp"
expect_error "shrink negative rate" "--min-rate: expected a share of runs in (0, 1], or 0 for the original's, got -0.5" \
  "$ppp" shrink "$work/open.ppp" --agent bumper --min-rate -0.5 -o "$work/none.ppp"
expect_error "shrink by what" "--by: expected descriptors or cells, got 'rows'" \
  "$ppp" shrink "$work/open.ppp" --agent bumper --by rows -o "$work/none.ppp"
[ ! -e "$work/none.ppp" ] && pass || fail "a refused shrink wrote a file"
# Interrupted (Ctrl-C) while shrinking a whole set with many runs per candidate: nothing is written.
"$ppp" shrink "$work/hunt_a" --agent bumper --runs 20000 -o "$work/stopped" > "$work/out" 2> "$work/err" &
sleep 1
kill -INT $!
wait $! && status=0 || status=$?
[ "$status" -eq 130 ] && pass || fail "an interrupted shrink exited $status: $(cat "$work/err")"
[ ! -e "$work/stopped" ] && pass || fail "an interrupted shrink left output"

# --- shrink into a corpus, then check: exit 0 all pass, 1 any fails, 2 bad input
expect_ok "shrink a set into a corpus" "$ppp" shrink "$work/hunt_a" --agent bumper --runs 2 --corpus "$work/corpus"
shrunk=$(grep -c "^  added to the corpus as \|^  in the corpus already, as " "$work/out")
added=$(grep -c "^  added to the corpus as " "$work/out")
[ "$shrunk" -ge 1 ] && [ "$added" -ge 1 ] && [ "$(ls "$work/corpus" | wc -l)" -eq "$added" ] && pass || \
  fail "the corpus holds $(ls "$work/corpus" | wc -l) files for $added added: $(cat "$work/out")"
# A corpus (no set.csv) shrinks into a set like any directory: its PPPs keep the corpus's names.
expect_ok "shrink a corpus into a set" "$ppp" shrink "$work/corpus" --agent bumper --runs 2 -o "$work/corpus_set"
[ "$(cut -d, -f1 "$work/corpus_set/set.csv" | tail -n +2 | sort | tr '\n' ' ')" = \
  "$(ls "$work/corpus" | sed 's/\.ppp$//' | sort | tr '\n' ' ')" ] && pass || \
  fail "the corpus's set is not named as its files: $(cat "$work/corpus_set/set.csv")"
check_status() {  # NAME EXPECTED_STATUS ARGS...: `ppp check ARGS` exits EXPECTED_STATUS
  local name="$1" expected="$2"; shift 2
  "$ppp" check "$@" > "$work/out" 2> "$work/err" && status=0 || status=$?
  [ "$status" -eq "$expected" ] && pass || fail "$name: exit $status, expected $expected: $(cat "$work/out" "$work/err")"
}
check_status "check the corpus's own agent" 1 "$work/corpus" --agent bumper --junit "$work/check.xml"
grep -q "<testsuite name=\"corpus\" tests=\"$added\" failures=\"$added\"" "$work/check.xml" && pass || \
  fail "the JUnit XML does not count $added failing PPPs: $(head -3 "$work/check.xml")"
check_status "check the corpus against astar" 0 "$work/corpus" --agent astar
grep -q "astar passes all $added PPPs of $work/corpus" "$work/out" && pass || fail "check summary: $(cat "$work/out")"
check_status "check with no agent" 2 "$work/corpus"
check_status "check with a flag and no value" 2 "$work/corpus" --agent
check_status "check an unknown agent" 2 "$work/corpus" --agent nobody
grep -q "no built-in agent 'nobody'" "$work/err" && pass || fail "unknown agent: $(cat "$work/err")"
check_status "check an agent not in the config" 2 "$work/corpus" --agent nobody --config "$config_dir/experiment.yaml"
check_status "check a planner in process" 2 "$work/corpus" --agent mrpt --config "$config_dir/experiment.yaml"
grep -q "check it with launch/check.launch" "$work/err" && pass || fail "planner in process: $(cat "$work/err")"
mkdir -p "$work/no_ppp"
check_status "check an empty corpus" 2 "$work/no_ppp" --agent astar
grep -q "holds no PPP" "$work/err" && pass || fail "empty corpus: $(cat "$work/err")"
touch "$work/a_file"
check_status "check into a JUnit file that cannot be written" 2 "$work/corpus" --agent astar \
  --junit "$work/a_file/check.xml"
grep -q "a_file/check.xml: cannot be written" "$work/err" && pass || fail "unwritable JUnit: $(cat "$work/err")"

finish
