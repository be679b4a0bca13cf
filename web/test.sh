#!/usr/bin/env bash
# The page in headless Chromium (run from the repository root, after web/build.sh and
# `cargo build --release`): serves target/web on a free local port with Python's static
# server and runs web/test.mjs against it, which compares the page's results with those of
# target/release/wdm-crust. Screenshots go to target/web-test/.
set -euo pipefail
cd "$(dirname "$0")/.."

if [ ! -f target/web/index.html ]; then
  echo "web/test.sh: no target/web/index.html; run web/build.sh first" >&2
  exit 1
fi
if [ ! -x "${WDM_CRUST:-target/release/wdm-crust}" ]; then
  echo "web/test.sh: no target/release/wdm-crust; run cargo build --release first" >&2
  exit 1
fi

port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
python3 -m http.server "$port" --bind 127.0.0.1 --directory target/web >/dev/null 2>&1 &
server=$!
trap 'kill "$server" 2>/dev/null || true' EXIT
for _ in $(seq 100); do
  if python3 -c "import urllib.request; urllib.request.urlopen('http://127.0.0.1:$port/index.html')" 2>/dev/null; then
    break
  fi
  sleep 0.1
done

node web/test.mjs "http://127.0.0.1:$port/index.html"
