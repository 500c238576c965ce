// Which axis points up when the page opens a mesh, the "Up" menu's auto choice. No rule reads the up
// axis off every mesh's shape (the elephant, y up, is thinnest along z, like a relief; Nefertiti's bust
// too), so the rule is a convention with one exception that geometry does settle:
// - the built-in samples are height fields z = h(x, y): z up;
// - a file whose z extent is under half of both its x and y extents is a relief or terrain lying in
//   the xy plane: z up;
// - any other file: y up, the convention of three.js, glTF and most modellers' OBJ exports.
// The menu's x / y / z override it.

/** 'y' or 'z' for a mesh with bounding box `bbox` ({ min, max }); `builtIn` for the samples. */
export function autoUpAxis(bbox, builtIn) {
  if (builtIn) return 'z';
  const [dx, dy, dz] = [0, 1, 2].map((axis) => bbox.max[axis] - bbox.min[axis]);
  return dz < 0.5 * Math.min(dx, dy) ? 'z' : 'y';
}
