#!/usr/bin/env bash
# The core's own command, as a user of the ROS-free core runs it: draw, evaluate and convert a PPP, see only the
# core's subcommands in --help, and get errors that name the command and the bad input.
# Usage: ppp_core_cli_test.sh PATH_TO_PPP_CORE
set -u
core="$1"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
failures=0
check() { if eval "$2"; then echo "ok: $1"; else echo "FAIL: $1"; failures=$((failures + 1)); fi; }

"$core" random --size 12x9 --obstacles 6 --seed 7 -o "$work/a.ppp" > "$work/out" 2>&1
check "random writes a PPP" '[ -s "$work/a.ppp" ] && head -1 "$work/a.ppp" | grep -q "^ppp 1$"'
"$core" random --size 12x9 --obstacles 6 --seed 7 -o "$work/b.ppp" > /dev/null 2>&1
check "the same seed draws the same PPP" 'cmp -s "$work/a.ppp" "$work/b.ppp"'
"$core" evaluate "$work/a.ppp" --json > "$work/eval.json" 2>&1
check "evaluate prints JSON with the optimal turns" 'grep -q "\"turns\"" "$work/eval.json"'
"$core" convert "$work/a.ppp" "$work/a.yaml" > /dev/null 2>&1
check "convert writes map_server YAML and PGM" '[ -s "$work/a.yaml" ] && [ -s "$work/a.pgm" ]'
"$core" convert "$work/a.ppp" "$work/a.map" > /dev/null 2>&1
check "convert writes a MovingAI map" '[ "$(head -4 "$work/a.map" | tr "\n" " ")" = "type octile height 9 width 12 map " ]'
"$core" convert "$work/a.map" "$work/from_map.ppp" > /dev/null 2>&1
"$core" convert "$work/from_map.ppp" "$work/again.map" > /dev/null 2>&1
check "a .map read and written again is the same map" 'cmp -s "$work/a.map" "$work/again.map"'
check "a .map's first and last free cells are start and goal" \
  'grep -qx "start 0 0" "$work/from_map.ppp" && grep -qx "goal 11 8" "$work/from_map.ppp"'
printf 'type octile\nheight 2\nwidth 3\nmap\n.@.\n.T.\n' > "$work/walled.map"
"$core" convert "$work/walled.map" "$work/walled.ppp" --start 0,1 --goal 2,0 > /dev/null 2>&1
check "--start and --goal choose a .map's start and goal" \
  'grep -qx "start 0 1" "$work/walled.ppp" && grep -qx "goal 2 0" "$work/walled.ppp"'
printf 'type octile\nheight 2\nwidth 3\nmap\n.@.\n.x.\n' > "$work/bad.map"
"$core" convert "$work/bad.map" "$work/bad.ppp" > "$work/err" 2>&1
status=$?
check "a bad .map is an error naming file, line and field" \
  '[ "$status" -ne 0 ] && grep -q "bad.map:6: map: unknown terrain character" "$work/err" && [ ! -e "$work/bad.ppp" ]'
"$core" --help > "$work/help" 2>&1
check "help lists the core's subcommands only" \
  'grep -q "random" "$work/help" && grep -q "convert" "$work/help" && ! grep -q "generate" "$work/help"'
"$core" evaluate "$work/missing.ppp" > "$work/err" 2>&1
status=$?
check "a missing file is an error naming it" '[ "$status" -ne 0 ] && grep -q "^ppp-core: error: .*missing.ppp" "$work/err"'
"$core" generate > "$work/err" 2>&1
check "the generator's subcommands are not the core's" '[ $? -ne 0 ]'
[ "$failures" -eq 0 ] || { echo "$failures checks failed"; exit 1; }
