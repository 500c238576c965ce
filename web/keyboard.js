// The 3D view from the keyboard: the canvas takes focus (tabindex in index.html) and, while it has
// it, the arrow keys orbit, + and − zoom, and 0 or Home go back to the view the mesh opened with —
// what a mouse does with the orbit controls, for keyboard users and screen readers.

const ORBIT_STEP = Math.PI / 24; // 7.5° per key press
// The orbit controls' dolly factor per key press (< 1, as their wheel's: dollyIn(s) scales the distance by s).
const ZOOM_STEP = 0.8;

/** The key's action on the view, or null for a key the view does not use. */
function actionFor(key, view) {
  const controls = view.controls;
  switch (key) {
    case 'ArrowLeft':
      return () => controls.rotateLeft(ORBIT_STEP);
    case 'ArrowRight':
      return () => controls.rotateLeft(-ORBIT_STEP);
    case 'ArrowUp':
      return () => controls.rotateUp(ORBIT_STEP);
    case 'ArrowDown':
      return () => controls.rotateUp(-ORBIT_STEP);
    case '+':
    case '=':
      return () => controls.dollyIn(ZOOM_STEP);
    case '-':
    case '_':
      return () => controls.dollyOut(ZOOM_STEP);
    case '0':
    case 'Home':
      return () => view.resetView();
    default:
      return null;
  }
}

/** view: scene.js (its canvas, controls, resetView and render scheduling). */
export function createKeyboard(view) {
  view.canvas.addEventListener('keydown', (event) => {
    if (event.altKey || event.ctrlKey || event.metaKey) return; // the browser's own shortcuts
    const action = actionFor(event.key, view);
    if (!action) return;
    event.preventDefault(); // arrows would scroll the page
    action();
    view.requestRender();
  });
}
