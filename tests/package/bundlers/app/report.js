// Leaves an app's result (or its error) on window.__result, where tests/package/chromium.mjs reads it.
export function report(promise) {
  promise.then(
    (result) => {
      window.__result = result;
    },
    (error) => {
      window.__result = { error: String(error?.stack ?? error), category: error?.category };
    },
  );
}

/** Which module runs (threads, and why not more) and whether the cap sample parameterizes bijectively. */
export function capResult(st) {
  const mesh = st.sample('cap');
  const result = {
    threads: st.threads,
    threadsUnavailable: st.threadsUnavailable,
    bijective: mesh.parameterize().bijective,
  };
  mesh.delete();
  return result;
}
