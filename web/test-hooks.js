// The page's test hooks, in one place: window.__straightest and document.body.dataset.state, the
// only things the browser tests read besides the DOM. Every module that reports something writes
// the field documented here (and nothing else on window).

export const hooks = {
  // 'loading' | 'ready' | 'error' (also document.body.dataset.state): 'ready' once the mesh and its
  // paths are drawn.
  state: 'loading',
  // The other fields are read from the modules' status() and getters by main.js (expose below);
  // docs/PAGE.md lists them all.
};
window.__straightest = hooks;

export function setState(state) {
  hooks.state = state;
  document.body.dataset.state = state;
}

/**
 * Adds read-only fields to window.__straightest, each read from the module that has it on display
 * when a test asks (getters: fields: { name: () => value }). The page's modules keep what they show
 * to themselves; only main.js, which holds them all, calls this.
 */
export function expose(fields) {
  for (const [name, get] of Object.entries(fields)) {
    Object.defineProperty(hooks, name, { get, enumerable: true });
  }
}
