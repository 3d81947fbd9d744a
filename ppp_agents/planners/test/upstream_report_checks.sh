# What every upstream report's test checks besides its own program's behaviour, sourced by each: that the report
# shows the program tested line for line and its output as a text block; and the pass/fail count of the test.
failures=0 checks=0
pass() { echo "ok: $1"; checks=$((checks + 1)); }
fail() { echo "FAIL: $1"; checks=$((checks + 1)); failures=$((failures + 1)); }

# report_shows_output REPORT TEXT: REPORT has a ```text block that is TEXT.
report_shows_output() {
  python3 -c '
import re, sys
blocks = re.findall(r"^```text\n(.*?)^```$", open(sys.argv[1]).read(), re.S | re.M)
sys.exit(0 if any(b.rstrip("\n") == sys.argv[2] for b in blocks) else 1)' "$1" "$2" && \
    pass "the report shows that output" || fail "$1 does not show that output as a text block"
}

# report_shows_program REPORT SOURCE: REPORT's first ```cpp block is SOURCE, line for line.
report_shows_program() {
  sed -n '/^```cpp$/,/^```$/p' "$1" | sed '1d;$d' | diff -q - "$2" > /dev/null && \
    pass "the report shows the program tested" || fail "$1's program differs from $2"
}

# Prints the count; exits 1 on any failure.
finish() {
  echo "$((checks - failures)) passed, $failures failed"
  [ "$failures" -eq 0 ]
}
