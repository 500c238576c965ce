// Benchmark: measured-boundary parameterization (shape-preserving weights) of generated height
// fields, per stage, with each sparse solver. Prints a table; never pass/fail.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "straightest/parameterize.hpp"
#include "straightest/samples.hpp"

using namespace straightest;

int main(int argc, char** argv) {
  const char* target = argc > 1 ? argv[1] : "native";
  const int maxN = argc > 2 ? std::atoi(argv[2]) : 1000;
  std::printf(
      "| target | vertices | solver | source ms | trace ms | boundary ms | weights ms | solve ms | metrics ms | total "
      "ms | L2 | residual |\n");
  std::printf("|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (int n : {100, 317, 1000}) {
    if (n > maxN) break;
    const TriMesh mesh = makeHeightField(n);
    for (LinearSolver solver : {LinearSolver::Multigrid, LinearSolver::SparseLU, LinearSolver::BiCGSTAB}) {
      if (solver != LinearSolver::Multigrid && mesh.numVertices() > 200000) continue;  // minutes; see docs
      ParamOptions o;
      o.solver = solver;
      Timings t;
      o.timings = &t;
      const auto r = parameterize(mesh, o);
      if (!r) {
        std::printf("| %s | %d | error: %s |\n", target, mesh.numVertices(), r.error().message.c_str());
        continue;
      }
      std::printf("| %s | %d | %s | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.4f | %.1e |\n", target,
                  mesh.numVertices(),
                  solver == LinearSolver::SparseLU   ? "SparseLU"
                  : solver == LinearSolver::BiCGSTAB ? "BiCGSTAB+ILUT"
                                                     : "BiCGSTAB+AMG",
                  t["source"], t["trace"], t["boundary"], t["weights"], t["solve"], t["metrics"], t["total"],
                  r.value().metrics.l2, r.value().residual);
      std::fflush(stdout);
    }
  }
  return 0;
}
