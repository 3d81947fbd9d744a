#!/usr/bin/env bash
# `ppp experiment`, `simulate`, `replay` and `compare` as a user runs them, including a real SIGKILL and
# SIGTERM part-way through an experiment and the resume. Usage: experiment_cli_test.sh PATH_TO_PPP
set -u
ppp="$1"
source "$(dirname "${BASH_SOURCE[0]}")/cli_harness.sh"
rows() { if [ -f "$1" ]; then wc -l < "$1"; else echo 0; fi; }

# A small experiment: 2 sets x 6 PPPs x 3 agents x 1500 runs = 54,000 runs.
small_experiment 1500
total=$((2 * 6 * 3 * 1500 + 1))

expect_ok "uninterrupted experiment" "$ppp" experiment "$work/experiment.yaml" -o "$work/a" --quiet
[ "$(rows "$work/a/results.csv")" -eq "$total" ] && pass || fail "results.csv has $(rows "$work/a/results.csv") lines, expected $total"
for f in experiment.yaml summary.csv report.md report.html sets/turns/set.csv sets/difficulty/tree.html; do
  [ -s "$work/a/$f" ] && pass || fail "experiment did not write $f"
done
ls "$work/a/pictures/"*.png > /dev/null 2>&1 && pass || fail "report has no pictures"
# Each pictured worst PPP of a built-in agent is shown shrunk too, with its file (shrink_worst, on by default).
shrunk_lines=$(grep -c "^- shrunk: " "$work/a/report.md")
[ "$shrunk_lines" -ge 1 ] && [ "$(ls "$work/a/ppps/"*_shrunk.ppp | wc -l)" -eq "$shrunk_lines" ] && pass || \
  fail "the report shows $shrunk_lines shrunk PPPs: $(ls "$work/a/ppps")"
# Each agent's failures by signature: the report's count of kinds and failed runs is results.csv's, and the most
# common kind's replay command, run from the report's directory, plays a run of that kind on its smallest PPP.
listed=$(sed -n 's/^`\([a-z0-9_]*\)`: \([0-9]*\) distinct failures\{0,1\} in \([0-9]*\) failed runs\{0,1\}.*/\1 \2 \3/p' \
  "$work/a/report.md")
