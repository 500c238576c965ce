// pack_input.hpp — what packCharts accepts: the options' and the charts' checks, and the atlas frame they give.
#pragma once
#include <optional>
#include <vector>

#include "pack_at_scale.hpp"
#include "straightest/atlas/chart_packing.hpp"

namespace straightest::atlas_detail {

/// An InvalidArgument error naming the first bad option or chart; nothing when everything is usable.
std::optional<Error> checkPackInput(const std::vector<ChartShape>& charts, const PackOptions& options);

/// The atlas size (resolution² unless width and height are given), the border of ceil(padding / 2) texels
/// and the padding, for options that passed checkPackInput.
AtlasFrame atlasFrame(const PackOptions& options);

}  // namespace straightest::atlas_detail
