#!/bin/bash
# scripts/docs_commands.py on a fake repository (test/docs/commands, copied into a fresh git repository): a page
# whose blocks pass (shared variables, working directory and /tmp/, instead and skip markers, a picture made the
# same), and pages that must fail naming what failed: a failing command (FILE:LINE), a picture its command makes
# differently, stray markers, a command writing into the repository, a page slower than --timeout. Then the real
# documentation, with the built workspace (BUILD_DIR, default the repository's build/).
#   docs_commands_test.sh [BUILD_DIR]
source "$(dirname "$0")/cli_harness.sh"
here="$(cd "$(dirname "$0")" && pwd)"
runner="$here/../../scripts/docs_commands.py"
repo="$work/repo"
build_dir="${1:-$here/../../build}"

cp -r "$here/docs/commands" "$repo"
git -C "$repo" init -q
git -C "$repo" add -A
# A fake build directory: the scratch's build/ must point at $PPP_BUILD_DIR.
mkdir -p "$work/build/devel" && touch "$work/build/devel/marker"
line_of() {  # line_of PAGE TEXT: the line of the block (its opening fence) whose first command is TEXT
  echo $(($(grep -nF -- "$2" "$repo/$1" | head -1 | cut -d: -f1) - 1))
}
mkdir "$work/tmp"
docs() { TMPDIR="$work/tmp" PPP_BUILD_DIR="$work/build" /usr/bin/python3 "$runner" --root "$repo" "$@"; }

# --list runs nothing and names every block with what runs for it; the stray markers are errors.
docs --list > "$work/out" 2> "$work/err"
status=$?
if [ "$status" -eq 1 ]; then pass; else fail "--list: exit status $status, expected 1 (stray markers)"; fi
instead=$(line_of README.md 'echo "this would take an hour"')
skip=$(line_of README.md 'false')
for text in "README.md:$instead: instead (marker at line $((instead - 3))) of:" \
  "    echo \"instead ran\" > /tmp/instead" "README.md:$skip: skip (needs a display)" \
  "ERROR docs/how-to/stray.md:3: docs-test marker not followed by a \`\`\`bash block (a \`\`\`text block follows)"; do
  if grep -qxF -- "  $text" "$work/out"; then pass; else fail "--list lacks '$text':"$'\n'"$(cat "$work/out")"; fi
done
if [ ! -e "$repo/scripts/made-by-the-docs" ] && [ -z "$(ls -A "$work/tmp")" ]; then pass
else fail "--list ran something"; fi
expect_ok "--list of a good page" docs --list README.md

# The page whose blocks all pass.
expect_ok "README.md" docs README.md
if grep -qxF "README.md: ok (4 blocks run (1 instead), 1 skipped)" <(sed 's/ in [0-9.]* s$//' "$work/out"); then pass
else fail "README.md's line: $(cat "$work/out")"; fi
if grep -qxF "  README.md:$skip: skipped (needs a display)" "$work/out" \
  && grep -qxF "docs_commands: 1 page, 5 bash blocks: 4 run (1 of them replaced by instead markers), 1 skipped:" \
    "$work/out"; then pass
else fail "README.md's summary: $(cat "$work/out")"; fi

# Every page with the default list, at a short timeout: only README.md passes.
docs --timeout 4 > "$work/out" 2> "$work/err"
status=$?
if [ "$status" -eq 1 ]; then pass; else fail "all pages: exit status $status, expected 1: $(cat "$work/err")"; fi
failing=$(line_of docs/how-to/failing.md 'echo "before failing"')
picture=$(line_of docs/how-to/picture.md "printf 'a different picture")
slow=$(line_of docs/tutorials/slow.md 'sleep 987 &')
expected=("README.md: ok (4 blocks run (1 instead), 1 skipped)"
  "docs/how-to/failing.md: FAILED: exit status 1 at docs/how-to/failing.md:$((failing + 2)) (the block at docs/how-to/failing.md:$failing)"
  "    | before failing"
  "    | === docs-test: failed with status 1: false"
  "docs/how-to/picture.md: FAILED: docs/images/a.txt: the command in docs/how-to/picture.md:$picture makes a different file"
  "docs/how-to/stray.md: FAILED (not run: its docs-test markers are wrong)"
  "    docs/how-to/stray.md:3: docs-test marker not followed by a \`\`\`bash block (a \`\`\`text block follows)"
  "    docs/how-to/stray.md:8: docs-test marker not followed by a \`\`\`bash block (it must be on the line just before the block)"
  "    docs/how-to/stray.md:14: unknown docs-test marker (expected \`<!-- docs-test: skip (reason) -->\` or \`<!-- docs-test: instead\`, commands, \`-->\`)"
  "    docs/how-to/stray.md:19: docs-test marker not followed by a \`\`\`bash block (it must be on the line just before the block)"
  "    docs/how-to/stray.md:25: a \`\`\`sh block is neither run nor plain text: commands go in \`\`\`bash (run by this test), output in \`\`\`text or \`\`\`console"
  "docs/how-to/writes-repo.md: FAILED: scripts/made-by-the-docs: changed in the repository while docs/how-to/writes-repo.md ran (its commands must write under the scratch or /tmp/)"
  "docs/tutorials/slow.md: FAILED: timed out after 4 s in docs/tutorials/slow.md:$slow (the page's processes were killed)"
  "docs_commands: FAILED: docs/tutorials/slow.md, docs/how-to/failing.md, docs/how-to/picture.md, docs/how-to/stray.md, docs/how-to/writes-repo.md")
sed 's/ in [0-9.]* s$//' "$work/out" > "$work/lines"
for text in "${expected[@]}"; do
  if grep -qxF -- "$text" "$work/lines"; then pass; else fail "all pages: not reported: $text"; fi
done
# The failing block stopped the page: neither the rest of its block nor the next block ran.
if ! grep -q "after the failure\|third block" "$work/out"; then pass; else fail "the failing page went on"; fi
# The page over its timeout was killed with what it started in the background; the scratch is removed.
if ! pgrep -f "^sleep 987$" > /dev/null; then pass; else fail "a background sleep of slow.md is still running"; fi
if [ -z "$(ls -A "$work/tmp")" ]; then pass; else fail "scratch directories left: $(ls -A "$work/tmp")"; fi

# Bad usage.
expect_error "no such page" "no such page in" docs nope.md
expect_error "bad timeout" "--timeout: expected a positive number" docs --timeout 0

# The real documentation, with the built workspace. A page may take up to 600 s: the corpus how-to hunts a Python
# planner through ROS (600 matings) and shrinks its failures while other tests share the cores (180 s then).
if PPP_BUILD_DIR="$build_dir" /usr/bin/python3 "$runner" --timeout 600 > "$work/out" 2>&1; then pass
else fail "the repository's documentation:"$'\n'"$(cat "$work/out")"; fi
finish
