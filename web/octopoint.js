// The page: reads the camera from the address (the meaning of octopoint-render's --yaw, --pitch,
// --roll, --zoom, --size and --style), draws the embedded model with the integer renderer compiled
// to WebAssembly (web/octopoint_web.cpp), and orbits with a mouse drag and zooms with the wheel;
// the style from the address, the menu, or the keys c (the next, as the viewer's) and 1-5.
'use strict';

(function () {
  const canvas = document.getElementById('view');
  const status = document.getElementById('status');
  const styleMenu = document.getElementById('style');
  const params = new URLSearchParams(window.location.search);
  // octopoint-render's --style names, in its order (the c key steps through them, as the viewer's).
  const kStyles = ['colour', 'shaded', 'lines', 'toon', 'outlined'];
  // emscripten's loader (octopoint_web.js, loaded after this file) takes this object as its
  // Module and calls onRuntimeInitialized once the wasm is compiled.
  const Module = {};
  window.Module = Module;

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
      report(name + '=' + text + ' is not a number in ' + low + '..' + high + ': using ' +
             fallback, true);
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
    width: Math.trunc(numberParam('w', 320, 1, 4096)),
    height: Math.trunc(numberParam('h', 240, 1, 4096)),
    style: 'colour',
  };
  if (params.has('style')) {
    if (kStyles.includes(params.get('style'))) {
      view.style = params.get('style');
    } else {
      report('style=' + params.get('style') + ' is not one of ' + kStyles.join(', ') +
             ': using colour', true);
    }
  }
  if (params.get('bare') === '1') document.body.classList.add('bare');

  let api = null;
  let pending = false;

  function draw() {
    pending = false;
    const started = performance.now();
    const failed = api.draw(roundAway(view.yaw * 1000), roundAway(view.pitch * 1000),
                            roundAway(view.roll * 1000), Math.round(view.zoom * 65536),
                            view.width, view.height);
    if (failed !== 0) {
      report('draw refused: ' + api.error(), true);
      return;
    }
    const bytes = view.width * view.height * 4;
    // A copy: the module's memory may grow (and move) at the next draw.
    const pixels = new Uint8ClampedArray(bytes);
    pixels.set(new Uint8Array(Module.HEAPU8.buffer, api.pixels(), bytes));
    if (canvas.width !== view.width) canvas.width = view.width;
    if (canvas.height !== view.height) canvas.height = view.height;
    canvas.getContext('2d').putImageData(new ImageData(pixels, view.width, view.height), 0, 0);
    const elapsed = performance.now() - started;
    if (!document.body.classList.contains('bare')) {
      report('yaw ' + view.yaw.toFixed(1) + ', pitch ' + view.pitch.toFixed(1) + ', zoom ' +
             view.zoom.toFixed(3) + ', ' + view.style + ', ' + view.width + 'x' + view.height +
             ': ' + elapsed.toFixed(1) + ' ms', false);
    }
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

  styleMenu.addEventListener('change', () => {
    if (setStyle(styleMenu.value)) {
      rememberView();
      requestDraw();
    }
  });
  window.addEventListener('keydown', (event) => {
    if (event.ctrlKey || event.metaKey || event.altKey) return;
    if (event.target instanceof HTMLSelectElement) return;  // the menu has its own keys
    let name = null;
    if (event.key === 'c') name = kStyles[(kStyles.indexOf(view.style) + 1) % kStyles.length];
    if (event.key >= '1' && event.key <= String(kStyles.length)) {
      name = kStyles[Number(event.key) - 1];
    }
    if (name === null) return;
    event.preventDefault();
    if (setStyle(name)) {
      rememberView();
      requestDraw();
    }
  });

  let dragging = null;
  canvas.addEventListener('pointerdown', (event) => {
    if (event.pointerType !== 'mouse') return;  // touch comes later
    dragging = {x: event.clientX, y: event.clientY};
    canvas.setPointerCapture(event.pointerId);
  });
  canvas.addEventListener('pointermove', (event) => {
    if (dragging === null) return;
    // Half a degree a pixel: a drag across a 320-pixel canvas turns the model 160 degrees.
    // Kept within [-180, 180): the same turn (angles wrap), and never past the C interface's int32
    // thousandths of a degree however long the drag.
    view.yaw = (((view.yaw + (event.clientX - dragging.x) * 0.5) % 360) + 540) % 360 - 180;
    view.pitch = Math.max(-90, Math.min(90, view.pitch + (event.clientY - dragging.y) * 0.5));
    dragging = {x: event.clientX, y: event.clientY};
    requestDraw();
  });
  const endDrag = () => {
    if (dragging !== null) rememberView();
    dragging = null;
  };
  canvas.addEventListener('pointerup', endDrag);
  canvas.addEventListener('pointercancel', endDrag);
  canvas.addEventListener('wheel', (event) => {
    event.preventDefault();
    // One wheel notch (about 100 pixels of delta) zooms by 10%.
    const factor = Math.pow(1.1, -event.deltaY / 100);
    view.zoom = Math.max(1 / 65536, Math.min(32767, view.zoom * factor));
    requestDraw();
    rememberView();
  }, {passive: false});

  Module.onRuntimeInitialized = () => {
    api = {
      draw: Module.cwrap('octopoint_web_draw', 'number',
                         ['number', 'number', 'number', 'number', 'number', 'number']),
      setStyle: Module.cwrap('octopoint_web_set_style', 'number', ['string']),
      pixels: Module.cwrap('octopoint_web_pixels', 'number', []),
      error: () => Module.UTF8ToString(Module.ccall('octopoint_web_error', 'number', [], [])),
    };
    if (Module.ccall('octopoint_web_create', 'number', [], []) !== 0) {
      report('cannot start the renderer: ' + api.error(), true);
      api = null;
      return;
    }
    if (!setStyle(view.style)) setStyle('colour');
    draw();
  };
})();
