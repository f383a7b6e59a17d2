#!/usr/bin/env python3
"""The page in a real browser: headless Chromium (SwiftShader's WebGL2) opens
build-web/site/atrium.html from a server on 127.0.0.1, every mode's picture
comes back from the page (?capture: the page POSTs them with every error it
saw), and each is compared with the native build's compute-free render of the
same options (atrium render --no-compute) by PSNR; Sponza's files are fetched
by the page when asked for, not packaged with it. The canvas must show the
frame's aspect in three window sizes, a bad URL parameter must leave a working
page with the command line's own one-line message shown, and a scripted check
(tests/web/checks/page.js) drives the page as a user: panel values refused
with the URL's words, a light count too slow for this renderer refused until
asked again, a mode change whose frame took over 5 s undone until asked again,
fewer lights kept on a page whose frame took over 5 s,
a refused view shown as refused, taps of t at one frame a second
acting once each, holds of w moving for their own length, and a dropped .glb,
a .gltf dropped with its files and an .obj with its .mtl and texture drawn as
the native build draws them.

usage: browser_test.py --site DIR --atrium BIN --psnr BIN [--sponza GLTF] [--testdata DIR] [--out DIR]
"""
import argparse
import base64
import json
import os
import queue
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "web"))
from page_driver import open_page, serve  # noqa: E402

# The bound: two rasterisers. SwiftShader (the page) and llvmpipe (native)
# agree on nearly every pixel; they part at sub-pixel geometry, the small
# bright light markers and silhouettes (docs/architecture.md, the WebAssembly
# build), which costs 34.9 to 36.6 dB in every mode, built-in scene and
# Sponza alike. A missing light, a wrong target or a broken mode costs far
# more (a wrong G-buffer binding measured 4.8 dB, light-generation that
# differed between standard libraries 24.6 dB), so 32 dB keeps them out.
MIN_PSNR = 32.0
SIZE = "160x90"
LIGHTS = "64"


def page(port, query, results, timeout=180, window=None):
    """open_page, printing how long the page took against its limit: the margin
    that a slower machine has, read from the log of a run that passed."""
    start = time.monotonic()
    result, console = open_page(port, query, results, timeout=timeout, window=window)
    print(f"page ?{query}: answered in {time.monotonic() - start:.0f} s of the {timeout} s allowed")
    return result, console


