// The progress panel over the 3D view: while the worker runs, one group per request of the current
// job (loading a mesh, then its paths, then its parameterization, …) and in it one bar per stage
// with its percentage, fed by each request's progress (the core's progress callbacks; see
// requests.js). A stage that the core only reports as started and finished (parsing, the weights, the
// solver's setup) shows a moving bar while it runs. The Cancel button stops the job (session.js
// restarts the worker). The panel appears only when a job takes longer than a moment and hides when
// the worker is idle again; everything here is DOM, and the page stays interactive meanwhile.
//
// What it has shown, as plain data, is status() (main.js puts it in the page's observable state as
// progress, docs/PAGE.md), its stages keyed by the request type ('file', 'paths', 'parameterize', …)
// and stage.

const $ = (id) => document.getElementById(id);

const SHOW_DELAY_MS = 150; // jobs shorter than this never show the panel
const LINGER_MS = 350; // the finished bars stay this long (a follow-up request continues the job)

const STAGE_LABELS = {
  load: 'parse and check',
  upload: 'transfer',
  trace: 'trace paths',
  heat: 'heat method',
  source: 'find the center',
  weights: 'weights',
  solve: 'solve',
  metrics: 'metrics',
  refine: 'refine (free boundary)',
  overlays: 'other boundaries',
  compare: 'runs',
  export: 'write OBJ',
  distances: 'exact shortest path',
  shoot: 'shoot the geodesic',
  segment: 'segment into charts',
  flatten: 'flatten the charts',
  pack: 'pack',
  measure: 'measure (independent check)',
};

function requestTitle(type, payload) {
  switch (type) {
    case 'file':
    case 'sample': {
      const name = payload.name ?? '';
      return payload.restore ? `Reloading “${name}” in a new worker` : `Loading “${name}”`;
    }
    case 'paths':
      return 'Straightest paths';
    case 'distances':
      return 'Heat distances';
    case 'parameterize':
      return `Parameterization (${payload.boundary ?? 'measured'} boundary)`;
    case 'compare':
      return 'Comparison (every boundary × weights)';
    case 'exportObj':
      return 'OBJ export';
    case 'atlas':
      return `Texture atlas (${payload.resolution ?? 1024} texels, padding ${payload.padding ?? 2})`;
    case 'geodesics':
      return 'Geodesics to the destination';
    default:
      return null; // 'init' and the like: no group
  }
}

/**
 * One request's group in the progress list: its title and a row per stage, added as the stages are
 * announced; markActive() shows which stage runs.
 */
function progressGroup(list, title) {
  const group = document.createElement('li');
  group.className = 'progress-group running';
  const heading = document.createElement('span');
  heading.className = 'progress-title';
  heading.textContent = title;
  const stages = document.createElement('ol');
  group.append(heading, stages);
  list.append(group);
  const rows = new Map(); // stage -> { item, bar, pct, fraction, started }

  function row(stage) {
    let entry = rows.get(stage);
    if (entry) return entry;
    const item = document.createElement('li');
    item.className = 'stage pending';
    item.dataset.stage = stage;
    const name = document.createElement('span');
    name.className = 'stage-name';
    name.textContent = STAGE_LABELS[stage] ?? stage;
    const bar = document.createElement('progress');
    bar.max = 1;
    bar.value = 0;
    const pct = document.createElement('span');
    pct.className = 'stage-pct';
    pct.textContent = '0%';
    item.append(name, bar, pct);
    stages.append(item);
    entry = { item, bar, pct, fraction: 0, started: false };
    rows.set(stage, entry);
    return entry;
  }

  /** The running stage is the first started one not finished; it moves while at 0%. */
  function markActive() {
    let found = false;
    for (const entry of rows.values()) {
      const running = !found && entry.started && entry.fraction < 1;
      if (running) found = true;
      entry.item.className = `stage ${entry.fraction >= 1 ? 'done' : running ? 'active' : entry.started ? 'started' : 'pending'}`;
      if (running && entry.fraction === 0)
        entry.bar.removeAttribute('value'); // indeterminate
      else entry.bar.value = entry.fraction;
    }
  }

  /** The request ended: what did not finish shows as stopped. */
  function stop() {
    group.classList.remove('running');
    for (const entry of rows.values()) if (entry.fraction < 1) entry.item.className = 'stage stopped';
  }

  return { row, markActive, stop };
}

