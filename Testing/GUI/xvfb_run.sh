#!/bin/bash
# usage: xvfb_run.sh COMMAND [ARGS...]
#
# Runs COMMAND under xvfb-run, in a private virtual X server: Debian's ParaView
# renders through GLX only, so anything that renders needs one. Two guards
# around xvfb-run's start-up handshake, which was seen (rarely, under ctest) to
# start the command before the server accepted connections ("bad X server
# connection", and an Xvfb left behind):
#  - the command starts only once the display's socket accepts a connection;
#  - a run that still could not reach its display is retried, on another one.
# Display numbers are searched from a random start, away from xvfb-run's
# default :99 that other jobs on the same machine may use.
set -u

if [ "${1:-}" = "--inside" ]; then
  shift
  socket=/tmp/.X11-unix/X${DISPLAY#:}
  /usr/bin/python3 - "$socket" <<'PY' || { echo "xvfb_run.sh: $DISPLAY never accepted a connection" >&2; exit 97; }
import socket, sys, time
for _ in range(300):
    try:
        s = socket.socket(socket.AF_UNIX)
        s.connect(sys.argv[1])
        s.close()
        sys.exit(0)
    except OSError:
        time.sleep(0.1)
sys.exit(1)
PY
  exec "$@"
fi

log=$(mktemp -t osm-xvfb.XXXXXX)
trap 'rm -f "$log"' EXIT
status=1
for attempt in 1 2 3; do
  : >"$log"
  xvfb-run -a -n $((100 + RANDOM % 800)) -s "-screen 0 1280x1024x24" \
    bash "$0" --inside "$@" 2>&1 | tee "$log"
  status=${PIPESTATUS[0]}
  if [ "$status" -eq 0 ] ||
    ! grep -q "bad X server connection\|never accepted a connection\|cannot open display\|Xvfb failed to start" "$log"; then
    break
  fi
  echo "xvfb_run.sh: no usable X display (attempt $attempt), retrying" >&2
done
exit "$status"
