// Any connected manifold mesh made a disk (see disk_cut.hpp): pick the largest component, fill holes
// virtually, cut a closed surface open along a seam (cut_graph.hpp, cut_open.hpp), and check the result.
#include "straightest/cut/disk_cut.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <utility>

#include "cut_graph.hpp"
#include "cut_open.hpp"

namespace straightest {
namespace {

constexpr const char* kStage = "cut";

struct Components {
  std::vector<int32_t> ofFace;  // component per face, numbered by lowest face index
  std::vector<int64_t> faces;   // face count per component
};

Components findComponents(const TriMesh& mesh) {
  Components c;
  c.ofFace.assign(mesh.numFaces(), -1);
  std::vector<int32_t> stack;
  for (int32_t seed = 0; seed < mesh.numFaces(); ++seed) {
    if (c.ofFace[seed] >= 0) continue;
    const int32_t id = int32_t(c.faces.size());
    c.faces.push_back(0);
    c.ofFace[seed] = id;
    stack.push_back(seed);
    while (!stack.empty()) {
      const int32_t f = stack.back();
      stack.pop_back();
      ++c.faces[id];
      for (int32_t t : mesh.adjacency(f).twins) {
        if (t < 0 || c.ofFace[TriMesh::face(t)] >= 0) continue;
        c.ofFace[TriMesh::face(t)] = id;
        stack.push_back(TriMesh::face(t));
      }
    }
  }
  return c;
}

double loopLength(const TriMesh& mesh, const std::vector<int32_t>& loop) {
  double length = 0;
  for (size_t i = 0; i < loop.size(); ++i)
    length += norm(mesh.position(loop[(i + 1) % loop.size()]) - mesh.position(loop[i]));
  return length;
}

/// The centroid of a loop as a curve (each edge's midpoint weighted by its length), so that unevenly
/// spaced vertices do not pull it; the vertex mean when the loop has no length.
Vec3 loopCentroid(const TriMesh& mesh, const std::vector<int32_t>& loop) {
  Vec3 sum{0, 0, 0}, mean{0, 0, 0};
  double total = 0;
  for (size_t i = 0; i < loop.size(); ++i) {
    const Vec3& a = mesh.position(loop[i]);
    const Vec3& b = mesh.position(loop[(i + 1) % loop.size()]);
    const double length = norm(b - a);
    sum = sum + (a + b) * (0.5 * length);
    total += length;
    mean = mean + a;
  }
  return total > 0 ? sum * (1 / total) : mean * (1.0 / double(loop.size()));
}

/// The component's faces (mesh order) on its own vertices (renumbered in mesh order), with one virtual
/// vertex per filled loop after them, fanned to the loop: the surface that gets cut.
struct Surface {
  std::vector<Vec3> positions;
  std::vector<Triangle> triangles;  // the component's faces first, then the fans
  std::vector<int32_t> meshVertex;  // per surface vertex: the mesh vertex; −1 for a virtual one
  std::vector<int32_t> meshFace;    // per surface face: the mesh face; −1 for a fan face
  int32_t firstVirtual = 0;
};

Surface componentSurface(const TriMesh& mesh, const std::vector<int32_t>& faceComponent, int32_t component,
                         const std::vector<int32_t>& loopsToFill) {
  Surface s;
  std::vector<int32_t> local(mesh.numVertices(), -1);
  for (int32_t f = 0; f < mesh.numFaces(); ++f)
    if (faceComponent[f] == component)
      for (int32_t v : mesh.triangle(f)) local[v] = 0;
  for (int32_t v = 0; v < mesh.numVertices(); ++v)
    if (local[v] == 0) {
      local[v] = int32_t(s.meshVertex.size());
      s.meshVertex.push_back(v);
      s.positions.push_back(mesh.position(v));
    }
  s.firstVirtual = int32_t(s.positions.size());
  for (int32_t f = 0; f < mesh.numFaces(); ++f)
    if (faceComponent[f] == component) {
      const Triangle& t = mesh.triangle(f);
      s.triangles.push_back({local[t[0]], local[t[1]], local[t[2]]});
      s.meshFace.push_back(f);
    }
  for (int32_t index : loopsToFill) {
    const std::vector<int32_t>& loop = mesh.boundaryLoops()[index];
    const int32_t centre = int32_t(s.positions.size());
    s.positions.push_back(loopCentroid(mesh, loop));
    s.meshVertex.push_back(-1);
    // The loop runs with the surface on its left (boundary halfedges a → b); the fan's face holds b → a.
    for (size_t i = 0; i < loop.size(); ++i) {
      s.triangles.push_back({centre, local[loop[(i + 1) % loop.size()]], local[loop[i]]});
      s.meshFace.push_back(-1);
    }
  }
  return s;
}

/// DiskCut's fields but the disk (a TriMesh has no empty state), filled in as the cut goes.
struct CutReport {
  std::vector<int32_t> vertexOrigin, faceOrigin;
  std::vector<std::array<int32_t, 2>> seam;
  std::vector<int32_t> filledLoops;
  CutMethod method = CutMethod::Disk;
  int32_t genus = 0;
  std::array<int32_t, 2> seamEnds{-1, -1};
  int32_t component = 0, components = 1;
  int64_t faces = 0;
  double seamLength = 0;
};

Error internal(const std::string& what) { return Error{ErrorCode::Internal, "cutting to a disk: " + what}; }

/// The largest component's topology (χ = V − E + F = 2 − 2g − k) and how to make it a disk: which
/// boundary loops are filled (all but the longest on a genus-0 surface with holes, all otherwise) and
/// whether a seam must be cut.
void chooseMethod(const TriMesh& mesh, const Components& components, CutReport& cut) {
  std::vector<uint8_t> inComponent(mesh.numVertices(), 0);
  int64_t boundaryHalfedges = 0;
  for (int32_t f = 0; f < mesh.numFaces(); ++f) {
    if (components.ofFace[f] != cut.component) continue;
    for (int k = 0; k < 3; ++k) {
      inComponent[mesh.triangle(f)[k]] = 1;
      if (mesh.twin(3 * f + k) < 0) ++boundaryHalfedges;
    }
  }
  int64_t vertices = 0;
  for (uint8_t in : inComponent) vertices += in;
  const int64_t edges = (3 * cut.faces + boundaryHalfedges) / 2;
  const int64_t chi = vertices - edges + cut.faces;
  std::vector<int32_t> loops;  // indices into mesh.boundaryLoops() of the component's loops
  for (int32_t i = 0; i < int32_t(mesh.boundaryLoops().size()); ++i)
    if (inComponent[mesh.boundaryLoops()[i][0]]) loops.push_back(i);
  const int64_t k = int64_t(loops.size());
  cut.genus = int32_t((2 - chi - k) / 2);

  if (cut.genus == 0 && k >= 1) {
    cut.method = k == 1 ? CutMethod::Disk : CutMethod::Fill;
    int32_t outer = loops[0];  // the longest loop stays the boundary
    double outerLength = loopLength(mesh, mesh.boundaryLoops()[outer]);
    for (int32_t i : loops) {
      const double length = loopLength(mesh, mesh.boundaryLoops()[i]);
      if (length > outerLength) outer = i, outerLength = length;
    }
    for (int32_t i : loops)
      if (i != outer) cut.filledLoops.push_back(i);
  } else {
    cut.method = cut.genus == 0 ? CutMethod::Path : CutMethod::CutGraph;
    cut.filledLoops = loops;
  }
}

bool cuts(CutMethod method) { return method == CutMethod::Path || method == CutMethod::CutGraph; }

/// The seam on the filled surface, as edges between the mesh's vertices (a seam through a filled hole's
/// virtual vertex would be a bug).
Expected<void> recordSeam(const TriMesh& mesh, const Surface& surface, const detail::Seam& seam, CutReport& cut) {
  for (const auto& e : seam.edges) {
    const int32_t a = surface.meshVertex[e[0]], b = surface.meshVertex[e[1]];
    if (a < 0 || b < 0) return internal("the seam runs through a filled hole");
    cut.seam.push_back({a, b});
    cut.seamLength += norm(mesh.position(a) - mesh.position(b));
  }
  if (cut.method == CutMethod::Path)
    cut.seamEnds = {surface.meshVertex[seam.ends[0]], surface.meshVertex[seam.ends[1]]};
  return {};
}

/// The filled surface opened along the seam into a new mesh (or, with no seam, the filled surface as it
/// is), and where each of its vertices came from.
Expected<TriMesh> openAlongSeam(std::optional<Expected<TriMesh>>& built, const TriMesh& filled, Surface& surface,
                                const detail::Seam& seam, const Progress& progress, CutReport& cut) {
  cut.faceOrigin = std::move(surface.meshFace);
  if (!cuts(cut.method)) {
    cut.vertexOrigin = std::move(surface.meshVertex);
    return std::move(*built);
  }
  auto open = detail::cutOpen(filled, seam.edges, progress.range(0.75, 0.9), kStage);
  if (!open) return cancelledError("cutting to a disk");
  for (int32_t v : open->copyOf) cut.vertexOrigin.push_back(surface.meshVertex[v]);
  Expected<TriMesh> disk = TriMesh::build(std::move(open->positions), std::move(open->triangles));
  if (!disk) return internal("the cut surface is not a mesh: " + disk.error().message);
  return disk;
}

Expected<void> checkDisk(const MeshSummary& summary) {
  if (summary.boundaryLoopSizes.size() == 1 && summary.eulerCharacteristic == 1 && summary.components == 1 &&
      summary.reorientedFaces == 0)
    return {};
  return internal("the cut surface is not a disk (" + std::to_string(summary.boundaryLoopSizes.size()) +
                  " boundary loops, Euler characteristic " + std::to_string(summary.eulerCharacteristic) + ")");
}

}  // namespace

Expected<DiskCut> cutToDisk(const TriMesh& mesh, const Progress& progress) {
  if (mesh.numFaces() == 0) return Error{ErrorCode::Topology, "the mesh has no face to cut into a disk"};
  if (!report(progress, kStage, 0)) return cancelledError("cutting to a disk");
  CutReport cut;
  const Components components = findComponents(mesh);
  cut.components = int32_t(components.faces.size());
  cut.component = int32_t(std::max_element(components.faces.begin(), components.faces.end()) -
                          components.faces.begin());  // the first of the largest: lowest face index
  cut.faces = components.faces[cut.component];
  chooseMethod(mesh, components, cut);
  if (!report(progress, kStage, 0.1)) return cancelledError("cutting to a disk");

  Surface surface = componentSurface(mesh, components.ofFace, cut.component, cut.filledLoops);
  const bool cutting = cuts(cut.method);
  // A closed mesh of one piece is its own surface to find the seam on: no need to build it again. (The
  // disk itself is always built, so that its summary is its own.)
  const bool meshIsSurface = cutting && cut.components == 1 && cut.filledLoops.empty() &&
                             surface.positions.size() == size_t(mesh.numVertices());
  std::optional<Expected<TriMesh>> built;
  if (!meshIsSurface) {
    built = TriMesh::build(surface.positions, surface.triangles);
    if (!*built) return built->error();
    if (built->value().summary().reorientedFaces != 0) return internal("the filled surface is not oriented");
  }
  const TriMesh& filled = meshIsSurface ? mesh : built->value();

  detail::Seam seam;
  if (cutting) {
    const Progress part = progress.range(0.1, 0.7);
    auto found = cut.method == CutMethod::Path ? detail::pathSeam(filled, part, kStage)
                                               : detail::treeCotreeSeam(filled, surface.firstVirtual, part, kStage);
    if (!found) return found.error();
    seam = std::move(found).value();
  }
  if (auto recorded = recordSeam(mesh, surface, seam, cut); !recorded) return recorded.error();
  Expected<TriMesh> disk = openAlongSeam(built, filled, surface, seam, progress, cut);
  if (!disk) return disk.error();
  if (auto checked = checkDisk(disk.value().summary()); !checked) return checked.error();
  if (!report(progress, kStage, 1)) return cancelledError("cutting to a disk");
  return DiskCut{std::move(disk).value(),
                 std::move(cut.vertexOrigin),
                 std::move(cut.faceOrigin),
                 std::move(cut.seam),
                 std::move(cut.filledLoops),
                 cut.method,
                 cut.genus,
                 cut.seamEnds,
                 cut.component,
                 cut.components,
                 cut.faces,
                 cut.seamLength};
}

const char* cutMethodName(CutMethod m) { return nameOf(kCutMethodNames, m); }

}  // namespace straightest
