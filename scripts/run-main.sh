#!/usr/bin/env bash
# The main job: installs what is missing, builds, then draws a few random PPPs, evaluates them and
# writes their files, pictures and measures under results/main/.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/env.sh"
cd "$PPP_ROOT"
scripts/install-deps.sh
mkdir -p "$PPP_BUILD_DIR"
scripts/build.sh > "$PPP_BUILD_DIR/build.log" 2>&1 || { tail -50 "$PPP_BUILD_DIR/build.log"; exit 1; }

out="$PPP_ROOT/results/main"
rm -rf "$out"
mkdir -p "$out"
ppp="$PPP_ROOT/scripts/ppp"
for seed in 1 2 3 4 5 6; do
  "$ppp" random --size 20x20 --obstacles 10 --seed "$seed" -o "$out/ppp_$seed.ppp"
  "$ppp" convert "$out/ppp_$seed.ppp" "$out/ppp_$seed.png" --route
done
"$ppp" convert "$out/ppp_1.ppp" "$out/ppp_1.yaml"
"$ppp" convert "$out/ppp_1.ppp" "$out/ppp_1.bt"
"$ppp" evaluate "$out"/ppp_*.ppp --csv "$out/measures.csv"
"$ppp" evaluate "$out"/ppp_*.ppp --json > "$out/measures.jsonl"
echo
awk -F, '{ printf "%-38s %-6s %-9s %-20s %-11s %-10s\n", $1, $5, $6, $7, $8, $18 }' "$out/measures.csv"
echo
echo "main job done: PPPs, pictures (.png with the optimal route), map_server and OctoMap exports and"
echo "measures (measures.csv, measures.jsonl) are in $out"
