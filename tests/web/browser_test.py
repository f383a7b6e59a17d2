#!/usr/bin/env python3
"""The page in a real browser: headless Chromium (SwiftShader's WebGL2) opens
build-web/site/atrium.html from a server on 127.0.0.1, every mode's picture
comes back from the page (?capture: the page POSTs them with every error it
saw), and each is compared with the native build's compute-free render of the
same options (atrium render --no-compute) by PSNR. The canvas must show the
frame's aspect (a frame wider than the window scaled down to fit), and a bad
URL parameter must show the command line's own one-line message on the page,
where the frame rate would be.

usage: browser_test.py --site DIR --atrium BIN --psnr BIN [--sponza GLTF] [--out DIR]
"""
import argparse
import base64
import os
import queue
import subprocess
import sys
import tempfile

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


def native_render(atrium, scene, mode, options, out):
    subprocess.run([atrium, "render", scene, "--mode", mode, "--size", SIZE, "--lights", LIGHTS, "--no-compute",
                    "--out", out] + options, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


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
    result, console = open_page(port, "capture&" + query, results)
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


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--site", required=True)
    parser.add_argument("--atrium", required=True)
    parser.add_argument("--psnr", required=True)
    parser.add_argument("--sponza")
    parser.add_argument("--out", default=tempfile.mkdtemp(prefix="atrium-web-"))
    args = parser.parse_args()
    if not os.path.exists(os.path.join(args.site, "atrium.html")):
        sys.exit(f"browser_test: {args.site}/atrium.html is missing: build the page with scripts/build-web.sh")
    os.makedirs(args.out, exist_ok=True)
    results = queue.Queue()
    server = serve(args.site, results)
    port = server.server_address[1]
    failures = compare(args, port, results, "builtin", "atrium", "atrium", ["--view", "1"])
    failures += compare(args, port, results, "builtin-gallery", "atrium", "atrium", ["--view", "3"])
    if args.sponza and os.path.exists(args.sponza):
        # The nave of scenes/sponza.json, on the model file itself (the page
        # packages it where that scene file looks).
        failures += compare(args, port, results, "sponza", "/assets/sponza/glTF/Sponza.gltf", args.sponza,
                            ["--camera", "-10.5,1.7,-0.25,90,4"])

    # A frame wider than Chromium's window: scaled down to fit, its aspect kept.
    result, _ = open_page(port, f"layout&size=1920x1080&lights={LIGHTS}&mode=clustered-deferred&pause=1", results)
    failures += check_aspect("wide", result["canvas"])
    if result["canvas"]["shown_width"] > result["canvas"]["window_width"]:
        failures.append(f"wide: the canvas is {result['canvas']['shown_width']:.0f} pixels wide in a "
                        f"{result['canvas']['window_width']}-pixel window")

    result, _ = open_page(port, "capture&mode=deferred-ish", results)
    expected = "unknown mode 'deferred-ish' (modes: forward"
    if not any(error.startswith(expected) for error in result["errors"]):
        failures.append(f"a bad URL parameter showed {result['errors']}, not the line starting {expected!r}")
    if not result["status"].startswith("not started: " + expected):
        failures.append(f"after a bad URL parameter the panel says {result['status']!r}, not that the page did not start")
    server.shutdown()
    for failure in failures:
        print("FAILED:", failure)
    print(f"pictures in {args.out}")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
