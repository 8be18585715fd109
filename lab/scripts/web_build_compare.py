#!/usr/bin/env python3
"""Two builds of the web page side by side (docs/web.md, "A SIMD build"): the embedded model's draw
in headless Chromium, one tab, the two pages alternating in every round, and their frames compared
pixel for pixel (the RGBA words the page copies to its canvas, octopoint_web_pixels).

usage: lab/scripts/web_build_compare.py DIR_A DIR_B [ROUNDS [DRAWS]]
  DIR_A, DIR_B: built pages (e.g. build/wasm/web and a build with -msimd128); after
  scripts/build release --target octopoint-serve

Each round draws, in each page in turn, the default model at yaw 30, pitch 10, zoom 1 at
320x240, 640x480 and 1280x960 (web_point_cost.py's timing: 20 draws to warm up, then the fastest
of 10 batches of DRAWS draws, default 20). Prints each round's times and B over A per round and
size, the median ratio (a ratio measured side by side holds on a shared machine where the times do
not) and the ratio of the fastest rounds (the others' load only ever adds time).
"""
import hashlib
import os
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from web_point_cost import (UNTHROTTLED, DevTools, median, serve_page, show,  # noqa: E402
                            stop_serving, timed)

SIZES = ((320, 240), (640, 480), (1280, 960))

# The RGBA bytes of one draw, read out of the page as a JSON array and hashed here (at 320x240:
# 307,200 numbers; a 1280x960 frame would be 4.9 million).
PIXELS = """(() => {
  const draw = Module.cwrap('octopoint_web_draw', 'number',
                            ['number', 'number', 'number', 'number', 'number', 'number']);
  if (draw(30000, 10000, 0, 65536, %(w)d, %(h)d) !== 0) return null;
  const at = Module.ccall('octopoint_web_pixels', 'number', [], []);
  return Array.from(new Uint8Array(Module.HEAPU8.buffer, at, %(w)d * %(h)d * 4));
})()"""


def main():
    if len(sys.argv) not in (3, 4, 5):
        sys.exit(__doc__.split("\n\n")[1])
    dirs = sys.argv[1:3]
    rounds = int(sys.argv[3]) if len(sys.argv) > 3 else 5
    draws = int(sys.argv[4]) if len(sys.argv) > 4 else 20
    servers, logs, pages = [], [], []
    with tempfile.TemporaryDirectory(ignore_cleanup_errors=True) as work:
        tools = None
        try:
            for site in dirs:
                pages.append(serve_page(work, site, servers, logs, 320, 240))
            tools = DevTools(os.path.join(work, "profile"), UNTHROTTLED)
            tab = tools.open("about:blank")
            digests = []
            for page in pages:
                show(tools, tab, page, "document.body.dataset.frames")
                pixels = tools.evaluate(tab, PIXELS % {"w": 320, "h": 240})
                if pixels is None:
                    sys.exit("web_build_compare: a draw failed in %s" % page)
                digests.append(hashlib.sha256(bytes(pixels)).hexdigest())
            times = []  # per round: {(i, w, h): ms}
            for _ in range(rounds):
                times.append({})
                for i, page in enumerate(pages):
                    show(tools, tab, page, "document.body.dataset.frames")
                    for w, h in SIZES:
                        times[-1][(i, w, h)] = timed(tools, tab, w, h, draws)[0]
        finally:
            if tools:
                tools.close()
            stop_serving(servers, logs)
    print("A: %s\nB: %s" % tuple(dirs))
    print("frames at 320x240: %s" % ("identical" if digests[0] == digests[1] else
                                     "DIFFERENT (%s, %s)" % tuple(digests)))
    for w, h in SIZES:
        a = [t[(0, w, h)] for t in times]
        b = [t[(1, w, h)] for t in times]
        ratios = [y / x for x, y in zip(a, b)]
        print("  %dx%d: A %.3f ms [%s], B %.3f ms [%s], B/A %.3f [%s]; fastest rounds' B/A %.3f "
              "(%.3f / %.3f ms)" %
              (w, h, median(a), ", ".join("%.3f" % v for v in a), median(b),
               ", ".join("%.3f" % v for v in b), median(ratios),
               ", ".join("%.3f" % v for v in ratios), min(b) / min(a), min(b), min(a)))
    sys.exit(0 if digests[0] == digests[1] else 1)


if __name__ == "__main__":
    main()
