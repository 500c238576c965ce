// Browser tests of the 3D view's camera: the Up menu (auto and x / y / z), Fit, Reset view and the
// top / front / side presets. Imported by browser.test.mjs, which owns the browser (useBrowser).

import assert from 'node:assert/strict';
import { describe } from 'node:test';
import { expectReady, pageTest } from './support/fixtures.mjs';

// A quarter cylinder standing on the xz plane, axis along y: x = cos θ, z = sin θ, y ∈ [0, 2]. Its z
// extent (1) is not small next to x (1) and y (2): not a relief, so auto picks y up.
function quarterCylinderObj(n = 8) {
  const lines = ['# quarter cylinder, y up'];
  for (let j = 0; j <= n; j += 1) {
    for (let i = 0; i <= n; i += 1) {
      const theta = (Math.PI / 2) * (i / n);
      lines.push(`v ${Math.cos(theta)} ${(2 * j) / n} ${Math.sin(theta)}`);
    }
  }
  const at = (i, j) => j * (n + 1) + i + 1;
  for (let j = 0; j < n; j += 1) {
    for (let i = 0; i < n; i += 1) lines.push(`f ${at(i, j)} ${at(i + 1, j)} ${at(i + 1, j + 1)} ${at(i, j + 1)}`);
  }
  return `${lines.join('\n')}\n`;
}

const sub = (a, b) => a.map((v, i) => v - b[i]);
const norm = (a) => Math.hypot(...a);
const unit = (a) => a.map((v) => v / norm(a));
const dot = (a, b) => a.reduce((s, v, i) => s + v * b[i], 0);

/** The camera after the next frame that satisfies `predicate` (a function of hooks.camera). */
async function cameraWhen(page, predicate, arg) {
  const handle = await page.waitForFunction(
    ([source, value]) => {
      const cam = window.__straightest.camera;
      return cam && new Function('cam', 'arg', `return (${source})(cam, arg)`)(cam, value) ? cam : null;
    },
    [predicate.toString(), arg],
  );
  return handle.jsonValue();
}

/** The bounding sphere of the mesh on display: { center, radius }. */
async function boundingSphere(page) {
  const { min, max } = await page.evaluate(() => window.__straightest.lastInfo.bbox);
  return { center: min.map((v, i) => (v + max[i]) / 2), radius: norm(sub(max, min)) / 2 };
}

/** The largest distance-to-radius ratio at which a sphere just fits the view's narrower angle. */
function fitDistance(cam, radius) {
  const halfFov = (cam.fovDeg * Math.PI) / 360;
  const fit = Math.min(halfFov, Math.atan(Math.tan(halfFov) * cam.aspect));
  return radius / Math.sin(fit);
}

async function loadQuarterCylinder(page) {
  await page.setInputFiles('#file-input', {
    name: 'quarter-cylinder.obj',
    mimeType: 'text/plain',
    buffer: Buffer.from(quarterCylinderObj()),
  });
  await expectReady(page, 'window.__straightest.lastInfo?.vertices === 81');
}

