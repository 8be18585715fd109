#!/usr/bin/env python3
"""Opens the page streaming a chunked model in headless Chromium (over its DevTools pipe, not under
virtual time: a shaped link takes real time) and waits for it (scripts/test-web's streaming checks,
docs/web.md's time to the first picture).

usage: web/test/stream_check.py URL complete OUT.png [SECONDS]
         waits until the page says the view is complete and has drawn it, writes the canvas as a
         PNG, and prints the first picture's and the complete view's times (ms from the request),
         the bytes received, the damaged parts refused and, in walk mode, the points the frame
         drew (walkPoints)
       web/test/stream_check.py URL stopped [SECONDS]
         waits until the page says it stopped asking (a server that kept failing) or that the
         model cannot be read, checks the tab still answers (an animation frame comes), and prints its message
       web/test/stream_check.py URL settled [SECONDS]
         as `stopped`, or until the view is complete: a server that sends the bytes asked for and
         then more gives the page verified chunks before it refuses the rest, so whether its
         requests fail five times in a row before the view is complete depends on how the bytes
         come in; prints the page's state either way

Exits 1, saying what the page last said, when that does not happen within SECONDS (default 30).
"""
import base64
import os
import sys
import tempfile

from devtools import DevTools

STATE = ("JSON.stringify({stream: document.body.dataset.stream, frames: document.body.dataset.frames,"
         " opened: document.body.dataset.opened, first: document.body.dataset.firstPicture,"
         " received: document.body.dataset.received,"
         " refused: document.body.dataset.refused, problem: document.body.dataset.problem,"
         " walkPoints: document.body.dataset.walkPoints})")


def main():
    args = sys.argv[1:]
    if len(args) < 2 or args[1] not in ("complete", "stopped", "settled") or \
            (args[1] == "complete" and len(args) not in (3, 4)) or \
            (args[1] != "complete" and len(args) not in (2, 3)):
        sys.exit(__doc__.split("\n\n")[1])
    url, mode = args[0], args[1]
    seconds = float(args[-1]) if len(args) == (4 if mode == "complete" else 3) else 30.0
    with tempfile.TemporaryDirectory(ignore_cleanup_errors=True) as profile:
        tools = DevTools(profile)
        try:
            session = tools.open(url)
            if mode == "complete":
                done = tools.wait_for(session, "document.body && document.body.dataset.stream === "
                                      "'complete' && performance.now()", seconds)
                if not done:
                    sys.exit("stream_check: not complete in %g s: %s" %
                             (seconds, tools.evaluate(session, STATE)))
                png = tools.evaluate(session, "document.getElementById('view')"
                                     ".toDataURL('image/png')")
                with open(args[2], "wb") as out:
                    out.write(base64.b64decode(png.split(",", 1)[1]))
                state = tools.evaluate(session, STATE)
                print("stream_check: complete at %.0f ms: %s" % (done, state))
            else:
                complete = " || document.body.dataset.stream === 'complete'" \
                    if mode == "settled" else ""
                stopped = tools.wait_for(session, "document.body && ((document.body.dataset.problem"
                                         " || '').startsWith('stopped asking') || document.body."
                                         "dataset.stream === 'failed'" + complete + ") && "
                                         "document.body.dataset.problem", seconds)
                if not stopped:
                    sys.exit("stream_check: did not stop in %g s: %s" %
                             (seconds, tools.evaluate(session, STATE)))
                # The tab still answers: an animation frame comes.
                answered = tools.call("Runtime.evaluate", {
                    "expression": "new Promise((done) => requestAnimationFrame(() => done(1)))",
                    "awaitPromise": True, "returnByValue": True}, session)
                if answered["result"].get("value") != 1:
                    sys.exit("stream_check: the tab no longer answers: %s" %
                             tools.evaluate(session, STATE))
                print("stream_check: %s, the tab still answering: %s" %
                      ("settled" if mode == "settled" else "stopped",
                       tools.evaluate(session, STATE)))
        finally:
            tools.close()


if __name__ == "__main__":
    main()