[ -n "$listed" ] && pass || fail "the report lists no distinct failures"
while read -r agent kinds runs; do
  counted=$(awk -F, -v a="$agent" 'NR > 1 && $3 == a && $17 != "" { n++; k[$17] = 1 }
    END { printf "%d %d", length(k), n }' "$work/a/results.csv")
  [ "$counted" = "$kinds $runs" ] && pass || fail "$agent: the report says $kinds kinds in $runs runs, results.csv $counted"
done <<< "$listed"
row=$(grep -m1 '^| `[a-z]*[0-9-]*/g' "$work/a/report.md")
signature=$(printf '%s\n' "$row" | cut -d'|' -f2 | tr -d ' `')
replay=$(printf '%s\n' "$row" | sed -n 's/.*| `ppp replay \(.*\) -o path\.png` |$/\1/p')
# shellcheck disable=SC2086  # the command's words, as a user pastes them
(cd "$work/a" && "$ppp" replay $replay -o "$work/kind.png" > "$work/out" 2> "$work/err") && \
  grep -qx "signature: $signature" "$work/out" && pass || \
  fail "the replay of $signature does not play it: $(cat "$work/out" "$work/err")"
# Every failing run pictured is also animated, beside the picture and inline in the HTML.
for png in "$work/a/pictures/"*.png; do
  [ -s "${png%.png}.gif" ] && pass || fail "no animation beside $png"
done
gifs="$(ls "$work/a/pictures/"*.gif 2> /dev/null | wc -l)"
[ "$(grep -o 'data:image/gif;base64,' "$work/a/report.html" | wc -l)" -eq "$gifs" ] && pass || \
  fail "report.html embeds $(grep -o 'data:image/gif;base64,' "$work/a/report.html" | wc -l) animations for $gifs files"
/usr/bin/python3 -c '
import sys
from PIL import Image
for name in sys.argv[1:]:
    im = Image.open(name)
    assert im.format == "GIF" and im.n_frames >= 2 and im.info.get("loop") == 0, name
' "$work/a/pictures/"*.gif && pass || fail "the animations of the report do not read as looping GIFs"
# The report is the same on one thread (its worst PPPs are shrunk side by side, an agent per thread).
expect_ok "experiment on one thread" "$ppp" experiment "$work/experiment.yaml" -o "$work/one" --threads 1 --quiet
cmp -s "$work/a/report.md" "$work/one/report.md" && cmp -s "$work/a/report.html" "$work/one/report.html" && pass || \
  fail "the report on one thread differs from the report on two"
# animation_frames caps every animation of the report (a presentation option: same rows, same fingerprint).
{ cat "$work/experiment.yaml"; echo "animation_frames: 3"; } > "$work/frames.yaml"
expect_ok "experiment with animation_frames 3" "$ppp" experiment "$work/frames.yaml" -o "$work/frames" --quiet
cmp -s "$work/a/results.csv" "$work/frames/results.csv" && pass || fail "animation_frames changed results.csv"
/usr/bin/python3 -c '
import sys
from PIL import Image
assert len(sys.argv) > 1
for name in sys.argv[1:]:
    assert Image.open(name).n_frames == 3, (name, Image.open(name).n_frames)
' "$work/frames/pictures/"*.gif && pass || fail "animation_frames 3 did not cap the animations at 3 frames"
expect_ok "rerun of a finished experiment" "$ppp" experiment "$work/experiment.yaml" -o "$work/a" --quiet
grep -q "0 runs simulated, 54000 resumed" "$work/out" && pass || fail "rerun did work again: $(cat "$work/out")"

# interrupt: wait (bounded) until some rows are written, then signal
interrupt() {
  local dir="$1" signal="$2"
  "$ppp" experiment "$work/experiment.yaml" -o "$dir" --quiet > "$work/int.out" 2> "$work/int.err" &
  local pid=$!
  for _ in $(seq 1 600); do
    [ "$(rows "$dir/results.csv")" -gt 3000 ] && break
    sleep 0.02
  done
  kill "-$signal" "$pid" 2>/dev/null
  wait "$pid"
  echo $?
}
status=$(interrupt "$work/b" KILL)
[ "$status" -eq 137 ] && pass || fail "SIGKILL: exit status $status (the experiment finished before the signal?)"
[ "$(rows "$work/b/results.csv")" -lt "$total" ] && pass || fail "SIGKILL came too late to test resuming"
expect_ok "resume after SIGKILL" "$ppp" experiment "$work/experiment.yaml" -o "$work/b" --quiet
grep -q "resumed" "$work/out" && pass || fail "no resume reported: $(cat "$work/out")"
cmp -s "$work/a/results.csv" "$work/b/results.csv" && pass || fail "results after SIGKILL + resume differ from an uninterrupted run"
cmp -s "$work/a/summary.csv" "$work/b/summary.csv" && pass || fail "summary after SIGKILL + resume differs"

# ppp shrink on the experiment's set, judged on the seeds of the agent's failed runs in its results.csv.
expect_ok "shrink with results" "$ppp" shrink "$work/a/sets/turns" --agents-file "$work/agents.yaml" \
  --agent explorer_memory_5x5 --results "$work/a/results.csv" --runs 2 -o "$work/shrunk_turns"
first=$(ls "$work/shrunk_turns" | head -1)
seeds=$(sed -n 's/^meta shrink_seeds //p' "$work/shrunk_turns/$first")
expected=$(awk -F, -v id="${first%.ppp}" '$1 == "turns" && $2 == id && $3 == "explorer_memory_5x5" && $6 == 0 { print $4, $5 }' \
  "$work/a/results.csv" | sort -n | head -2 | cut -d' ' -f2 | paste -sd,)
[ -n "$seeds" ] && [ "$seeds" = "$expected" ] && pass || fail "shrunk $first on seeds '$seeds', its failed runs' are '$expected'"
expect_error "shrink without a failed run" "--results: no failed run (lost runs left out) of astar on turns/ppp_000 in" \
  "$ppp" shrink "$work/a/sets/turns/ppp_000.ppp" --agent astar --results "$work/a/results.csv" -o "$work/none.ppp"

# Runs lost to the agent link (rows a ROS run records as timeout or agent_lost) are played again on a resume, and
# their new rows replace them: here every 997th run of the finished experiment is recorded as lost instead.
cp -r "$work/a" "$work/l"
awk 'NR == 1 || NR % 997 != 0' "$work/a/results.csv" > "$work/l/results.csv"
awk -F, -v OFS=, 'NR > 1 && NR % 997 == 0 {
  $6 = 0; $11 = (NR % 2 ? "timeout" : "agent_lost"); $12 = 0; $13 = "reported"; $14 = $15 = $16 = "";
  $17 = $11 "/g16-31/s0/t0/w0e2"; print }' "$work/a/results.csv" >> "$work/l/results.csv"