def native_render(atrium, scene, mode, options, out):
    subprocess.run([atrium, "render", scene, "--mode", mode, "--size", SIZE, "--lights", LIGHTS, "--no-compute",
                    "--out", out] + options, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def native_light_count(atrium):
    """The built-in scene's own light count, as the native build reports it."""
    info = json.loads(subprocess.run([atrium, "info", "--json"], check=True, capture_output=True, text=True).stdout)
    return sum(info["lights"].values())


def scene_file_lights(path):
    """The lights a scene file lists and generates."""
    with open(path) as f:
        scene = json.load(f)
    return len(scene.get("lights", [])) + sum(g["count"] for g in scene.get("light_generators", []))


def check_aspect(tag, canvas):
    """The canvas as the page lays it out shows the frame's aspect, not stretched."""
    frame = canvas["width"] / canvas["height"]
    shown = canvas["shown_width"] / canvas["shown_height"] if canvas["shown_height"] else 0.0
    print(f"{tag}: a {canvas['width']}x{canvas['height']} frame shown at {canvas['shown_width']:.0f}x{canvas['shown_height']:.0f}")
    if abs(shown - frame) > 0.02 * frame:
        return [f"{tag}: a {canvas['width']}x{canvas['height']} frame is shown at "
                f"{canvas['shown_width']:.0f}x{canvas['shown_height']:.0f}, another aspect"]
    return []


def compare(args, port, results, tag, page_scene, native_scene, options):
    """Every mode of one scene on the page against the native renders; options
    are command-line options, given to both."""
    query = f"scene={page_scene}&size={SIZE}&lights={LIGHTS}&pause=1"
    for name, value in zip(options[::2], options[1::2]):
        query += f"&{name[2:]}={value}"
    result, console = page(port, "capture&" + query, results)
    failures = []
    if result["errors"]:
        failures.append(f"{tag}: the page reported {result['errors']}")
    if console:
        failures.append(f"{tag}: console errors {console}")
    if not result["images"]:
        failures.append(f"{tag}: no pictures came back")
    failures += check_aspect(tag, result["canvas"])
    for name, data in sorted(result["images"].items()):
        mode = name[:-4]
        page_png = os.path.join(args.out, f"web-{tag}-{mode}.png")
        native_png = os.path.join(args.out, f"native-{tag}-{mode}.png")
        with open(page_png, "wb") as f:
            f.write(base64.b64decode(data))
        native_render(args.atrium, native_scene, mode, options, native_png)
        psnr = subprocess.run([args.psnr, native_png, page_png], check=True, capture_output=True, text=True).stdout.strip()
        print(f"{tag} {mode}: {psnr} dB ({result['webgl']}, {result.get('renderer', '?')})")
        if float(psnr) < MIN_PSNR:
            failures.append(f"{tag} {mode}: {psnr} dB against the native compute-free tier, under {MIN_PSNR}")
    return failures


def check_page(args, port, results, url_message):
    """tests/web/checks/page.js: the page driven as a user drives it."""
    # No lights= here: the check opens scenes with their own light counts, then chooses LIGHTS.
    result, console = page(port, f"check=page&size={SIZE}&pause=1", results, timeout=300)
    failures = [f"page check: {error}" for error in result["errors"] if error.startswith("check failed")]
    for error in result["errors"]:
        print(f"page check: the page said {error!r}")
    if console:
        failures.append(f"page check: console errors {console}")
    print(f"page check: first frame after {result.get('first_frame_ms', 0) / 1000:.1f} s")
    if result.get("panel_negative_lights") != url_message:
        failures.append(f"the panel refused lights -3 with {result.get('panel_negative_lights')!r}, the URL with {url_message!r}")
    slow = result.get("slow_lights", "")
    print(f"page check: lights 1048576 -> {slow!r}")
    if "a frame would take about" not in slow or result.get("lights_after_slow") != result.get("lights_before"):
        failures.append(f"1048576 lights were not refused as too slow: {slow!r}, lights {result.get('lights_after_slow')}")
    fireflies = (result.get("fireflies_bad"), result.get("fireflies_reply"), result.get("fireflies_value"))
    if fireflies != ("--fireflies expects a whole number from 0 to 4096, got '-1'", "", "8"):
        failures.append(f"the panel's fireflies row: refused -1 with {fireflies[0]!r}, set 8 with {fireflies[1]!r}, shows {fireflies[2]!r}")
    if not result.get("refused_status", "").startswith("refused: ") or result.get("refused_list") != "heatmap":
        failures.append(f"a refused view shows {result.get('refused_status')!r} with the list at {result.get('refused_list')!r}")
    modes = result.get("modes", [])
    if result.get("mode_before") in modes:
        i = modes.index(result["mode_before"])
        taps = [result.get("mode_after_one_tap"), result.get("mode_after_two_taps")]
        print(f"page check: taps of t at ~1 fps: {result['mode_before']} -> {taps[0]} -> {taps[1]}")
        if taps != [modes[(i + 1) % len(modes)], modes[(i + 2) % len(modes)]]:
            failures.append(f"two taps of t went {result['mode_before']} -> {taps}, not one mode each")
    else:
        failures.append(f"page check: mode {result.get('mode_before')!r} is not among {modes}")
    print(f"page check: a mode change with a 5.5 s frame: {result.get('trial_message')!r}")
    trial = (result.get("trial_set"), result.get("trial_mode_after") == result.get("trial_mode_before"),
             "it is undone (set it again to draw it anyway)" in (result.get("trial_message") or ""), result.get("trial_again"),
             result.get("trial_mode_kept") not in (None, result.get("trial_mode_before")))
    if trial != ("", True, True, "", True):
        failures.append(f"a mode change with a 5.5 s frame: set {trial[0]!r}, back to {result.get('trial_mode_after')!r} "
                        f"({result.get('trial_message')!r}), again {trial[3]!r}, kept {result.get('trial_mode_kept')!r}")
    fewer = result.get("fewer_lights", [0, 0])
    print(f"page check: lights {fewer[0]} -> {fewer[1]} with a 5.5 s frame: {result.get('fewer_kept')} kept")
    if (result.get("fewer_set"), result.get("fewer_kept"), result.get("fewer_restored")) != ("", fewer[1], ""):
        failures.append(f"fewer lights with a 5.5 s frame: set {result.get('fewer_set')!r}, {result.get('fewer_kept')} lights "
                        f"after it, not {fewer[1]}; back to {fewer[0]}: {result.get('fewer_restored')!r}")
    holds = result.get("holds", [])
    for hold in holds:
        print(f"page check: w held {hold['seconds']:.2f} s at ~1 fps moved {hold['metres']:.3f} m")
    if len(holds) == 2 and holds[1]["metres"] > 0:
        moved, held = holds[0]["metres"] / holds[1]["metres"], holds[0]["seconds"] / holds[1]["seconds"]
        if abs(moved / held - 1.0) > 0.1:
            failures.append(f"holds of w moved {moved:.2f} times as far for {held:.2f} times as long")
    else:
        failures.append(f"holds of w: {holds}")
    if args.sponza and os.path.exists(args.sponza):
        print(f"page check: Sponza from the picker: {result.get('sponza_progress_shown')!r}, then {result.get('sponza_status')!r}")
        if not result.get("sponza_progress_shown") or not result.get("sponza_picker_free"):
            failures.append("choosing Sponza showed no progress bar, or blocked the picker")
        if " fps, " not in result.get("sponza_status", ""):
            failures.append(f"after choosing Sponza the page says {result.get('sponza_status')!r}")
        own = scene_file_lights(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scenes", "sponza.json"))
        print(f"page check: lights of the built-in scene {result.get('builtin_lights')}, then of Sponza {result.get('sponza_lights')}")
        if result.get("sponza_lights") != own:
            failures.append(f"Sponza chosen after the built-in scene has {result.get('sponza_lights')} lights, not its own {own}")
    builtin = native_light_count(args.atrium)
    if result.get("builtin_lights") != builtin:
        failures.append(f"the page opened without lights= has {result.get('builtin_lights')} lights, not the built-in scene's {builtin}")
    if result.get("chosen_lights") != "":
        failures.append(f"the panel refused lights {LIGHTS}: {result.get('chosen_lights')!r}")
    images = result.get("images", {})
    here = os.path.dirname(os.path.abspath(__file__))
    dropped = [("dropped_glb", os.path.join(here, "..", "data", "gltf-tools", "blender-colors.glb")),
               ("dropped_obj", os.path.join(here, "..", "data", "model-tools", "mirror-f.plain.obj"))]
    if args.testdata and os.path.isdir(args.testdata):
        dropped.append(("dropped_gltf", os.path.join(args.testdata, "gltf", "tinygltf", "Cube", "Cube.gltf")))
    for key, model in dropped:
        name = os.path.basename(model)
        if name + ".png" not in images:
            failures.append(f"the dropped {name} gave no picture ({result.get(key)!r})")
            continue
        page_png = os.path.join(args.out, f"web-dropped-{name}.png")
        native_png = os.path.join(args.out, f"native-dropped-{name}.png")
        with open(page_png, "wb") as f:
            f.write(base64.b64decode(images[name + ".png"]))
        page_args = result[key]["args"]
        if result[key].get("lights") != int(LIGHTS):
            failures.append(f"the dropped {name} has {result[key].get('lights')} lights, not the {LIGHTS} the panel chose")
        mode = page_args[page_args.index("--mode") + 1]
        native_render(args.atrium, model, mode, [], native_png)
        psnr = subprocess.run([args.psnr, native_png, page_png], check=True, capture_output=True, text=True).stdout.strip()
        print(f"dropped {name} ({mode}): {psnr} dB against the native build")
        if float(psnr) < MIN_PSNR:
            failures.append(f"the dropped {name}: {psnr} dB against the native build, under {MIN_PSNR}")
    return failures


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--site", required=True)
    parser.add_argument("--atrium", required=True)
    parser.add_argument("--psnr", required=True)
    parser.add_argument("--sponza")
    parser.add_argument("--testdata", help="../shared/testdata: files other tools wrote, which the page may fetch")
    parser.add_argument("--out", default=tempfile.mkdtemp(prefix="atrium-web-"))
    args = parser.parse_args()
    if not os.path.exists(os.path.join(args.site, "atrium.html")):
        sys.exit(f"browser_test: {args.site}/atrium.html is missing: build the page with scripts/build-web.sh")
    os.makedirs(args.out, exist_ok=True)
    results = queue.Queue()
    here = os.path.dirname(os.path.abspath(__file__))
    mounts = {"/checks/": os.path.join(here, "checks"), "/testdata/": os.path.join(here, "..", "data")}
    if args.testdata:
        mounts["/shared/"] = args.testdata
    server = serve(args.site, results, mounts)
    port = server.server_address[1]
    failures = compare(args, port, results, "builtin", "atrium", "atrium", ["--view", "1"])
    if args.sponza and os.path.exists(args.sponza):
        # The nave of scenes/sponza.json, on the model file itself (the page
        # packages it where that scene file looks).
        failures += compare(args, port, results, "sponza", "/assets/sponza/glTF/Sponza.gltf", args.sponza,
                            ["--camera", "-10.5,1.7,-0.25,90,4"])

    # A frame wider than Chromium's window: scaled down to fit, its aspect kept.
    result, _ = page(port, f"layout&size=1920x1080&lights={LIGHTS}&mode=clustered-deferred&pause=1", results)
    failures += check_aspect("wide", result["canvas"])
    if result["canvas"]["shown_width"] > result["canvas"]["window_width"]:
        failures.append(f"wide: the canvas is {result['canvas']['shown_width']:.0f} pixels wide in a "
                        f"{result['canvas']['window_width']}-pixel window")
    # The page's own size in three windows (a narrow one puts the panel below):
    # the frame's aspect within a pixel, and the first frame's time.
    for width, height in ((480, 800), (1024, 700), (1600, 900)):
        tag = f"window {width}x{height}"
        result, _ = page(port, f"layout&pause=1", results, window=(width, height))
        canvas = result["canvas"]
        failures += check_aspect(tag, canvas)
        if abs(canvas["shown_height"] - canvas["shown_width"] * canvas["height"] / canvas["width"]) > 1.0:
            failures.append(f"{tag}: shown {canvas['shown_width']:.1f}x{canvas['shown_height']:.1f}, not the frame's aspect within a pixel")
        if canvas["shown_width"] > canvas["window_width"]:
            failures.append(f"{tag}: the canvas is wider than the window")
        print(f"{tag}: first frame after {result['first_frame_ms'] / 1000:.1f} s ({result['status']})")

    # A bad URL parameter: the message shown, the page running its defaults.
    result, _ = page(port, "layout&lights=-3", results)
    url_message = "--lights expects a whole number from 0 to 1048576, got '-3'"
    if url_message not in result["errors"]:
        failures.append(f"a bad URL parameter showed {result['errors']}, not {url_message!r}")
    if " fps, clustered-deferred, " not in result["status"]:
        failures.append(f"after a bad URL parameter the page says {result['status']!r}, not that it runs its defaults")
    failures += check_page(args, port, results, url_message)
    server.shutdown()
    for failure in failures:
        print("FAILED:", failure)
    print(f"pictures in {args.out}")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
