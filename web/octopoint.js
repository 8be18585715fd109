// The page: reads the view from the address (the meaning of octopoint-render's --yaw, --pitch,
// --roll, --zoom, --size and --style), draws the embedded model with the integer renderer compiled
// to WebAssembly (web/octopoint_web.cpp), or a chunked model from the same server as it arrives
// (model=NAME.oct or the model field; web/octopoint_stream.js fetches it), follows the window's
// size when the address gives none, and shows the frame time, and for a chunked model the bytes
// received and the chunks pending, in an overlay. Tab switches to walk mode and back
// (web/octopoint_walk.js; eye, look and fov in the address: octopoint-render's --eye, --look,
// --fov). Input is web/octopoint_input.js's.
'use strict';

(function () {
  const canvas = document.getElementById('view');
  const status = document.getElementById('status');
  const styleMenu = document.getElementById('style');
  const budgetMenu = document.getElementById('budget');
  const modelForm = document.getElementById('open');
  const modelField = document.getElementById('model');
  const params = new URLSearchParams(window.location.search);
  // octopoint-render's --style names, in its order (the c key steps through them, as the viewer's).
  const kStyles = ['colour', 'shaded', 'lines', 'toon', 'outlined'];
  // The page's largest side: a square of it is octopoint-render's most pixels (16777216).
  const kMaxSide = 4096;
  // emscripten's loader (octopoint_web.js, loaded after this file) takes this object as its
  // Module and calls onRuntimeInitialized once the wasm is compiled.
  const Module = {};
  window.Module = Module;

  let problem = '';  // a message about the address, kept in the overlay
  function report(text, isError) {
    status.textContent = text;
    status.className = isError ? 'error' : '';
  }

  // A number from the address within [low, high], else the default (and a message).
  function numberParam(name, fallback, low, high) {
    const text = params.get(name);
    if (text === null || text === '') return fallback;
    const value = Number(text);
    if (!Number.isFinite(value) || value < low || value > high) {
      problem = name + '=' + text + ' is not a number in ' + low + '..' + high + ': using ' +
                fallback;
      report(problem, true);
      return fallback;
    }
    return value;
  }

  // C's llround, which octopoint-render's option parsing uses: halves away from zero.
  function roundAway(x) {
    return x < 0 ? -Math.round(-x) : Math.round(x);
  }

  const view = {
    yaw: numberParam('yaw', 0, -1e6, 1e6),
    pitch: numberParam('pitch', 0, -1e6, 1e6),
    roll: numberParam('roll', 0, -1e6, 1e6),
    zoom: numberParam('zoom', 1, 1 / 65536, 32767),
    style: 'colour',
  };
  // The size: w and h (both, as octopoint-render's --size WxH) fix it; without them the canvas
  // follows the window, in device pixels (the window's CSS size times devicePixelRatio).
  const fixed = params.has('w') || params.has('h');
  const fixedWidth = Math.trunc(numberParam('w', 320, 1, kMaxSide));
  const fixedHeight = Math.trunc(numberParam('h', 240, 1, kMaxSide));
  if (params.has('style')) {
    if (kStyles.includes(params.get('style'))) {
      view.style = params.get('style');
    } else {
      problem = 'style=' + params.get('style') + ' is not one of ' + kStyles.join(', ') +
                ': using colour';
      report(problem, true);
    }
  }
  // A chunked model's point budget (octopoint-render's --point-budget; 0: none), from the menu's
  // choices (the b key steps through them).
  const kBudgets = Array.from(budgetMenu.options, (option) => Number(option.value));
  view.budget = Math.trunc(numberParam('budget', 0, 0, 2147483647));
  document.body.classList.add(fixed ? 'fixed' : 'fit');
  if (params.get('bare') === '1') document.body.classList.add('bare');

  // The frame's size in pixels, and the canvas's size on the page in CSS pixels.
  function frameSize() {
    if (fixed) return {width: fixedWidth, height: fixedHeight, css: null};
    const ratio = window.devicePixelRatio || 1;
    const cssWidth = Math.max(1, document.documentElement.clientWidth);
    const cssHeight = Math.max(1, document.documentElement.clientHeight);
    return {
      width: Math.max(1, Math.min(kMaxSide, Math.round(cssWidth * ratio))),
      height: Math.max(1, Math.min(kMaxSide, Math.round(cssHeight * ratio))),
      css: {width: cssWidth, height: cssHeight},
    };
  }

  let api = null;
  let pending = false;
  let image = null;  // the last frame's pixels in the module's memory, reused while they stay
  let stream = null;  // the chunked model's fetching (web/octopoint_stream.js), once one is open
  let streamProblem = '';  // what its server did wrong, kept in the overlay
  let walk = null;  // walk mode (web/octopoint_walk.js), where the module has it
  // The address's eye=, look=, fov= for a streamed model: placed when its head has come.
  let eyeToPlace = null;

  function kilobytes(bytes) {
    return (bytes / 1000).toFixed(1) + ' kB';
  }

  // The overlay's words about the chunked model: bytes received, chunks pending, what went wrong.
  function streamWords() {
    const now = stream.status();
    if (now === null) return '';
    let words = modelField.value + ': ' + kilobytes(now.received) +
                (now.fileBytes > 0 ? ' of ' + kilobytes(now.fileBytes) : '') + ' received, ';
    if (now.state !== 'drawing') words += now.state;
    else if (now.complete) words += 'view complete';
    else words += now.pending + ' chunks pending';
    if (now.refused > 0) words += ', ' + now.refused + ' damaged parts refused';
    // For the checks (scripts/test-web): the state, the bytes, the refusals, the server's fault.
    document.body.dataset.stream = now.complete ? 'complete' : now.state;
    document.body.dataset.received = String(now.received);
    document.body.dataset.refused = String(now.refused);
    document.body.dataset.problem = streamProblem;
    document.body.dataset.pending = String(now.pending);
    return words + (streamProblem ? ' (' + streamProblem + ')' : '') + '. ';
  }

  function walking() {
    return walk !== null && walk.active ? walk : null;
  }

  // The overlay's words about the eye and the points the frame drew (octopoint-render --eye's
  // "N points drawn"), and for the checks (scripts/test-web) the options that make octopoint-render
  // draw the same frame and its points (a fine frame: nothing held).
  function walkWords(size) {
    const now = walk.state();
    const options = '--size ' + size.width + 'x' + size.height + ' --eye ' + now.eye +
                    ' --look ' + now.look + ' --fov ' + now.fovText;
    document.body.dataset.walk = walk.moving() ? '' : options;
    document.body.dataset.walkPoints = String(now.points);
    return 'walk: ' + options + ', speed ' + now.speed.toPrecision(3) + ' units/s, ' +
           now.points.toLocaleString('en') + ' points drawn: ';
  }

  // Walk mode from the address's eye, once there is a model to walk in; '' or what is wrong.
  function placeEye(asked) {
    const wrong = walk === null ? 'eye: this page has no walk mode' :
                                  walk.place(asked.eye, asked.look, asked.fov);
    if (wrong === '') walk.active = true;
    else report(problem = wrong + ': the orbit view', true);
    return wrong;
  }

  function draw() {
    pending = false;
    if (eyeToPlace !== null && (walk === null || walk.ready())) {
      placeEye(eyeToPlace);
      eyeToPlace = null;
    }
    const size = frameSize();
    const started = performance.now();
    const walker = walking();
    const failed = walker !== null ? walker.draw(size.width, size.height)
                                   : api.draw(roundAway(view.yaw * 1000),
                                              roundAway(view.pitch * 1000),
                                              roundAway(view.roll * 1000),
                                              Math.round(view.zoom * 65536), size.width,
                                              size.height);
    if (failed !== 0) {
      const why = api.error();
      if (stream !== null) {
        report(streamWords() + why, streamProblem !== '');
        stream.pump();  // the view the module's order follows is this draw's
      } else if (document.body.classList.contains('without-model')) {
        report(why, false);  // no model opened yet: what to do, not an error
      } else {
        report('draw refused: ' + why, true);
      }
      return;
    }
    const bytes = size.width * size.height * 4;
    // An image over the module's own pixels (putImageData copies them: no copy of our own), made
    // anew when they move: another size, or the module's memory grown (a new buffer).
    const at = api.pixels();
    if (image === null || image.data.buffer !== Module.HEAPU8.buffer ||
        image.data.byteOffset !== at || image.width !== size.width ||
        image.height !== size.height) {
      image = new ImageData(new Uint8ClampedArray(Module.HEAPU8.buffer, at, bytes), size.width,
                            size.height);
    }
    if (canvas.width !== size.width) canvas.width = size.width;
    if (canvas.height !== size.height) canvas.height = size.height;
    if (size.css !== null) {
      canvas.style.width = size.css.width + 'px';
      canvas.style.height = size.css.height + 'px';
    }
    canvas.getContext('2d').putImageData(image, 0, 0);
    const elapsed = performance.now() - started;
    let streamed = '';
    if (stream !== null) {
      stream.pump();  // a new view asks for its own chunks first
      streamed = streamWords();
      // For the checks and measurements (scripts/test-web): when the first picture of the model
      // was shown, in ms from the page's request (performance.now's origin).
      if (!('firstPicture' in document.body.dataset))
        document.body.dataset.firstPicture = performance.now().toFixed(1);
    }
    if (walker !== null) {
      const words = walkWords(size);
      if (!document.body.classList.contains('bare')) {
        report((problem ? problem + '. ' : '') + words + elapsed.toFixed(1) + ' ms a frame',
               problem !== '');
      }
      if (walker.moving()) requestDraw();  // a held key walks on: the next frame
    } else {
      delete document.body.dataset.walk;
    }
    if (walker === null && !document.body.classList.contains('bare')) {
      report((problem ? problem + '. ' : '') + streamed + 'yaw ' +
             view.yaw.toFixed(1) + ', pitch ' +
             view.pitch.toFixed(1) + ', zoom ' + view.zoom.toFixed(3) + ', ' + view.style +
             ', ' + size.width + 'x' + size.height + ': ' + elapsed.toFixed(1) + ' ms a frame',
             problem !== '' || streamProblem !== '');
    }
    // For the measurements (lab/scripts/web_first_picture.py): when the page's first picture was
    // shown, in ms from the page's request.
    if (!('firstFrame' in document.body.dataset))
      document.body.dataset.firstFrame = performance.now().toFixed(1);
    document.body.dataset.frames = String(Number(document.body.dataset.frames || 0) + 1);
  }

  function requestDraw() {
    if (pending || api === null) return;
    pending = true;
    window.requestAnimationFrame(draw);
  }

  // The address follows the view, so that a link shows it (replaceState: no history entry a move).
  function rememberView() {
    params.set('yaw', view.yaw.toFixed(2));
    params.set('pitch', view.pitch.toFixed(2));
    params.set('zoom', view.zoom.toFixed(4));
    if (view.style === 'colour') params.delete('style'); else params.set('style', view.style);
    if (view.budget === 0) params.delete('budget'); else params.set('budget', String(view.budget));
    if (stream === null) params.delete('model'); else params.set('model', modelField.value);
    const walker = walking();
    if (walker === null) {
      ['eye', 'look', 'fov'].forEach((name) => params.delete(name));
    } else {
      const now = walker.state();
      params.set('eye', now.eye);
      params.set('look', now.look);
      params.set('fov', now.fovText);
    }
    window.history.replaceState(null, '', '?' + params.toString());
  }

  // Takes a style by name (the menu, a key, the address); false when the renderer refused it.
  function setStyle(name) {
    if (api !== null && api.setStyle(name) !== 0) {
      report('style ' + name + ' refused: ' + api.error(), true);
      styleMenu.value = view.style;
      return false;
    }
    view.style = name;
    styleMenu.value = name;
    return true;
  }

  // The point budget of a chunked model's frames (0: none).
  function setBudget(points) {
    view.budget = points;
    if (!kBudgets.includes(points)) {
      const option = document.createElement('option');
      option.value = String(points);
      option.textContent = points.toLocaleString('en') + ' points';
      budgetMenu.appendChild(option);
      kBudgets.push(points);
    }
    budgetMenu.value = String(points);
    if (api !== null) api.setBudget(points);
  }

  // Opens a chunked model by its address on this server (a name beside the page, or a path):
  // from now on the page draws it, coarse to fine as it arrives.
  function openModel(name) {
    const url = new URL(name, window.location.href);
    if (url.origin !== window.location.origin) {
      report('model=' + name + ': only a model on this server can be opened', true);
      return;
    }
    if (stream !== null) stream.stop();
    if (walking() !== null) walk.leave();  // another model: another cube, another eye
    if (walk !== null) walk.forget();
    modelField.value = name;
    streamProblem = '';
    setStyle('colour');  // a chunked model stores no normals: colour only
    Module.ccall('octopoint_web_stream_open', 'number', [], []);
    api.setBudget(view.budget);
    stream = window.octopointStream(Module, url.href, requestDraw, (text, isError) => {
      streamProblem = isError ? text : '';
      requestDraw();
    });
    document.body.dataset.stream = 'waiting for the head';
    document.body.dataset.opened = performance.now().toFixed(1);  // for the time to first picture
    rememberView();
    requestDraw();
  }

  // Tab: walk mode (the eye where octopoint-render --perspective puts it for the orbit view) and
  // back to the orbit view.
  function toggleWalk() {
    if (walk === null || !walk.ready()) {
      report('walk mode: ' + (walk === null ? 'this page has none' :
                              stream !== null ? "the model's head has not come yet" :
                                                'this page has no model with its place in the scan'),
             true);
      return;
    }
    if (walk.active) {
      walk.leave();
    } else {
      const size = frameSize();
      if (!walk.enter(view, size.width, size.height)) report('walk mode: ' + api.error(), true);
    }
    delete document.body.dataset.walk;
    rememberView();
    requestDraw();
  }

  function onKey(key) {
    if (key === 'Tab') {
      toggleWalk();
      return true;
    }
    if (key === 'b') {
      setBudget(kBudgets[(kBudgets.indexOf(view.budget) + 1) % kBudgets.length]);
      rememberView();
      requestDraw();
      return true;
    }
    let name = null;
    if (key === 'c') name = kStyles[(kStyles.indexOf(view.style) + 1) % kStyles.length];
    if (key >= '1' && key <= String(kStyles.length)) name = kStyles[Number(key) - 1];
    if (name === null) return false;
    if (setStyle(name)) {
      rememberView();
      requestDraw();
    }
    return true;
  }

  styleMenu.addEventListener('change', () => {
    if (setStyle(styleMenu.value)) {
      rememberView();
      requestDraw();
    }
  });
  budgetMenu.addEventListener('change', () => {
    setBudget(Number(budgetMenu.value));
    rememberView();
    requestDraw();
  });
  modelForm.addEventListener('submit', (event) => {
    event.preventDefault();
    if (api !== null && modelField.value !== '') openModel(modelField.value);
  });
  window.octopointInput(canvas, view, requestDraw, rememberView, onKey, walking);
  // A new window size or device pixel ratio (a browser zoom, a move to another screen) fires it.
  if (!fixed) window.addEventListener('resize', requestDraw);

  Module.onRuntimeInitialized = () => {
    api = {
      draw: Module.cwrap('octopoint_web_draw', 'number',
                         ['number', 'number', 'number', 'number', 'number', 'number']),
      setStyle: Module.cwrap('octopoint_web_set_style', 'number', ['string']),
      pixels: Module.cwrap('octopoint_web_pixels', 'number', []),
      setBudget: Module.cwrap('octopoint_web_set_point_budget', 'number', ['number']),
      error: () => Module.UTF8ToString(Module.ccall('octopoint_web_error', 'number', [], [])),
    };
    if (Module.ccall('octopoint_web_create', 'number', [], []) !== 0) {
      report('cannot start the renderer: ' + api.error(), true);
      api = null;
      return;
    }
    if (!setStyle(view.style)) setStyle('colour');
    setBudget(view.budget);
    walk = window.octopointWalk(Module);
    // The address's eye: the page starts in walk mode (in a streamed model once its head is in).
    const asked = params.has('eye') ?
        {eye: params.get('eye'), look: params.get('look'), fov: params.get('fov')} : null;
    if (params.has('model') && params.get('model') !== '') {
      openModel(params.get('model'));
      eyeToPlace = asked;
    } else if (asked !== null) {
      placeEye(asked);
    }
    draw();
  };
})();
