#!/usr/bin/env bash
# Installs what is missing, builds Release and starts Atrium. Arguments go to
# the atrium program: ./run.sh --mode forward --lights 512, or
# ./run.sh render --out frame.png for a headless frame.
set -euo pipefail
cd "$(dirname "$0")"
./scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target atrium -j"$(nproc)" >/dev/null
exec ./build/atrium "$@"
