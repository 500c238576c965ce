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
