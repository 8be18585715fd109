#!/usr/bin/env python3
"""Time to the web page's first picture (docs/web.md, "Time to the first picture").

usage: lab/scripts/web_first_picture.py URL [RUNS]

Opens URL (e.g. the page served by octopoint-serve on loopback, drawing its embedded model) RUNS
times (default 5), each in a new headless Chromium with an empty profile (nothing cached), and
prints the ms to its first picture on the canvas (the page's data-first-frame, web/octopoint.js)
from the navigation's start (performance.now's origin: it includes the new tab's and the
network's start-up in the browser) and from the page's request (the navigation's requestStart:
when the request for the HTML went out).
"""
import os
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "web",
                                "test"))
from devtools import DevTools  # noqa: E402


def main():
    if len(sys.argv) not in (2, 3):
        sys.exit(__doc__.split("\n\n")[1])
    url, runs = sys.argv[1], int(sys.argv[2]) if len(sys.argv) == 3 else 5
    times = []
    for _ in range(runs):
        with tempfile.TemporaryDirectory(ignore_cleanup_errors=True) as profile:
            tools = DevTools(profile)
            try:
                session = tools.open(url)
                first = tools.wait_for(session, "document.body && "
                                       "document.body.dataset.firstFrame", 30)
                if not first:
                    sys.exit("web_first_picture: no picture in 30 s")
                sent = tools.evaluate(session, "performance.getEntriesByType('navigation')[0]"
                                      ".requestStart")
                times.append((float(first), float(first) - sent))
            finally:
                tools.close()
    for label, k in (("the navigation's start", 0), ("the page's request", 1)):
        ms = sorted(t[k] for t in times)
        print("web_first_picture: from %s to the first picture: %s ms (median %.1f ms)" %
              (label, ", ".join("%.1f" % t[k] for t in times), ms[len(ms) // 2]))


if __name__ == "__main__":
    main()
