#!/usr/bin/env bash
# Headless video of a bag in rviz with the shipped view (launch/ppp.rviz):
#   scripts/rviz-video.sh BAG OUT.mp4|OUT.webm [SECONDS]
# Under a virtual X server (xvfb-run, a 1280x960 screen) it starts a private roscore on a free port and rviz,
# waits until rviz has subscribed to /map (at most 60 s), then plays the bag once from its start at normal rate
# (`rosbag play --clock BAG`, not looped) and at the same moment records the whole screen with ffmpeg (x11grab)
# for SECONDS, and stops everything it started. The video is 1280x960 at 10 frames per second:
#   .mp4   H.264 (libx264, yuv420p, moov atom first), plays in browsers;
#   .webm  VP9 (libvpx-vp9, yuv420p).
# SECONDS (a positive number) defaults to the bag's length (`rosbag info` duration), at least 1 s (a bag of one
# instant still gives a 1 s video). Longer than the bag, the video keeps showing the last state. rosbag play
# takes about 0.4 s to start (its default 0.2 s delay after advertising included), so the first frames show rviz
# before the map and the default length ends that much before the bag's last messages: give SECONDS a second
# more than the bag to see its very end.
# The video is written beside OUT under a temporary name (.OUT.XXXXXX) and renamed to OUT only once ffmpeg has
# finished it; on SIGINT/SIGTERM everything is stopped (ffmpeg with SIGINT, so it closes the file) and no file is
# left. Bad input (no bag, not a bag, unknown extension, unwritable OUT, bad SECONDS) exits 2 before starting
# anything; a failure later exits 1, an interruption 130. Needs: rviz xvfb xauth ffmpeg
# (scripts/install-deps.sh). Set-up shared with rviz-screenshot.sh: rviz-headless.sh.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/env.sh"
source "$(dirname "${BASH_SOURCE[0]}")/rviz-headless.sh"
rviz_headless_name=rviz-video
fps=10
min_seconds=1

error() { echo "rviz-video: $*" >&2; exit 2; }

if [ $# -lt 2 ] || [ $# -gt 3 ]; then
  echo "usage: $0 BAG OUT.mp4|OUT.webm [SECONDS]" >&2
  exit 2
fi
bag="$(realpath -m "$1")"
out="$(realpath -m "$2")"
seconds="${3:-}"
[ -f "$bag" ] || error "no bag at $1"
case "${out,,}" in
  *.mp4) codec=(-c:v libx264 -preset veryfast -crf 23 -pix_fmt yuv420p -movflags +faststart -f mp4) ;;
  *.webm) codec=(-c:v libvpx-vp9 -deadline realtime -cpu-used 8 -row-mt 1 -crf 32 -b:v 0 -pix_fmt yuv420p -f webm) ;;
  *) error "unknown output type of $2: the name must end in .mp4 (H.264) or .webm (VP9)" ;;
esac
if [ -n "$seconds" ]; then
  [[ "$seconds" =~ ^[0-9]+([.][0-9]+)?$ ]] && awk -v s="$seconds" 'BEGIN { exit !(s > 0) }' ||
    error "SECONDS must be a positive number, got '$seconds'"
fi

if ! rviz_headless_in_xvfb; then
  dir="$(dirname "$out")"
  [ -d "$dir" ] || error "cannot write $2: no directory $dir"
  [ ! -d "$out" ] || error "cannot write $2: it is a directory"
  probe="$(mktemp "$dir/.rviz-video.XXXXXX" 2>/dev/null)" || error "cannot write $2: directory $dir is not writable"
  rm -f "$probe"
  info="$(rosbag info --yaml "$bag" 2>&1)" ||
    error "$1 is not a readable bag: rosbag info says: $(tail -1 <<< "${info//"ERROR reading $bag: "/}")"
  duration="$(sed -n 's/^duration: *//p' <<< "$info")"  # none in a bag without messages
  [ -n "$seconds" ] || seconds="$(awk -v d="${duration:-0}" -v m="$min_seconds" 'BEGIN { printf "%.3f", d < m ? m : d }')"
fi

# Re-run this script inside a virtual X server; there: roscore and rviz, then the bag and the recording.
rviz_headless_xvfb "$bag" "$out" "$seconds"
rviz_headless_start
rviz_headless_wait_map

part="$(mktemp "$(dirname "$out")/.$(basename "$out").XXXXXX")"
rviz_headless_remove "$part"
ffmpeg -nostdin -hide_banner -loglevel error -y -f x11grab -draw_mouse 0 -framerate "$fps" \
  -video_size "$RVIZ_HEADLESS_SCREEN" -i "$DISPLAY" -t "$seconds" -r "$fps" -fps_mode cfr "${codec[@]}" "$part" \
  > "$work/ffmpeg.log" 2>&1 &
ffmpeg_pid=$!
rviz_headless_track "$ffmpeg_pid" 30  # time to close the file when stopped early
rosbag play --clock -q "$bag" > "$work/rosbag.log" 2>&1 &
rosbag_pid=$!
rviz_headless_track "$rosbag_pid"

status=0
wait "$ffmpeg_pid" || status=$?
rviz_headless_untrack "$ffmpeg_pid"
[ "$status" -ne 255 ] || exit 130  # ffmpeg stopped by a Ctrl-C to the process group: interrupted, not failed
if [ "$status" -ne 0 ] || [ ! -s "$part" ]; then
  cat "$work/ffmpeg.log" >&2
  echo "rviz-video: ffmpeg failed (exit $status), no video written" >&2
  exit 1
fi
if ! kill -0 "$rosbag_pid" 2>/dev/null; then  # played to its end (else stopped at exit)
  status=0
  wait "$rosbag_pid" || status=$?
  rviz_headless_untrack "$rosbag_pid"
  [ "$status" -eq 0 ] || echo "rviz-video: warning: rosbag play failed (exit $status): $(tail -3 "$work/rosbag.log")" >&2
fi
chmod "$(printf '%o' $((0666 & ~0$(umask))))" "$part"  # mktemp made it private
mv -f "$part" "$out"
echo "rviz-video: wrote $out ($seconds s, ${RVIZ_HEADLESS_SCREEN} at $fps fps)"
