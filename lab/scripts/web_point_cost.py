#!/usr/bin/env python3
"""The web page's frame time, in one run (docs/web.md, "Frame time"): the page's draw of the
embedded model in headless Chromium beside the same draw compiled natively with fixed_fast and
fixed_simd (bench/web_draw_bench.cpp) at 320x240 and 1280x960, and, in Potree's terms, the
page's nanoseconds per drawn point and fixed cost per frame at 640x480 and 1280x960.

usage: lab/scripts/web_point_cost.py [ROUNDS [DRAWS [PAGE...]]]
  (after scripts/build-web and scripts/build release --target octopoint-prepare octopoint-render
   octopoint-serve web_draw_bench)
  PAGE: a built page's folder (default build/wasm/web); with two or more (e.g. a copy of the page
  before a change and build/wasm/web after it) each round measures every page in turn, and the
  pages are compared round by round (a ratio measured side by side holds on a shared machine where
  the times do not).

Points per frame are varied at a fixed splat size: the default model's scan (as docs/streaming.md
prepares it, depths 6..8) thinned by space (lab/scripts/thinned_scan.py: whole depth-4 cells of the
same cube kept, fractions 1/4 to 1), each prepared --chunked; a model whose depth auto would not
draw depth 8 (too thin to count as densely sampled), or whose depth 8 stores a sample reach over one
footprint (wider splats), is left out. ROUNDS times (default 3), each
round: the native benchmark (the fastest of 10 repetitions); in one tab of headless Chromium
(web/test/devtools.py, the DevTools pipe), for each page, the page from octopoint-serve, its
embedded model drawn at 320x240 and 1280x960 (and the page's putImageData of the frame to its
canvas timed alone, with and without a copy into an ImageData of its own first); then each thinned
model streamed into the same tab until its view is complete and drawn at 640x480 and 1280x960.
Each page time is the fastest of 10 batches of DRAWS draws (default 20) after 20 to warm up, yaw
30, pitch 10, zoom 1 (performance.now() in the page; the draw: frame clear, draw and the resolve
into RGBA, not the canvas's putImageData). The fastest, on
both sides: on a shared machine the others' load only ever adds time. The fit
time = fixed + per_point * points is least squares over every round's sample, printed with its
residuals (root mean square and largest), each round's own fit and the fit of each model's fastest
round.
"""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "web", "test"))
sys.path.insert(0, HERE)
from devtools import DevTools  # noqa: E402
from thinned_scan import read_pcd, thin, write_pcd  # noqa: E402

TOOLS = os.path.join(ROOT, "build", "release", "tools")
BENCH = os.path.join(ROOT, "build", "release", "bench", "web_draw_bench")
SCAN = os.path.join(ROOT, "data", "scans", "milk_cartoon_all_small_clorox.pcd")
CROP = "-0.35,-0.25,-1.1,0.35,0.45,-0.45"  # docs/streaming.md's tabletop
FRACTIONS = (0.25, 0.375, 0.5, 0.625, 0.75, 0.875, 1.0)
EMBEDDED_SIZES = ((320, 240), (1280, 960))
FIT_SIZES = ((640, 480), (1280, 960))
BATCHES = 10
# The page's renderer runs as a tab in front (headless Chromium otherwise may lower its priority:
# on a loaded machine its draws then take many times longer).
UNTHROTTLED = ("--disable-renderer-backgrounding", "--disable-background-timer-throttling",
               "--disable-backgrounding-occluded-windows")

# Draws of the page's model (the embedded one, or the streamed one of its tab) at yaw 30, pitch 10,
# zoom 1: 20 to warm up, then BATCHES batches of DRAWS; [the fastest batch's mean ms, points the
# last draw drew (0 for the embedded model)]. The fastest batch: on a shared machine the others'
# load only ever adds time.
TIMING = """(() => {
  const draw = Module.cwrap('octopoint_web_draw', 'number',
                            ['number', 'number', 'number', 'number', 'number', 'number']);
  for (let i = 0; i < 20; ++i) draw(30000, 10000, 0, 65536, %(w)d, %(h)d);
  let ms = Infinity;
  for (let batch = 0; batch < %(batches)d; ++batch) {
    const started = performance.now();
    for (let i = 0; i < %(n)d; ++i) {
      if (draw(30000, 10000, 0, 65536, %(w)d, %(h)d) !== 0) return [-1, 0];
    }
    ms = Math.min(ms, (performance.now() - started) / %(n)d);
  }
  const status = Module.ccall('octopoint_web_stream_status', 'number', [], []);
  return [ms, status === 0 ? 0 : new Uint32Array(Module.HEAPU8.buffer, status, 11)[10]];
})()"""


