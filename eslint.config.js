// JavaScript lint (eslint flat config): @eslint/js's recommended rules, with each directory's globals —
// the npm package runs in browsers and Node, the page in a browser, the
// scripts and tests under Node (the browser tests' page.evaluate callbacks run in the page).
// `npm run lint` (scripts/lint.sh) runs it with the format and type checks.
import js from '@eslint/js';
import globals from 'globals';

export default [
  { ignores: ['wasm/dist/', 'build/', 'node_modules/'] },
  js.configs.recommended,
  {
    linterOptions: { reportUnusedDisableDirectives: 'error' },
  },
  { files: ['wasm/**/*.js'], languageOptions: { globals: { ...globals.browser, ...globals.node } } },
  { files: ['web/**/*.js'], languageOptions: { globals: globals.browser } },
  {
    files: ['scripts/**/*.mjs', 'tests/js/**/*.mjs', 'tests/cli/**/*.mjs'],
    languageOptions: { globals: globals.node },
  },
  { files: ['tests/e2e/**/*.mjs'], languageOptions: { globals: { ...globals.node, ...globals.browser } } },
  // The consumer tests' helpers run under Node; the consumer apps they build run in a browser.
  { files: ['tests/package/*.mjs'], languageOptions: { globals: globals.node } },
  { files: ['tests/package/**/app/*.js'], languageOptions: { globals: globals.browser } },
  { files: ['eslint.config.js'], languageOptions: { globals: globals.node } },
];