/** onCancel(): the Cancel button was pressed. */
export function createProgressView({ onCancel }) {
  const panel = $('progress-panel');
  const list = $('progress-groups');
  const elapsed = $('progress-elapsed');
  const cancelButton = $('cancel-button');

  let active = 0; // tasks running
  let jobStart = 0; // performance.now() when the job began; 0 when idle
  let showTimer = 0;
  let hideTimer = 0;
  let tick = 0; // interval updating the elapsed time while the panel is shown
  // For status(): busy while a job runs (and its bars linger), the jobs and progress messages so far,
  // the largest fraction each stage ('type:stage') of the current (or last) job reached, and when (ms
  // after the job began) it was first reported and reached 100%: [first, done or null].
  const progress = { busy: false, jobs: 0, messages: 0, stages: {}, times: {} };

  function updateElapsed() {
    if (jobStart) elapsed.textContent = `${((performance.now() - jobStart) / 1000).toFixed(1)} s`;
  }

  function show() {
    showTimer = 0;
    panel.hidden = false;
    updateElapsed();
    tick ||= setInterval(updateElapsed, 100);
  }

  function idle() {
    hideTimer = 0;
    jobStart = 0;
    panel.hidden = true;
    clearInterval(tick);
    tick = 0;
    progress.busy = false;
  }

  /** The worker was idle: a new job, its panel shown if it lasts. */
  function startJob() {
    jobStart = performance.now();
    list.replaceChildren();
    progress.stages = {};
    progress.times = {};
    progress.jobs += 1;
    showTimer = setTimeout(show, SHOW_DELAY_MS);
  }

  /** A request starts: a new job if the worker was idle, else another group of the same one. */
  function begin(type, payload) {
    const title = requestTitle(type, payload);
    if (!title) return null;
    clearTimeout(hideTimer);
    hideTimer = 0;
    if (!jobStart) startJob();
    progress.busy = true;
    active += 1;
    cancelButton.disabled = false;

    const group = progressGroup(list, title);

    let ended = false;
    return {
      update({ stage, fraction, stages: planned }) {
        if (ended) return;
        progress.messages += 1;
        for (const name of planned ?? []) group.row(name);
        const entry = group.row(stage);
        entry.started = true;
        entry.fraction = Math.max(entry.fraction, fraction);
        entry.pct.textContent = `${Math.floor(100 * entry.fraction)}%`;
        const key = `${type}:${stage}`;
        progress.stages[key] = Math.max(progress.stages[key] ?? 0, entry.fraction);
        const now = Math.round(performance.now() - jobStart);
        const times = (progress.times[key] ??= [now, null]);
        if (entry.fraction >= 1) times[1] ??= now;
        group.markActive();
      },
      end() {
        if (ended) return;
        ended = true;
        group.stop();
        active -= 1;
        if (active > 0) return;
        cancelButton.disabled = true; // the finished bars linger: nothing left to cancel
        clearTimeout(showTimer);
        showTimer = 0;
        updateElapsed();
        hideTimer = setTimeout(idle, LINGER_MS);
      },
    };
  }

  cancelButton.addEventListener('click', () => {
    if (active > 0) onCancel();
  });

  return {
    begin,
    /** True while a request with a group runs (the Cancel button is useful). */
    busy: () => active > 0,
    /** What it has shown: { busy, jobs, messages, stages, times } (a copy: see `progress` above). */
    status: () => structuredClone(progress),
  };
}
