#!/usr/bin/env python3
"""A static server that misbehaves on purpose, for scripts/test-web's checks of the page streaming a
chunked model (docs/web.md, "Streaming"): it serves a folder (the page and the models) with byte
ranges, the page's content types and its Content-Security-Policy, and, for requests of ranges of
*.oct files, does one wrong thing:

  --damage-once      flips the last byte of the first answer reaching past the first 4096 bytes
                     (the last byte of the last chunk or record table asked for, whose CRC-32 then
                     fails): once; later answers are right (the page must refuse it and ask again)
  --whole-file       answers 200 with the whole file instead of 206 (a server ignoring ranges)
  --endless          answers 206 with the right headers and body, then sends zeros for ever
  --short            answers 206 with the right headers and half the body, then closes
  --wrong-range      answers a range past the head (the file's first bytes come right, so the
                     page has a model to draw) with 206 and the bytes one further on, saying so in
                     its Content-Range: not the bytes asked for (the page must refuse them)

usage: web/test/hostile_server.py DIR MODE   (prints "port N" once it listens on 127.0.0.1)
"""
import http.server
import os
import re
import sys
import threading

TYPES = {".html": "text/html; charset=utf-8", ".js": "text/javascript", ".css": "text/css",
         ".wasm": "application/wasm", ".oct": "application/octet-stream", ".png": "image/png"}
POLICY = ("default-src 'self'; script-src 'self' 'wasm-unsafe-eval'; style-src 'self'; "
          "img-src 'self' data:; object-src 'none'; base-uri 'none'; frame-ancestors 'self'")


def make_handler(folder, mode):
    state = {"damaged": False}
    lock = threading.Lock()

    class Handler(http.server.BaseHTTPRequestHandler):
        protocol_version = "HTTP/1.1"

        def log_message(self, *args):
            pass

        def do_GET(self):
            name = os.path.basename(self.path.split("?")[0]) or "index.html"
            path = os.path.join(folder, name)
            if not os.path.isfile(path):
                self.send_error(404)
                return
            with open(path, "rb") as f:
                data = f.read()
            asked = re.fullmatch(r"bytes=(\d+)-(\d+)", self.headers.get("Range", ""))
            if not name.endswith(".oct") or asked is None:
                self.answer(200, name, data, {})
                return
            first, last = int(asked.group(1)), min(int(asked.group(2)), len(data) - 1)
            body = bytearray(data[first:last + 1])
            ranged = {"Content-Range": "bytes %d-%d/%d" % (first, last, len(data))}
            if mode == "--whole-file":
                self.answer(200, name, data, {})
            elif mode == "--endless":
                self.send_response(206)
                self.send_header("Content-Range", ranged["Content-Range"])
                self.send_header("Content-Type", TYPES[".oct"])
                self.send_header("Connection", "close")  # no length: the body runs to the close
                self.end_headers()
                try:
                    self.wfile.write(body)
                    while True:
                        self.wfile.write(bytes(65536))
                except OSError:
                    pass
                self.close_connection = True
            elif mode == "--wrong-range" and first > 0:
                first, last = first + 1, min(last + 1, len(data) - 1)
                self.answer(206, name, data[first:last + 1],
                            {"Content-Range": "bytes %d-%d/%d" % (first, last, len(data))})
            elif mode == "--short":
                self.send_response(206)
                self.send_header("Content-Range", ranged["Content-Range"])
                self.send_header("Content-Length", str(len(body)))
                self.send_header("Connection", "close")
                self.end_headers()
                self.wfile.write(body[:len(body) // 2])
                self.close_connection = True
            else:
                with lock:
                    if mode == "--damage-once" and not state["damaged"] and last >= 4096:
                        state["damaged"] = True
                        body[-1] ^= 0x5A
                        sys.stderr.write("hostile_server: damaged byte %d\n" % last)
                self.answer(206, name, bytes(body), ranged)

        def answer(self, status, name, body, headers):
            self.send_response(status)
            self.send_header("Content-Type", TYPES.get(os.path.splitext(name)[1], "text/plain"))
            self.send_header("Content-Length", str(len(body)))
            self.send_header("Content-Security-Policy", POLICY)
            self.send_header("Cache-Control", "no-store")
            for key, value in headers.items():
                self.send_header(key, value)
            self.end_headers()
            self.wfile.write(body)

    return Handler


def main():
    modes = ("--damage-once", "--whole-file", "--endless", "--short", "--wrong-range")
    if len(sys.argv) != 3 or sys.argv[2] not in modes:
        sys.exit("usage: web/test/hostile_server.py DIR " + "|".join(modes))
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0),
                                             make_handler(sys.argv[1], sys.argv[2]))
    server.daemon_threads = True
    print("port %d" % server.server_address[1], flush=True)
    server.serve_forever()


if __name__ == "__main__":
    main()
