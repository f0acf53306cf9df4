#!/usr/bin/env python3
"""Opens a run's report.html in Debian's headless Chromium, as a reader would.

The run's output folder is served on http://127.0.0.1 (a port of its own), and
Chromium loads the page there. The page passes when
  * every request it makes is answered (no figure missing: the server sees a 404),
  * every <img> has loaded with a size (checked inside the browser, from a page
    that holds report.html in a frame of the same origin),
  * Chromium's console shows no error (a script error, a resource refused);
and a screenshot of the whole page is kept beside it, report_screenshot.png.

Usage: scripts/report_in_browser.py OUTPUT_FOLDER [--chromium PATH] [--width PX]
Exit status: 0 the page passed, 1 it did not (each failure on a line), 2 no
Chromium or no report.html (scripts/setup.sh installs Debian's chromium).
"""
import argparse
import functools
import http.server
import os
import re
import shutil
import subprocess
import sys
import tempfile
import threading

# The check page: report.html in a frame of the same origin; once it has loaded, wait until
# every image is complete and write the count and the broken ones into the page, which
# Chromium's --dump-dom prints.
CHECK_PAGE = """<!doctype html><html><body>
<pre id="result">pending</pre>
<iframe id="frame" src="report.html" style="width:1280px;height:2000px"></iframe>
<script>
const frame = document.getElementById("frame");
frame.addEventListener("load", () => {
  const images = Array.from(frame.contentDocument.images);
  const settle = () => {
    if (!images.every(i => i.complete)) { setTimeout(settle, 20); return; }
    const broken = images.filter(i => i.naturalWidth === 0).map(i => i.getAttribute("src"));
    document.getElementById("result").textContent =
        "images " + images.length + " broken " + broken.length + (broken.length ? " " + broken.join(" ") : "");
  };
  settle();
});
</script></body></html>
"""
CHECK_PATH = "/__report_check__.html"


class Handler(http.server.SimpleHTTPRequestHandler):
    """Serves the folder and the check page; remembers every request answered with an error."""

    failed = []  # (path, status), shared by the server's threads

    def do_GET(self):
        if self.path == CHECK_PATH:
            body = CHECK_PAGE.encode()
            self.send_response(200)
            self.send_header("Content-Type", "text/html; charset=utf-8")
            self.send_header("Content-Length", str(len(body)))
            self.end_headers()
            self.wfile.write(body)
            return
        super().do_GET()

    def log_request(self, code="-", size="-"):
        if str(code).isdigit() and int(code) >= 400 and not self.path.endswith("favicon.ico"):
            Handler.failed.append((self.path, int(code)))

    def log_message(self, *args):  # quiet: the failures are reported at the end
        pass


def chromium_command(chromium, profile, extra):
    # The flags a closed network needs (docs of this machine kind): no background connections,
    # no component updates, a fresh profile; root needs --no-sandbox.
    return [chromium, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
            "--disable-background-networking", "--disable-component-update", "--disable-sync",
            "--hide-scrollbars", f"--user-data-dir={profile}", "--virtual-time-budget=20000"] + extra


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder", help="a run's output folder, after `camouflet report`")
    parser.add_argument("--chromium", default=shutil.which("chromium") or "/usr/bin/chromium")
    parser.add_argument("--width", type=int, default=1280, help="window width of the screenshot (px)")
    args = parser.parse_args()
    folder = os.path.abspath(args.folder)
    if not os.path.isfile(os.path.join(folder, "report.html")):
        print(f"report_in_browser: no report.html in {folder} (run `camouflet report` first)")
        return 2
    if not os.access(args.chromium, os.X_OK):
        print(f"report_in_browser: no Chromium at {args.chromium} (scripts/setup.sh installs Debian's chromium)")
        return 2

    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), functools.partial(Handler, directory=folder))
    threading.Thread(target=server.serve_forever, daemon=True).start()
    base = f"http://127.0.0.1:{server.server_address[1]}"
    failures = []
    with tempfile.TemporaryDirectory() as profile:
        # 1. The images, checked in the browser; the console of the page's own load.
        check = subprocess.run(
            chromium_command(chromium=args.chromium, profile=profile,
                             extra=["--enable-logging=stderr", "--v=0", "--dump-dom", base + CHECK_PATH]),
            capture_output=True, text=True, timeout=180)
        found = re.search(r'<pre id="result">([^<]*)</pre>', check.stdout)
        result = found.group(1) if found else "no result"
        print(f"report_in_browser: {result}")
        counted = re.match(r"images (\d+) broken (\d+)", result)
        if not counted:
            failures.append(f"the check page did not finish ({result}); Chromium exit {check.returncode}: "
                            f"{check.stderr.strip()[-400:]}")
        elif int(counted.group(1)) == 0:
            failures.append("the page has no images")
        elif int(counted.group(2)) > 0:
            failures.append(f"images that did not load: {result}")
        for line in check.stderr.splitlines():
            # Console messages of the page: "CONSOLE(...)" lines; an error is logged at level ERROR.
            if "CONSOLE" in line and ("ERROR" in line or "Uncaught" in line or "Failed to load" in line):
                failures.append(f"console: {line.strip()}")
        # 2. The screenshot of the page as a reader sees it, beside it.
        shot = os.path.join(folder, "report_screenshot.png")
        if os.path.exists(shot):
            os.remove(shot)
        run = subprocess.run(
            chromium_command(chromium=args.chromium, profile=profile,
                             extra=[f"--window-size={args.width},6000", f"--screenshot={shot}",
                                    base + "/report.html"]),
            capture_output=True, text=True, timeout=180)
        if not os.path.isfile(shot) or os.path.getsize(shot) == 0:
            failures.append(f"no screenshot written (Chromium exit {run.returncode}: {run.stderr.strip()[-400:]})")
        else:
            print(f"report_in_browser: screenshot {shot}")
    server.shutdown()
    for path, status in Handler.failed:
        failures.append(f"request {path} answered {status}")
    for f in failures:
        print(f"report_in_browser: FAILED: {f}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
