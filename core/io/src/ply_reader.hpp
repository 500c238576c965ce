// ply_reader.hpp — the PLY reader: ASCII, binary little endian and binary big endian (format 1.0).
// Only two things are read: the `vertex` element's x, y, z (any numeric type) and the `face` element's
// list property `vertex_indices` (or `vertex_index`) with any integer count and index types; every
// other element and property (normals, colours, edges, materials) is skipped. Counts in the header are
// checked against the caps and against the bytes that follow before anything is allocated, so a
// header that lies is an error, not an allocation; a file that ends early, an index out of range, a
// non-finite coordinate or an unsupported format (another version, a float index list) is an error that
// says which element and where. Polygons are triangulated. Private to core/src: callers go through
// mesh_io.hpp.
#pragma once
#include <string_view>

#include "straightest/io/mesh_io.hpp"

namespace straightest {

/// True when the bytes start with the PLY magic line ("ply" and a line end).
bool looksLikePly(std::string_view bytes);

Expected<PolygonSoup> readPly(std::string_view bytes, const BuildLimits& limits);

}  // namespace straightest
