#!/usr/bin/env bash
# scripts/rviz-video.sh on the small bag of scripts/make_test_bag.py (2.9 s): a 4 s .mp4 is H.264, yuv420p,
# 1280x960, 4 s long (± one frame at 10 fps), and its middle frame shows the map (scripts/check_screenshot.py);
# a 2 s .webm is VP9 and 2 s long; without SECONDS the video lasts the bag (at least the documented 1 s);
# SIGINT and SIGTERM mid-recording exit 130 and leave neither OUT, nor its temporary file, nor any process.
# Bad input (no bag, not a bag, unknown extension, unwritable OUT, bad SECONDS) exits 2 with a one-line message
# naming the problem. Prints a PASS or FAIL line per check.
# Usage: rviz_video_test.sh DEVEL_DIR
source "$(dirname "${BASH_SOURCE[0]}")/ros_harness.sh"
video="$root/scripts/rviz-video.sh"
frame=0.1  # one frame at the script's 10 fps

ok() { echo "PASS: $*"; pass; }
# near VALUE EXPECTED: |VALUE - EXPECTED| <= one frame.
near() { awk -v v="$1" -v e="$2" -v t="$frame" 'BEGIN { d = v - e; exit !(v != "" && d <= t + 1e-6 && -d <= t + 1e-6) }'; }
# probe FILE KEY: one value of ffprobe on the video stream and the container (codec_name, pix_fmt, width,
# height, duration).
probe() {
  ffprobe -v error -select_streams v:0 -show_entries stream=codec_name,pix_fmt,width,height:format=duration \
    -of default=noprint_wrappers=1 "$1" 2>/dev/null | sed -n "s/^$2=//p" | head -1
}
# leftovers MARK: the processes (pid and command) whose environment holds PPP_RVIZ_VIDEO_TEST=MARK.
leftovers() {
  local f pid
  for f in /proc/[0-9]*/environ; do
    grep -qzxF "PPP_RVIZ_VIDEO_TEST=$1" "$f" 2>/dev/null || continue
    pid="${f#/proc/}"; pid="${pid%/environ}"
    echo -n "$pid $(tr '\0' ' ' < "/proc/$pid/cmdline" 2>/dev/null | cut -c1-80); "
  done
}
# record NAME ARGS...: runs rviz-video.sh ARGS, marked NAME; its output in $work/NAME.log.
record() {
  local name="$1"; shift
  PPP_RVIZ_VIDEO_TEST="$work/$name" "$video" "$@" > "$work/$name.log" 2>&1
}
# clean NAME OUT: after a run, nothing of it is left: no process and no temporary file beside OUT.
clean() {
  local left
  sleep 0.2
  left="$(leftovers "$work/$1")"
  [ -z "$left" ] && ok "$1: no process left" || fail "$1: processes left: $left"
  left="$(find "$(dirname "$2")" -maxdepth 1 -name ".$(basename "$2").*")"
  [ -z "$left" ] && ok "$1: no temporary file left" || fail "$1: temporary files left: $left"
}
# check_video NAME FILE CODEC SECONDS: codec, 1280x960 and the duration (± one frame).
check_video() {
  local name="$1" file="$2" codec="$3" seconds="$4" got
  got="$(probe "$file" codec_name) $(probe "$file" pix_fmt) $(probe "$file" width)x$(probe "$file" height)"
  [ "$got" = "$codec yuv420p 1280x960" ] && ok "$name: $got" || fail "$name: codec, pixels and size '$got'"
  got="$(probe "$file" duration)"
  near "$got" "$seconds" && ok "$name: lasts $got s" || fail "$name: lasts '$got' s, expected $seconds ± $frame"
}

/usr/bin/python3 "$root/scripts/make_test_bag.py" "$work/test.bag"
length="$(rosbag info --yaml "$work/test.bag" | sed -n 's/^duration: *//p')"

# A 4 s mp4 of the 2.9 s bag, and its middle frame.
if record mp4 "$work/test.bag" "$work/out.mp4" 4; then
  ok "mp4: $(tail -1 "$work/mp4.log")"
  check_video mp4 "$work/out.mp4" h264 4
  # Converted back to RGB with accurate rounding: swscale's default turns rviz's background grey 48 into 47.
  if ffmpeg -v error -nostdin -ss 2 -i "$work/out.mp4" -sws_flags accurate_rnd+full_chroma_int -frames:v 1 \
      "$work/middle.png" > "$work/frame.log" 2>&1; then
    /usr/bin/python3 "$root/scripts/check_screenshot.py" "$work/middle.png" > "$work/check.log" 2>&1 &&
      ok "mp4: the middle frame shows the map: $(head -1 "$work/check.log")" ||
      fail "mp4: the middle frame does not show the map: $(cat "$work/check.log")"
    [ -n "${PPP_KEEP_VIDEO_FRAME:-}" ] && cp "$work/middle.png" "$PPP_KEEP_VIDEO_FRAME"
  else
    fail "mp4: no frame at 2 s: $(cat "$work/frame.log")"
  fi
