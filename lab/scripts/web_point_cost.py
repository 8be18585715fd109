#!/usr/bin/env python3
"""The web page's frame time in Potree's terms (docs/web.md, "Frame time per point"): nanoseconds per
drawn point and a fixed cost per frame, at 640x480 and 1280x960.

usage: lab/scripts/web_point_cost.py PORT MODEL.oct [DRAWS]

Opens http://127.0.0.1:PORT/index.html?model=MODEL.oct (the page and a chunked model served by
octopoint-serve) in Debian's headless Chromium over its DevTools pipe (web/test/devtools.py), waits
until the whole view has arrived, then for each size and each point budget (10,000, 20,000,
40,000, none) times DRAWS (default 200) calls of octopoint_web_draw at yaw 30, pitch 10, zoom 1
after 20 to warm up (performance.now() in the page; the draw: frame clear, progressive draw,
resolve and RGBA copy, not the canvas's putImageData), reads the points each drew, and fits
time = fixed + per_point * points by least squares over the budgets.
"""
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "web", "test"))
from devtools import DevTools  # noqa: E402

TIMING = """(() => {
  const draw = Module.cwrap('octopoint_web_draw', 'number',
                            ['number', 'number', 'number', 'number', 'number', 'number']);
  Module.ccall('octopoint_web_set_point_budget', 'number', ['number'], [%(budget)d]);
  for (let i = 0; i < 20; ++i) draw(30000, 10000, 0, 65536, %(w)d, %(h)d);
  const started = performance.now();
  for (let i = 0; i < %(n)d; ++i) {
    if (draw(30000, 10000, 0, 65536, %(w)d, %(h)d) !== 0) return [-1, 0];
  }
  const ms = (performance.now() - started) / %(n)d;
  const words = new Uint32Array(Module.HEAPU8.buffer,
                                Module.ccall('octopoint_web_stream_status', 'number', [], []), 11);
  return [ms, words[10]];
})()"""


def fit(samples):
    """Least squares of ms = fixed + per_point * points: (fixed ms, ns per point)."""
    n = len(samples)
    mean_p = sum(p for p, _ in samples) / n
    mean_t = sum(t for _, t in samples) / n
    slope = sum((p - mean_p) * (t - mean_t) for p, t in samples) / \
        sum((p - mean_p) ** 2 for p, _ in samples)
    return mean_t - slope * mean_p, slope * 1e6


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit("usage: lab/scripts/web_point_cost.py PORT MODEL.oct [DRAWS]")
    port, model = int(sys.argv[1]), sys.argv[2]
    draws = int(sys.argv[3]) if len(sys.argv) == 4 else 200
    with tempfile.TemporaryDirectory(ignore_cleanup_errors=True) as profile:
        tools = DevTools(profile)
        try:
            session = tools.open("http://127.0.0.1:%d/index.html?model=%s&yaw=30&pitch=10&w=1280"
                                 "&h=960&bare=1" % (port, model))
            if not tools.wait_for(session, "document.body && document.body.dataset.stream === "
                                  "'complete'", 60):
                sys.exit("web_point_cost: the view did not arrive in 60 s")
            for width, height in ((640, 480), (1280, 960)):
                samples = []
                for budget in (10000, 20000, 40000, 0):
                    ms, points = tools.evaluate(session, TIMING % {
                        "budget": budget, "w": width, "h": height, "n": draws})
                    if ms < 0:
                        sys.exit("web_point_cost: a draw failed at %dx%d" % (width, height))
                    samples.append((points, ms))
                    print("web_point_cost/%dx%d budget %d: %d points, %.4f ms (mean of %d)" %
                          (width, height, budget, points, ms, draws))
                fixed, per_point = fit(samples)
                print("web_point_cost/%dx%d: %.3f ms a frame + %.2f ns a point" %
                      (width, height, fixed, per_point))
        finally:
            tools.close()


if __name__ == "__main__":
    main()
