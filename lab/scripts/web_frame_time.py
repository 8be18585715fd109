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
import json
import os
import subprocess
import sys
import tempfile
import time

CHROMIUM = "/usr/lib/chromium/chromium"  # the binary: Debian's /usr/bin/chromium wrapper drops fds


class DevTools:
    """The DevTools protocol over Chromium's pipe: JSON messages ended by a NUL byte."""

    def __init__(self, profile):
        to_chromium_read, self.to_chromium = os.pipe()
        self.from_chromium, from_chromium_write = os.pipe()

        def wire():  # in the child: the pipe's ends as fds 3 (commands) and 4 (answers)
            read_end, write_end = os.dup(to_chromium_read), os.dup(from_chromium_write)
            os.dup2(read_end, 3)
            os.dup2(write_end, 4)

        args = [CHROMIUM, "--headless", "--disable-gpu", "--remote-debugging-pipe",
                "--user-data-dir=" + profile, "about:blank"]
        if os.getuid() == 0:
            args.insert(2, "--no-sandbox")  # Chromium refuses to run as root with its sandbox
        self.process = subprocess.Popen(args, close_fds=False, preexec_fn=wire,
                                        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        os.close(to_chromium_read)
        os.close(from_chromium_write)
        self.pending = b""
        self.next_id = 0

    def call(self, method, params=None, session=None):
        self.next_id += 1
        message = {"id": self.next_id, "method": method, "params": params or {}}
        if session:
            message["sessionId"] = session
        os.write(self.to_chromium, json.dumps(message).encode() + b"\0")
        while True:
            while b"\0" in self.pending:
                text, self.pending = self.pending.split(b"\0", 1)
                answer = json.loads(text)
                if answer.get("id") == self.next_id:
                    if "error" in answer:
                        sys.exit("web_frame_time: %s: %s" % (method, answer["error"]))
                    return answer["result"]
            chunk = os.read(self.from_chromium, 1 << 20)
            if not chunk:
                sys.exit("web_frame_time: Chromium ended")
            self.pending += chunk

    def evaluate(self, session, expression):
        result = self.call("Runtime.evaluate",
                           {"expression": expression, "returnByValue": True}, session)
        return result["result"].get("value")

    def close(self):
        # Browser.close ends Chromium and its helper processes (a kill would leave them behind).
        closing = {"id": 0, "method": "Browser.close"}
        os.write(self.to_chromium, json.dumps(closing).encode() + b"\0")
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()


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
            target = tools.call("Target.createTarget", {"url": url})["targetId"]
            session = tools.call("Target.attachToTarget",
                                 {"targetId": target, "flatten": True})["sessionId"]
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
