// The page's modes: tabs over the view (index.html #mode-tabs): the 3D surface, and the Atlas mode
// (atlas-mode.js). A mode registers here with its tab's label and is shown with body[data-mode] set to
// its id — its own 2D panel goes in #mode-side beside the view (hidden in the surface mode), its results
// in the results bar. Only the tab switching lives here.

const $ = (id) => document.getElementById(id);

let instance = null;

/** The page's modes (made on first use, after the DOM is parsed). */
export function pageModes() {
  instance ??= createModes();
  return instance;
}

function createModes() {
  const modes = new Map(); // id → { tab, enter(), leave() }
  const changed = new Set(); // listeners told the new mode's id after each switch (the URL's sync)
  let current = 'surface';

  function select(id) {
    if (!modes.has(id) || id === current) return;
    modes.get(current)?.leave();
    current = id;
    document.body.dataset.mode = id;
    for (const [key, { tab }] of modes) tab.setAttribute('aria-selected', String(key === id));
    $('mode-side').hidden = !modes.get(id).side;
    modes.get(id).enter();
    for (const listener of changed) listener(id);
  }

  /**
   * Adds a mode: { id, label, side (whether it uses #mode-side), enter(), leave() }; returns its tab.
   * The surface mode is registered by the page itself (its tab is in the HTML).
   */
  function register({ id, label, side = false, enter = () => {}, leave = () => {} }) {
    let tab = $(`mode-tab-${id}`);
    if (!tab) {
      tab = document.createElement('button');
      tab.type = 'button';
      tab.role = 'tab';
      tab.id = `mode-tab-${id}`;
      tab.dataset.mode = id;
      tab.textContent = label;
      tab.setAttribute('aria-selected', 'false');
      $('mode-tabs').append(tab);
    }
    tab.addEventListener('click', () => select(id));
    modes.set(id, { tab, side, enter, leave });
    return tab;
  }

  register({ id: 'surface', label: '3D surface' });
  return {
    register,
    select,
    /** Calls listener(id) after every switch of mode. */
    onChange(listener) {
      changed.add(listener);
    },
    get current() {
      return current;
    },
  };
}
