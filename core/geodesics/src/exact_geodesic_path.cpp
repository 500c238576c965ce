// exact_geodesic_path.cpp — back-tracing an exact shortest path: from the target, walk the straight line
// toward the origin's image recorded with the target's distance, face by face (unfolding each face into
// the frame of the edge it is entered by), until the image is a corner of the face (a pseudo-source
// vertex: continue from its own record) or the face holds the source point.
#include <algorithm>
#include <string>

#include "straightest/geodesics/exact_geodesic.hpp"
#include "straightest/mesh/unfolding.hpp"

namespace straightest {

Expected<std::vector<Vec3>> exactShortestPath(const TriMesh& mesh, const ExactGeodesics& field, int32_t target) {
  if (target < 0 || target >= mesh.numVertices())
    return Error{ErrorCode::InvalidArgument, "target vertex " + std::to_string(target) +
                                                 " is out of range (the mesh has " +
                                                 std::to_string(mesh.numVertices()) + " vertices)"};
  if (!(field.distances[target] < std::numeric_limits<double>::infinity()))
    return Error{ErrorCode::InvalidArgument,
                 "target vertex " + std::to_string(target) + " cannot be reached from the source (another component)"};
  const std::vector<double> len = unfolding::halfedgeLengths(mesh);
  std::vector<int32_t> sourceFaces;
  incidentFaces(mesh, field.source, sourceFaces);
  const Vec3 sourcePosition = position(mesh, field.source);
  const bool vertexSource = field.source.kind == SurfacePoint::Kind::Vertex;
  const double cornerTolerance = 1e-6 * mesh.meanEdgeLength();

  std::vector<Vec3> points{mesh.position(target)};
  int64_t budget = 4 * static_cast<int64_t>(mesh.numFaces()) + 16;  // more than any back-trace crosses
  int32_t v = target;
  while (!(vertexSource && v == field.source.index)) {
    const GeodesicParent& parent = field.parents[v];
    if (parent.halfedge < 0) {  // a straight segment inside one face
      if (parent.origin < 0) {
        points.push_back(sourcePosition);
        break;
      }
      v = parent.origin;
      points.push_back(mesh.position(v));
      continue;
    }
    int32_t k = parent.halfedge;
    const int32_t origin = parent.origin;
    Vec2 image = parent.image;
    Vec2 p = v == mesh.tail(k) ? Vec2{0, 0} : v == mesh.head(k) ? Vec2{len[k], 0} : unfolding::oppositeCorner(len, k);
    bool arrived = false;
    while (!arrived) {
      if (--budget < 0)
        return Error{ErrorCode::Internal, "exact shortest path to vertex " + std::to_string(target) + " did not close"};
      const double l = len[k];
      const double x = std::clamp(p.y > 0 ? p.x + (image.x - p.x) * p.y / (p.y - image.y) : p.x, 0.0, l);
      if (p.y > 0) points.push_back(mesh.position(mesh.tail(k)) * (1 - x / l) + mesh.position(mesh.head(k)) * (x / l));
      const int32_t t = mesh.twin(k);
      if (t < 0) return Error{ErrorCode::Internal, "exact shortest path left the surface at a boundary edge"};
      const Vec2 from{l - x, 0}, toward{l - image.x, -image.y};
      const Vec2 a{0, 0}, b{l, 0}, c = unfolding::oppositeCorner(len, t);
      const int32_t corners[3] = {mesh.tail(t), mesh.head(t), mesh.head(TriMesh::next(t))};
      const Vec2 corner2d[3] = {a, b, c};
      if (origin >= 0) {
        for (int i = 0; i < 3 && !arrived; ++i)
          if (corners[i] == origin && unfolding::length(toward - corner2d[i]) <= cornerTolerance) arrived = true;
        if (arrived) {
          v = origin;
          points.push_back(mesh.position(v));
          break;
        }
      } else if (std::find(sourceFaces.begin(), sourceFaces.end(), TriMesh::face(t)) != sourceFaces.end()) {
        points.push_back(sourcePosition);
        return std::vector<Vec3>(points.rbegin(), points.rend());
      }
      // Leave through b–c when c lies left of the ray, else through c–a; continue in that edge's frame.
      if (cross(toward - from, c - from) > 0) {
        k = TriMesh::next(t);
        p = unfolding::toFrame(from, b, c);
        image = unfolding::toFrame(toward, b, c);
      } else {
        k = TriMesh::prev(t);
        p = unfolding::toFrame(from, c, a);
        image = unfolding::toFrame(toward, c, a);
      }
    }
  }
  return std::vector<Vec3>(points.rbegin(), points.rend());
}

}  // namespace straightest