lost=$(grep -c ",\(timeout\|agent_lost\),0,reported,,,,\(timeout\|agent_lost\)/" "$work/l/results.csv")
expect_ok "resume with lost runs" "$ppp" experiment "$work/experiment.yaml" -o "$work/l"
grep -q "playing again $lost runs lost to the agent link" "$work/err" "$work/out" && pass || \
  fail "no word about $lost lost runs: $(cat "$work/err")"
cmp -s "$work/a/results.csv" "$work/l/results.csv" && pass || fail "lost runs played again differ from an uninterrupted run"

status=$(interrupt "$work/c" TERM)
[ "$status" -eq 130 ] && pass || fail "SIGTERM: exit status $status, expected 130"
grep -q "Rerun the same command to resume" "$work/int.err" && pass || fail "SIGTERM message: $(cat "$work/int.err")"
expect_ok "resume after SIGTERM" "$ppp" experiment "$work/experiment.yaml" -o "$work/c" --quiet
cmp -s "$work/a/results.csv" "$work/c/results.csv" && pass || fail "results after SIGTERM + resume differ"

# SIGINT and SIGTERM also stop the generation and the hunting phases, within a second, writing no half-made
# set; a rerun completes to the result of an uninterrupted run.
cat > "$work/phases.yaml" <<'YAML'
seed: 5
runs: 5
hardest: 1
agents:
  - {name: random, type: random}
  - {name: explorer, type: explorer}
sets:
  - name: evolved
    generator: {fitness: turns, matings: 60000, seed: 3}
  - name: hunted
    generator: {fitness: failure, agents: [explorer], runs_per_eval: 10, matings: 4000, seed: 4}
YAML
expect_ok "phases uninterrupted" "$ppp" experiment "$work/phases.yaml" -o "$work/p_ref" --quiet
# signal_in_phase DIR SIGNAL TEXT: starts the experiment, signals it 0.3 s after TEXT appears in its log and
# prints its exit status and the milliseconds from the signal to its exit.
signal_in_phase() {
  local dir="$1" signal="$2" text="$3"
  "$ppp" experiment "$work/phases.yaml" -o "$dir" > /dev/null 2> "$work/phase.err" &
  local pid=$!
  for _ in $(seq 1 1500); do grep -q "$text" "$work/phase.err" && break; sleep 0.01; done
  sleep 0.3
  local start; start=$(date +%s%N)
  kill "-$signal" "$pid"
  wait "$pid"
  local status=$?
  echo "$status $(( ($(date +%s%N) - start) / 1000000 ))"
}
for phase in "p_gen INT evolved" "p_hunt TERM hunted"; do
  read -r dir signal set <<< "$phase"
  read -r status ms <<< "$(signal_in_phase "$work/$dir" "$signal" "generating set '$set'")"
  [ "$status" -eq 130 ] && pass || fail "SIG$signal while generating $set: exit status $status, expected 130"
  [ "$ms" -le 1000 ] && pass || fail "SIG$signal while generating $set: stopped $ms ms after the signal"
  [ ! -e "$work/$dir/sets/$set/set.csv" ] && [ ! -e "$work/$dir/results.csv" ] && pass \
    || fail "SIG$signal while generating $set left a set or results behind"
  grep -q "interrupted" "$work/phase.err" && pass || fail "SIG$signal message: $(tail -2 "$work/phase.err")"
  expect_ok "resume after SIG$signal in $set" "$ppp" experiment "$work/phases.yaml" -o "$work/$dir" --quiet
  cmp -s "$work/p_ref/results.csv" "$work/$dir/results.csv" && pass \
    || fail "results after SIG$signal while generating $set + resume differ from an uninterrupted run"
  cmp -s "$work/p_ref/sets/$set/set.csv" "$work/$dir/sets/$set/set.csv" && pass || fail "set $set differs after resume"
done

# An experiment above the size limits says so with its estimate before anything is written.
sed 's/^runs: 5$/runs: 100000000/' "$work/phases.yaml" > "$work/huge.yaml"
expect_error "huge experiment" "work: a large experiment (more than 1e8 episodes, results.csv above 10 GB): 2.4e+10 episodes" \
  "$ppp" experiment "$work/huge.yaml" -o "$work/huge"
[ ! -e "$work/huge" ] && pass || fail "the refused experiment wrote $work/huge"
expect_error "huge experiment through ROS" "pass --large" "$ppp" launch-file "$work/huge.yaml" -o "$work/huge"

