// pack_input.cpp — the checks of packCharts' options and charts, each error saying what was found and where.
#include "pack_input.hpp"

#include <cmath>
#include <string>

#include "straightest/base/tolerances.hpp"

namespace straightest::atlas_detail {
namespace {

Error invalid(const std::string& message) { return Error{ErrorCode::InvalidArgument, message}; }

std::optional<Error> checkSize(const PackOptions& options) {
  const std::string limit = std::to_string(kMaxAtlasSide);
  if (options.width == 0 && options.height == 0) {
    if (options.resolution <= 0 || options.resolution > kMaxAtlasSide)
      return invalid("pack: resolution must be 1.." + limit + " texels, got " + std::to_string(options.resolution));
    return std::nullopt;
  }
  if (options.width <= 0 || options.height <= 0 || options.width > kMaxAtlasSide || options.height > kMaxAtlasSide)
    return invalid("pack: width and height must both be 0 (use resolution) or both 1.." + limit + ", got " +
                   std::to_string(options.width) + " x " + std::to_string(options.height));
  return std::nullopt;
}

std::optional<Error> checkScaleAndPadding(const PackOptions& options) {
  if (!std::isfinite(options.padding) || options.padding < 0)
    return invalid("pack: padding must be a finite number of texels >= 0, got " + numberText(options.padding));
  if (!std::isfinite(options.texelsPerUnit) || options.texelsPerUnit < 0)
    return invalid("pack: texelsPerUnit must be finite and >= 0 (0: the largest that fits), got " +
                   numberText(options.texelsPerUnit));
  const AtlasFrame frame = atlasFrame(options);
  if (2 * static_cast<double>(frame.border) >= std::min(frame.width, frame.height))
    return invalid("pack: a padding of " + numberText(options.padding) + " texels leaves no room in a " +
                   std::to_string(frame.width) + " x " + std::to_string(frame.height) + " atlas");
  return std::nullopt;
}

std::optional<Error> checkChart(const ChartShape& chart, size_t index) {
  const std::string name = "pack: chart " + std::to_string(index);
  if (chart.triangles.empty()) return invalid(name + " has no triangles");
  if (chart.triangles.size() % 3 != 0)
    return invalid(name + " has " + std::to_string(chart.triangles.size()) + " points, not 3 per triangle");
  for (size_t i = 0; i < chart.triangles.size(); ++i) {
    const Vec2 p = chart.triangles[i];
    if (!isFinite(p) || std::abs(p.x) > kMaxCoordinate || std::abs(p.y) > kMaxCoordinate)
      return invalid(name + ", triangle " + std::to_string(i / 3) + ": point (" + numberText(p.x) + ", " +
                     numberText(p.y) + ") is not finite (or beyond 1e50)");
  }
  return std::nullopt;
}

}  // namespace

AtlasFrame atlasFrame(const PackOptions& options) {
  AtlasFrame frame;
  const bool square = options.width == 0 && options.height == 0;
  frame.width = square ? options.resolution : options.width;
  frame.height = square ? options.resolution : options.height;
  frame.padding = options.padding;
  // Half the padding on each side of the border keeps the padding between tiled copies of the atlas.
  frame.border = static_cast<int32_t>(std::min(std::ceil(options.padding / 2), double{kMaxAtlasSide}));
  return frame;
}

std::optional<Error> checkPackInput(const std::vector<ChartShape>& charts, const PackOptions& options) {
  if (auto error = checkSize(options)) return error;
  if (auto error = checkScaleAndPadding(options)) return error;
  for (size_t i = 0; i < charts.size(); ++i) {
    if (auto error = checkChart(charts[i], i)) return error;
  }
  return std::nullopt;
}

}  // namespace straightest::atlas_detail
