// "Latest request wins": the one rule behind every asynchronous update of the page. A newer
// request, a cancel or a new mesh makes the replies of older requests stale, and a stale reply
// must not touch the view.
//
//   const traces = latest();            // one channel per kind of request
//   const request = traces.begin(meshes); // a new trace: older traces are stale from now on
//   ... await ...;
//   if (request.stale()) return;         // a newer trace, traces.supersede() or a new mesh came
//
// begin(...watched) also watches other channels without advancing them (a reply for the previous
// mesh is stale even if no newer trace began).

/** A channel of requests of which only the latest counts. */
export function latest() {
  let generation = 0;
  const channel = {
    /** The current generation (what begin() captures of a watched channel). */
    get generation() {
      return generation;
    },

    /** Starts a request: every earlier one of this channel is stale from now on. */
    begin(...watched) {
      generation += 1;
      const channels = [channel, ...watched];
      const seen = channels.map((c) => c.generation);
      return { stale: () => channels.some((c, i) => c.generation !== seen[i]) };
    },

    /** Makes every request of this channel stale (a cancel, a new mesh). */
    supersede() {
      generation += 1;
    },
  };
  return channel;
}
