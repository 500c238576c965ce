// Side panels that fold away: each panel's heading becomes a button that hides everything else in
// the panel (CSS: .panel.collapsed), so the panels in use fit on one screen. Which ones are folded is
// remembered in localStorage (a preference of the reader, not state of the result: not in the URL).

const STORAGE_KEY = 'straightest.collapsedPanels';

function remembered() {
  try {
    return new Set(JSON.parse(localStorage.getItem(STORAGE_KEY) ?? '[]'));
  } catch {
    return new Set(); // storage blocked or garbled: all open
  }
}

function remember(collapsed) {
  try {
    localStorage.setItem(STORAGE_KEY, JSON.stringify([...collapsed]));
  } catch {
    /* storage blocked: not remembered */
  }
}

/** Makes every `.panel` with an id and an h2 in `root` collapsible (the error panel stays open). */
export function makePanelsCollapsible(root) {
  const collapsed = remembered();
  for (const panel of root.querySelectorAll('.panel[id]')) {
    const heading = panel.querySelector(':scope > h2');
    if (!heading || panel.getAttribute('role') === 'alert') continue;
    const button = document.createElement('button');
    button.type = 'button';
    button.className = 'panel-toggle';
    button.append(...heading.childNodes); // the heading's text and spans (e.g. the info panel's source)
    heading.append(button);
    const setCollapsed = (value) => {
      panel.classList.toggle('collapsed', value);
      button.setAttribute('aria-expanded', String(!value));
    };
    setCollapsed(collapsed.has(panel.id));
    button.addEventListener('click', () => {
      const value = !panel.classList.contains('collapsed');
      setCollapsed(value);
      if (value) collapsed.add(panel.id);
      else collapsed.delete(panel.id);
      remember(collapsed);
    });
  }
}
