// Streams a chunked model into the page (docs/web.md, "Streaming"): fetches the byte ranges the
// module asks for (web/octopoint_web.h, octopoint_web_stream_next: the native client's order for
// the view of the last draw), a few at once, and hands it every piece of a body as it arrives; the
// module checks every byte as the native renderer does and draws what it holds. Nothing the server
// says is trusted: a status other than 206, a Content-Range other than the bytes asked for, a body
// longer than asked (an endless one) or shorter, a stall, are each one failed request; the page
// asks again after a back-off and, after a few failures in a row, stops asking and keeps drawing
// what it has, saying why. A damaged chunk is refused by the module and asked for again.
'use strict';

(function () {
  const kInFlight = 2;  // requests at once: the native client's two connections
  const kStallMs = 10000;  // no byte for this long: the request is given up (the native 10 s)
  const kGiveUpAfter = 5;  // failed requests in a row before the page stops asking
  const kFirstBackoffMs = 100;  // then doubling, up to kLastBackoffMs (the native client's)
  const kLastBackoffMs = 2000;

  // Opens `url` (same origin) in the module `Module`: `changed()` after every piece that arrived
  // (draw again), `say(text, isError)` for what went wrong. Returns {pump, stop, status}.
  window.octopointStream = function (Module, url, changed, say) {
    const c = {
      next: Module.cwrap('octopoint_web_stream_next', 'number', []),
      request: Module.cwrap('octopoint_web_stream_request', 'number', []),
      input: Module.cwrap('octopoint_web_input', 'number', ['number']),
      receive: Module.cwrap('octopoint_web_stream_receive', 'number', ['number', 'number']),
      end: Module.cwrap('octopoint_web_stream_end', 'number', ['number']),
      status: Module.cwrap('octopoint_web_stream_status', 'number', []),
      error: () => Module.UTF8ToString(Module.ccall('octopoint_web_error', 'number', [], [])),
    };
    let inFlight = 0;
    let failures = 0;  // in a row
    let backoff = 0;
    let retryTimer = null;
    let stopped = false;
    const controllers = new Set();

    // One request: its body handed to the module piece by piece. Resolves with '' when all of it
    // came, else with what went wrong.
    async function fetchRange(id, offset, size) {
      const controller = new AbortController();
      controllers.add(controller);
      let stall = window.setTimeout(() => controller.abort(), kStallMs);
      const last = offset + size - 1;
      let got = 0;
      try {
        const response = await fetch(url, {
          headers: {Range: 'bytes=' + offset + '-' + last},
          cache: 'no-store',
          signal: controller.signal,
        });
        if (response.status !== 206) {
          controller.abort();  // not the body: a whole file, or an error page
          return response.status === 200 ?
              'the server answered 200 (the whole file) instead of 206 (the bytes asked for): ' +
              'it does not serve byte ranges' :
              'the server answered ' + response.status + ' ' + response.statusText;
        }
        const said = response.headers.get('Content-Range') || '';
        const range = /^bytes (\d+)-(\d+)\/(\d+)$/.exec(said);
        // The bytes asked for, or (the head's first request) cut at the file's end.
        if (range === null || Number(range[1]) !== offset ||
            !(Number(range[2]) === last ||
              (Number(range[2]) < last && Number(range[2]) + 1 === Number(range[3])))) {
          controller.abort();
          return 'the server answered Content-Range "' + said + '" for bytes ' + offset + '-' +
                 last;
        }
        const reader = response.body.getReader();
        for (;;) {
          const piece = await reader.read();
          if (piece.done) return '';
          window.clearTimeout(stall);
          stall = window.setTimeout(() => controller.abort(), kStallMs);
          const bytes = piece.value;
          if (bytes.length === 0) continue;
          got += bytes.length;
          // The module's memory may grow (and move) in octopoint_web_input: HEAPU8 after it.
          const room = c.input(bytes.length);
          if (room === 0) return c.error();
          Module.HEAPU8.set(bytes, room);
          const taken = c.receive(id, bytes.length);
          if (taken < 0) {
            controller.abort();
            return c.error();
          }
          if (taken === 1) say(c.error() + ': asked for again', true);
          changed();
        }
      } catch (error) {
        if (controller.signal.aborted) return 'no byte came for ' + kStallMs / 1000 + ' s';
        return got > 0 ? 'the body broke off after ' + got + ' of the ' + size + ' bytes asked for' :
                         'the request failed: ' + error.message;
      } finally {
        window.clearTimeout(stall);
        controllers.delete(controller);
      }
    }

    function finished(id, problem) {
      --inFlight;
      const ended = c.end(id);
      if (problem === '' && ended !== 0) problem = c.error();
      if (stopped) return;
      if (problem === '') {
        failures = 0;
        backoff = 0;
      } else {
        ++failures;
        if (failures >= kGiveUpAfter) {
          stop();
          say('stopped asking after ' + failures + ' failed requests in a row (last: ' + problem +
              '); drawing what arrived', true);
          return;
        }
        backoff = Math.min(kLastBackoffMs, Math.max(kFirstBackoffMs, backoff * 2));
        say(problem + '; asking again in ' + backoff + ' ms', true);
        retryTimer = window.setTimeout(() => {
          retryTimer = null;
          pump();
        }, backoff);
      }
      changed();
      pump();
    }

    // Makes the requests the module wants now, up to kInFlight at once (called after every draw:
    // a new view asks for its own chunks first).
    function pump() {
      while (!stopped && retryTimer === null && inFlight < kInFlight) {
        const id = c.next();
        if (id < 0) {
          stop();
          say(c.error(), true);
          return;
        }
        if (id === 0) return;
        const words = new Uint32Array(Module.HEAPU8.buffer, c.request(), 3);
        const offset = words[0] + words[1] * 4294967296;
        const size = words[2];
        ++inFlight;
        fetchRange(id, offset, size).then((problem) => finished(id, problem));
      }
    }

    function stop() {
      stopped = true;
      if (retryTimer !== null) window.clearTimeout(retryTimer);
      retryTimer = null;
      for (const controller of controllers) controller.abort();
    }

    // The module's ten words (octopoint_web_stream_status), named.
    function status() {
      const at = c.status();
      if (at === 0) return null;
      const w = new Uint32Array(Module.HEAPU8.buffer, at, 10);
      return {
        state: ['', 'waiting for the head', 'drawing', 'failed'][w[0]],
        received: w[1] + w[2] * 4294967296,
        fileBytes: w[3] + w[4] * 4294967296,
        held: w[5],
        pending: w[6],
        complete: w[7] === 1,
        refused: w[8],
        inFlight: w[9],
        stopped: stopped,
      };
    }

    return {pump: pump, stop: stop, status: status};
  };
})();
