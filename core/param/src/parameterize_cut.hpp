// parameterize_cut.hpp — the parameterization of a mesh that is not a disk: cut (and fill) it into one
// (disk_cut.hpp), parameterize the disk, and map the result back onto the mesh's own vertices, faces
// and corners. Private to the core: parameterize.hpp is the public face of all of it.
//
// Two meshes: `disk` (real and virtual faces: what the boundary maps, the weights and the linear solve
// see, so a convex-combination map stays a disk map) and `real` (the real faces only: what the stretch
// is measured on and what the free boundary refines, its filled holes left free). For a cut without
// filling both are the same mesh. `real` numbers its vertices as the disk does, plus one extra vertex
// per further fan of real faces around a disk vertex whose real faces only meet at it (a seam vertex on
// a filled hole's rim can have real faces on both sides of the filling): the real faces stay a manifold,
// and the extra copy takes the uv of its disk vertex (realExtraOrigin) until the free boundary moves it.
#pragma once
#include <optional>
#include <utility>
#include <vector>

#include "straightest/cut/disk_cut.hpp"
#include "straightest/param/parameterize.hpp"

namespace straightest {

/// A mesh made a disk, with the inverse look-ups parameterize needs.
struct CutDisk {
  explicit CutDisk(DiskCut c) : cut(std::move(c)) {}
  DiskCut cut;
  std::optional<TriMesh> realFaces;      // the disk's real faces when some are virtual (same vertices)
  std::vector<int32_t> realFaceDisk;     // per face of real(): its disk face
  std::vector<int32_t> realExtraOrigin;  // per vertex of real() past the disk's: the disk vertex it copies
  std::vector<int32_t> diskFaceOf;       // per mesh face: its disk face, −1 outside the parameterized component
  std::vector<int32_t> copies;           // per mesh vertex: how many disk vertices copy it (2+ on the seam)
  std::vector<int32_t> copyOf;           // per mesh vertex: its first disk copy, −1 outside the component
  int64_t virtualVertices = 0;
  /// The real faces as a mesh: the disk itself when nothing was filled.
  const TriMesh& real() const { return realFaces ? *realFaces : cut.disk; }
};

/// cutToDisk and the look-ups (progress stage "cut"). Errors: cutToDisk's, Cancelled.
Expected<CutDisk> makeCutDisk(const TriMesh& mesh, const Progress& progress);

/// A mesh point as a point of the disk: InvalidArgument when it lies on the seam (a seam vertex or
/// edge has several copies) or outside the parameterized component.
Expected<SurfacePoint> pointOnDisk(const TriMesh& mesh, const CutDisk& c, const SurfacePoint& p);

/// The disk's default source as a real vertex: defaultSource of the disk, or when that is a virtual
/// (filling) vertex or on a hole's rim, the real interior vertex farthest from the disk's boundary along
/// edges (a mesh without one: a rim vertex, else any real vertex).
Expected<SurfacePoint> diskDefaultSource(const CutDisk& c);

/// parameterize's work on a disk mesh, with the stretch measured and the free boundary refined on
/// `real` (the disk's real faces; its vertices the disk's, then extra copies: extraOrigin). parameterize
/// calls it with real = disk for a disk. The result's uv is per disk vertex for a fixed boundary, per
/// real vertex for the free one.
Expected<Parameterization> parameterizeDisk(const TriMesh& disk, const TriMesh& real,
                                            const std::vector<int32_t>& extraOrigin, const ParamOptions& options,
                                            const Progress& progress);

/// uv per disk vertex extended to real's vertices (each extra copy takes its disk vertex's uv).
std::vector<Vec2> onRealVertices(std::vector<Vec2> uv, const std::vector<int32_t>& extraOrigin);

/// refineParameterization without the disk check: `mesh` may have holes (real faces of a filled disk).
Expected<Parameterization> refineOnDisk(const TriMesh& mesh, const Parameterization& start,
                                        const FreeBoundaryOptions& options, const Progress& progress, Timings* timings);

/// parameterize of a mesh that is not a disk: cut, map the source, parameterizeDisk, map back.
Expected<Parameterization> parameterizeByCut(const TriMesh& mesh, const ParamOptions& options,
                                             const Progress& progress);

/// refineParameterization of a cut mesh's map (start.cut != Disk): the same cut again (cutToDisk is
/// deterministic), the start's cornerUv onto the disk, refineOnDisk on the real faces, mapped back.
Expected<Parameterization> refineByCut(const TriMesh& mesh, const Parameterization& start,
                                       const FreeBoundaryOptions& options, const Progress& progress, Timings* timings);

/// A disk parameterization (disk numbers) as the mesh's: uv per mesh vertex (one copy's), cornerUv,
/// loop, face stretch, source, and the cut's report.
Parameterization mapBack(const TriMesh& mesh, const CutDisk& c, Parameterization disk);

}  // namespace straightest
