// scripts/test-web's live resize (test (d) of the web page): shows the page (index.html, the rest
// of this address's query, without w and h so that the canvas follows its window) in a frame of
// `first` (WxH CSS pixels), waits for its first frame at that size, then resizes the frame to
// `then` and waits for a second frame at the new size. The window is `then`'s size, so the
// screenshot is the page's canvas after the resize, compared with octopoint-render's PNG of that
// size. A first frame of another size hides the frame (the screenshot then differs); a page that
// does not redraw leaves the first frame, larger than the window, which differs too.
'use strict';

(function () {
  const params = new URLSearchParams(window.location.search);
  const size = (text) => text.split('x').map(Number);
  const [firstWidth, firstHeight] = size(params.get('first'));
  const [thenWidth, thenHeight] = size(params.get('then'));
  params.delete('first');
  params.delete('then');
  const frame = document.getElementById('page');
  function resizeFrame(width, height) {
    frame.style.width = width + 'px';
    frame.style.height = height + 'px';
  }
  resizeFrame(firstWidth, firstHeight);
  frame.src = 'index.html?' + params.toString();

  let stage = 'first';
  const timer = window.setInterval(() => {
    const page = frame.contentDocument;
    const canvas = page && page.getElementById('view');
    const frames = page && page.body ? Number(page.body.dataset.frames || 0) : 0;
    if (canvas === null || frames === 0) return;
    if (stage === 'first') {
      if (canvas.width !== firstWidth || canvas.height !== firstHeight) {
        document.body.classList.add('failed');
        window.clearInterval(timer);
        return;
      }
      stage = 'then';
      resizeFrame(thenWidth, thenHeight);
    } else if (frames >= 2 && canvas.width === thenWidth && canvas.height === thenHeight) {
      document.body.classList.add('done');
      window.clearInterval(timer);
    }
  }, 20);
})();
