#!/usr/bin/env bash
# Runs a command under a private Xvfb server, then stops the server and waits for it to exit.
#
# -noreset: by default Xvfb resets when its last client disconnects, and a client that
# connects during the reset (a test running several pvbatch processes one after the other)
# fails with "bad X server connection". -displayfd: Xvfb picks a free display itself and
# reports it only once it accepts connections. Waiting for the server to exit keeps the next
# test from starting a server while this one still removes its socket.
set -u
ready=$(mktemp)
Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp -noreset 3>"$ready" >/dev/null 2>&1 &
server=$!
for _ in $(seq 1 100); do
  [ -s "$ready" ] && break
  sleep 0.1
done
display=$(tr -d '[:space:]' < "$ready")
rm -f "$ready"
if [ -z "$display" ]; then
  echo "run-with-xvfb: Xvfb did not start" >&2
  kill "$server" 2>/dev/null
  exit 1
fi
DISPLAY=":$display" "$@"
status=$?
kill "$server" 2>/dev/null
wait "$server" 2>/dev/null
exit $status
