// The README's C++ example: load a mesh, trace straightest paths to its boundary, parameterize it, write the OBJ.
#include <cstdio>
#include <fstream>

#include "straightest/geodesics/geodesic_distance.hpp"
#include "straightest/io/mesh_io.hpp"
#include "straightest/param/parameterize.hpp"
#include "straightest/paths/straightest_path.hpp"

int main(int argc, char** argv) {
  using namespace straightest;
  if (argc != 3) return std::fprintf(stderr, "usage: flatten MESH OUT.obj\n"), 2;
  Expected<TriMesh> mesh = loadMeshFile(argv[1]);
  if (!mesh) return std::fprintf(stderr, "%s\n", mesh.error().message.c_str()), 2;
  Expected<SurfacePoint> source = resolveSource(mesh.value(), std::nullopt);
  Expected<PathBatch> paths = traceStraightestPaths(mesh.value(), source.value(), boundaryTargets(mesh.value()));
  Expected<Parameterization> map = parameterize(mesh.value(), ParamOptions{});
  if (!paths || !map) return std::fprintf(stderr, "%s\n", (paths ? map.error() : paths.error()).message.c_str()), 2;
  std::ofstream(argv[2]) << writeObjWithCornerUv(mesh.value(), map.value().cornerUv);
  std::printf("%lld paths reached, stretch L2 %.4f\n", static_cast<long long>(summarize(paths.value()).reached),
              map.value().metrics.l2);
}
