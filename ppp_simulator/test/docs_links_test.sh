#!/bin/bash
# scripts/docs_links.py on a fake repository (test/docs/links, copied into a fresh git repository): every bad link,
# anchor and outside citation is reported at its line, and nothing else (the good links are not); then on the real
# repository, whose README, BENCHMARKS and docs/ must have no problem.
source "$(dirname "$0")/cli_harness.sh"
here="$(cd "$(dirname "$0")" && pwd)"
checker="$here/../../scripts/docs_links.py"
repo="$work/repo"

cp -r "$here/docs/links" "$repo"
cd "$repo" || exit 1
git init -q .
echo "/build/" > .gitignore
mkdir build && echo "made by a build" > build/out.txt
# The citations are written here, not committed in the fixture, so that the real repository's check does not
# find them: the word is spelled in two pieces.
word="SP""EC"
shared="../""shared"
shared_docs="shared""/docs"
printf 'line one\nsee %s 6 for the rules\n%sS and %s_x and X%s are other words\n' "$word" "$word" "$word" "$word" \
  > notes.txt
printf 'the %s/docs folder\nthe shared%s notes\n' "$shared" "/docs" > config.yaml
printf 'binary \0 %s\n' "$word" > picture.bin
printf 'a %s in a map file\n' "$word" > map.ppp
git add -A
# Not tracked: a text file (not scanned) and a docs page (scanned: it is a checked page).
printf '%s\n' "$word" > untracked.txt
printf '# Draft\n\nAs the %s says.\n' "$word" > docs/how-to/draft.md
cd - > /dev/null || exit 1

cited="cites a document outside the repository"
cat > "$work/expected" <<EOF
README.md:27: link to docs/how-to/nope.md: no such file
README.md:28: anchor #no-such-heading not found in docs/how-to/page.md
README.md:29: image docs/images/missing.png: no such file
README.md:30: anchor #Fixture-README not found in README.md (did you mean #fixture-readme?)
README.md:31: link to ../outside.md: outside the repository
README.md:32: link to /docs/how-to/page.md: an absolute path (use a path relative to README.md)
README.md:33: reference [nolabel] is not defined
README.md:34: image docs/images/gone.png: no such file
README.md:35: link to build/out.txt: ignored by git (not in the repository)
README.md:36: anchor #somewhere on docs/images/pic.txt, which is not Markdown
README.md:37: link with an empty destination
README.md:41: link to docs/missing-ref.md: no such file
config.yaml:1: $cited ("$shared")
config.yaml:1: $cited ("$shared_docs")
config.yaml:2: $cited ("$shared_docs")
docs/how-to/draft.md:3: $cited ("$word")
docs/how-to/page.md:14: link to ../../../BENCHMARKS.md: outside the repository
docs/how-to/page.md:14: anchor #second-sections not found in docs/how-to/page.md (did you mean #second-section?)
docs/how-to/page.md:15: link to ../reference/reference.md: no such file
docs/reference/ref.md:10: anchor #repeated-2 not found in docs/how-to/page.md (did you mean #repeated-1?)
notes.txt:2: $cited ("$word")
EOF

/usr/bin/python3 "$checker" --root "$repo" > "$work/out" 2> "$work/err"
status=$?
if [ "$status" -eq 1 ]; then pass; else fail "fixture: exit status $status, expected 1: $(cat "$work/err")"; fi
# Each expected problem is reported...
while IFS= read -r line; do
  if grep -qxF -- "$line" "$work/out"; then pass; else fail "fixture: not reported: $line"; fi
done < "$work/expected"
# ... and nothing else: no good link, no link in code or a comment, no other word, no binary, .ppp or untracked file.
extra="$(grep -vxF -f "$work/expected" "$work/out")"
if [ -z "$extra" ]; then pass; else fail "fixture: unexpected reports:"$'\n'"$extra"; fi
if grep -q "^docs_links: 21 problems (5 Markdown files, 35 relative links checked, " "$work/err"; then pass
else fail "fixture summary: $(cat "$work/err")"; fi

# Once every problem is fixed the checker says so and exits 0.
cd "$repo" || exit 1
rm -rf docs/how-to/draft.md notes.txt config.yaml untracked.txt README.md docs/how-to/page.md docs/reference/ref.md
printf '# Fixture README\n\n[a page](docs/images/pic.txt) and [a heading](#fixture-readme)\n' > README.md
git add -A
cd - > /dev/null || exit 1
expect_ok "fixed fixture" /usr/bin/python3 "$checker" --root "$repo"
if grep -q "^docs_links: ok: 2 Markdown files, 3 relative links checked (0 external not fetched), " "$work/out"
then pass; else fail "fixed fixture summary: $(cat "$work/out")"; fi

# Bad usage.
expect_error "no such root" "--root: no such directory" /usr/bin/python3 "$checker" --root "$work/none"

# The real repository.
if /usr/bin/python3 "$checker" > "$work/out" 2> "$work/err"; then pass
else fail "the repository's documentation:"$'\n'"$(cat "$work/out" "$work/err")"; fi
finish
