// The page's pure rules, in Node: when a result gets a poor-result hint (web/hints.js) and how typed
// surface points are read (web/point-entry.js). Neither module touches the DOM when imported.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { L2_MARGIN, comparisonHint, parameterizationHint, poorResultHint } from '../../web/hints.js';
import { parsePoints } from '../../web/point-entry.js';

test('hint: none when every trace reached and the measured map is no worse than the circle', () => {
  assert.equal(poorResultHint({ failedTraces: 0, traces: 196, measuredL2: 1.03, circleL2: 1.23 }), null);
  assert.equal(poorResultHint({}), null, 'nothing known: nothing to say');
  // Within the margin: near-developable meshes where the two maps agree to a few digits.
  assert.equal(poorResultHint({ measuredL2: 1.0105036, circleL2: 1.010501 }), null);
});

test('hint: failed traces name how many of how many, and advise moving the centre, auto and free', () => {
  const hint = poorResultHint({ failedTraces: 21, traces: 36, boundary: 'measured', freeAvailable: true });
  assert(hint.reasons[0].startsWith('21 of 36 '), hint.text);
  assert.equal(hint.advice.length, 3);
  assert.match(hint.advice[0], /Move the centre/);
  assert.match(hint.advice[1], /auto/);
  assert.match(hint.advice[2], /free/);
  assert.equal(hint.text, [...hint.reasons, ...hint.advice].join(' '));
  // No advice to pick what is already chosen, nor the free boundary where there is none.
  const onAuto = poorResultHint({ failedTraces: 1, traces: 10, boundary: 'auto', freeAvailable: false });
  assert.equal(onAuto.advice.length, 1);
});

test('hint: a measured L2 above the circle by more than the margin is a reason on its own', () => {
  const circle = 8.8776;
  const above = poorResultHint({ measuredL2: circle * (1 + 2 * L2_MARGIN), circleL2: circle, boundary: 'measured' });
  assert.equal(above.reasons.length, 1);
  assert.match(above.reasons[0], /stretches more than the circle/);
  assert.equal(poorResultHint({ measuredL2: circle * (1 + L2_MARGIN / 2), circleL2: circle }), null);
  assert.equal(poorResultHint({ measuredL2: NaN, circleL2: circle }), null, 'not compared: no reason');
});

test('hint of a parameterization: fallbacks of the traced loop, L2s from the auto candidates', () => {
  const kinds = ['measured', 'circle', 'square', 'free'];
  const reply = (boundary, fallbacks, candidates) => ({
    boundary,
    init: null,
    fallbacks,
    boundaryLoop: new Int32Array(36),
    candidates,
  });
  // lion-head's numbers: 21 of 36 traces fell back; measured 9.21 > circle 8.88.
  const lion = [
    { boundary: 'measured', l2: 9.2085 },
    { boundary: 'circle', l2: 8.8776 },
    { boundary: 'free', l2: 1.33 },
  ];
  const auto = parameterizationHint(reply('free', 21, lion), 'auto', kinds);
  assert.equal(auto.reasons.length, 2, auto.text);
  assert(!auto.advice.some((a) => /free/.test(a)), 'auto chose free: no advice to choose it');
  assert.equal(parameterizationHint(reply('circle', 5, []), 'circle', kinds), null, 'a circle map traces nothing');
  assert.equal(
    parameterizationHint(reply('measured', 0, [{ boundary: 'measured', l2: 1.03 }]), 'measured', kinds),
    null,
  );
});

test('hint of a comparison: the measured and circle rows of the weights on display', () => {
  const row = (boundary, weights, l2) => ({ boundary, weights, l2, error: null });
  // lion-head's shape-preserving rows: measured 9.21 > circle 8.88; with cotan weights 5.75 > 5.63 too.
  const lion = [
    row('measured', 'shape-preserving', 9.2085),
    row('circle', 'shape-preserving', 8.8776),
    row('measured', 'cotan', 5.7482),
    row('circle', 'cotan', 5.6321),
    row('free', 'cotan', 1.3334),
  ];
  const hint = comparisonHint(lion);
  assert.match(hint.text, /L2 9\.209 > 8\.878/);
  assert(
    hint.advice.some((a) => /free/.test(a)),
    'the free rows exist',
  );
  assert.match(comparisonHint(lion, 'cotan').text, /L2 5\.748 > 5\.632/);
  // The mountain: measured 1.03 well below circle 1.23.
  assert.equal(
    comparisonHint([row('measured', 'shape-preserving', 1.0256), row('circle', 'shape-preserving', 1.2296)]),
    null,
  );
  assert.equal(comparisonHint([row('measured', 'uniform', 2)]), null, 'no circle row: nothing to compare');
});

test('typed points: vertices and faces with barycentric coordinates, every mistake named', () => {
  const mesh = { vertices: 100, faces: 50 };
  assert.deepEqual(parsePoints('12', mesh), [{ vertex: 12 }]);
  assert.deepEqual(parsePoints(' 3, 40;77 ', mesh), [{ vertex: 3 }, { vertex: 40 }, { vertex: 77 }]);
  assert.deepEqual(parsePoints('face 3 1 1 2, 7', mesh), [{ face: 3, bary: [0.25, 0.25, 0.5] }, { vertex: 7 }]);
  assert.deepEqual(parsePoints('f 3 (0.2, 0.3, 0.5)', mesh), [{ face: 3, bary: [0.2, 0.3, 0.5] }]);
  assert.deepEqual(parsePoints('', mesh), []);
  assert.throws(() => parsePoints('100', mesh), /vertex 100 does not exist: the mesh has vertices 0 to 99/);
  assert.throws(() => parsePoints('face 50 1 0 0', mesh), /face 50 does not exist/);
  assert.throws(() => parsePoints('face 3 -1 1 1', mesh), /barycentric coordinates must be three numbers ≥ 0/);
  assert.throws(() => parsePoints('face 3 0 0 0', mesh), /not all 0/);
  assert.throws(() => parsePoints('12abc', mesh), /after "12"/);
  assert.throws(() => parsePoints('x', mesh), /cannot read "x"/);
});
