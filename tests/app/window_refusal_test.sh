#!/usr/bin/env bash
# window_refusal_test.sh ATRIUM OUT_DIR: in the demo window, + doubles the
# lights of forward shading past what llvmpipe can loop over in one shader; the
# frame is refused with its reason on stderr, the window goes back to the light
# count that rendered, keeps drawing, and Esc still ends it with exit 0.
set -u
atrium=$1 out=$2
. "$(dirname "$0")/window_driver.sh"
rm -rf "$out" && mkdir -p "$out" && cd "$out" || exit 1

start_atrium --size 32x18 --lights 40000 --mode forward --gl-debug
expect_line "^renderer: llvmpipe"  # the loop limit is llvmpipe's
expect_line "^mode: forward$"
expect_line "^view: 1 court$"
expect_line "^lights: 40000 "
find_window
press plus; expect_line "^lights: 80000$"
expect_line "^refused: back to forward with 40000 lights$"
grep -q "forward with 80000 lights: each pixel loops over every light" err || fail "no reason on stderr"
press t; expect_line "^mode: deferred$"
quit_cleanly
