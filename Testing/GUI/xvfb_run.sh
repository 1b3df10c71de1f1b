#!/bin/bash
# usage: xvfb_run.sh COMMAND [ARGS...]
#
# Runs COMMAND under xvfb-run, in a private virtual X server: Debian's ParaView
# renders through GLX only, so anything that renders needs one. Two guards
# around xvfb-run's start-up handshake, which was seen (rarely, under ctest on
# a loaded machine) to start the command before the server took clients
# ("bad X server connection", three attempts in a row once, while a fuzzer
# and a compiler ran; an Xvfb left behind):
#  - the command starts only once an X client can open the display (libX11's
#    XOpenDisplay, with the server's authority file, as ParaView opens it;
#    a socket that accepts a connection was not enough);
#  - a run that still could not reach its display is retried, on another
#    one, after a pause that grows with each attempt.
# Display numbers are searched from a random start, away from xvfb-run's
# default :99 that other jobs on the same machine may use.
set -u

if [ "${1:-}" = "--inside" ]; then
  shift
  /usr/bin/python3 - <<'PY' || { echo "xvfb_run.sh: $DISPLAY never took a client" >&2; exit 97; }
import ctypes, sys, time
x11 = ctypes.cdll.LoadLibrary("libX11.so.6")
x11.XOpenDisplay.restype = ctypes.c_void_p
x11.XOpenDisplay.argtypes = [ctypes.c_char_p]
x11.XCloseDisplay.argtypes = [ctypes.c_void_p]
for _ in range(300):
    display = x11.XOpenDisplay(None)
    if display:
        x11.XCloseDisplay(display)
        sys.exit(0)
    time.sleep(0.1)
sys.exit(1)
PY
  exec "$@"
fi

log=$(mktemp -t osm-xvfb.XXXXXX)
trap 'rm -f "$log"' EXIT
status=1
for attempt in 1 2 3 4 5; do
  [ "$attempt" -gt 1 ] && sleep $((2 * attempt))
  : >"$log"
  xvfb-run -a -n $((100 + RANDOM % 800)) -s "-screen 0 1280x1024x24" \
    bash "$0" --inside "$@" 2>&1 | tee "$log"
  status=${PIPESTATUS[0]}
  if [ "$status" -eq 0 ] ||
    ! grep -q "bad X server connection\|never took a client\|cannot open display\|Xvfb failed to start" "$log"; then
    break
  fi
  echo "xvfb_run.sh: no usable X display (attempt $attempt), retrying" >&2
done
exit "$status"
