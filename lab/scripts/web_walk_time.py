#!/usr/bin/env python3
"""The web page's draw times in headless Chromium, of pages served at the URLs given, round after
round in one tab (docs/web.md, "Walk mode"): the orbit view (yaw 30, pitch 10, zoom 1, 320x240 and
1280x960), and, where the page has walk mode, the walk's fine and coarse frames from the eye at the
table's edge (eye 0.05,0.1,-0.45, look -5,-20, fov 70: tests/paths/table_walk.json's first key)
at 320x240 and 1280x960. Each time is the fastest of 10 batches of 10 draws after 5 to warm up
(performance.now() in the page; the module's draw, resolve and RGBA copy, not putImageData); the
median over the rounds is printed, each round's in brackets. A URL with a query naming a chunked
model (`index.html?model=NAME.oct`) streams it first, until the page says the view is complete,
and times the same draws of the model it then holds (the walk's: its held parts).

usage: lab/scripts/web_walk_time.py ROUNDS URL... (each the page's index.html on a server)
"""
import os
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "web", "test"))
from devtools import DevTools  # noqa: E402

UNTHROTTLED = ("--disable-renderer-backgrounding", "--disable-background-timer-throttling",
               "--disable-backgrounding-occluded-windows")
SIZES = ((320, 240), (1280, 960))

# [orbit ms, walk fine ms, walk coarse ms] at w x h; -1 where the page has no walk mode.
TIMING = """(() => {
  const best = (draw) => {
    for (let i = 0; i < 5; ++i) draw();
    let ms = Infinity;
    for (let batch = 0; batch < 10; ++batch) {
      const started = performance.now();
      for (let i = 0; i < 10; ++i) if (draw() !== 0) return -2;
      ms = Math.min(ms, (performance.now() - started) / 10);
    }
    return ms;
  };
  const orbit = best(() => Module._octopoint_web_draw(30000, 10000, 0, 65536, %(w)d, %(h)d));
  const walk = window.octopointWalk(Module);
  if (!walk.ready()) return [orbit, -1, -1];
  if (walk.place('0.05,0.1,-0.45', '-5,-20', '70') !== '') return [orbit, -2, -2];
  const fine = best(() => Module._octopoint_web_walk_draw(%(w)d, %(h)d, 0, 0, 0, 0, 0, 0, 0));
  const coarse = best(() => Module._octopoint_web_walk_draw(%(w)d, %(h)d, 1, 0, 0, 0, 0, 0, 0));
  return [orbit, fine, coarse];
})()"""


def median(values):
    ordered = sorted(values)
    middle = len(ordered) // 2
    return ordered[middle] if len(ordered) % 2 else (ordered[middle - 1] + ordered[middle]) / 2


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__.split("\n\n")[1])
    rounds, urls = int(sys.argv[1]), sys.argv[2:]
    samples = {}  # (url, size, what) -> [ms of each round]
    with tempfile.TemporaryDirectory(ignore_cleanup_errors=True) as profile:
        tools = DevTools(profile, UNTHROTTLED)
        try:
            tab = tools.open("about:blank")
            for _ in range(rounds):
                for url in urls:
                    tools.evaluate(tab, "window.leftBehind = true")
                    streamed = "model=" in url
                    tools.call("Page.navigate", {"url": url + ("&" if "?" in url else "?") +
                                                 "w=320&h=240&bare=1"}, tab)
                    if not tools.wait_for(tab, "!window.leftBehind && document.body && " +
                                          ("document.body.dataset.stream === 'complete'"
                                           if streamed else "document.body.dataset.frames"), 60):
                        sys.exit("web_walk_time: %s drew nothing in 60 s" % url)
                    for w, h in SIZES:
                        times = tools.evaluate(tab, TIMING % {"w": w, "h": h})
                        if min(times) < -1:
                            sys.exit("web_walk_time: a draw failed in %s at %dx%d" % (url, w, h))
                        for what, ms in zip(("orbit", "walk fine", "walk coarse"), times):
                            if ms >= 0:
                                samples.setdefault((url, "%dx%d" % (w, h), what), []).append(ms)
        finally:
            tools.close()
    for (url, size, what), times in samples.items():
        print("%s %s %s: %.3f ms [%s]" % (url, size, what, median(times),
                                          ", ".join("%.3f" % t for t in times)))


if __name__ == "__main__":
    main()
