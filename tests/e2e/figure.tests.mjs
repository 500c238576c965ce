// Browser tests of figure mode and the image exports: the grid of every boundary with its stretch,
// the PNG exports' sizes at a chosen resolution, the SVG layout's caption, and the path style
// controls. Imported by browser.test.mjs, which owns the browser (useBrowser).

import assert from 'node:assert/strict';
import { describe } from 'node:test';
import { pageTest, streamText } from './support/fixtures.mjs';
import { decodePng } from './support/images.mjs';

const IDLE = 'window.__straightest.param && !window.__straightest.progress.busy';

/** A download's bytes. */
async function downloaded(download) {
  return Buffer.from(await streamText(await download.createReadStream(), 'latin1'), 'latin1');
}

/** A PNG's width and height from its IHDR header (bytes 16–23), checked against its signature. */
function pngSize(png) {
  assert.equal(png.subarray(1, 4).toString('latin1'), 'PNG', 'not a PNG file');
  assert.equal(png.subarray(12, 16).toString('latin1'), 'IHDR', 'no IHDR chunk first');
  return { width: png.readUInt32BE(16), height: png.readUInt32BE(20) };
}

/** Clicks `selector` and returns the download it starts. */
async function downloadOf(page, selector) {
  const [download] = await Promise.all([page.waitForEvent('download'), page.click(selector)]);
  return download;
}

/** Sets an input's value as the user's dragging or picking would (an 'input' event). */
function setInput(page, selector, value) {
  return page.$eval(
    selector,
    (input, v) => {
      input.value = v;
      input.dispatchEvent(new Event('input', { bubbles: true }));
    },
    value,
  );
}

/** The share of the view's pixels in the reached paths' colour (blue, which the mesh never has). */
async function pathPixels(page) {
  const image = decodePng(await page.locator('#view-canvas').screenshot());
  let blue = 0;
  for (let i = 0; i < image.width * image.height; i++) {
    const [r, g, b] = image.data.subarray(i * image.channels, i * image.channels + 3);
    if (b > r + 60 && b > g + 20) blue++;
  }
  return blue / (image.width * image.height);
}

