// The heat-distance colours: the surface coloured by the heat-method distance from the paths'
// source (computed by the worker), with its legend over the view.

import { heatColors, heatGradient } from './colormap.js';
import { latest } from './latest.js';
import { formatNumber } from './panels.js';

const $ = (id) => document.getElementById(id);

/**
 * session: session.js (request, meshes); surface: surface-view.js; paths: path-view.js (the source
 * of the paths on display); wanted(): the toggle is still on when the distances arrive.
 */
export function createHeatDistance({ session, surface, paths, wanted }) {
  const requests = latest();
  $('heat-legend').querySelector('.ramp').style.background = heatGradient();

  return {
    /** Colours the surface by the distance from the shown paths' source. */
    async show() {
      if (!surface.mesh || !paths.shown) return;
      const request = requests.begin(session.meshes);
      const reply = await session.request('distances', { source: paths.shown.reply.source });
      if (request.stale() || !wanted()) return;
      surface.setColors(heatColors(reply.distances, reply.max)); // they replace the texture
      $('heat-max').textContent = formatNumber(reply.max);
      $('heat-legend').hidden = false;
    },

    /** Back to the plain surface (distances still coming are dropped). */
    reset() {
      requests.supersede();
      surface.setColors(null);
      $('heat-legend').hidden = true;
    },

    /** Distances still coming are dropped (Cancel). */
    cancel() {
      requests.supersede();
    },
  };
}
