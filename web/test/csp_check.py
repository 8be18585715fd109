#!/usr/bin/env python3
"""Checks a page is served with the Content-Security-Policy and runs under it (scripts/test-web).

usage: web/test/csp_check.py URL POLICY clean
         the page at URL is sent (text/html) with exactly the header
         Content-Security-Policy: POLICY, draws a frame in headless Chromium, and the policy
         blocked nothing on the way (no securitypolicyviolation event: no inline script or style,
         no eval, nothing from another site)
       web/test/csp_check.py URL POLICY blocked
         the same header, and the policy blocked something (web/test/inline.html's inline
         script): the check sees a violation when there is one

Prints what it found; exits 1 saying what is wrong.
"""
import os
import sys
import tempfile
import urllib.request

from devtools import DevTools

# Runs before the page's scripts: records every violation the policy reports.
WATCH = """window.cspViolations = [];
document.addEventListener('securitypolicyviolation', (e) => {
  window.cspViolations.push(e.violatedDirective + ' ' + (e.blockedURI || '(inline)'));
});"""


def main():
    if len(sys.argv) != 4 or sys.argv[3] not in ("clean", "blocked"):
        sys.exit(__doc__.split("\n\n")[1])
    url, policy, expect = sys.argv[1:]
    with urllib.request.urlopen(url, timeout=10) as response:
        sent = response.headers.get_all("Content-Security-Policy") or []
        kind = response.headers.get("Content-Type", "")
    if sent != [policy]:
        sys.exit("csp_check: %s was sent with Content-Security-Policy %s, not [%r]" %
                 (url, sent, policy))
    if not kind.startswith("text/html"):
        sys.exit("csp_check: %s was sent as %r, not text/html" % (url, kind))
    with tempfile.TemporaryDirectory(ignore_cleanup_errors=True) as profile:
        tools = DevTools(profile)
        try:
            session = tools.open_watched(url, WATCH)
            if expect == "clean":
                if not tools.wait_for(session, "document.body && document.body.dataset.frames",
                                      30):
                    sys.exit("csp_check: the page drew no frame in 30 s; violations: %s" %
                             tools.evaluate(session, "window.cspViolations", tolerate=True))
                violations = tools.evaluate(session, "window.cspViolations")
                if violations:
                    sys.exit("csp_check: the policy blocked %s" % violations)
                print("csp_check: %s sent with the policy, drew under it, nothing blocked" % url)
            else:
                violations = tools.wait_for(session, "window.cspViolations && "
                                            "window.cspViolations.length && "
                                            "window.cspViolations", 30)
                if not violations:
                    sys.exit("csp_check: the policy blocked nothing on %s" % url)
                print("csp_check: the policy blocked %s on %s" % (violations, url))
        finally:
            tools.close()


if __name__ == "__main__":
    main()
