// The page's input (loaded before web/octopoint.js, which calls it): orbit with a mouse drag or
// one finger, zoom with the wheel or a two-finger pinch (pointer events, so a pen works too), and
// the style keys. It changes the view object it is given and calls back; drawing is
// octopoint.js's.
'use strict';

// view: {yaw, pitch, zoom} in degrees and a factor (octopoint-render's meaning).
// onChange(): the view changed, draw it. onSettled(): a gesture ended, remember the view.
// onKey(key): a key press the page may want (returns true when it used the key).
window.octopointInput = function (canvas, view, onChange, onSettled, onKey) {
  const kMinZoom = 1 / 65536;  // octopoint-render's --zoom range
  const kMaxZoom = 32767;
  const pointers = new Map();  // pointerId -> its last position, while pressed on the canvas

  function zoomBy(factor) {
    view.zoom = Math.max(kMinZoom, Math.min(kMaxZoom, view.zoom * factor));
  }

  // Half a degree a pixel: a drag across a 320-pixel canvas turns the model 160 degrees. The yaw is
  // kept within [-180, 180): the same turn (angles wrap), and never past the C interface's int32
  // thousandths of a degree however long the drag.
  function orbit(dx, dy) {
    view.yaw = (((view.yaw + dx * 0.5) % 360) + 540) % 360 - 180;
    view.pitch = Math.max(-90, Math.min(90, view.pitch + dy * 0.5));
  }

  // The distance between the first two pointers pressed (a pinch), or 0.
  function spread() {
    const [a, b] = pointers.values();
    return b === undefined ? 0 : Math.hypot(a.x - b.x, a.y - b.y);
  }

  canvas.addEventListener('pointerdown', (event) => {
    if (event.pointerType === 'mouse' && event.button !== 0) return;
    pointers.set(event.pointerId, {x: event.clientX, y: event.clientY});
    canvas.setPointerCapture(event.pointerId);
  });
  canvas.addEventListener('pointermove', (event) => {
    const last = pointers.get(event.pointerId);
    if (last === undefined) return;
    if (pointers.size === 1) {
      orbit(event.clientX - last.x, event.clientY - last.y);
      last.x = event.clientX;
      last.y = event.clientY;
    } else {
      // Two fingers: the zoom follows the ratio of their distances (a pinch to half the distance
      // halves the zoom). Only the first two count: a third finger changes nothing.
      const before = spread();
      last.x = event.clientX;
      last.y = event.clientY;
      const after = spread();
      if (before > 0 && after > 0) zoomBy(after / before);
    }
    onChange();
  });
  const release = (event) => {
    if (!pointers.delete(event.pointerId)) return;
    if (pointers.size === 0) onSettled();
  };
  canvas.addEventListener('pointerup', release);
  canvas.addEventListener('pointercancel', release);
  canvas.addEventListener('wheel', (event) => {
    event.preventDefault();
    // One wheel notch (about 100 pixels of delta) zooms by 10%.
    zoomBy(Math.pow(1.1, -event.deltaY / 100));
    onChange();
    onSettled();
  }, {passive: false});
  window.addEventListener('keydown', (event) => {
    if (event.ctrlKey || event.metaKey || event.altKey) return;
    // The menus have their own keys, and the model field takes letters.
    if (event.target instanceof HTMLSelectElement || event.target instanceof HTMLInputElement) return;
    if (onKey(event.key)) event.preventDefault();
  });
};
