#!/usr/bin/env bash
# Installs what is missing, builds Release and starts Atrium. Arguments go to
# the atrium program: ./run.sh --mode forward --lights 512, or
# ./run.sh render --out frame.png for a headless frame. ./run.sh --web builds
# the WebAssembly page and serves it on 127.0.0.1 (port $ATRIUM_WEB_PORT, 8080).
set -euo pipefail
cd "$(dirname "$0")"
if [ "${1:-}" = "--web" ]; then
  ./scripts/build-web.sh >/dev/null
  port=${ATRIUM_WEB_PORT:-8080}
  echo "Atrium in the browser: http://127.0.0.1:$port/atrium.html (?mode=clustered-deferred&lights=1024&scene=sponza; Ctrl+C stops)"
  exec python3 -m http.server "$port" --bind 127.0.0.1 --directory build-web/site
fi
./scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target atrium -j"$(nproc)" >/dev/null
exec ./build/atrium "$@"
