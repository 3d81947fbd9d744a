#!/usr/bin/env bash
# The main job: installs what is missing, builds, then runs the default experiment (config/experiment.yaml:
# two evolved sets of 60 PPPs, ten agents, 1,000 runs each) into results/experiment/ and says where the
# report is. Rerunning resumes an interrupted experiment; a finished one is reported again at once.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/env.sh"
cd "$PPP_ROOT"
scripts/install-deps.sh
mkdir -p "$PPP_BUILD_DIR"
echo "building (log: $PPP_BUILD_DIR/build.log)"
scripts/build.sh > "$PPP_BUILD_DIR/build.log" 2>&1 || { tail -50 "$PPP_BUILD_DIR/build.log"; exit 1; }

out="$PPP_ROOT/results/experiment"
scripts/ppp experiment config/experiment.yaml -o "$out"
echo
sed -n '/^## Pass rates/,/^## Mann/p' "$out/report.md" | sed '$d'
echo "Open the report: $out/report.html (Markdown: $out/report.md)"
