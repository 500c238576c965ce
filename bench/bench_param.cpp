// Benchmark: measured-boundary parameterization (shape-preserving weights) of generated height
// fields, per stage, with each sparse solver, then the free boundary (multigrid; its refine stage and
// iterations). Prints a table; never pass/fail.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>

#include "../core/cli/huge_pages.hpp"
#include "straightest/mesh/samples.hpp"
#include "straightest/param/parameterize.hpp"

using namespace straightest;

int main(int argc, char** argv) {
  straightest::cli::reexecWithHugePages(argv);  // as the CLI runs
  const char* target = argc > 1 ? argv[1] : "native";
  const int maxN = argc > 2 ? std::atoi(argv[2]) : 1000;
  std::printf(
      "| target | vertices | boundary | solver | source ms | trace ms | boundary ms | weights ms | solve ms | refine "
      "ms "
      "| metrics ms | total ms | L2 | iterations | residual |\n");
  std::printf("|---|---:|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (int n : {100, 317, 1000}) {
    if (n > maxN) break;
    const TriMesh mesh = makeHeightField(n);
    const std::pair<BoundaryKind, LinearSolver> runs[] = {{BoundaryKind::Measured, LinearSolver::Multigrid},
                                                          {BoundaryKind::Measured, LinearSolver::SparseLU},
                                                          {BoundaryKind::Measured, LinearSolver::BiCGSTAB},
                                                          {BoundaryKind::Free, LinearSolver::Multigrid}};
    for (const auto& [boundary, solver] : runs) {
      if (solver != LinearSolver::Multigrid && mesh.numVertices() > 200000) continue;  // minutes; see docs
      ParamOptions o;
      o.boundary = boundary;
      o.solver = solver;
      Timings t;
      o.timings = &t;
      const auto r = parameterize(mesh, o);
      if (!r) {
        std::printf("| %s | %d | error: %s |\n", target, mesh.numVertices(), r.error().message.c_str());
        continue;
      }
      const Parameterization& p = r.value();
      std::printf("| %s | %d | %s | %s | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.4f | %s | %.1e |\n",
                  target, mesh.numVertices(),
                  p.init ? (std::string("free from ") + boundaryKindName(*p.init)).c_str()
                         : boundaryKindName(p.boundary),
                  solver == LinearSolver::SparseLU   ? "SparseLU"
                  : solver == LinearSolver::BiCGSTAB ? "BiCGSTAB+ILUT"
                                                     : "BiCGSTAB+AMG",
                  t["source"], t["trace"], t["boundary"], t["weights"], t["solve"], t["refine"], t["metrics"],
                  t["total"], p.metrics.l2, p.init ? std::to_string(p.iterations).c_str() : "–", p.residual);
      std::fflush(stdout);
    }
  }
  return 0;
}
