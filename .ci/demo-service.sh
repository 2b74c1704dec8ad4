#!/usr/bin/env bash
# `make demo`, service part: start the embedded service (`artimo serve`: SQLite database and
# broker in a temporary ARTIMO_DATA_DIR, a real Celery worker) on a free port, wait for
# /readyz, submit the pedal-bin job with `artimo submit --wait`, download its outputs into
# $DEMO_OUT, validate the GLB, stop the service. The trap stops the service (and removes
# the temporary data dir) whether the demo succeeds, fails or is interrupted.
set -euo pipefail
cd "$(dirname "$0")/.."

VENV=${VENV:-.venv}
PY="$VENV/bin/python"
ARTIMO="$VENV/bin/artimo"
OUT=${DEMO_OUT:-out/demo}
READY_TIMEOUT_S=${READY_TIMEOUT_S:-60}

data_dir=$(mktemp -d "${TMPDIR:-/tmp}/artimo-demo.XXXXXX")
log="$data_dir/serve.log"
server_pid=""

stop_server() {
  if [ -n "$server_pid" ] && kill -0 "$server_pid" 2>/dev/null; then
    kill -TERM "$server_pid" 2>/dev/null || true
    for _ in $(seq 1 150); do kill -0 "$server_pid" 2>/dev/null || break; sleep 0.2; done
    kill -KILL "$server_pid" 2>/dev/null || true
    wait "$server_pid" 2>/dev/null || true
  fi
  server_pid=""
}

cleanup() {
  status=$?
  trap - EXIT INT TERM
  stop_server
  if [ "$status" -ne 0 ] && [ -f "$log" ]; then
    echo "demo failed (exit $status); last lines of the service log:" >&2
    tail -n 40 "$log" >&2 || true
  fi
  rm -rf "$data_dir"
  exit "$status"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

port=$("$PY" -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1]); s.close()')
url="http://127.0.0.1:$port"
export ARTIMO_DATA_DIR="$data_dir"
export ARTIMO_API_KEY="demo_$("$PY" -c 'import secrets; print(secrets.token_urlsafe(24))')"
unset DATABASE_URL REDIS_URL  # the embedded default: SQLite database and broker

echo "starting the embedded service on $url (data: $data_dir)"
"$ARTIMO" serve --host 127.0.0.1 --port "$port" --workers 1 >"$log" 2>&1 &
server_pid=$!

"$PY" - "$url/readyz" "$READY_TIMEOUT_S" "$server_pid" <<'PY'
import os, sys, time, urllib.error, urllib.request
url, timeout, pid = sys.argv[1], float(sys.argv[2]), int(sys.argv[3])
deadline = time.monotonic() + timeout
while time.monotonic() < deadline:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        sys.exit("artimo serve exited before it was ready")
    try:
        with urllib.request.urlopen(url, timeout=2) as answer:
            if answer.status == 200:
                sys.exit(0)
    except (urllib.error.URLError, OSError):
        pass
    time.sleep(0.2)
sys.exit(f"{url} not ready after {timeout:.0f} s")
PY
echo "service ready"

rm -rf "$OUT"
"$ARTIMO" submit examples/pedal_bin --prompt "press the pedal to open the bin" --server "$url" --wait --out "$OUT"
"$PY" -m tests.support.gltf_validator "$OUT/animation.glb"
stop_server
echo "demo: job run by the embedded service, outputs in $OUT"
echo "to look at results in the browser: $ARTIMO serve  (then open the Page: link it prints)"