describe('figure mode and exports', () => {
  pageTest(
    "Figure shows every boundary side by side with its L2; the measured one is the single view's",
    {
      ready: IDLE,
    },
    async ({ page }) => {
      const single = await page.evaluate(() => window.__straightest.param);
      assert.equal(single.boundary, 'measured', 'the page opens with the measured boundary');
      const singleText = (await page.textContent('#param-l2')).trim();
      await page.click('#figure-button');
      await page.waitForFunction(() => window.__straightest.figure?.state === 'done');
      const { figure } = await page.evaluate(() => window.__straightest);
      const boundaries = figure.panels.map((p) => p.boundary);
      assert(figure.panels.length >= 3 && figure.panels.length <= 4, `${figure.panels.length} panels: ${boundaries}`);
      for (const kind of ['square', 'circle', 'measured'])
        assert(boundaries.includes(kind), `no ${kind} panel: ${boundaries}`);
      assert(
        figure.panels.every((p) => Number.isFinite(p.l2) && p.l2 >= 1),
        `stretch: ${JSON.stringify(figure.panels)}`,
      );

      // What the grid shows: one panel per boundary, its L2 written under it, a drawn 3D image and layout.
      const shown = await page.$$eval('#figure-view .figure-panel', (panels) =>
        panels.map((panel) => {
          const drawn = (canvas) => {
            const { data } = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height);
            const corner = data.slice(0, 3);
            let differing = 0;
            for (let i = 0; i < data.length; i += 4) {
              if (
                Math.abs(data[i] - corner[0]) + Math.abs(data[i + 1] - corner[1]) + Math.abs(data[i + 2] - corner[2]) >
                30
              )
                differing++;
            }
            return differing / (data.length / 4);
          };
          return {
            boundary: panel.dataset.boundary,
            text: panel.querySelector('figcaption').textContent,
            image: drawn(panel.querySelector('.figure-3d')),
            layout: drawn(panel.querySelector('.figure-uv')),
          };
        }),
      );
      assert.deepEqual(
        shown.map((s) => s.boundary),
        boundaries,
        'the grid and the hook disagree',
      );
      for (const [i, panel] of shown.entries()) {
        const l2 = Number(/L2 ([\d.,]+)/.exec(panel.text)?.[1]);
        assert(
          Number.isFinite(l2) && Math.abs(l2 - figure.panels[i].l2) < 1e-3 * l2,
          `${panel.boundary}: '${panel.text}'`,
        );
        assert(
          panel.image > 0.05,
          `${panel.boundary}: only ${(panel.image * 100).toFixed(1)}% of its 3D image is drawn`,
        );
        assert(
          panel.layout > 0.05,
          `${panel.boundary}: only ${(panel.layout * 100).toFixed(1)}% of its layout is drawn`,
        );
      }
      // The same options give the same map: the measured panel is the single view's, to the last digit.
      const measured = figure.panels.find((p) => p.boundary === 'measured');
      assert.equal(measured.l2, single.l2, "the measured panel's L2 differs from the single view's");
      const measuredText = shown.find((s) => s.boundary === 'measured').text;
      assert(
        measuredText.includes(`L2 ${singleText}`),
        `measured panel '${measuredText}', single view L2 '${singleText}'`,
      );

      // The grid as one image at 1× and 2×: twice the pixels each way.
      await page.selectOption('#export-scale', '1');
      const one = pngSize(await downloaded(await downloadOf(page, '#export-figure-button')));
      await page.selectOption('#export-scale', '2');
      const two = pngSize(await downloaded(await downloadOf(page, '#export-figure-button')));
      assert(
        one.width > 3 * 300 && two.width === 2 * one.width && two.height === 2 * one.height,
        `figure PNG ${one.width}×${one.height} at 1×, ${two.width}×${two.height} at 2×`,
      );

      // Back to the 3D view: the grid goes, the view is drawn again as it was.
      const renders = await page.evaluate(() => window.__straightest.renders);
      await page.click('#figure-close-button');
      assert(await page.isHidden('#figure-view'), 'the grid stays over the view');
      await page.waitForFunction((n) => window.__straightest.renders > n, renders);
      assert.equal((await page.evaluate(() => window.__straightest.param)).l2, single.l2, 'the single view changed');
    },
  );

  pageTest(
    "the 3D view PNG at 2× has twice the canvas's pixels; the layout SVG carries its whole caption",
    {
      ready: IDLE,
    },
    async ({ page }) => {
      const css = await page.$eval('#view-canvas', (canvas) => ({
        width: canvas.clientWidth,
        height: canvas.clientHeight,
      }));
      await page.selectOption('#export-scale', '1');
      const one = pngSize(await downloaded(await downloadOf(page, '#export-view-button')));
      assert.deepEqual(one, css, `1× view PNG ${one.width}×${one.height}, canvas ${css.width}×${css.height}`);
      await page.selectOption('#export-scale', '2');
      await page.selectOption('#export-background', 'transparent');
      const png = await downloaded(await downloadOf(page, '#export-view-button'));
      const two = pngSize(png);
      assert.deepEqual(two, { width: 2 * css.width, height: 2 * css.height }, `2× view PNG ${two.width}×${two.height}`);
      const image = decodePng(png);
      assert.equal(image.channels, 4, 'a transparent export has an alpha channel');
      const transparent = image.data[3] === 0; // a corner: background, no mesh
      assert(transparent, `the corner's alpha is ${image.data[3]}`);

      // The layout: the PNG at 2× the export width, the SVG with the title, the caption and the key whole.
      const layoutPng = pngSize(await downloaded(await downloadOf(page, '#export-png-button')));
      assert(
        layoutPng.width === 2 * 720 && layoutPng.height > layoutPng.width,
        `layout PNG ${layoutPng.width}×${layoutPng.height}`,
      );
      const svgDownload = await downloadOf(page, '#export-svg-button');
      assert(
        svgDownload.suggestedFilename().endsWith('-measured-shape-preserving-uv-layout.svg'),
        svgDownload.suggestedFilename(),
      );
      const svg = (await downloaded(svgDownload)).toString('utf8');
      assert(svg.startsWith('<svg') && svg.trimEnd().endsWith('</svg>'), 'not an SVG document');
      const texts = [...svg.matchAll(/<text[^>]*>([^<]*)<\/text>/g)].map((m) => m[1].replace(/&#38;/g, '&')).join(' ');
      const l2 = (await page.textContent('#param-l2')).trim();
      for (const part of [
        'mountain — measured boundary',
        'shape-preserving',
        `L2 ${l2}`,
        'L∞',
        'thin lines: mesh edges · dashed square: the uv frame [0,1]²',
      ]) {
        assert(texts.includes(part), `the SVG's text lacks '${part}': ${texts}`);
      }
      assert(!texts.includes('…'), `the SVG's caption is cut: ${texts}`);
      const edges = /d="(M[^"]*)" fill="none" stroke="[^"]*" stroke-width="0.5"/.exec(svg)?.[1] ?? '';
      const triangles = (edges.match(/Z/g) ?? []).length;
      const faces = await page.evaluate(() => window.__straightest.lastInfo.faces);
      assert.equal(triangles, faces, "the SVG draws every face's edges once");
    },
  );

  pageTest(
    'hiding the paths takes them off the view; width and colour restyle them; counts have thousands separators',
    {
      ready: IDLE,
    },
    async ({ page }) => {
      // Counts of five digits or more have thousands separators (the mountain's paths cross over 10,000 faces).
      const faces = (await page.textContent('#stats-faces')).trim();
      const [sum, max] = faces.split(' / ').map((text) => Number(text.replace(/,/g, '')));
      assert(sum >= 10_000 && faces === `${sum.toLocaleString('en-US')} / ${max}`, `faces crossed: '${faces}'`);
      assert(!/\b0\.0 ms/.test(await page.textContent('#side-panel')), 'a time reads "0.0 ms"');

      const shown = await pathPixels(page);
      assert(shown > 0.005, `only ${(shown * 100).toFixed(2)}% of the view shows the paths`);
      let renders = await page.evaluate(() => window.__straightest.renders);
      await page.uncheck('#paths-toggle');
      await page.waitForFunction((n) => window.__straightest.renders > n, renders);
      const hidden = await pathPixels(page);
      assert(
        hidden < shown / 10,
        `${(hidden * 100).toFixed(2)}% path pixels with the paths hidden, ${(shown * 100).toFixed(2)}% shown`,
      );

      renders = await page.evaluate(() => window.__straightest.renders);
      await page.check('#paths-toggle');
      await setInput(page, '#path-width', '3');
      await page.waitForFunction((n) => window.__straightest.renders > n, renders);
      const wide = await pathPixels(page);
      assert(
        wide > 1.5 * shown,
        `${(wide * 100).toFixed(2)}% path pixels at 3× width, ${(shown * 100).toFixed(2)}% at 1×`,
      );

      renders = await page.evaluate(() => window.__straightest.renders);
      await setInput(page, '#path-color', '#e08a00'); // orange: no longer the blue the count looks for
      await page.waitForFunction((n) => window.__straightest.renders > n, renders);
      const recoloured = await pathPixels(page);
      assert(recoloured < shown / 10, `${(recoloured * 100).toFixed(2)}% blue pixels with orange paths`);
    },
  );
});
