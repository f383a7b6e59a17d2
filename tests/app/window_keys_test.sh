#!/usr/bin/env bash
# window_keys_test.sh ATRIUM OUT_DIR: drives the demo window with real X key
# events (xdotool, under xvfb-run) as a user would: every mode with t and
# Shift+t, the five views, every debug view deferred offers with g, light count, pause,
# benchmark, shader reload, help, vsync, overlay, a resize and screenshots;
# checks each stdout line, compares screenshots by PSNR, and expects exit 0 on
# Esc with no GL errors.
set -u
atrium=$1 out=$2
. "$(dirname "$0")/window_driver.sh"
rm -rf "$out" && mkdir -p "$out" && cd "$out" || exit 1

start_atrium --size 160x90 --lights 16 --gl-debug
expect_line "^renderer: "
expect_line "^mode: forward$"
expect_line "^view: 1 court$"
expect_line "^lights: 16 "
find_window

# 16 lights of the built-in scene are all its lamps', which do not move.
press p; expect_line "^light animation: paused \(no light here moves: generated lights do, and \+ adds them\)$"
modes=$("$atrium" --help | sed -n '/^Modes:/,/^$/p' | awk 'NF > 1 && $1 != "Modes:" {print $1}')
[ "$(echo "$modes" | wc -l)" -ge 8 ] || fail "could not read the modes from --help"
for mode in $(echo "$modes" | tail -n +2) forward; do press t; expect_line "^mode: $mode$"; done
press shift+t; expect_line "^mode: $(echo "$modes" | tail -1)$"
press t; expect_line "^mode: forward$"

press F12; expect_line "^screenshot: .*\.png$"; forward_view1=$(sed -n "${lines_seen}p" log | cut -d' ' -f2)
press t; expect_line "^mode: deferred$"
press F12; expect_line "^screenshot: "; deferred_view1=$(sed -n "${lines_seen}p" log | cut -d' ' -f2)
names=(court gallery lamps overview colonnade)
for v in 2 3 4 5 1; do press "$v"; expect_line "^view: $v ${names[$((v - 1))]}$"; done
press 3; expect_line "^view: 3 lamps$"
press F12; expect_line "^screenshot: "; deferred_view3=$(sed -n "${lines_seen}p" log | cut -d' ' -f2)
press 1; expect_line "^view: 1 court$"

# g steps through the views the mode's frame graph offers: deferred has no
# light lists, light buffer, MSAA or shadows here; its HDR image is a
# resource shown by its kind.
for view in position normal albedo metallic-roughness emissive depth light-volumes heatmap depth-slices fragments diffuse-light specular-light hdr; do
  press g; expect_line "^debug view: $view$"
  if [ "$view" = normal ]; then press F12; expect_line "^screenshot: "; normal_view1=$(sed -n "${lines_seen}p" log | cut -d' ' -f2); fi
done
press g; expect_line "^debug view: off$"
press l; expect_line "^debug view: light-volumes$"
press l; expect_line "^debug view: off$"

press plus; expect_line "^lights: 32$"
press p; expect_line "^light animation: running$"
press minus; expect_line "^lights: 16$"
press b; expect_line "^benchmark: every mode"; expect_line "^\| lights \| forward \| deferred"
press r; expect_line "^shaders: reloaded$"
press h; expect_line "t / Shift\+t"
press c; expect_line "^camera: --camera -?[0-9.]+,-?[0-9.]+,-?[0-9.]+,-?[0-9.]+,-?[0-9.]+  view: \{ \"name\": \"here\", \"position\": \["
press v; expect_line "^vsync: off$"
press F1; sleep 2
xdotool getwindowname "$wid" | grep -Eq "^Atrium - deferred - [0-9]+ fps$" || fail "with the overlay hidden the title shows mode and fps (got '$(xdotool getwindowname "$wid")')"
xdotool windowsize "$wid" 400 240
sleep 2
press F12; expect_line "^screenshot: "; resized=$(sed -n "${lines_seen}p" log | cut -d' ' -f2)
quit_cleanly

/usr/bin/python3 - "$forward_view1" "$deferred_view1" "$deferred_view3" "$normal_view1" "$resized" <<'PY' || fail "screenshots"
import sys
import numpy as np
import matplotlib.image as mpimg
forward1, deferred1, deferred3, normal1, resized = (mpimg.imread(p)[..., :3].astype(np.float64) for p in sys.argv[1:])
def psnr(a, b):
    mse = np.mean((a - b) ** 2)
    return float("inf") if mse == 0 else 10 * np.log10(1.0 / mse)
checks = [
    ("forward and deferred draw the same picture", psnr(forward1, deferred1) >= 40),
    ("view 3 differs from view 1", psnr(deferred1, deferred3) < 25),
    ("the normal debug view differs from the lit image", psnr(deferred1, normal1) < 25),
    ("the screenshot follows the resized window", resized.shape[:2] == (240, 400)),
]
for name, ok in checks:
    print(("ok   " if ok else "FAIL ") + name)
sys.exit(0 if all(ok for _, ok in checks) else 1)
PY
echo "window keys: all checks passed"
