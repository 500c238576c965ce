// The 3D view: the three.js renderer, camera, lights and orbit controls, render scheduling (one
// frame per change, on demand) and framing a mesh's bounding box. Everything drawn is added to
// view.scene by the other views; they call view.requestRender() after a change.

import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { hooks } from './test-hooks.js';

const BACKGROUND = 0x14171c;

/** Creates the view on `canvas`, sized to follow `viewport`. */
export function createView({ canvas, viewport }) {
  const renderer = new THREE.WebGLRenderer({ canvas, antialias: true });
  renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
  renderer.setClearColor(BACKGROUND);
  hooks.background = [(BACKGROUND >> 16) & 255, (BACKGROUND >> 8) & 255, BACKGROUND & 255];

  const scene = new THREE.Scene();
  const camera = new THREE.PerspectiveCamera(40, 1, 0.01, 100);
  camera.up.set(0, 0, 1); // the samples are height fields z = h(x, y)
  camera.position.set(2, -3, 2);
  scene.add(camera);

  scene.add(new THREE.HemisphereLight(0xdde6ff, 0x2a2418, 0.7));
  const headlight = new THREE.DirectionalLight(0xffffff, 2.6);
  headlight.position.set(1, 1.5, 0.3); // relative to the camera (upper right): follows the view
  camera.add(headlight);
  camera.add(headlight.target);
  headlight.target.position.set(0, 0, -1);

  const controls = new OrbitControls(camera, canvas);
  controls.addEventListener('change', () => requestRender());

  let scale = 1; // bounding-box diagonal of the framed mesh: sizes markers and planes
  let scheduledFrame = 0; // requestAnimationFrame id of a pending render, 0 if none

  function render() {
    cancelAnimationFrame(scheduledFrame); // rendering now makes a pending frame redundant
    scheduledFrame = 0;
    renderer.render(scene, camera);
    hooks.renders += 1;
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

  /** Points the camera at the bounding box, from the front-right and above, so it fills the view. */
  function frameBox(bbox) {
    const min = new THREE.Vector3(...bbox.min);
    const max = new THREE.Vector3(...bbox.max);
    const center = min.clone().add(max).multiplyScalar(0.5);
    const radius = Math.max(max.distanceTo(min) / 2, 1e-6);
    const halfFov = THREE.MathUtils.degToRad(camera.fov / 2);
    const fit = Math.min(halfFov, Math.atan(Math.tan(halfFov) * camera.aspect));
    scale = 2 * radius;
    const distance = (radius / Math.sin(fit)) * 0.95;
    const direction = new THREE.Vector3(0.55, -1.0, 0.75).normalize();
    camera.position.copy(center).addScaledVector(direction, distance);
    camera.near = distance / 100;
    camera.far = distance * 100;
    camera.updateProjectionMatrix();
    controls.target.copy(center);
    controls.update();
  }

  return {
    canvas,
    viewport,
    renderer,
    scene,
    camera,
    render,
    requestRender,
    gpuIdle,
    frameBox,
    /** The framed mesh's bounding-box diagonal (sizes markers, planes and picking tolerances). */
    get scale() {
      return scale;
    },
  };
}
