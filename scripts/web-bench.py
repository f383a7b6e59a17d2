#!/usr/bin/env python3
"""Frame times of every mode in the browser (the WebAssembly page in headless
Chromium, SwiftShader's WebGL2) beside the native build's compute-free and full
tiers on this machine's GL, same scene, view, size and light count: a Markdown
table for docs/benchmarks.md. Each frame is drawn and waited for (glFinish) on
both sides; the figures are medians, as atrium bench reports them.

usage: scripts/web-bench.py [--scene atrium] [--view 1] [--size 320x180] [--lights 1024] [--frames 10]
"""
import argparse
import csv
import os
import queue
import subprocess
import sys
import tempfile

root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
sys.path.insert(0, os.path.join(root, "web"))
from page_driver import open_page, serve  # noqa: E402


def native(atrium, args, extra):
    """atrium bench's median frame time per mode (ms)."""
    with tempfile.NamedTemporaryFile(suffix=".csv") as table:
        subprocess.run([atrium, "bench", args.scene, "--views", str(args.view), "--size", args.size, "--lights",
                        str(args.lights), "--frames", str(args.frames), "--warmup", "3", "--frame-limit", "100000",
                        "--csv", table.name] + extra, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        with open(table.name) as f:
            return {row["mode"]: float(row["median_ms"]) for row in csv.DictReader(f)}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--scene", default="atrium")
    parser.add_argument("--view", type=int, default=1)
    parser.add_argument("--size", default="320x180")
    parser.add_argument("--lights", type=int, default=1024)
    parser.add_argument("--frames", type=int, default=10)
    parser.add_argument("--atrium", default=os.path.join(root, "build", "atrium"))
    parser.add_argument("--site", default=os.path.join(root, "build-web", "site"))
    args = parser.parse_args()
    page_scene = {"atrium": "atrium"}.get(args.scene, "/assets/sponza/glTF/Sponza.gltf")
    results = queue.Queue()
    server = serve(args.site, results)
    query = (f"bench={args.frames}&scene={page_scene}&view={args.view}&size={args.size}&lights={args.lights}&pause=1")
    page, console = open_page(server.server_address[1], query, results, timeout=1800)
    server.shutdown()
    if page["errors"] or not page["bench"]:
        sys.exit(f"web-bench: the page reported {page['errors']} {console}")
    free = native(args.atrium, args, ["--no-compute"])
    full = native(args.atrium, args, [])
    print(f"Scene {args.scene}, view {args.view}, {args.size}, {args.lights} lights, median of {args.frames} frames "
          f"after 3 (ms per frame); browser: headless Chromium, {page['renderer']}")
    print()
    print("| mode | browser (WebGL2, compute-free) | native compute-free tier | native full tier |")
    print("|---|---:|---:|---:|")
    for mode, ms in page["bench"].items():
        print(f"| {mode} | {ms:.1f} | {free.get(mode, float('nan')):.1f} | {full.get(mode, float('nan')):.1f} |")


if __name__ == "__main__":
    main()
