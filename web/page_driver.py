"""Opening the WebAssembly page (build-web/site) in headless Chromium: a server
on 127.0.0.1 serves it and takes what the page POSTs back (?capture: every
mode's picture; ?bench=N: every mode's frame time). Used by
tests/web/browser_test.py and scripts/web-bench.py.

Chromium 156 headless with --use-angle=swiftshader --enable-unsafe-swiftshader
gives WebGL2 on SwiftShader; it needs --no-sandbox when run as root, and
--disable-dev-shm-usage keeps it off a container's small /dev/shm.
"""
import http.server
import os
import json
import queue
import shutil
import subprocess
import sys
import tempfile
import threading


def serve(site, results, mounts=None):
    """A server for `site` that puts each POSTed JSON body on `results`;
    `mounts` maps URL prefixes ("/checks/") to folders served beside it."""
    mounts = mounts or {}

    class Handler(http.server.SimpleHTTPRequestHandler):
        def __init__(self, *args, **kwargs):
            super().__init__(*args, directory=site, **kwargs)

        def translate_path(self, path):
            for prefix, folder in mounts.items():
                if path.startswith(prefix):
                    relative = path[len(prefix):].split("?", 1)[0]
                    full = os.path.realpath(os.path.join(folder, relative))
                    if full.startswith(os.path.realpath(folder) + os.sep):
                        return full
            return super().translate_path(path)

        def do_POST(self):
            body = self.rfile.read(int(self.headers["Content-Length"]))
            results.put(json.loads(body))
            self.send_response(204)
            self.end_headers()

        def log_message(self, *args):
            pass

    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), Handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server


def open_page(port, query, results, timeout=180, window=None):
    """What the page at ?QUERY POSTs (capture, bench, layout or a check), with
    Chromium's console errors; `window` is the window's (width, height)."""
    profile = tempfile.mkdtemp(prefix="atrium-chromium-")
    url = f"http://127.0.0.1:{port}/atrium.html?{query}"
    size = [f"--window-size={window[0]},{window[1]}"] if window else []
    chromium = subprocess.Popen(
        ["chromium", "--headless=new", "--use-angle=swiftshader", "--enable-unsafe-swiftshader", "--no-sandbox",
         "--no-first-run", "--disable-extensions", "--disable-dev-shm-usage", "--enable-logging=stderr", "--v=0",
         f"--user-data-dir={profile}"] + size + [url],
        stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    try:
        result = results.get(timeout=timeout)
    except queue.Empty:
        result = None
    chromium.kill()
    _, log = chromium.communicate()
    shutil.rmtree(profile, ignore_errors=True)
    if result is None:
        sys.exit(f"browser_test: no result from {url} within {timeout} s\n{log[-3000:]}")
    console = [line for line in log.splitlines() if "CONSOLE" in line and ("ERROR" in line or "Uncaught" in line)]
    return result, console