# The rest of the page's frame (web/octopoint.js's draw), at the size of the last draw: the
# module's RGBA put into the page's canvas (putImageData) from an ImageData over the module's
# memory, as the page does, and, as it did before, copied into an ImageData of its own first; the
# fastest batch's mean ms of each.
CANVAS_COPY = """(() => {
  const w = %(w)d, h = %(h)d;
  const canvas = document.querySelector('canvas');
  canvas.width = w;
  canvas.height = h;
  const context = canvas.getContext('2d');
  const at = Module.ccall('octopoint_web_pixels', 'number', [], []);
  const own = new ImageData(w, h);
  const over = new ImageData(new Uint8ClampedArray(Module.HEAPU8.buffer, at, w * h * 4), w, h);
  let put = Infinity, copied = Infinity;
  for (let batch = 0; batch < %(batches)d; ++batch) {
    let started = performance.now();
    for (let i = 0; i < %(n)d; ++i) context.putImageData(over, 0, 0);
    put = Math.min(put, (performance.now() - started) / %(n)d);
    started = performance.now();
    for (let i = 0; i < %(n)d; ++i) {
      own.data.set(new Uint8Array(Module.HEAPU8.buffer, at, w * h * 4));
      context.putImageData(own, 0, 0);
    }
    copied = Math.min(copied, (performance.now() - started) / %(n)d);
  }
  return [put, copied];
})()"""


def run(*args):
    return subprocess.run(args, check=True, capture_output=True, text=True).stdout


def prepare(scan, out, name):
    run(os.path.join(TOOLS, "octopoint-prepare"), scan, "-o", out, "--name", name, "--axes",
        "y-up", "--crop", CROP, "--depths", "6..8", "--chunked")
    return os.path.join(out, name + ".oct")


def thinned_models(work):
    """{fraction: path of its chunked model}, each drawing depth 8 at 640x480."""
    whole = prepare(SCAN, os.path.join(work, "whole"), "tabletop")
    info = run(os.path.join(TOOLS, "octopoint-render"), "--file", whole, "--info")
    corner, edge = re.search(r"^cube (\S+) (\S+)$", info, re.M).groups()
    cube = [float(v) for v in corner.split(",")] + [float(edge)]
    points = read_pcd(SCAN)
    box = [float(v) for v in CROP.split(",")]
    models = {}
    for fraction in FRACTIONS:
        if fraction == 1.0:
            model = whole
        else:
            scan = os.path.join(work, "thin%g.pcd" % fraction)
            write_pcd(scan, thin(points, fraction, box, cube))
            model = prepare(scan, os.path.join(work, "thin%g" % fraction), "tabletop")
        said = run(os.path.join(TOOLS, "octopoint-render"), "--file", model, "--yaw", "30",
                   "--pitch", "10", "--size", "640x480", "-o", os.path.join(work, "check.png"))
        if ", depth 8," not in said:
            print("web_point_cost: fraction %g left out (%s)" % (fraction, said.strip()))
            continue
        # A depth whose measured sample reach is over one footprint draws wider splats
        # (docs/splats.md): its frame costs more a point, and is left out of a fit at one size.
        info = run(os.path.join(TOOLS, "octopoint-render"), "--file", model, "--info")
        reach = re.search(r"^depth 8: .*sample reach (\S+) footprints$", info, re.M).group(1)
        if reach != "1.00":
            print("web_point_cost: fraction %g left out (its depth 8 has a sample reach of %s "
                  "footprints)" % (fraction, reach))
            continue
        models[fraction] = model
    return models


def native_round():
    """{(variant, w, h): ms}, the fastest of BATCHES repetitions of bench/web_draw_bench."""
    out = json.loads(run(BENCH, "--benchmark_format=json",
                         "--benchmark_repetitions=%d" % BATCHES))
    times = {}
    for bench in out["benchmarks"]:
        if bench.get("run_type") != "iteration":
            continue  # the aggregates
        _, variant, size = bench["run_name"].split("/")
        w, h = (int(v) for v in size.split("x"))
        key = (variant, w, h)
        times[key] = min(times.get(key, bench["real_time"]), bench["real_time"])  # ms
    return times


def fit(samples):
    """Least squares of ms = fixed + per_point * points: fixed ms, ns a point, residuals (ms)."""
    n = len(samples)
    mean_p = sum(p for p, _ in samples) / n
    mean_t = sum(t for _, t in samples) / n
    slope = sum((p - mean_p) * (t - mean_t) for p, t in samples) / \
        sum((p - mean_p) ** 2 for p, _ in samples)
    fixed = mean_t - slope * mean_p
    residuals = [t - fixed - slope * p for p, t in samples]
    return fixed, slope * 1e6, residuals