# simulate and replay
ppp_file="$work/a/sets/turns/ppp_000.ppp"
expect_ok "simulate json" "$ppp" simulate --agent astar --problem "$ppp_file" --runs 20 --seed 1 --json
/usr/bin/python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); assert d["runs"]==20 and d["passes"]==20 and d["pass_rate"]==1.0 and d["mean_steps"]>0, d' \
  "$work/out" && pass || fail "simulate --json: $(cat "$work/out")"
expect_ok "simulate empty grid" "$ppp" simulate --agent random --problem empty:5x5 --runs 200 --seed 2
expect_ok "replay" "$ppp" replay "$ppp_file" --agent explorer --memory 5x5 --seed 12345 -o "$work/replay.png"
[ -s "$work/replay.png" ] && pass || fail "replay wrote no picture"
# The animation, read by another decoder (Pillow): one frame per step plus the start, the agent's disc on the start
# cell first and on its last cell at the end, the same bytes for the same seed.
expect_ok "replay gif" "$ppp" replay "$ppp_file" --agent bumper --seed 7 -o "$work/replay.gif"
steps="$(sed -n 's/.* after \([0-9]*\) steps.*/\1/p' "$work/out")"
/usr/bin/python3 - "$work/replay.gif" "$ppp_file" "$steps" <<'PY' && pass || fail "replay gif frames: $(cat "$work/out")"
import sys
from PIL import Image
gif, ppp_file, steps = sys.argv[1], sys.argv[2], int(sys.argv[3])
lines = open(ppp_file).read().splitlines()
field = lambda key: next(l.split()[1:] for l in lines if l.startswith(key + ' '))
start = tuple(int(v) for v in field('start'))
im = Image.open(gif)
assert im.n_frames == steps + 1, (im.n_frames, steps)
centre = lambda c: (c[0] * 12 + 6, c[1] * 12 + 6)
im.seek(0)
assert im.convert('RGB').getpixel(centre(start)) == (255, 120, 0), 'first frame: no agent on the start cell'
im.seek(im.n_frames - 1)
last = im.convert('RGB')
agent = [(x, y) for y in range(last.height // 12) for x in range(last.width // 12)
         if last.getpixel(centre((x, y))) == (255, 120, 0)]
assert len(agent) == 1, agent
print('last cell', agent[0])
PY
"$ppp" replay "$ppp_file" --agent bumper --seed 7 -o "$work/replay2.gif" > /dev/null 2>&1
cmp -s "$work/replay.gif" "$work/replay2.gif" && pass || fail "replay gif: the same seed gave different bytes"
expect_error "replay unknown extension" "--output: expected a .png (the path drawn) or .gif (the episode animated) file name, got '$work/replay.jpg'" \
  "$ppp" replay "$ppp_file" --agent bumper --seed 7 -o "$work/replay.jpg"
[ ! -e "$work/replay.jpg" ] && pass || fail "replay wrote a .jpg"
expect_error "replay unwritable" "$work/no/such/dir/replay.gif" "$ppp" replay "$ppp_file" --agent bumper --seed 7 -o "$work/no/such/dir/replay.gif"
expect_error "replay frame ms" "--frame-ms: expected a multiple of 10 ms" "$ppp" replay "$ppp_file" --agent bumper --seed 7 --frame-ms 15 -o "$work/r.gif"
expect_error "replay max frames" "--max-frames: expected an integer in [2, 10000], got 1" "$ppp" replay "$ppp_file" --agent bumper --seed 7 --max-frames 1 -o "$work/r.gif"
expect_error "replay map too large to animate" "map: a 2731x2 map is too large to animate at 3 pixels per cell (at most 2730 cells a side" \
  "$ppp" replay empty:2731x2 --agent random --seed 1 -o "$work/huge.gif"
[ ! -e "$work/huge.gif" ] && pass || fail "replay wrote a GIF of a map too large to animate"
expect_ok "compare" "$ppp" compare "$work/a" "$work/a" --set-a turns --set-b difficulty
grep -q "long_term_explorer" "$work/out" && pass || fail "compare lacks an agent row: $(cat "$work/out")"

# bad input: clear errors, non-zero exits, nothing half-written
expect_error "unknown agent" "--agent: unknown agent type 'flier'; valid: astar, random" \
  "$ppp" simulate --agent flier --problem empty:5x5
expect_error "budget 0" "--budget: expected an integer in [1, 1000000], got 0" "$ppp" simulate --agent random --problem empty:5x5 --budget 0
expect_error "runs 0" "--runs: expected a number of runs >= 1" "$ppp" simulate --agent random --problem empty:5x5 --runs 0
expect_error "even memory" "--memory" "$ppp" simulate --agent explorer --problem empty:5x5 --memory 4x4
# A robot with a body that cannot stand at the corner start: refused, not 0 % passes.
expect_error "robot off its start" "--robot-radius: a robot of radius 1 cannot reach the goal of empty:20x20 (the disc does not fit at its start (0, 0)" \
  "$ppp" simulate --agent astar --problem empty:20x20 --robot-radius 1
expect_error "robot off its start, replay" "--robot-radius: a robot of radius 1 cannot reach the goal" \
  "$ppp" replay empty:20x20 --agent astar --robot-radius 1 --seed 1 -o "$work/body.png"
[ ! -e "$work/body.png" ] && pass || fail "a refused replay wrote its picture"
printf 'ppp 1\nsize 6 6\nstart 1 1\ngoal 4 4\nmax_obstacles 0\nobstacles 0\ngrid\n......\n.S....\n......\n......\n....G.\n......\nend\n' > "$work/room.ppp"
expect_ok "robot inside" "$ppp" simulate --agent astar --problem "$work/room.ppp" --robot-radius 1 --runs 3 --seed 1
grep -q "3 of 3 runs passed" "$work/out" && pass || fail "astar with a body inside the room: $(cat "$work/out")"
expect_error "memory 0" "--memory" "$ppp" simulate --agent explorer --problem empty:5x5 --memory 0x0
expect_error "noise" "--sensor-noise: expected a number in [0, 1], got 1.5" \
  "$ppp" simulate --agent explorer --problem empty:5x5 --sensor-noise 1.5
expect_error "range 0" "--sensor-range: expected an integer in [1, 7], got 0" \
  "$ppp" simulate --agent explorer --problem empty:5x5 --sensor-range 0
expect_error "missing ppp" "$work/none.ppp: cannot open" "$ppp" simulate --agent random --problem "$work/none.ppp"
printf 'ppp 1\nsize 5 5\nstart 9 9\n' > "$work/bad.ppp"
expect_error "invalid ppp" "bad.ppp:3: start: cell (9, 9) is outside the 5x5 grid" \
  "$ppp" simulate --agent random --problem "$work/bad.ppp"
printf 'agents: agents.yaml\nrusn: 5\nsets:\n  - {name: a}\n' > "$work/typo.yaml"
expect_error "unknown yaml key" "typo.yaml:2: rusn: unknown key" "$ppp" experiment "$work/typo.yaml" -o "$work/typo"
printf 'agents: agents.yaml\nruns: lots\nsets:\n  - {name: a}\n' > "$work/type.yaml"
expect_error "wrong yaml type" "type.yaml:2: runs: expected an integer, got 'lots'" \
  "$ppp" experiment "$work/type.yaml" -o "$work/typo"
[ ! -e "$work/typo" ] && pass || fail "a refused experiment left an output directory"
sed 's/runs: 1500/runs: 1400/' "$work/experiment.yaml" > "$work/other.yaml"
cp "$work/agents.yaml" "$work/other_agents.yaml"
expect_error "different experiment" "runs: '1500' there, '1400' here" "$ppp" experiment "$work/other.yaml" -o "$work/a"
printf 'connectivity: 8\n' | cat - "$work/experiment.yaml" > "$work/diagonal.yaml"
expect_error "other move model" "connectivity: '4' there, '8' here" "$ppp" experiment "$work/diagonal.yaml" -o "$work/a"
cmp -s "$work/a/results.csv" "$work/b/results.csv" && pass || fail "a refused experiment touched the results"

# Planner agents are external ROS planners: the in-process run says it skips them and reports the others.
cat > "$work/planner_agents.yaml" <<'YAML'
agents:
  - {name: random, type: random}
  - {name: ompl, type: planner, prior_map: true, runs: 2}
YAML
sed -e 's/runs: 1500/runs: 5/' -e 's/agents: agents.yaml/agents: planner_agents.yaml/' "$work/experiment.yaml" \
  > "$work/planners.yaml"
expect_ok "experiment with a planner agent" "$ppp" experiment "$work/planners.yaml" -o "$work/p"
grep -q "skipping the planner agents (ompl)" "$work/err" && pass || fail "no word about the planner: $(cat "$work/err")"
[ "$(rows "$work/p/results.csv")" -eq $((2 * 6 * 5 + 1)) ] && pass || fail "planner runs in process: $(rows "$work/p/results.csv")"
grep -q "1 agents, 5 runs each" "$work/p/report.md" && pass || fail "report title: $(head -3 "$work/p/report.md")"

finish
