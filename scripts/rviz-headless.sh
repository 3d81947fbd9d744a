# Shared set-up of the headless rviz scripts (rviz-screenshot.sh, rviz-video.sh); source it after env.sh, with
# rviz_headless_name set to the script's name (the prefix of its messages). Argument-independent parts only:
#   rviz_headless_xvfb ARGS...    first run (the user's): reruns "$0" ARGS under xvfb-run (-a: a free display;
#                                 a 1280x960x24 screen, $RVIZ_HEADLESS_SCREEN), waits for it and exits with its
#                                 status.
#                                 SIGINT or SIGTERM to this first run is passed on to the rerun as SIGTERM, so
#                                 the rerun stops what it started and xvfb-run then stops Xvfb. In the rerun:
#                                 sets the exit trap (below) and returns.
#   rviz_headless_in_xvfb         true in the rerun (e.g. to skip checks the first run made).
#   rviz_headless_start           a scratch directory $work, a private roscore on a free loopback port
#                                 (ROS_HOME in $work, /use_sim_time true) and rviz with launch/ppp.rviz
#                                 ($rviz_pid); logs in $work/roscore.log and $work/rviz.log.
#   rviz_headless_wait_map        waits until rviz has subscribed to /map (at most 60 s); else exits 1.
#   rviz_headless_track PID [S]   stops PID at exit: SIGINT, then SIGKILL after S seconds (default 5); waited for
#                                 in reverse order of tracking.
#   rviz_headless_untrack PID     forgets PID (call it once the script has waited for PID itself).
#   rviz_headless_remove PATH     removes PATH at exit, after the processes stopped.
#   rviz_headless_sleep S         sleeps S seconds, cut short by SIGINT/SIGTERM (a foreground sleep would delay
#                                 the trap until it ends).
# The exit trap stops every tracked process (all at once, then waiting for each) and removes $work and the
# paths; SIGTERM (what the first run sends on SIGINT or SIGTERM) exits with status 130 through it, and further
# signals do not cut it short. (The rerun starts as a background job of the first run, so it ignores SIGINT
# itself; a Ctrl-C to the whole process group reaches it as the first run's SIGTERM.)
# shellcheck shell=bash
RVIZ_HEADLESS_SCREEN=1280x960

_rh_rerun="${PPP_RVIZ_HEADLESS_PIDFILE:+1}"
_rh_pids=()
declare -A _rh_grace=()
_rh_remove=()
_rh_sleep=""
work=""

rviz_headless_in_xvfb() {
  [ -n "$_rh_rerun" ]
}

rviz_headless_xvfb() {
  if rviz_headless_in_xvfb; then
    # The rerun under xvfb-run: trap first, then tell the first run where to send signals.
    trap _rviz_headless_cleanup EXIT
    trap 'exit 130' INT TERM
    echo "$$" > "$PPP_RVIZ_HEADLESS_PIDFILE"
    unset PPP_RVIZ_HEADLESS_PIDFILE
    return 0
  fi
  _rh_pidfile="$(mktemp)"
  _rh_xvfb_run=""
  _rh_pending=""
  trap _rviz_headless_forward INT TERM
  PPP_RVIZ_HEADLESS_PIDFILE="$_rh_pidfile" \
    xvfb-run -a -s "-screen 0 ${RVIZ_HEADLESS_SCREEN}x24" "$0" "$@" &
  _rh_xvfb_run=$!
  [ -z "$_rh_pending" ] || _rviz_headless_forward  # a signal came before xvfb-run started
  local status
  while :; do
    status=0
    wait "$_rh_xvfb_run" || status=$?
    kill -0 "$_rh_xvfb_run" 2>/dev/null || break  # else wait was cut short by a signal: wait again
  done
  rm -f "$_rh_pidfile"
  # Interrupted: 130, also when a Ctrl-C to the whole process group made xvfb-run fail on its own.
  [ -z "$_rh_pending" ] || [ "$status" -eq 0 ] || status=130
  exit "$status"
}

# The first run on SIGINT/SIGTERM: SIGTERM to the rerun, once it has said its pid (its first act under
# xvfb-run); nothing when xvfb-run ended first. A signal before xvfb-run started is passed on right after.
_rviz_headless_forward() {
  local inner=""
  _rh_pending=1
  [ -n "$_rh_xvfb_run" ] || return 0
  while [ -z "$inner" ]; do
    inner="$(cat "$_rh_pidfile" 2>/dev/null)" || true
    [ -n "$inner" ] || kill -0 "$_rh_xvfb_run" 2>/dev/null || return 0
    [ -n "$inner" ] || sleep 0.1
  done
  kill -TERM "$inner" 2>/dev/null || true
}

_rviz_headless_cleanup() {
  trap '' INT TERM
  local pid i
  [ -z "$_rh_sleep" ] || kill -TERM "$_rh_sleep" 2>/dev/null || true
  for pid in "${_rh_pids[@]}"; do kill -INT "$pid" 2>/dev/null || true; done
  for pid in "${_rh_pids[@]}"; do
    for ((i = 0; i < 10 * ${_rh_grace[$pid]:-5}; i++)); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -KILL "$pid" 2>/dev/null || true
    wait "$pid" 2>/dev/null || true
  done
  [ -z "$work" ] || rm -rf "$work"
  [ ${#_rh_remove[@]} -eq 0 ] || rm -rf "${_rh_remove[@]}"
}

rviz_headless_track() {
  _rh_pids=("$1" "${_rh_pids[@]}")
  _rh_grace[$1]="${2:-5}"
}

rviz_headless_untrack() {
  local pid kept=()
  for pid in "${_rh_pids[@]}"; do [ "$pid" = "$1" ] || kept+=("$pid"); done
  _rh_pids=("${kept[@]}")
  unset "_rh_grace[$1]"
}

rviz_headless_remove() {
  _rh_remove+=("$1")
}

rviz_headless_sleep() {
  sleep "$1" &
  _rh_sleep=$!
  wait "$_rh_sleep"
  _rh_sleep=""
}

rviz_headless_start() {
  work="$(mktemp -d)"
  # A private master on a free loopback port; logs in a scratch ROS_HOME.
  local port _
  port="$(/usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')"
  export ROS_MASTER_URI="http://127.0.0.1:$port" ROS_IP=127.0.0.1 ROS_HOME="$work/ros"
  roscore -p "$port" > "$work/roscore.log" 2>&1 &
  rviz_headless_track "$!"
  for _ in $(seq 100); do rosparam set /use_sim_time true 2>/dev/null && break; sleep 0.2; done
  rosparam get /use_sim_time > /dev/null 2>&1 || {
    cat "$work/roscore.log" >&2
    echo "$rviz_headless_name: roscore did not start" >&2
    exit 1
  }
  rviz -d "$PPP_ROOT/launch/ppp.rviz" > "$work/rviz.log" 2>&1 &
  rviz_pid=$!
  rviz_headless_track "$rviz_pid"
}

rviz_headless_wait_map() {
  local ready="" _
  for _ in $(seq 300); do
    if rostopic info /map 2>/dev/null | sed -n '/^Subscribers:/,$p' | grep -q rviz; then ready=1; break; fi
    kill -0 "$rviz_pid" 2>/dev/null || break  # rviz died
    sleep 0.2
  done
  if [ -z "$ready" ]; then
    cat "$work/rviz.log" >&2
    echo "$rviz_headless_name: rviz did not subscribe to /map within 60 s" >&2
    exit 1
  fi
}
