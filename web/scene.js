// The 3D view: the three.js renderer, camera, lights and orbit controls, render scheduling (one
// frame per change, on demand) and where the camera looks from: the up axis, framing a mesh's
// bounding box (reset), fitting its bounding sphere (fit) and the top/front/side presets. Everything drawn is added to
// view.scene by the other views; they call view.requestRender() after a change. What it has drawn,
// as plain data, is status() (main.js puts it in the page's observable state, docs/PAGE.md).

import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { createGpuUpload } from './gpu-upload.js';

const BACKGROUND = 0x14171c;

/** Creates the view on `canvas`, sized to follow `viewport`. */
export function createView({ canvas, viewport }) {
  const renderer = new THREE.WebGLRenderer({ canvas, antialias: true });
  renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
  renderer.setClearColor(BACKGROUND);

  const scene = new THREE.Scene();
  const camera = new THREE.PerspectiveCamera(40, 1, 0.01, 100);
  camera.up.set(0, 0, 1); // until setUpAxis: the samples are height fields z = h(x, y)
  camera.position.set(2, -3, 2);
  scene.add(camera);

  scene.add(new THREE.HemisphereLight(0xdde6ff, 0x2a2418, 0.7));
  const headlight = new THREE.DirectionalLight(0xffffff, 2.6);
  headlight.position.set(1, 1.5, 0.3); // relative to the camera (upper right): follows the view
  camera.add(headlight);
  camera.add(headlight.target);
  headlight.target.position.set(0, 0, -1);

  let controls = createControls();
  let upAxis = 'z';
  let framed = null; // { center, radius } of the framed mesh's bounding box

  // OrbitControls reads camera.up once, when it is made: a new up axis needs new controls.
  function createControls() {
    const made = new OrbitControls(camera, canvas);
    made.addEventListener('change', () => requestRender());
    return made;
  }

  let scale = 1; // bounding-box diagonal of the framed mesh: sizes markers and planes
  let scheduledFrame = 0; // requestAnimationFrame id of a pending render, 0 if none
  let renders = 0; // frames rendered (for status())
  let lastCamera = null; // the camera at the last frame (for status())

  function render() {
    cancelAnimationFrame(scheduledFrame); // rendering now makes a pending frame redundant
    scheduledFrame = 0;
    renderer.render(scene, camera);
    renders += 1;
    lastCamera = {
      upAxis,
      up: camera.up.toArray(),
      position: camera.position.toArray(),
      target: controls.target.toArray(),
      fovDeg: camera.fov,
      aspect: camera.aspect,
    };
  }

  function requestRender() {
    if (!scheduledFrame) scheduledFrame = requestAnimationFrame(render);
  }

  /**
   * Resolves once the GPU has finished the frames queued so far (polled, never waited for). A large
   * upload waits for it: WebGL hands buffers to the GPU process through a bounded transfer buffer, so
   * an upload queued behind slow frames (seconds each with a software renderer and a million-vertex
   * mesh) would block the main thread until they are done.
   */
  function gpuIdle() {
    const gl = renderer.getContext();
    const fence = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
    gl.flush();
    return new Promise((resolve) => {
      const poll = () => {
        if (!fence || gl.isContextLost() || gl.getSyncParameter(fence, gl.SYNC_STATUS) === gl.SIGNALED) {
          if (fence) gl.deleteSync(fence);
          resolve();
        } else {
          setTimeout(poll, 30);
        }
      };
      poll();
    });
  }

  function resize() {
    const { clientWidth: w, clientHeight: h } = viewport;
    if (w === 0 || h === 0) return;
    renderer.setSize(w, h, false);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
    requestRender();
  }
  new ResizeObserver(resize).observe(viewport);
  resize();

  // The camera's frame for each up axis: right × up = front (right-handed), the direction the front
  // view looks from. z up: looking along +y from -y (x to the right); y up: three's own convention,
  // looking along -z from +z; x up: y to the right.
  const FRAMES = {
    x: { up: [1, 0, 0], right: [0, 1, 0] },
    y: { up: [0, 1, 0], right: [1, 0, 0] },
    z: { up: [0, 0, 1], right: [1, 0, 0] },
  };
  function frameOf(axis) {
    const up = new THREE.Vector3(...FRAMES[axis].up);
    const right = new THREE.Vector3(...FRAMES[axis].right);
    return { up, right, front: right.clone().cross(up) };
  }
  // Where each preset looks from, in the frame of the up axis. Top is tilted a hair toward the front:
  // looking exactly along the up axis leaves the orbit controls no direction for "up" on screen.
  const PRESETS = {
    home: { right: 0.55, front: 1.0, up: 0.75 }, // front-right and above, as the page opens
    top: { right: 0, front: 1e-3, up: 1 },
    front: { right: 0, front: 1, up: 0 },
    side: { right: 1, front: 0, up: 0 },
  };

  /** The distance at which a sphere of `radius` just fits the narrower of the view's two angles. */
  function fitDistance(radius) {
    const halfFov = THREE.MathUtils.degToRad(camera.fov / 2);
    const fit = Math.min(halfFov, Math.atan(Math.tan(halfFov) * camera.aspect));
    return radius / Math.sin(fit);
  }

  /** Puts the camera `distance` from the framed centre along `direction` (a unit vector). */
  function place(direction, distance) {
    const { center } = framed;
    camera.position.copy(center).addScaledVector(direction, distance);
    camera.near = distance / 100;
    camera.far = distance * 100;
    camera.updateProjectionMatrix();
    controls.target.copy(center);
    controls.update();
    requestRender();
  }

  /** Looks at the framed mesh from a preset direction (PRESETS) at `distance`. */
  function lookFrom(preset, distance) {
    if (!framed) return;
    const frame = frameOf(upAxis);
    const weights = PRESETS[preset];
    const direction = new THREE.Vector3()
      .addScaledVector(frame.right, weights.right)
      .addScaledVector(frame.front, weights.front)
      .addScaledVector(frame.up, weights.up)
      .normalize();
    place(direction, distance);
  }

  /**
   * Points the camera at the bounding box, from the front-right and above, so it fills the view (a
   * little closer than the bounding sphere: a box's corners rarely reach it).
   */
  function frameBox(bbox) {
    const min = new THREE.Vector3(...bbox.min);
    const max = new THREE.Vector3(...bbox.max);
    const radius = Math.max(max.distanceTo(min) / 2, 1e-6);
    framed = { center: min.clone().add(max).multiplyScalar(0.5), radius };
    scale = 2 * radius;
    resetView();
  }

  /** Back to the view the mesh opened with (for the current up axis). */
  function resetView() {
    lookFrom('home', fitDistance(framed?.radius ?? 1) * 0.95);
  }

  /** Keeps the direction the camera looks from and moves it so the whole bounding sphere is in view. */
  function fit() {
    if (!framed) return;
    const direction = camera.position.clone().sub(controls.target);
    if (direction.lengthSq() === 0) direction.copy(frameOf(upAxis).front);
    place(direction.normalize(), fitDistance(framed.radius));
  }

  /** Looks from the top, front or side, the whole bounding sphere in view. */
  function viewFrom(preset) {
    lookFrom(preset, fitDistance(framed?.radius ?? 1));
  }

  /** Makes 'x', 'y' or 'z' point up on screen and looks at the mesh as it opens. */
  function setUpAxis(axis) {
    if (!FRAMES[axis]) throw new Error(`unknown up axis ${axis}`);
    upAxis = axis;
    camera.up.set(...FRAMES[axis].up);
    controls.dispose();
    controls = createControls();
    resetView();
  }

  return {
    canvas,
    viewport,
    renderer,
    scene,
    camera,
    /** Uploads large geometry a slice per frame (gpu-upload.js): the views' big meshes and lines. */
    gpu: createGpuUpload(renderer),
    render,
    requestRender,
    gpuIdle,
    frameBox,
    resetView,
    fit,
    viewFrom,
    setUpAxis,
    /** The orbit controls (remade with each up axis): keyboard.js turns key presses into their moves. */
    get controls() {
      return controls;
    },
    /** 'x', 'y' or 'z': the axis pointing up on screen. */
    get upAxis() {
      return upAxis;
    },
    /** The framed mesh's bounding-box diagonal (sizes markers, planes and picking tolerances). */
    get scale() {
      return scale;
    },
    /**
     * What it has drawn: { renders (frames rendered), background (the clear colour as [r, g, b] bytes),
     * camera (at the last frame: { upAxis, up, position, target (the orbit centre), fovDeg (vertical),
     * aspect }, arrays of 3 numbers; null before the first) }.
     */
    status: () => ({
      renders,
      background: [(BACKGROUND >> 16) & 255, (BACKGROUND >> 8) & 255, BACKGROUND & 255],
      camera: lastCamera,
    }),
  };
}
