#!/usr/bin/env python3
"""The page's walk mode in headless Chromium, driven over its DevTools pipe with Chromium's own
input (Input.dispatchKeyEvent, Input.dispatchMouseEvent: the events a keyboard and a mouse send),
for scripts/test-web's walk checks.

usage: web/test/walk_check.py URL OUT.png [walk]
         waits for the page's first walk frame (URL starts in walk mode: eye=...), or without one
         presses Tab first; with `walk`, then walks: holds w for 0.4 s, d for 0.2 s, e for 0.2 s,
         drags the mouse 48 pixels right and 20 up, turns the wheel one notch towards the screen
         and holds w for 0.2 s more. Waits for the fine frame once everything is let go, writes
         the canvas as a PNG and prints, on its last line, the options the page says make
         octopoint-render draw that frame (--size WxH --eye X,Y,Z --look Y,P,R --fov F); on the
         line before, the points the overlay says that frame drew (octopoint-render --eye's
         "N points drawn"); on the first line, the eye and look before the walk.

Exits 1, saying what the page last said, when a frame does not come within 30 s.
"""
import base64
import sys
import tempfile
import time

from devtools import DevTools

# The options of the page's last fine walk frame ('' while a key is held), once it has drawn one.
WALK = "document.body && document.body.dataset.walk"
STATE = ("JSON.stringify({walk: document.body.dataset.walk, frames: document.body.dataset.frames,"
         " status: document.getElementById('status').textContent})")
# The DevTools key events of a key by its name: (key, code, Windows virtual key code).
KEYS = {"Tab": ("Tab", "Tab", 9), "w": ("w", "KeyW", 87), "d": ("d", "KeyD", 68),
        "e": ("e", "KeyE", 69)}


def key(tools, session, name, kind):
    value, code, virtual = KEYS[name]
    event = {"type": kind, "key": value, "code": code, "windowsVirtualKeyCode": virtual}
    if kind == "keyDown" and len(value) == 1:
        event["text"] = value
    tools.call("Input.dispatchKeyEvent", event, session)


def hold(tools, session, name, seconds):
    key(tools, session, name, "keyDown")
    time.sleep(seconds)
    key(tools, session, name, "keyUp")


def mouse(tools, session, kind, x, y, **more):
    tools.call("Input.dispatchMouseEvent", {"type": kind, "x": x, "y": y, **more}, session)


def fine_frame(tools, session, after):
    """Waits for a fine walk frame drawn after frame number `after`; its options."""
    said = tools.wait_for(session, "%s && Number(document.body.dataset.frames) > %d && %s" %
                          (WALK, after, WALK), 30)
    if not said:
        sys.exit("walk_check: no walk frame in 30 s: %s" % tools.evaluate(session, STATE))
    return said


def frames(tools, session):
    return int(tools.evaluate(session, "document.body.dataset.frames || '0'"))


def main():
    args = sys.argv[1:]
    if len(args) not in (2, 3) or (len(args) == 3 and args[2] != "walk"):
        sys.exit(__doc__.split("\n\n")[1])
    url, out = args[0], args[1]
    with tempfile.TemporaryDirectory(ignore_cleanup_errors=True) as profile:
        tools = DevTools(profile)
        try:
            session = tools.open(url)
            if not tools.wait_for(session, "document.body && Number(document.body.dataset.frames"
                                  " || 0) > 0", 30):
                sys.exit("walk_check: the page drew nothing in 30 s")
            if not tools.evaluate(session, WALK):
                count = frames(tools, session)
                key(tools, session, "Tab", "keyDown")
                key(tools, session, "Tab", "keyUp")
                fine_frame(tools, session, count)
            before = tools.evaluate(session, WALK)
            if len(args) == 3:
                hold(tools, session, "w", 0.4)
                hold(tools, session, "d", 0.2)
                hold(tools, session, "e", 0.2)
                mouse(tools, session, "mousePressed", 100, 100, button="left", clickCount=1)
                for step in range(1, 5):
                    mouse(tools, session, "mouseMoved", 100 + 12 * step, 100 - 5 * step,
                          button="left", buttons=1)
                    time.sleep(0.02)
                mouse(tools, session, "mouseReleased", 148, 80, button="left", clickCount=1)
                mouse(tools, session, "mouseWheel", 148, 80, deltaX=0, deltaY=-100)
                hold(tools, session, "w", 0.2)
            # The frame after the last event: fine, nothing held.
            time.sleep(0.1)
            said = fine_frame(tools, session, frames(tools, session) - 1)
            png = tools.evaluate(session, "document.getElementById('view').toDataURL('image/png')")
            points = tools.evaluate(session, "document.body.dataset.walkPoints")
            with open(out, "wb") as written:
                written.write(base64.b64decode(png.split(",", 1)[1]))
            print(before)
            print(points)
            print(said)
        finally:
            tools.close()


if __name__ == "__main__":
    main()
