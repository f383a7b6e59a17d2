# Sourced by the window tests: start_atrium ARGS... launches the demo window
# in the current folder (stdout to log, stderr to err); expect_line waits for
# its next stdout line to match; press sends a key to its window with xdotool.
fail() { echo "FAIL: $*" >&2; echo "--- stdout"; cat log; echo "--- stderr"; cat err; kill "$pid" 2>/dev/null; exit 1; }

start_atrium() {
  "$atrium" "$@" > log 2> err &
  pid=$!
  lines_seen=0
}

# Waits for the next stdout line after the ones already checked to match $1.
expect_line() {
  for _ in $(seq 1 600); do
    if [ "$(wc -l < log)" -gt "$lines_seen" ]; then
      lines_seen=$((lines_seen + 1))
      if sed -n "${lines_seen}p" log | grep -Eq -- "$1"; then return 0; fi
      continue
    fi
    kill -0 "$pid" 2>/dev/null || fail "atrium exited while waiting for '$1'"
    sleep 0.2
  done
  fail "no line matching '$1'"
}

find_window() {
  wid=$(xdotool search --name "^Atrium" | head -1)
  [ -n "$wid" ] || fail "no window named Atrium"
}

press() { xdotool key --window "$wid" "$1"; }

# Esc must end the program with exit 0 and no GL error.
quit_cleanly() {
  press Escape
  wait "$pid"; code=$?
  [ "$code" -eq 0 ] || fail "exit code $code on Esc"
  grep -q "^GL errors: 0$" log || fail "GL errors reported"
}