else
  fail "mp4: rviz-video.sh failed: $(tail -20 "$work/mp4.log")"
fi
clean mp4 "$work/out.mp4"

# A 2 s webm.
if record webm "$work/test.bag" "$work/out.webm" 2; then
  ok "webm: $(tail -1 "$work/webm.log")"
  check_video webm "$work/out.webm" vp9 2
else
  fail "webm: rviz-video.sh failed: $(tail -20 "$work/webm.log")"
fi
clean webm "$work/out.webm"

# Without SECONDS: the bag's length (at least 1 s).
expected="$(awk -v d="$length" 'BEGIN { print d < 1 ? 1 : d }')"
if record default "$work/test.bag" "$work/default.mp4"; then
  got="$(probe "$work/default.mp4" duration)"
  near "$got" "$expected" && ok "default: lasts $got s, the bag $length s" ||
    fail "default: lasts '$got' s, expected the bag's $expected ± $frame"
else
  fail "default: rviz-video.sh failed: $(tail -20 "$work/default.log")"
fi

# Interrupted mid-recording (once the temporary file exists): exit 130, nothing left. A background job of this
# script ignores SIGINT, so SIGINT is sent to a run started with SIGINT's default action restored.
for sig in INT TERM; do
  PPP_RVIZ_VIDEO_TEST="$work/$sig" /usr/bin/python3 -c \
    'import os, signal, sys; signal.signal(signal.SIGINT, signal.SIG_DFL); os.execv(sys.argv[1], sys.argv[1:])' \
    "$video" "$work/test.bag" "$work/$sig.mp4" 60 > "$work/$sig.log" 2>&1 &
  pid=$!
  for _ in $(seq 600); do
    compgen -G "$work/.$sig.mp4.*" > /dev/null && break
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.1
  done
  sleep 1
  kill -"$sig" "$pid"
  status=0
  wait "$pid" || status=$?
  [ "$status" -eq 130 ] && ok "SIG$sig: exit 130" || fail "SIG$sig: exit $status: $(tail "$work/$sig.log")"
  [ ! -e "$work/$sig.mp4" ] && ok "SIG$sig: no video written" || fail "SIG$sig: $work/$sig.mp4 written"
  clean "SIG$sig" "$work/$sig.mp4"
done

# Bad input: exit 2 with one line naming the problem, before starting anything.
bad() {
  local name="$1" text="$2" status=0; shift 2
  PPP_RVIZ_VIDEO_TEST="$work/bad" "$video" "$@" > "$work/bad.out" 2> "$work/bad.err" || status=$?
  if [ "$status" -eq 2 ] && [ "$(wc -l < "$work/bad.err")" -eq 1 ] && grep -qF -- "$text" "$work/bad.err"; then
    ok "$name: $(cat "$work/bad.err")"
  else
    fail "$name: exit $status, expected 2 and one line with '$text': $(cat "$work/bad.err")"
  fi
}
echo "not a bag" > "$work/text.bag"
mkdir "$work/dir.mp4"
bad "no bag" "no bag at $work/missing.bag" "$work/missing.bag" "$work/o.mp4"
bad "not a bag" "$work/text.bag is not a readable bag" "$work/text.bag" "$work/o.mp4"
bad "unknown extension" "unknown output type of $work/o.avi: the name must end in .mp4 (H.264) or .webm (VP9)" \
  "$work/test.bag" "$work/o.avi"
bad "no directory" "cannot write $work/none/o.mp4: no directory $work/none" "$work/test.bag" "$work/none/o.mp4"
bad "unwritable directory" "cannot write /proc/o.mp4: directory /proc is not writable" "$work/test.bag" /proc/o.mp4
bad "a directory" "cannot write $work/dir.mp4: it is a directory" "$work/test.bag" "$work/dir.mp4"
for seconds in 0 0.0 -1 abc; do
  bad "SECONDS $seconds" "SECONDS must be a positive number, got '$seconds'" "$work/test.bag" "$work/o.mp4" "$seconds"
done
bad "usage" "usage: $video BAG OUT.mp4|OUT.webm [SECONDS]" "$work/test.bag"
left="$(leftovers "$work/bad")"
[ -z "$left" ] && [ ! -e "$work/o.mp4" ] && ok "bad input: nothing started or written" ||
  fail "bad input started $left or wrote $work/o.mp4"
finish
