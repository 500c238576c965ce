// off_reader.hpp — the OFF reader: OFF, COFF (a colour per vertex) and NOFF (a normal per vertex),
// with `#` comments and blank lines anywhere. Strict: the header's counts must match what follows,
// every vertex has exactly its three coordinates (plus the variant's extras), every face its announced
// number of 0-based indices, and nothing may follow the last face. Counts are checked against the caps
// and against the bytes left before anything is allocated. Polygons are triangulated on the way.
// Private to core/src: callers go through mesh_io.hpp.
#pragma once
#include <string_view>

#include "straightest/io/mesh_io.hpp"

namespace straightest {

/// Every error names its line (and vertex or face).
Expected<PolygonSoup> readOff(std::string_view text, const BuildLimits& limits);

}  // namespace straightest
