// stl_reader.hpp — the STL reader, binary and ASCII. STL stores each triangle with its own three corners,
// so corners are welded by exact coordinate equality (+0 and −0 as one) into a shared-vertex mesh, in
// the order the file first uses each point; a triangle that welding collapses (two equal corners) is
// dropped and counted in the soup's notes. Binary: an 80-byte header, a 32-bit triangle count, 50 bytes
// per triangle; a count the file is too short for is an error before anything is allocated. ASCII:
// `solid … facet normal … outer loop vertex ×3 endloop endfacet … endsolid`, several solids allowed.
// Private to core/src: callers go through mesh_io.hpp.
#pragma once
#include <string_view>

#include "straightest/io/mesh_io.hpp"

namespace straightest {

/// True when the bytes are a binary STL by their size: 84 + 50 × the header's triangle count.
bool looksLikeBinaryStl(std::string_view bytes);

/// True when the first word is `solid` and no NUL byte follows in the first 4 KB (a binary STL's
/// header may begin with "solid" too).
bool looksLikeAsciiStl(std::string_view bytes);

/// ASCII when looksLikeAsciiStl, otherwise binary.
Expected<PolygonSoup> readStl(std::string_view bytes, const BuildLimits& limits);

}  // namespace straightest
