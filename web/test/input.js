// scripts/test-web's input check: shows the page (index.html, the rest of this address's query,
// which gives w and h) in a frame of that size, waits for its first frame, plays one `gesture` on
// it with the events a browser sends, and waits for the next frame; the screenshot of the window
// (the frame's size) is then compared with octopoint-render's PNG of the view the gesture should
// give. The gestures, each from the view of the address:
//   drag:  one finger (a touch pointer) moves 60 pixels right: the yaw turns by 30 degrees
//   pinch: two fingers 100 pixels apart, one moves away to 150: the zoom grows 1.5 times
//   wheel: one notch towards the screen (deltaY -100): the zoom grows 1.1 times
//   key:   the key c: the next style (colour to shaded)
'use strict';

(function () {
  const params = new URLSearchParams(window.location.search);
  const gesture = params.get('gesture');
  params.delete('gesture');
  const frame = document.getElementById('page');
  frame.style.width = params.get('w') + 'px';
  frame.style.height = params.get('h') + 'px';
  frame.src = 'index.html?' + params.toString();

  // A pointer event of a touch pointer `id` at (x, y) on the page's canvas.
  function touch(page, type, id, x, y) {
    const canvas = page.document.getElementById('view');
    canvas.dispatchEvent(new page.PointerEvent(type, {
      pointerId: id, pointerType: 'touch', isPrimary: id === 11, clientX: x, clientY: y,
      button: 0, buttons: type === 'pointerup' ? 0 : 1, bubbles: true, cancelable: true,
    }));
  }

  function play(page) {
    const canvas = page.document.getElementById('view');
    if (gesture === 'drag') {
      touch(page, 'pointerdown', 11, 100, 100);
      touch(page, 'pointermove', 11, 160, 100);
      touch(page, 'pointerup', 11, 160, 100);
    } else if (gesture === 'pinch') {
      touch(page, 'pointerdown', 11, 100, 100);
      touch(page, 'pointerdown', 12, 200, 100);
      touch(page, 'pointermove', 12, 250, 100);
      touch(page, 'pointerup', 12, 250, 100);
      touch(page, 'pointerup', 11, 100, 100);
    } else if (gesture === 'wheel') {
      canvas.dispatchEvent(new page.WheelEvent('wheel', {
        deltaY: -100, deltaMode: 0, clientX: 100, clientY: 100, bubbles: true, cancelable: true,
      }));
    } else if (gesture === 'key') {
      page.document.body.dispatchEvent(
          new page.KeyboardEvent('keydown', {key: 'c', bubbles: true, cancelable: true}));
    }
  }

  let played = -1;  // the page's frame count when the gesture was played
  const timer = window.setInterval(() => {
    const page = frame.contentWindow;
    const body = page && page.document.body;
    const frames = body ? Number(body.dataset.frames || 0) : 0;
    if (frames === 0) return;
    if (played < 0) {
      played = frames;
      play(page);
    } else if (frames > played) {
      window.clearInterval(timer);
    }
  }, 20);
})();
