// StraightestError: the one error type of the npm package, shared by its entries (index.js, the loader,
// the three.js helpers). `category` is machine-readable (st.errorCategories lists the core's).

/** An error from the core: `message` says what was found and where; `category` is machine-readable. */
export class StraightestError extends Error {
  constructor(message, category = 'internal', options = undefined) {
    super(message, options);
    this.name = 'StraightestError';
    this.category = category;
  }
}
