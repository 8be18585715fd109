"""Headless Chromium driven over its DevTools pipe (--remote-debugging-pipe: no socket, no package
beyond Python's own library), for the web page's checks and measurements (scripts/test-web's
streaming checks, web/test/stream_check.py, web/test/csp_check.py; lab/scripts/web_*.py)."""
import json
import os
import subprocess
import sys
import time

CHROMIUM = "/usr/lib/chromium/chromium"  # the binary: Debian's /usr/bin/chromium wrapper drops fds


class DevTools:
    """The DevTools protocol over Chromium's pipe: JSON messages ended by a NUL byte."""

    def __init__(self, profile, extra_args=()):
        to_chromium_read, self.to_chromium = os.pipe()
        self.from_chromium, from_chromium_write = os.pipe()

        def wire():  # in the child: the pipe's ends as fds 3 (commands) and 4 (answers)
            read_end, write_end = os.dup(to_chromium_read), os.dup(from_chromium_write)
            os.dup2(read_end, 3)
            os.dup2(write_end, 4)

        args = [CHROMIUM, "--headless", "--disable-gpu", "--remote-debugging-pipe",
                "--user-data-dir=" + profile, *extra_args, "about:blank"]
        if os.getuid() == 0:
            args.insert(2, "--no-sandbox")  # Chromium refuses to run as root with its sandbox
        self.process = subprocess.Popen(args, close_fds=False, preexec_fn=wire,
                                        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        os.close(to_chromium_read)
        os.close(from_chromium_write)
        self.pending = b""
        self.next_id = 0

    def call(self, method, params=None, session=None, tolerate=False):
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
                    if "error" in answer and tolerate:
                        return None
                    if "error" in answer:
                        sys.exit("devtools: %s: %s" % (method, answer["error"]))
                    return answer["result"]
            chunk = os.read(self.from_chromium, 1 << 20)
            if not chunk:
                sys.exit("devtools: Chromium ended")
            self.pending += chunk

    def evaluate(self, session, expression, tolerate=False):
        """The expression's value; with `tolerate`, None when it cannot be evaluated (yet)."""
        result = self.call("Runtime.evaluate",
                           {"expression": expression, "returnByValue": True}, session, tolerate)
        return None if result is None else result["result"].get("value")

    def close(self):
        # Browser.close ends Chromium and its helper processes (a kill would leave them behind).
        closing = {"id": 0, "method": "Browser.close"}
        os.write(self.to_chromium, json.dumps(closing).encode() + b"\0")
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()

    def open(self, url):
        """Opens `url` in a new tab; returns the session to evaluate in."""
        target = self.call("Target.createTarget", {"url": url})["targetId"]
        return self.call("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]

    def open_watched(self, url, script):
        """Opens `url` in a new tab that runs `script` first, before any of the page's own (and
        whatever the page's Content-Security-Policy says); returns the session."""
        target = self.call("Target.createTarget", {"url": "about:blank"})["targetId"]
        session = self.call("Target.attachToTarget", {"targetId": target, "flatten": True})[
            "sessionId"]
        self.call("Page.enable", {}, session)
        self.call("Page.addScriptToEvaluateOnNewDocument", {"source": script}, session)
        self.call("Page.navigate", {"url": url}, session)
        return session

    def wait_for(self, session, expression, seconds):
        """Evaluates `expression` every 50 ms until it is true; its last value (false at timeout)."""
        deadline = time.monotonic() + seconds
        while True:
            value = self.evaluate(session, expression, tolerate=True)
            if value or time.monotonic() > deadline:
                return value
            time.sleep(0.05)
