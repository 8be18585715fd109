// The page's walk mode (docs/web.md, "Walk mode"; loaded before web/octopoint.js, which calls it):
// the eye stands in the embedded model or a streamed chunked one, as in octopoint-view's walk mode. The module keeps the eye
// in integers and draws (web/octopoint_web_walk.cpp); here are the keys held and their times, the
// drag and the wheel, and the conversion between the scan's units and the camera's Q.24 cube edges,
// with the doubles of tools/scan_eye.cpp, so that the address and the overlay speak
// octopoint-render's --eye X,Y,Z --look YAW,PITCH[,ROLL] --fov DEG.
'use strict';

// Returns null when the module has no walk mode; otherwise the walk, with its methods (walk.ready()
// says whether there is a model to walk in: the embedded one, or a streamed one once its head came).
window.octopointWalk = function (Module) {
  if (typeof Module._octopoint_web_walk_cube !== 'function') return null;
  const kUnit = 16777216;  // Q.24: one cube edge
  const kTurn = 65536;     // the module's angles: 1/65536 turn
  // The walk keys, in the module's order (0 forward ... 5 down), by the key's name.
  const kKeys = {w: 0, ArrowUp: 0, s: 1, ArrowDown: 1, a: 2, ArrowLeft: 2, d: 3, ArrowRight: 3,
                 e: 4, PageUp: 4, q: 5, PageDown: 5};
  const api = {
    place: Module.cwrap('octopoint_web_walk_place', 'number', Array(10).fill('number')),
    enter: Module.cwrap('octopoint_web_walk_enter', 'number', Array(6).fill('number')),
    move: Module.cwrap('octopoint_web_walk_move', 'number', ['number', 'number']),
    turn: Module.cwrap('octopoint_web_walk_turn', 'number', ['number', 'number']),
    faster: Module.cwrap('octopoint_web_walk_faster', 'number', ['number']),
    draw: Module.cwrap('octopoint_web_walk_draw', 'number', Array(9).fill('number')),
    state: Module.cwrap('octopoint_web_walk_state', 'number', []),
  };

  // The module's words (uint32) from `address`, and a binary64 from two of them.
  function words(address, count) {
    return new Uint32Array(Module.HEAPU8.buffer, address, count).slice();
  }
  function float64(low, high) {
    const view = new DataView(new ArrayBuffer(8));
    view.setUint32(0, low, true);
    view.setUint32(4, high, true);
    return view.getFloat64(0, true);
  }
  function int64(low, high) {  // exact: the eye stays within 2^31 units
    return (high | 0) * 4294967296 + low;
  }
  // Where the walked model's cube lies in the scan: read when first needed, and again for a model
  // opened later (walk.forget); null while there is none (no model, or its head still to come).
  let cube = null;
  function cubeNow() {
    if (cube !== null) return cube;
    const at = Module._octopoint_web_walk_cube();
    if (at === 0) return null;
    const placement = words(at, 9);
    cube = {
      corner: [0, 1, 2].map((axis) => float64(placement[axis * 2], placement[axis * 2 + 1])),
      edge: float64(placement[6], placement[7]),
      yUp: placement[8] === 1,
    };
    return cube;
  }

  // C's llround, which octopoint-render's option parsing uses: halves away from zero.
  function roundAway(x) {
    return x < 0 ? -Math.round(-x) : Math.round(x);
  }
  // tools/scan_eye.cpp's modelCoordinate: a coordinate in the scan's units to Q.24 cube edges
  // about the cube's centre; null when more than 128 cube edges away.
  function modelCoordinate(axis, value) {
    let edges = (value - cube.corner[axis]) / cube.edge - 0.5;
    if (cube.yUp && axis > 0) edges = -edges;
    return Math.abs(edges) <= 128 ? roundAway(edges * kUnit) : null;
  }
  // And modelPointOf: a point in the scan's units to a model point; null if too far.
  function modelPoint(scan) {
    const point = [0, 1, 2].map((axis) => modelCoordinate(axis, scan[axis]));
    return point.includes(null) ? null : point;
  }
  // tools/scan_eye.cpp's eyeText: each coordinate with the fewest decimals that modelPoint reads
  // back as this model point, written as cli::realText writes it.
  function eyeText(model) {
    return scanPoint(model).map((value, axis) => {
      let shortest = value;
      for (let decimals = 0; decimals <= 17; ++decimals) {
        const candidate = Number(value.toFixed(decimals));
        if (modelCoordinate(axis, candidate) === model[axis]) {
          shortest = candidate;
          break;
        }
      }
      return shortest !== 0 && Math.abs(shortest) < 1e-6 ?
          shortest.toExponential().replace(/e([+-])(\d)$/, 'e$10$2') : String(shortest);
    }).join(',');
  }
  // And scanPointOf: back to the scan's units.
  function scanPoint(model) {
    let edges = model.map((q) => q / kUnit);
    if (cube.yUp) edges = [edges[0], -edges[1], -edges[2]];
    return [0, 1, 2].map((axis) => cube.corner[axis] + (edges[axis] + 0.5) * cube.edge);
  }
  // Angle::fromMilliDegrees: thousandths of a degree to 1/65536 turns, rounded (ties up).
  function turnsOf(millidegrees) {
    const reduced = ((millidegrees % 360000) + 360000) % 360000;
    return Math.floor((2 * reduced * kTurn + 360000) / 720000) % kTurn;
  }
  // tools/scan_eye.cpp's degreesText: the fewest decimals (at most 3) that --look reads back as
  // this very angle, within (-180, 180].
  function degreesText(turns) {
    const units = turns > kTurn / 2 ? turns - kTurn : turns;
    const degrees = units * (360 / kTurn);  // exact in a double
    let text = '';
    for (let decimals = 0; decimals <= 3; ++decimals) {
      text = degrees.toFixed(decimals);
      if (turnsOf(roundAway(Number(text) * 1000)) === turns) break;
    }
    return text === '-0' ? '0' : text;
  }

  const held = new Map();  // walk key (0..5) -> since when it moves the eye, in microseconds
  let dragged = null;      // while a drag turns the eye: the pixels it spans and the turn sent
  const walk = {active: false};
  // Whether there is a model with its cube's place in the scan to walk in.
  walk.ready = function () {
    return cubeNow() !== null;
  };
  // Another model is opened: its cube is read when its head has come.
  walk.forget = function () {
    cube = null;
  };

  function now() {
    return Math.round(performance.now() * 1000);
  }
  // Makes every hold so far part of the eye (before a turn, a new speed, a mode change).
  function fold(time) {
    for (const [key, since] of held) {
      api.move(key, Math.min(2147483647, time - since));
      held.set(key, time);
    }
  }

  // Places the eye from the address's eye=X,Y,Z, look=YAW,PITCH[,ROLL] and fov=DEG (degrees);
  // returns what is wrong with them, or ''.
  walk.place = function (eyeText, lookText, fovText) {
    if (!walk.ready()) return 'eye: there is no model with its place in the scan to walk in';
    const eye = eyeText.split(',').map(Number);
    if (eye.length !== 3 || !eye.every(Number.isFinite)) return 'eye=' + eyeText + ' is not X,Y,Z';
    const look = lookText === null ? [0, 0, 0] : lookText.split(',').map(Number);
    if (look.length === 2) look.push(0);
    if (look.length !== 3 || !look.every((a) => Number.isFinite(a) && Math.abs(a) <= 1e6))
      return 'look=' + lookText + ' is not YAW,PITCH or YAW,PITCH,ROLL in degrees';
    const fov = fovText === null ? 60 : Number(fovText);
    if (!(fov >= 10 && fov <= 120)) return 'fov=' + fovText + ' is not 10..120 degrees';
    const point = modelPoint(eye);
    if (point === null) return 'eye=' + eyeText + ' is more than 128 cube edges from the model';
    const halves = point.flatMap((q) => [q | 0, Math.floor(q / 4294967296)]);
    const angles = look.concat([fov]).map((a) => roundAway(a * 1000));
    return api.place(...halves, ...angles) === 0 ? '' : 'the eye is refused';
  };
  // Enters walk mode from the orbit view (view: the page's yaw, pitch, roll, zoom) at the eye
  // octopoint-render --perspective puts there; false (and no walk) when the module refuses it.
  walk.enter = function (view, width, height) {
    const entered = api.enter(roundAway(view.yaw * 1000), roundAway(view.pitch * 1000),
                              roundAway(view.roll * 1000), Math.round(view.zoom * 65536), width,
                              height) === 0;
    walk.active = true;
    return entered;
  };
  walk.leave = function () {
    fold(now());
    held.clear();
    dragged = null;
    walk.active = false;
  };
  // A key pressed or let go: true when it is a walk key (the eye moves while it is held).
  walk.key = function (name, down) {
    const key = kKeys[name.length === 1 ? name.toLowerCase() : name];
    if (key === undefined) return false;
    const time = now();
    if (down && !held.has(key)) {
      held.set(key, time);
    } else if (!down && held.has(key)) {
      api.move(key, Math.min(2147483647, time - held.get(key)));
      held.delete(key);
    }
    return true;
  };
  walk.releaseAll = function () {
    fold(now());
    held.clear();
  };
  // A drag: `dx`, `dy` CSS pixels since it began on a canvas `height` CSS pixels tall turn the eye
  // by the angle they span on screen (the field of view per height), right and up as the pointer
  // moves right and up; sums since the drag began, so that no rounding adds up.
  walk.drag = function (dx, dy, height) {
    const fov = walk.state().fov;
    if (dragged === null) {
      fold(now());
      dragged = {yaw: 0, pitch: 0};
    }
    const pixels = Math.max(1, Math.round(height));
    const yaw = Math.trunc(Math.round(dx) * fov / pixels);
    const pitch = Math.trunc(-Math.round(dy) * fov / pixels);
    api.turn(yaw - dragged.yaw, pitch - dragged.pitch);
    dragged.yaw = yaw;
    dragged.pitch = pitch;
  };
  walk.dragEnd = function () {
    dragged = null;
  };
  walk.faster = function (faster) {
    fold(now());
    api.faster(faster ? 1 : 0);
  };
  // Whether the eye is moving (a key held or a drag): the frames are coarse and keep coming.
  walk.moving = function () {
    return held.size > 0 || dragged !== null;
  };

  // Draws the eye's frame at this time: 0 when drawn (pixels in octopoint_web_pixels).
  walk.draw = function (width, height) {
    const time = now();
    for (const [key, since] of held) {  // a day's hold: fold it before it passes an int32
      if (time - since > 1e9) {
        api.move(key, time - since);
        held.set(key, time);
      }
    }
    const times = [0, 1, 2, 3, 4, 5].map((key) => (held.has(key) ? time - held.get(key) : 0));
    return api.draw(width, height, walk.moving() ? 1 : 0, ...times);
  };
  // The eye of the last frame: in the scan's units, its look and field of view in degrees as
  // octopoint-render reads them, the speed in scan units a second, and the points that frame drew.
  walk.state = function () {
    const w = words(api.state(), 13);
    return {
      eye: eyeText([int64(w[0], w[1]), int64(w[2], w[3]), int64(w[4], w[5])]),
      look: [w[6], w[7], w[8]].map(degreesText).join(','),
      fov: w[9],
      fovText: degreesText(w[9]),
      speed: int64(w[10], w[11]) / kUnit * cube.edge,
      points: w[12],
    };
  };
  return walk;
};
