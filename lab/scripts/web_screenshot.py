#!/usr/bin/env python3
"""A screenshot of the web page with its overlay, in real time (docs/web.md's picture,
docs/images/web_page.png): under Chromium's --screenshot the page runs in virtual time, where the
overlay's frame time reads 0.0 ms.

usage: lab/scripts/web_screenshot.py URL WIDTH HEIGHT OUT.png
  e.g. with octopoint-serve serving build/wasm/web/ and a chunked model beside it:
       lab/scripts/web_screenshot.py \\
         'http://127.0.0.1:PORT/index.html?model=tabletop.oct&yaw=30&pitch=10&zoom=1.5' 800 500 \\
         docs/images/web_page.png

Opens URL in headless Chromium (web/test/devtools.py) in a window of WIDTH x HEIGHT CSS pixels at
a device pixel ratio of 1, waits until the page has drawn and, when it streams a model, until its
view is complete (up to 60 s), then draws once more (so that the overlay says the time of a draw
of the whole view) and writes the page as a PNG.
"""
import base64
import os
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "web",
                                "test"))
from devtools import DevTools  # noqa: E402

READY = ("document.body && document.body.dataset.frames && (!new URLSearchParams(location.search)"
         ".get('model') || document.body.dataset.stream === 'complete')")


def main():
    if len(sys.argv) != 5:
        sys.exit(__doc__.split("\n\n")[1])
    url, width, height, out = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
    with tempfile.TemporaryDirectory(ignore_cleanup_errors=True) as profile:
        tools = DevTools(profile)
        try:
            session = tools.open("about:blank")
            tools.call("Emulation.setDeviceMetricsOverride", {
                "width": width, "height": height, "deviceScaleFactor": 1, "mobile": False},
                session)
            tools.call("Page.navigate", {"url": url}, session)
            if not tools.wait_for(session, READY, 60):
                sys.exit("web_screenshot: the page did not finish drawing in 60 s")
            # One more draw of the whole view, by the page's own resize path.
            tools.evaluate(session, "window.dispatchEvent(new Event('resize')), 1")
            time.sleep(0.5)
            shot = tools.call("Page.captureScreenshot", {"format": "png"}, session)
            with open(out, "wb") as png:
                png.write(base64.b64decode(shot["data"]))
            print("web_screenshot: %s (%dx%d)" % (out, width, height))
        finally:
            tools.close()


if __name__ == "__main__":
    main()
