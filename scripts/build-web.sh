#!/usr/bin/env bash
# Builds the WebAssembly page with Debian's emscripten into build-web/site/
# (atrium.html, .js, .wasm, .data). Offline: emscripten's frozen cache has
# what the build uses (GLFW for the canvas); the engine's dependencies are
# Debian's header-only libraries (web/dependencies.cmake).
#   scripts/build-web.sh [Release|Debug]
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
# emcc's link step runs node with its own modules; a node that is not
# Debian's does not look in Debian's folder for them.
export NODE_PATH=${NODE_PATH:-/usr/share/nodejs}
emcmake cmake -S . -B build-web -DCMAKE_BUILD_TYPE="${1:-Release}" >/dev/null
cmake --build build-web -j"$(nproc)"
echo "build-web/site/atrium.html"
