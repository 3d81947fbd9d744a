#!/usr/bin/env bash
# `ppp scenarios` on a large map: a 512 x 512 maze (a depth-first-search maze with corridors and walls 3 cells
# wide, every free cell reachable, drawn from a fixed seed) and 2,000 scenarios between random free cells, played
# by astar at connectivity 4 and 8 and by the explorer, each with the default budget (the map's free cells). The
# scenarios' published lengths are written as 0: this measures time, not lengths (the arena map's tests check
# those). Usage: scripts/bench-scenarios.sh (after scripts/build.sh). Figures go in BENCHMARKS.md.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/env.sh"
cd "$PPP_ROOT"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

/usr/bin/python3 - "$work" <<'PY'
import random, sys
work = sys.argv[1]
rng = random.Random(1)
side, cell = 512, 3                      # 512 cells; maze nodes every 2 * cell cells
nodes = (side - cell) // (2 * cell) + 1
grid = [['@'] * side for _ in range(side)]
def carve(x0, y0, w, h):
    for y in range(y0, min(y0 + h, side)):
        for x in range(x0, min(x0 + w, side)):
            grid[y][x] = '.'
seen = [[False] * nodes for _ in range(nodes)]
stack = [(0, 0)]
seen[0][0] = True
carve(0, 0, cell, cell)
while stack:
    x, y = stack[-1]
    options = [(x + dx, y + dy) for dx, dy in ((1, 0), (-1, 0), (0, 1), (0, -1))
               if 0 <= x + dx < nodes and 0 <= y + dy < nodes and not seen[y + dy][x + dx]]
    if not options:
        stack.pop()
        continue
    nx, ny = rng.choice(options)
    seen[ny][nx] = True
    carve(min(x, nx) * 2 * cell, min(y, ny) * 2 * cell, (abs(nx - x) * 2 + 1) * cell, (abs(ny - y) * 2 + 1) * cell)
    stack.append((nx, ny))
with open(f"{work}/maze.map", "w") as f:
    f.write(f"type octile\nheight {side}\nwidth {side}\nmap\n")
    f.write("".join("".join(row) + "\n" for row in grid))
free = [(x, y) for y in range(side) for x in range(side) if grid[y][x] == '.']
with open(f"{work}/maze.map.scen", "w") as f:
    f.write("version 1\n")
    for i in range(2000):
        (sx, sy), (gx, gy) = rng.sample(free, 2)
        f.write(f"0\tmaze.map\t{side}\t{side}\t{sx}\t{sy}\t{gx}\t{gy}\t0\n")
PY

echo "machine: nproc=$(nproc) cpu='$(grep -m1 '^model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//')'" \
  "date=$(date -u +%Y-%m-%dT%H:%M:%SZ) commit=$(git rev-parse --short HEAD 2>/dev/null || echo none)"
for run in "astar 4" "astar 8" "explorer 4"; do
  set -- $run
  /usr/bin/time -f "%e %M" -o "$work/time" scripts/ppp scenarios "$work/maze.map.scen" --agent "$1" \
    --connectivity "$2" --json > "$work/out.json"
  read -r seconds kilobytes < "$work/time"
  summary="$(/usr/bin/python3 -c "
import json, sys
j = json.load(open(sys.argv[1]))
s = j['scenarios']
passed = [x for x in s if x['passed']]
steps = sum(x['steps'] for x in s)
print(f\"{len(passed)} of {len(s)} passed, {steps} steps, mean path length {sum(x['path_length'] for x in passed) / max(1, len(passed)):.1f}\")
" "$work/out.json")"
  echo "$1, connectivity $2, 2,000 scenarios on the 512x512 maze: $seconds s, peak memory $((kilobytes / 1024)) MB; $summary"
done