def show(tools, tab, url, ready):
    """Opens `url` in the tab (one tab for all: Chromium slows a tab in the background) and waits
    until `ready` holds in it (up to 60 s)."""
    tools.evaluate(tab, "window.leftBehind = true")  # marks the document navigated away from
    tools.call("Page.navigate", {"url": url}, tab)
    if not tools.wait_for(tab, "!window.leftBehind && document.body && (%s)" % ready, 60):
        sys.exit("web_point_cost: %s not ready in 60 s" % url)


def timed(tools, tab, w, h, draws):
    """TIMING's [ms, points] in the tab."""
    ms, points = tools.evaluate(tab, TIMING % {"w": w, "h": h, "n": draws, "batches": BATCHES})
    if ms < 0:
        sys.exit("web_point_cost: a draw failed at %dx%d in %s" %
                 (w, h, tools.evaluate(tab, "location.href")))
    return ms, points


def served_port(log):
    """The port octopoint-serve says it serves at (it says so first, within 10 s)."""
    for _ in range(100):
        log.seek(0)
        said = re.search(r"http://127\.0\.0\.1:(\d+)/", log.read())
        if said:
            return int(said.group(1))
        time.sleep(0.1)
    sys.exit("web_point_cost: octopoint-serve did not say its port")


def serve_page(work, site, servers, logs, width, height):
    """Serves `site` by octopoint-serve on a free port (its process and log appended to `servers`
    and `logs`, for stop_serving) and returns the address of its page at yaw 30, pitch 10 and
    width x height, bare."""
    log = open(os.path.join(work, "serve%d.log" % len(logs)), "w+")
    logs.append(log)
    servers.append(subprocess.Popen([os.path.join(TOOLS, "octopoint-serve"), site, "--port", "0"],
                                    stdout=log, stderr=subprocess.STDOUT))
    return "http://127.0.0.1:%d/index.html?yaw=30&pitch=10&w=%d&h=%d&bare=1" % (
        served_port(log), width, height)


def stop_serving(servers, logs):
    for server in servers:
        server.terminate()
        server.wait()
    for log in logs:
        log.close()


