#!/usr/bin/env python3
"""The page's gestures played by Chromium's own input pipeline, for scripts/test-web: headless
Chromium driven over its DevTools pipe, the touches sent as a touch screen sends them
(Input.dispatchTouchEvent, with touch emulation on: Chromium makes the touch and pointer events the
page sees), the wheel and the key as a mouse and a keyboard send them (Input.dispatchMouseEvent,
Input.dispatchKeyEvent). Where web/test/input.js makes the DOM events itself, this goes through
what a browser does with a real finger: hit testing, pointer capture, touch-action, coalescing.

usage: web/test/gesture_check.py URL GESTURE OUT.png
         opens URL (the page in orbit mode at a fixed canvas size), waits for its first frame,
         plays GESTURE on the canvas and writes the canvas, once the page has drawn the frame
         after it, as a PNG. GESTURE is one of:
           drag:  one finger at (100, 100) moves 60 pixels right in three steps: the yaw turns
                  30 degrees
           pinch: two fingers at (100, 100) and (200, 100); the second moves to (250, 100): the
                  zoom grows 1.5 times
           wheel: one notch of the wheel towards the screen at (100, 100): the zoom grows 1.1 times
           key:   the key c: the next style (colour to shaded)

Exits 1, saying what the page last said, when a frame does not come within 30 s.
"""
import base64
import sys
import tempfile
import time

from devtools import DevTools

FRAMES = "document.body ? Number(document.body.dataset.frames || 0) : 0"
STATE = ("JSON.stringify({frames: document.body.dataset.frames,"
         " status: document.getElementById('status').textContent})")


def touch(tools, session, kind, points):
    """One touch event; `points` the fingers down after it (x, y, id)."""
    tools.call("Input.dispatchTouchEvent",
               {"type": kind, "touchPoints": [{"x": x, "y": y, "id": finger}
                                              for x, y, finger in points]}, session)


def play(tools, session, gesture):
    if gesture == "drag":
        touch(tools, session, "touchStart", [(100, 100, 1)])
        for x in (120, 140, 160):
            touch(tools, session, "touchMove", [(x, 100, 1)])
        touch(tools, session, "touchEnd", [])
    elif gesture == "pinch":
        touch(tools, session, "touchStart", [(100, 100, 1)])
        touch(tools, session, "touchStart", [(100, 100, 1), (200, 100, 2)])
        touch(tools, session, "touchMove", [(100, 100, 1), (250, 100, 2)])
        touch(tools, session, "touchEnd", [(100, 100, 1)])
        touch(tools, session, "touchEnd", [])
    elif gesture == "wheel":
        tools.call("Input.dispatchMouseEvent", {"type": "mouseWheel", "x": 100, "y": 100,
                                                "deltaX": 0, "deltaY": -100}, session)
    elif gesture == "key":
        for kind in ("keyDown", "keyUp"):
            event = {"type": kind, "key": "c", "code": "KeyC", "windowsVirtualKeyCode": 67}
            if kind == "keyDown":
                event["text"] = "c"
            tools.call("Input.dispatchKeyEvent", event, session)
    else:
        sys.exit(__doc__.split("\n\n")[1])


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__.split("\n\n")[1])
    url, gesture, out = sys.argv[1:]
    with tempfile.TemporaryDirectory(ignore_cleanup_errors=True) as profile:
        tools = DevTools(profile)
        try:
            session = tools.open(url)
            tools.call("Emulation.setTouchEmulationEnabled", {"enabled": True, "maxTouchPoints": 2},
                       session)
            if not tools.wait_for(session, "(%s) > 0" % FRAMES, 30):
                sys.exit("gesture_check: the page drew nothing in 30 s")
            before = tools.evaluate(session, FRAMES)
            play(tools, session, gesture)
            # The frames a gesture asks for are drawn on animation frames: wait until they stop.
            if not tools.wait_for(session, "(%s) > %d" % (FRAMES, before), 30):
                sys.exit("gesture_check: no frame after the %s in 30 s: %s" %
                         (gesture, tools.evaluate(session, STATE)))
            settled = tools.evaluate(session, FRAMES)
            while True:
                time.sleep(0.3)
                now = tools.evaluate(session, FRAMES)
                if now == settled:
                    break
                settled = now
            png = tools.evaluate(session, "document.getElementById('view').toDataURL('image/png')")
            with open(out, "wb") as written:
                written.write(base64.b64decode(png.split(",", 1)[1]))
        finally:
            tools.close()


if __name__ == "__main__":
    main()