describe('camera', () => {
  pageTest(
    'Up: auto is z for a sample and y for a standing file; the menu sets the camera up vector',
    {},
    async ({ page }) => {
      let cam = await cameraWhen(page, (c) => c.upAxis === 'z');
      assert.deepEqual(cam.up, [0, 0, 1], 'the mountain sample opens z up');
      assert.equal((await page.textContent('#up-select option[value="auto"]')).trim(), 'auto (z)');

      await loadQuarterCylinder(page);
      cam = await cameraWhen(page, (c) => c.upAxis === 'y');
      assert.deepEqual(cam.up, [0, 1, 0], 'a file that is no relief opens y up');
      assert.equal((await page.textContent('#up-select option[value="auto"]')).trim(), 'auto (y)');
      const { center } = await boundingSphere(page);
      assert(norm(sub(cam.target, center)) < 1e-9, `the view orbits ${cam.target}, not the box centre ${center}`);
      // Opened from above: the camera sits on the +y side of the centre.
      assert(dot(unit(sub(cam.position, cam.target)), [0, 1, 0]) > 0.3, 'the camera is not above the mesh');

      for (const [axis, up] of [
        ['z', [0, 0, 1]],
        ['x', [1, 0, 0]],
        ['y', [0, 1, 0]],
      ]) {
        await page.selectOption('#up-select', axis);
        cam = await cameraWhen(page, (c, a) => c.upAxis === a, axis);
        assert.deepEqual(cam.up, up, `Up ${axis}: camera.up is ${cam.up}`);
        assert(dot(unit(sub(cam.position, cam.target)), up) > 0.3, `Up ${axis}: the camera is not above the mesh`);
      }
    },
  );

  pageTest(
    'Fit keeps the direction and puts the whole bounding sphere in view; Reset view restores the opening view',
    {},
    async ({ page }) => {
      await loadQuarterCylinder(page);
      // The wheel goes to whatever is under the mouse: the progress panel covers the view while the new
      // mesh's parameterization runs.
      await expectReady(page, 'window.__straightest.param && !window.__straightest.progress.busy');
      const opening = await cameraWhen(page, (c) => c.upAxis === 'y');
      const { center, radius } = await boundingSphere(page);
      // Zoom far in with the mouse wheel: the sphere no longer fits.
      const box = await page.locator('#view-canvas').boundingBox();
      await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
      for (let i = 0; i < 8; i += 1) await page.mouse.wheel(0, -400);
      const zoomed = await cameraWhen(
        page,
        (c, r) => Math.hypot(...c.position.map((v, i) => v - c.target[i])) < r,
        radius,
      );
      assert(norm(sub(zoomed.position, zoomed.target)) < fitDistance(zoomed, radius), 'the wheel did not zoom in');

      await page.click('#fit-button');
      const fitted = await cameraWhen(
        page,
        (c, r) => Math.hypot(...c.position.map((v, i) => v - c.target[i])) > r,
        radius,
      );
      const distance = norm(sub(fitted.position, fitted.target));
      const needed = fitDistance(fitted, radius);
      assert(distance >= needed * (1 - 1e-9), `at ${distance} the bounding sphere (radius ${radius}) needs ${needed}`);
      assert(distance <= needed * 1.01, `Fit stands back ${distance}, more than the ${needed} the sphere needs`);
      assert(norm(sub(fitted.target, center)) < 1e-9, 'Fit does not look at the bounding box centre');
      const before = unit(sub(zoomed.position, zoomed.target));
      assert(dot(unit(sub(fitted.position, fitted.target)), before) > 0.999, 'Fit changed the viewing direction');

      await page.click('#view-reset-button');
      const reset = await cameraWhen(
        page,
        (c, d) => Math.abs(Math.hypot(...c.position.map((v, i) => v - c.target[i])) - d) < 1e-6 * d,
        norm(sub(opening.position, opening.target)),
      );
      assert(
        norm(sub(reset.position, opening.position)) < 1e-6 * radius,
        `Reset view put the camera at ${reset.position}, opened at ${opening.position}`,
      );
    },
  );

  pageTest(
    'Top, Front and Side look from the up axis, the front and the right of the current up axis',
    {},
    async ({ page }) => {
      // z up (the mountain): right x, front = x × z = -y. y up (the quarter cylinder): front = x × y = +z.
      const expected = {
        z: { top: [0, 0, 1], front: [0, -1, 0], side: [1, 0, 0] },
        y: { top: [0, 1, 0], front: [0, 0, 1], side: [1, 0, 0] },
      };
      for (const axis of ['z', 'y']) {
        if (axis === 'y') await loadQuarterCylinder(page);
        await cameraWhen(page, (c, a) => c.upAxis === a, axis);
        const { radius } = await boundingSphere(page);
        for (const [preset, direction] of Object.entries(expected[axis])) {
          await page.click(`#view-${preset}-button`);
          const cam = await cameraWhen(
            page,
            (c, d) => {
              const v = c.position.map((x, i) => x - c.target[i]);
              return v.reduce((s, x, i) => s + x * d[i], 0) / Math.hypot(...v) > 0.999;
            },
            direction,
          );
          const distance = norm(sub(cam.position, cam.target));
          assert(
            Math.abs(distance - fitDistance(cam, radius)) < 1e-6 * distance,
            `${axis} up, ${preset}: the sphere is not fitted`,
          );
        }
      }
    },
  );
});
