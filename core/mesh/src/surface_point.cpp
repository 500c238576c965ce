// Surface points: positions, the canonical form with its one snapping rule, validation, incident faces.
#include "straightest/mesh/surface_point.hpp"

#include <cmath>
#include <string>

namespace straightest {

Vec3 position(const TriMesh& mesh, const SurfacePoint& p) {
  switch (p.kind) {
    case SurfacePoint::Kind::Vertex: return mesh.position(p.index);
    case SurfacePoint::Kind::Edge:
      return mesh.position(mesh.tail(p.index)) * (1 - p.t) + mesh.position(mesh.head(p.index)) * p.t;
    case SurfacePoint::Kind::Face: {
      const Triangle& t = mesh.triangle(p.index);
      return mesh.position(t[0]) * p.bary[0] + mesh.position(t[1]) * p.bary[1] + mesh.position(t[2]) * p.bary[2];
    }
  }
  return {};
}

SurfacePoint canonical(const TriMesh& mesh, SurfacePoint p, double snapTolerance) {
  switch (p.kind) {
    case SurfacePoint::Kind::Vertex: return p;
    case SurfacePoint::Kind::Edge: {
      if (p.t <= snapTolerance) return SurfacePoint::vertex(mesh.tail(p.index));
      if (p.t >= 1 - snapTolerance) return SurfacePoint::vertex(mesh.head(p.index));
      const int32_t twin = mesh.twin(p.index);
      if (twin >= 0 && twin < p.index) return SurfacePoint::edge(twin, 1 - p.t);
      return p;
    }
    case SurfacePoint::Kind::Face: {
      const std::array<double, 3>& b = p.bary;
      if (b[0] > snapTolerance && b[1] > snapTolerance && b[2] > snapTolerance) return p;
      const double sum = b[0] + b[1] + b[2];
      std::array<double, 3> kept{};
      int zeros = 0, nonzero = 0;
      for (int k = 0; k < 3; ++k) {
        kept[k] = b[k] <= snapTolerance ? 0.0 : b[k] / sum;
        if (kept[k] == 0) ++zeros;
        else nonzero = k;
      }
      if (zeros == 2) return SurfacePoint::vertex(mesh.triangle(p.index)[nonzero]);
      if (zeros == 1)
        for (int k = 0; k < 3; ++k)
          if (kept[k] == 0) {  // on the edge opposite corner k: halfedge from corner k+1 to corner k+2
            const int a = (k + 1) % 3, c = (k + 2) % 3;
            return canonical(mesh, SurfacePoint::edge(3 * p.index + a, kept[c] / (kept[a] + kept[c])), 0.0);
          }
      return p;  // every coordinate zero: not a point (validateSurfacePoint refuses it before)
    }
  }
  return p;
}

Expected<SurfacePoint> validateSurfacePoint(const TriMesh& mesh, const SurfacePoint& p) {
  auto invalid = [](const std::string& m) { return Error{ErrorCode::InvalidArgument, m}; };
  switch (p.kind) {
    case SurfacePoint::Kind::Vertex:
      if (p.index < 0 || p.index >= mesh.numVertices())
        return invalid("vertex " + std::to_string(p.index) + " is out of range (the mesh has " +
                       std::to_string(mesh.numVertices()) + " vertices)");
      if (mesh.vertexHalfedge(p.index) < 0)
        return invalid("vertex " + std::to_string(p.index) + " is not used by any face");
      return p;
    case SurfacePoint::Kind::Edge: {
      if (p.index < 0 || p.index >= 3 * mesh.numFaces())
        return invalid("halfedge " + std::to_string(p.index) + " is out of range");
      if (!std::isfinite(p.t) || p.t < -kExactSnap || p.t > 1 + kExactSnap)
        return invalid("edge parameter " + std::to_string(p.t) + " is outside [0, 1]");
      return canonical(mesh, p, kExactSnap);
    }
    case SurfacePoint::Kind::Face: {
      if (p.index < 0 || p.index >= mesh.numFaces())
        return invalid("face " + std::to_string(p.index) + " is out of range (the mesh has " +
                       std::to_string(mesh.numFaces()) + " faces)");
      double sum = 0;
      for (double b : p.bary) {
        if (!std::isfinite(b) || b < -kExactSnap)
          return invalid("barycentric coordinates must be finite and non-negative");
        sum += b;
      }
      if (std::abs(sum - 1) > kBarycentricSumTolerance) return invalid("barycentric coordinates must sum to 1");
      SurfacePoint q = canonical(mesh, p, kExactSnap);
      if (q.kind == SurfacePoint::Kind::Face)
        for (double& b : q.bary) b /= sum;
      return q;
    }
  }
  return invalid("unknown surface point kind");
}

void incidentFaces(const TriMesh& mesh, const SurfacePoint& p, std::vector<int32_t>& out) {
  out.clear();
  switch (p.kind) {
    case SurfacePoint::Kind::Vertex:
      for (int32_t f : mesh.vertexFaces(p.index)) out.push_back(f);
      break;
    case SurfacePoint::Kind::Edge:
      out.push_back(TriMesh::face(p.index));
      if (mesh.twin(p.index) >= 0) out.push_back(TriMesh::face(mesh.twin(p.index)));
      break;
    case SurfacePoint::Kind::Face: out.push_back(p.index); break;
  }
}

}  // namespace straightest