def median(values):
    ordered = sorted(values)
    return ordered[len(ordered) // 2] if len(ordered) % 2 else \
        (ordered[len(ordered) // 2 - 1] + ordered[len(ordered) // 2]) / 2


def fit_lines(rows, rounds):
    """The fits of one page's (round, points, ms) samples at one size, as printed lines."""
    fixed, per_point, residuals = fit([(p, t) for _, p, t in rows])
    rms = (sum(e * e for e in residuals) / len(residuals)) ** 0.5
    lines = ["fit over %d samples: %.3f ms a frame + %.2f ns a drawn point; residuals %.3f ms rms, "
             "%.3f ms at most" % (len(rows), fixed, per_point, rms,
                                  max(abs(e) for e in residuals))]
    for r in range(rounds):
        fixed, per_point, _ = fit([(p, t) for q, p, t in rows if q == r])
        lines.append("  round %d alone: %.3f ms + %.2f ns a point" % (r + 1, fixed, per_point))
    fastest = {}
    for _, points, ms in rows:
        fastest[points] = min(ms, fastest.get(points, ms))
    fixed, per_point, residuals = fit(sorted(fastest.items()))
    lines.append("  each model's fastest round: %.3f ms + %.2f ns a point, residuals %.3f ms rms" %
                 (fixed, per_point, (sum(e * e for e in residuals) / len(residuals)) ** 0.5))
    return lines


def listed(values, form):
    return ", ".join(form % v for v in values)


def main():
    if len(sys.argv) > 1 and not sys.argv[1].isdigit() or \
            len(sys.argv) > 2 and not sys.argv[2].isdigit():
        sys.exit(__doc__.split("\n\n")[1])
    rounds = int(sys.argv[1]) if len(sys.argv) > 1 else 3
    draws = int(sys.argv[2]) if len(sys.argv) > 2 else 20
    dirs = sys.argv[3:] or [os.path.join(ROOT, "build", "wasm", "web")]
    for folder in dirs:
        if not os.path.isfile(os.path.join(folder, "octopoint_web.wasm")):
            sys.exit("web_point_cost: no built page in %s" % folder)
    servers, logs, pages = [], [], []
    with tempfile.TemporaryDirectory(ignore_cleanup_errors=True) as work:
        models = thinned_models(work)
        tools = None
        try:
            for i, folder in enumerate(dirs):
                site = os.path.join(work, "site%d" % i)
                shutil.copytree(folder, site)
                for fraction, model in models.items():
                    shutil.copy(model, os.path.join(site, "thin%g.oct" % fraction))
                pages.append(serve_page(work, site, servers, logs, 1280, 960))
            tools = DevTools(os.path.join(work, "profile"), UNTHROTTLED)
            tab = tools.open("about:blank")
            native = []
            page_ms = [[] for _ in pages]  # per page, per round: {(w, h): ms}
            copy_ms = [[] for _ in pages]  # the same, of the copy to the canvas
            samples = [{size: [] for size in FIT_SIZES} for _ in pages]
            for r in range(rounds):
                native.append(native_round())
                for i, page in enumerate(pages):
                    page_ms[i].append({})
                    copy_ms[i].append({})
                    show(tools, tab, page, "document.body.dataset.frames")
                    for w, h in EMBEDDED_SIZES:
                        page_ms[i][r][(w, h)] = timed(tools, tab, w, h, draws)[0]
                        copy_ms[i][r][(w, h)] = tools.evaluate(tab, CANVAS_COPY % {
                            "w": w, "h": h, "n": draws, "batches": BATCHES})
                    for fraction in models:
                        show(tools, tab, page + "&model=thin%g.oct" % fraction,
                             "document.body.dataset.stream === 'complete'")
                        for w, h in FIT_SIZES:
                            ms, points = timed(tools, tab, w, h, draws)
                            samples[i][(w, h)].append((r, points, ms))
        finally:
            if tools:
                tools.close()
            stop_serving(servers, logs)
    for i, folder in enumerate(dirs):
        print("Page %s: %s" % ("AB"[i] if len(dirs) <= 2 else str(i + 1), folder))
    print("Embedded model (62,502 points), yaw 30, pitch 10, zoom 1; ms a frame (the fastest "
          "batch), median of %d rounds (each round's in brackets); wasm in Chromium over native "
          "fixed_fast per round; putImageData to the canvas alone (without and with a copy "
          "first):" % rounds)
    for w, h in EMBEDDED_SIZES:
        fast = [n[("fixed_fast", w, h)] for n in native]
        simd = [n[("fixed_simd", w, h)] for n in native]
        print("  %dx%d: native fixed_fast %.3f [%s], fixed_simd %.3f [%s]" %
              (w, h, median(fast), listed(fast, "%.3f"), median(simd), listed(simd, "%.3f")))
        for i in range(len(pages)):
            wasm = [p[(w, h)] for p in page_ms[i]]
            put = [p[(w, h)][0] for p in copy_ms[i]]
            copied = [p[(w, h)][1] for p in copy_ms[i]]
            ratios = [a / b for a, b in zip(wasm, fast)]
            print("    page %d: wasm %.3f [%s], wasm/fixed_fast %.2fx [%s]; putImageData %.3f [%s], "
                  "after a copy %.3f [%s]" %
                  (i + 1, median(wasm), listed(wasm, "%.3f"), median(ratios),
                   listed(ratios, "%.2f"), median(put), listed(put, "%.3f"), median(copied),
                   listed(copied, "%.3f")))
            if i > 0:
                first = [p[(w, h)] for p in page_ms[0]]
                versus = [b / a for a, b in zip(first, wasm)]
                print("    page %d / page 1: %.3f [%s]; fastest rounds' %.3f" %
                      (i + 1, median(versus), listed(versus, "%.3f"), min(wasm) / min(first)))
    print("Thinned models (%s), wasm in Chromium, the fastest of %d batches of %d draws each:" %
          (", ".join("%g" % f for f in models), BATCHES, draws))
    for w, h in FIT_SIZES:
        for i in range(len(pages)):
            rows = samples[i][(w, h)]
            for r, points, ms in rows:
                print("  page %d %dx%d round %d: %6d points %.4f ms" % (i + 1, w, h, r + 1, points,
                                                                       ms))
            for line in fit_lines(rows, rounds):
                print("  page %d %dx%d %s" % (i + 1, w, h, line))
            if i > 0:
                versus = [b[2] / a[2] for a, b in zip(samples[0][(w, h)], rows)]
                print("  page %d / page 1 %dx%d, sample by sample: median %.3f [%.3f to %.3f]" %
                      (i + 1, w, h, median(versus), min(versus), max(versus)))


if __name__ == "__main__":
    main()
