// The page's input (loaded before web/octopoint.js, which calls it): orbit with a mouse drag or
// one finger, zoom with the wheel or a two-finger pinch (pointer events, so a pen works too), and
// the style keys; in walk mode (web/octopoint_walk.js) the drag turns the eye, the wheel sets the
// speed and the walk keys move it while held. It changes the view object it is given, or tells the
// walk, and calls back; drawing is octopoint.js's.
'use strict';

// view: {yaw, pitch, zoom} in degrees and a factor (octopoint-render's meaning).
// onChange(): the view changed, draw it. onSettled(): a gesture ended, remember the view.
// onKey(key): a key press the page may want (returns true when it used the key).
// walking(): the walk (web/octopoint_walk.js) when walk mode is on, else null.
window.octopointInput = function (canvas, view, onChange, onSettled, onKey, walking) {
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
    pointers.set(event.pointerId,
                 {x: event.clientX, y: event.clientY, startX: event.clientX, startY: event.clientY});
    canvas.setPointerCapture(event.pointerId);
  });
  canvas.addEventListener('pointermove', (event) => {
    const last = pointers.get(event.pointerId);
    if (last === undefined) return;
    const walk = walking();
    if (walk !== null) {  // one pointer turns the eye, by the whole drag so far
      if (pointers.size !== 1) return;
      walk.drag(event.clientX - last.startX, event.clientY - last.startY, canvas.clientHeight);
    } else if (pointers.size === 1) {
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
    if (pointers.size > 0) return;
    const walk = walking();
    if (walk !== null) {
      walk.dragEnd();
      onChange();  // the fine frame
    }
    onSettled();
  };
  canvas.addEventListener('pointerup', release);
  canvas.addEventListener('pointercancel', release);
  canvas.addEventListener('wheel', (event) => {
    event.preventDefault();
    const walk = walking();
    // In walk mode a notch towards the screen walks 5/4 faster, away 4/5 as fast.
    if (walk !== null) {
      if (event.deltaY !== 0) walk.faster(event.deltaY < 0);
    } else {
      // One wheel notch (about 100 pixels of delta) zooms by 10%.
      zoomBy(Math.pow(1.1, -event.deltaY / 100));
    }
    onChange();
    onSettled();
  }, {passive: false});
  window.addEventListener('keydown', (event) => {
    if (event.ctrlKey || event.metaKey || event.altKey) return;
    // The menus have their own keys, and the model field takes letters.
    if (event.target instanceof HTMLSelectElement || event.target instanceof HTMLInputElement) return;
    const walk = walking();
    if (walk !== null && walk.key(event.key, true)) {  // held: the eye moves until it is let go
      event.preventDefault();
      onChange();
    } else if (onKey(event.key)) {
      event.preventDefault();
    }
  });
  window.addEventListener('keyup', (event) => {
    const walk = walking();
    if (walk !== null && walk.key(event.key, false)) {
      onChange();  // the fine frame
      onSettled();
    }
  });
  // A key let go while the page had no focus never comes: stop every walk there.
  window.addEventListener('blur', () => {
    const walk = walking();
    if (walk !== null) {
      walk.releaseAll();
      onChange();
    }
  });
};
