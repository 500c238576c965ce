// atlas_compare — measures an atlas written as JSON (bench/atlas/xatlas-run.mjs's output, or ours in the
// same shape) with measureAtlas, and prints the measurement as one JSON line.
//   usage: atlas_compare ATLAS.json [--mesh MESH] [--padding TEXELS]
// The mesh is loaded through core's loadMeshFile (the JSON's "mesh" unless --mesh is given), so the faces
// are the ones TriMesh validated; the JSON's per-corner uv is matched to them face by face and corner by
// corner through the JSON's indices (TriMesh may have reversed a face to orient it consistently).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "straightest/atlas/atlas_quality.hpp"
#include "straightest/io/mesh_io.hpp"

using namespace straightest;
using nlohmann::json;

namespace {

/// Per-corner uv in TriMesh's corner order, or an empty vector and a message when the faces differ.
std::vector<Vec2> cornerUvOfMesh(const TriMesh& mesh, const json& atlas, std::string& problem) {
  const std::vector<int64_t> indices = atlas.at("indices").get<std::vector<int64_t>>();
  const std::vector<double> uv = atlas.at("cornerUv").get<std::vector<double>>();
  const size_t corners = 3 * static_cast<size_t>(mesh.numFaces());
  if (indices.size() != corners || uv.size() != 2 * corners) {
    problem = "the atlas has " + std::to_string(indices.size() / 3) + " faces, the mesh " +
              std::to_string(mesh.numFaces());
    return {};
  }
  std::vector<Vec2> cornerUv(corners);
  for (size_t c = 0; c < corners; c += 3) {
    for (size_t k = 0; k < 3; ++k) {
      const int32_t v = mesh.triangle(static_cast<int32_t>(c / 3))[k];
      size_t j = 0;
      while (j < 3 && indices[c + j] != v) ++j;
      if (j == 3) {
        problem = "face " + std::to_string(c / 3) + " differs between the atlas and the mesh";
        return {};
      }
      cornerUv[c + k] = {uv[2 * (c + j)], uv[2 * (c + j) + 1]};
    }
  }
  return cornerUv;
}

/// A number for JSON: infinities as the strings "inf" (nlohmann would write null).
json number(double x) { return std::isinf(x) ? json(x > 0 ? "inf" : "-inf") : json(x); }

json measurementJson(const AtlasQuality& q, double seconds) {
  return {{"charts", q.charts},
          {"non_disk_charts", q.nonDiskCharts},
          {"l2", number(q.l2)},
          {"linf", number(q.linf)},
          {"flipped", q.flipped},
          {"mirrored_charts", q.mirroredCharts},
          {"degenerate", q.degenerate},
          {"overlaps", q.overlaps},
          {"min_gap_texels", number(q.minGapTexels)},
          {"padding_violations", q.paddingViolations},
          {"utilization", q.utilization},
          {"outside", q.outside},
          {"non_finite", q.nonFinite},
          {"seam_edges", q.seamEdges},
          {"seam_length", q.seamLength},
          {"measure_seconds", seconds}};
}

json failure(const std::string& meshPath, const json& error) { return {{"mesh", meshPath}, {"error", error}}; }

json measure(const json& atlas, const std::string& meshPath, double padding) {
  if (atlas.contains("error")) return failure(meshPath, atlas["error"]);
  auto mesh = loadMeshFile(meshPath);
  if (!mesh) return failure(meshPath, mesh.error().message);
  std::string problem;
  const std::vector<Vec2> cornerUv = cornerUvOfMesh(mesh.value(), atlas, problem);
  if (!problem.empty()) return failure(meshPath, problem);
  QualityOptions options;
  options.width = atlas.at("width").get<int32_t>();
  options.height = atlas.at("height").get<int32_t>();
  options.padding = padding;
  const auto start = std::chrono::steady_clock::now();
  const AtlasQuality q = measureAtlas(mesh.value(), cornerUv, options);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  json out = {{"mesh", meshPath},
              {"vertices", mesh.value().numVertices()},
              {"faces", mesh.value().numFaces()},
              {"width", options.width},
              {"height", options.height},
              {"padding", padding},
              {"seconds", atlas.value("seconds", json())}};
  out.update(measurementJson(q, seconds));
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: atlas_compare ATLAS.json [--mesh MESH] [--padding TEXELS]\n");
    return 2;
  }
  std::string meshPath;
  double padding = 0;
  for (int i = 2; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--mesh") meshPath = argv[i + 1];
    else if (flag == "--padding") padding = std::stod(argv[i + 1]);
  }
  std::ifstream file(argv[1]);
  const json atlas = json::parse(file, nullptr, false);
  if (atlas.is_discarded()) {
    std::fprintf(stderr, "atlas_compare: %s is not JSON\n", argv[1]);
    return 1;
  }
  if (meshPath.empty()) meshPath = atlas.value("mesh", "");
  const json out = measure(atlas, meshPath, padding);
  std::printf("%s\n", out.dump().c_str());
  return out.contains("error") ? 1 : 0;
}
