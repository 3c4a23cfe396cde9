# Helpers shared by the tmux tests (sourced): a private tmux server and a temporary folder, both
# removed at exit; screen capture, waiting for a pattern, failing with the screen and the log.

e2e_start() {
  command -v tmux >/dev/null || { echo "e2e: tmux is not installed (scripts/bootstrap installs it)" >&2; exit 1; }
  socket="qrterm-e2e-$$-$RANDOM"
  work=$(mktemp -d /tmp/qrterm-e2e.XXXXXX)
  tmux=(tmux -L "$socket")
  sim_pid=""
  trap e2e_cleanup EXIT
}

e2e_cleanup() {
  "${tmux[@]}" kill-server 2>/dev/null || true
  # The simulator is qrterm's child; if qrterm could not stop it, it is ours to stop.
  if [[ -n $sim_pid ]] && kill -0 "$sim_pid" 2>/dev/null; then kill "$sim_pid" 2>/dev/null || true; fi
  rm -rf "$work"
}

# Runs the command (qrterm and its arguments) in an 80x24 pane. The pane's shell records the
# terminal's settings before and after, the command's pid ($work/qrterm.pid) and exit status,
# then stays open for the capture.
e2e_pane() {
  local command
  printf -v command '%q ' "$@"
  {
    echo "stty -g >'$work/stty.before'"
    echo "bash -c 'echo \$\$ >\"\$0\"; exec \"\$@\"' '$work/qrterm.pid' $command"
    echo "echo \$? >'$work/status'"
    echo "stty -g >'$work/stty.after'"
    echo "echo 'QRTERM ENDED'"
    echo "sleep 600"
  } >"$work/pane.sh"
  # Without the test's descriptor 7 (e2e_joystick.sh's end of the joystick FIFO): a tmux server
  # holding it would keep the "device" from ever going away.
  "${tmux[@]}" -f /dev/null new-session -d -s e2e -x 80 -y 24 "bash $work/pane.sh" 7>&-
}

screen() { "${tmux[@]}" capture-pane -p -t e2e; }
keys() { "${tmux[@]}" send-keys -t e2e "$@"; }

fail() {
  echo "e2e: FAILED: $*" >&2
  echo "---- screen ----" >&2
  screen >&2 || true
  echo "---- console.log ----" >&2
  cat "$work/logs/console.log" >&2 2>/dev/null || true
  exit 1
}

# Waits until the screen matches the regular expression (grep -E), at most `seconds`.
wait_for() {
  local pattern=$1 seconds=$2 what=$3
  local deadline=$((SECONDS + seconds + 1)) start=$EPOCHREALTIME
  while ((SECONDS <= deadline)); do
    if screen | grep -Eq -- "$pattern"; then
      echo "e2e: ok: $what ($(awk "BEGIN { printf \"%.1f\", $EPOCHREALTIME - $start }") s)"
      return 0
    fi
    sleep 0.1
  done
  fail "$what: no /$pattern/ within $seconds s"
}

# The simulator's pid, from the first lines of console.log.
find_sim_pid() {
  for _ in $(seq 50); do
    sim_pid=$(sed -nE 's/.*simulator pid ([0-9]+).*/\1/p' "$work/logs/console.log" 2>/dev/null | head -1)
    [[ -n $sim_pid ]] && return 0
    sleep 0.1
  done
  fail "no simulator pid in console.log"
}

# x, then: qrterm ended with status 0 and the terminal is as it was.
exit_and_check_terminal() {
  keys x
  wait_for 'QRTERM ENDED' 5 "x exits"
  [[ $(cat "$work/status") == 0 ]] || fail "qrterm ended with status $(cat "$work/status")"
  [[ $("${tmux[@]}" display-message -p -t e2e '#{alternate_on}') == 0 ]] || fail "still on the alternate screen"
  cmp -s "$work/stty.before" "$work/stty.after" || fail "terminal settings not restored"
  echo "e2e: ok: terminal restored"
}

# The joystick tests' FIFO standing in for /dev/input/js0: one struct js_event { u32 time;
# s16 value; u8 type; u8 number; }, little-endian, written to descriptor 7.
readonly AXIS=0x02 BUTTON=0x01 INIT=0x80
js_event() {
  local type=$1 number=$2 value=$(($3 & 0xFFFF))
  printf "$(printf '\\x00\\x00\\x00\\x00\\x%02x\\x%02x\\x%02x\\x%02x' $((value & 0xFF)) $((value >> 8)) "$type" "$number")" >&7
}
