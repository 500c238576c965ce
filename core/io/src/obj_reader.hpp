// obj_reader.hpp — the OBJ reader: positions (`v`) and faces (`f`) in one pass over the bytes; every
// other statement (`vt`, `vn`, `vw`, `l`, `o`, `g`, `usemtl`, ...) is skipped unread. Lines end at
// "\n", "\r\n" or a lone "\r"; a keyword is delimited by spaces or tabs only. Face corners may be
// `v`, `v/vt`, `v//vn` or `v/vt/vn`; only the vertex index is used, 1-based or negative (relative to
// the vertices defined so far). Polygons are triangulated on the way. Private to core/src: callers go
// through mesh_io.hpp.
#pragma once
#include <string_view>

#include "straightest/io/mesh_io.hpp"

namespace straightest {

/// Every error names its line (and vertex or face): a coordinate that is not a finite plain decimal,
/// a `v` line with fewer than 3 coordinates, a face with fewer than 3 corners, an index that is 0,
/// not an integer, or refers to a vertex the file does not have.
Expected<PolygonSoup> readObj(std::string_view text, const BuildLimits& limits);

}  // namespace straightest
