#!/usr/bin/env python3
"""Times the web page's draw in headless Chromium (docs/web.md, "Frame time").

usage: lab/scripts/web_frame_time.py PORT [DRAWS]

Opens http://127.0.0.1:PORT/index.html (the page served from build/wasm/web/) in Debian's headless
Chromium, driven over its DevTools pipe (--remote-debugging-pipe: no socket, no package beyond
Python's own library), waits for the first frame, then runs in the page DRAWS (default 300) calls
of octopoint_web_draw at yaw 30, pitch 10, zoom 1 (the view of bench/web_draw_bench.cpp), after 20
to warm up, at 320x240 and 1280x960, and prints the mean milliseconds a draw as measured by the
page's performance.now(). Not under virtual time, which would stop that clock.
"""
import os
import sys
import tempfile
import time

# The DevTools pipe, shared with scripts/test-web's checks.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "web", "test"))
from devtools import DevTools  # noqa: E402

TIMING = """(() => {
  const draw = Module.cwrap('octopoint_web_draw', 'number',
                            ['number', 'number', 'number', 'number', 'number', 'number']);
  for (let i = 0; i < 20; ++i) draw(30000, 10000, 0, 65536, %(w)d, %(h)d);
  const started = performance.now();
  for (let i = 0; i < %(n)d; ++i) {
    if (draw(30000, 10000, 0, 65536, %(w)d, %(h)d) !== 0) return -1;
  }
  return (performance.now() - started) / %(n)d;
})()"""


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit("usage: lab/scripts/web_frame_time.py PORT [DRAWS]")
    port, draws = int(sys.argv[1]), int(sys.argv[2]) if len(sys.argv) == 3 else 300
    with tempfile.TemporaryDirectory(ignore_cleanup_errors=True) as profile:
        tools = DevTools(profile)
        try:
            url = "http://127.0.0.1:%d/index.html?bare=1" % port
            session = tools.open(url)
            for _ in range(300):  # up to 30 s for the first frame
                if tools.evaluate(session, "document.body && document.body.dataset.frames"):
                    break
                time.sleep(0.1)
            else:
                sys.exit("web_frame_time: the page drew no frame in 30 s")
            for width, height in ((320, 240), (1280, 960)):
                mean = tools.evaluate(session, TIMING % {"w": width, "h": height, "n": draws})
                if mean is None or mean < 0:
                    sys.exit("web_frame_time: a draw failed at %dx%d" % (width, height))
                print("web_draw/wasm_chromium/%dx%d %.4f ms (mean of %d)" %
                      (width, height, mean, draws))
        finally:
            tools.close()


if __name__ == "__main__":
    main()
