// Keeps the page's URL and the page in step (the encoding: url-state.js): on opening, the URL's view
// options are set on their controls, its mode is selected, its sample is the one loaded and its source
// and destinations are restored on that mesh; afterwards every change is written back with history.replaceState. A link to
// a file asks for the file by name (#file-wanted) and restores the rest once a file of that name is
// opened; until then the URL is left as it came, so the link still works when copied again.

import { OPTIONS, decodeState, encodeState, pointsFit } from './url-state.js';
import { pageModes } from './modes.js';

const $ = (id) => document.getElementById(id);

// Checkboxes and menus whose listeners must run when the URL sets them (the others are read when used).
const DISPATCHED = ['wire', 'flat', 'base', 'paths', 'checker'];

/**
 * session: session.js (origin of the mesh on display); param: param-view.js (chooseBoundary,
 * boundaryChosen); points(): { source, destinations } of the paths on display.
 */
export function createUrlSync({ session, param, points }) {
  const wanted = decodeState(location.search);
  // The mesh whose source and destinations the URL holds, until it is on display (or another is opened).
  let pending = wanted.sample || wanted.file ? wanted : null;
  let opening = true; // the page's own first mesh (a link to a file shows the default sample meanwhile)

  function save() {
    if (pending?.file) return; // the link's file is not open yet: keep the link as it came
    const origin = session.origin;
    if (!origin) return;
    const options = {};
    for (const [name, option] of Object.entries(OPTIONS)) {
      const control = $(option.id);
      if (name === 'boundary' && !param.boundaryChosen) continue; // each mesh's own default otherwise
      options[name] = 'check' in option ? control.checked : control.value;
    }
    const { source, destinations } = points();
    const mode = pageModes().current;
    const query = encodeState({ sample: origin.sample, file: origin.file?.name, mode, source, destinations, options });
    const url = `${location.pathname}${query ? `?${query}` : ''}${location.hash}`;
    if (url !== `${location.pathname}${location.search}${location.hash}`) history.replaceState(null, '', url);
  }

  for (const { id } of Object.values(OPTIONS)) $(id).addEventListener('change', () => save());
  pageModes().onChange(() => save());

  return {
    /**
     * Sets the URL's view options on their controls and selects its mode (once every control has its
     * listeners and every mode is registered), and asks for its file.
     */
    applyOptions() {
      for (const [name, value] of Object.entries(wanted.options)) {
        const option = OPTIONS[name];
        const control = $(option.id);
        if (name === 'boundary' || !control) continue; // the menu is filled by the worker: see meshShown
        if ('check' in option) control.checked = value;
        else if (control.tagName !== 'SELECT')
          control.value = value; // a field: its reader names a bad value
        else if ([...control.options].some((o) => o.value === value && !o.disabled)) control.value = value;
        if (DISPATCHED.includes(name)) control.dispatchEvent(new Event('change'));
      }
      pageModes().select(wanted.mode); // (an unknown mode is ignored)
      if (wanted.file) {
        $('file-wanted').textContent =
          `This link shows “${wanted.file}”: open that file (Open file, or drop it ` +
          'on the view) to see it with the link’s source, destinations and options.';
        $('file-wanted').hidden = false;
      }
    },

    /** The sample to open with: the URL's, if the worker has it. */
    initialSample(samples) {
      return samples.includes(wanted.sample) ? wanted.sample : null;
    },

    /**
     * A mesh is on display (label: its sample or file name; info: mesh.info()): the URL's source and
     * destinations if they belong to it ({ source, destinations }, or null), and its boundary choice.
     */
    meshShown(label, info) {
      const first = opening;
      opening = false;
      if (!pending) return null;
      const mine = (pending.file ?? pending.sample) === label;
      if (!mine && first && pending.file) return null; // still waiting for the link's file
      const restore = pending;
      pending = null;
      $('file-wanted').hidden = true;
      if (!mine) return null;
      if (restore.options.boundary) param.chooseBoundary(restore.options.boundary);
      const counts = { vertices: info.vertices, faces: info.faces };
      const source = restore.source === 'auto' || pointsFit([restore.source], counts) ? restore.source : 'auto';
      return { source, destinations: pointsFit(restore.destinations, counts) ? restore.destinations : [] };
    },

    /** Writes the page's state into the URL (after a trace, a parameterization, an option change). */
    save,
  };
}
