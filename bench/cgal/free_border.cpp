// free_border.cpp — CGAL's ARAP and LSCM with a free border vs our free boundary (free_border.hpp).
#include "free_border.hpp"

#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_parameterization/ARAP_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Error_code.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>

#include "straightest/param/parameterize.hpp"

namespace bench_cgal {
namespace {

namespace SMP = CGAL::Surface_mesh_parameterization;
namespace PMP = CGAL::Polygon_mesh_processing;
using CgalArap = SMP::ARAP_parameterizer_3<SM>;  // default border: Two_vertices_parameterizer_3 (free)
using CgalLscm = SMP::LSCM_parameterizer_3<SM>;  // the same default border

/// The free-boundary refinement's iteration count when Parameterization has one (it comes with the
/// free boundary), −1 otherwise: this file builds before and after that lands.
template <class P>
auto iterationsOf(const P& p, int) -> decltype(static_cast<int64_t>(p.iterations)) {
  return static_cast<int64_t>(p.iterations);
}
template <class P>
int64_t iterationsOf(const P&, long) {
  return -1;
}

void methodFields(Obj& o, const FreeBorderMethod& m) {
  if (!m.note.empty()) o.addStr("note", m.note);
  if (!m.ran) return;
  o.add("ms", m.ms, 4)
      .add("l2", m.metrics.l2, 9)
      .add("linf", m.metrics.linf, 9)
      .add("flipped", m.metrics.flipped)
      .add("degenerate", m.metrics.degenerate)
      .add("overlaps", m.metrics.overlaps)
      .add("bijective", m.metrics.bijective);
  if (m.iterations >= 0) o.add("iterations", m.iterations);
}

template <class Parameterizer>
FreeBorderMethod runCgal(const TriMesh& mesh, SM& sm, const FreeBorderSettings& settings) {
  FreeBorderMethod m;
  if (mesh.numVertices() > settings.cgalMaxVertices) {
    m.note = "skipped: more than " + std::to_string(settings.cgalMaxVertices) + " vertices";
    return m;
  }
  auto uvMap = sm.add_property_map<VertexIndex, Point2>("v:uv_free", Point2(0, 0)).first;
  const auto border = PMP::longest_border(sm).first;
  SMP::Error_code status = SMP::OK;
  const Timed t = timeIt(settings.repeats, settings.onceAboveMs, [&] {
    for (VertexIndex v : sm.vertices()) uvMap[v] = Point2(0, 0);
    status = SMP::parameterize(sm, Parameterizer(), border, uvMap);
  });
  if (status != SMP::OK) {
    m.note = std::string("CGAL: ") + SMP::get_error_message(status);
    return m;
  }
  std::vector<Vec2> uv(mesh.numVertices());
  for (int32_t v = 0; v < mesh.numVertices(); ++v) uv[v] = {uvMap[VertexIndex(v)].x(), uvMap[VertexIndex(v)].y()};
  m.ran = true;
  m.ms = t.ms;
  m.metrics = stretchOf(mesh, uv).m;
  return m;
}

FreeBorderMethod runOurs(const TriMesh& mesh, int32_t source, const FreeBorderSettings& settings) {
  FreeBorderMethod m;
  const auto kind = parseBoundaryChoice("free");
  if (!kind || !kind.value()) {
    m.note = "n/a: the core has no free boundary";
    return m;
  }
  ParamOptions po;
  po.source = SurfacePoint::vertex(source);
  po.boundary = kind.value();
  po.weights = WeightKind::ShapePreserving;
  std::vector<double> totals;
  Expected<Parameterization> last = Error{ErrorCode::InvalidArgument, "not run"};
  for (int i = 0; i < settings.repeats; ++i) {
    Timings timings;
    po.timings = &timings;
    last = parameterize(mesh, po);
    if (!last) break;
    totals.push_back(timings["total"]);
    if (i == 0 && totals[0] > settings.onceAboveMs) break;
  }
  if (!last) {
    m.note = "error: " + last.error().message;
    return m;
  }
  m.ran = true;
  m.ms = median(totals);
  m.metrics = stretchOf(mesh, last.value().uv).m;  // the same function as CGAL's UVs go through
  m.iterations = iterationsOf(last.value(), 0);
  return m;
}

std::string l2Cell(const FreeBorderMethod& m) {
  if (!m.ran) return m.note.rfind("n/a", 0) == 0 ? "n/a" : m.note.rfind("skipped", 0) == 0 ? "skipped" : "failed";
  return m.metrics.bijective ? fmt(m.metrics.l2, "%.4f") : "∞";
}

std::string flippedCell(const FreeBorderMethod& m) {
  if (!m.ran) return "";
  std::string cell = std::to_string(m.metrics.flipped);
  if (m.metrics.degenerate > 0) cell += " +" + std::to_string(m.metrics.degenerate) + " deg.";
  return cell;
}

std::string cells(const FreeBorderMethod& m, bool iterations) {
  std::string out = l2Cell(m) + " | " + (m.ran ? fmt(m.metrics.linf, "%.3g") : "") + " | " + flippedCell(m) + " | " +
                    (m.ran ? std::to_string(m.metrics.overlaps) : "") + " | ";
  if (iterations) out += (m.ran && m.iterations >= 0 ? std::to_string(m.iterations) : "") + " | ";
  return out + (m.ran ? fmtMs(m.ms) : "");
}

/// "bijective on N of M run; not bijective on a (12 flipped), …; failed on b (CGAL's message); not run
/// on …" for one method.
std::string verdict(const std::vector<FreeBorderRow>& rows, FreeBorderMethod FreeBorderRow::*method) {
  int bijective = 0, ran = 0;
  std::string folds, fails, skipped;
  auto append = [](std::string& list, const std::string& item) { list += (list.empty() ? "" : ", ") + item; };
  for (const FreeBorderRow& r : rows) {
    const FreeBorderMethod& m = r.*method;
    if (!m.ran) {
      if (m.note.rfind("skipped", 0) == 0 || m.note.rfind("n/a", 0) == 0) append(skipped, r.name);
      else append(fails, r.name + " (" + m.note + ")");
      continue;
    }
    ++ran;
    if (m.metrics.bijective) {
      ++bijective;
      continue;
    }
    std::string counts;
    if (m.metrics.flipped > 0) append(counts, std::to_string(m.metrics.flipped) + " flipped");
    if (m.metrics.degenerate > 0) append(counts, std::to_string(m.metrics.degenerate) + " degenerate");
    if (m.metrics.overlaps > 0) append(counts, std::to_string(m.metrics.overlaps) + " overlaps");
    append(folds, r.name + " (" + counts + ")");
  }
  if (ran == 0 && fails.empty()) return (rows.empty() ? std::string("") : (rows[0].*method).note) + " (every mesh)";
  std::string out = "bijective on " + std::to_string(bijective) + " of " + std::to_string(ran) + " run";
  if (!folds.empty()) out += "; not bijective on " + std::to_string(ran - bijective) + ": " + folds;
  if (!fails.empty()) out += "; failed on " + fails;
  if (!skipped.empty()) out += "; not run on " + skipped;
  return out;
}

}  // namespace

std::string compareFreeBorders(const TriMesh& mesh, SM& sm, int32_t source, const FreeBorderSettings& settings,
                               FreeBorderRow& row) {
  row.vertices = mesh.numVertices();
  std::fprintf(stderr, "bench_cgal: %s: CGAL ARAP (free border)\n", row.name.c_str());
  row.arap = runCgal<CgalArap>(mesh, sm, settings);
  std::fprintf(stderr, "bench_cgal: %s: CGAL LSCM (free border)\n", row.name.c_str());
  row.lscm = runCgal<CgalLscm>(mesh, sm, settings);
  std::fprintf(stderr, "bench_cgal: %s: ours free\n", row.name.c_str());
  row.ours = runOurs(mesh, source, settings);
  Obj arap, lscm, ours;
  arap.addStr("method", "ARAP_parameterizer_3 (Two_vertices_parameterizer_3 border, SparseLU, lambda 1000)");
  lscm.addStr("method", "LSCM_parameterizer_3 (Two_vertices_parameterizer_3 border, OpenNL)");
  ours.addStr("method", "parameterize, boundary free, shape-preserving weights");
  methodFields(arap, row.arap);
  methodFields(lscm, row.lscm);
  methodFields(ours, row.ours);
  return Obj().add("cgal_arap", arap.done()).add("cgal_lscm", lscm.done()).add("ours_free", ours.done()).done();
}

void printFreeBorderTable(const std::vector<FreeBorderRow>& rows, const FreeBorderSettings& settings) {
  std::printf(
      "\n### Free border: CGAL ARAP and LSCM vs ours\n\n"
      "| mesh | vertices | ARAP L2 | L∞ | flipped | overlaps | ms | LSCM L2 | L∞ | flipped | overlaps | ms "
      "| ours free L2 | L∞ | flipped | overlaps | iterations | ms |\n"
      "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const FreeBorderRow& r : rows)
    std::printf("| %s | %lld | %s | %s | %s |\n", r.name.c_str(), static_cast<long long>(r.vertices),
                cells(r.arap, false).c_str(), cells(r.lscm, false).c_str(), cells(r.ours, true).c_str());
  std::printf(
      "\nL2, L∞: our textureStretch of each UV set (a reflected map is mirrored first); ∞ = not bijective: a "
      "flipped or degenerate (deg.) triangle, or a boundary that crosses itself (overlaps: crossing pairs of "
      "boundary edges). Times in ms, median of up to %d runs (a run over %.0f s is not repeated); CGAL = the "
      "SMP::parameterize call (ARAP includes its LSCM start and, when its result is not one-to-one, its MVC "
      "post-processing), ours = parameterize's \"total\" (source given; traces, solve, refinement, metrics). "
      "CGAL's methods skip meshes of more than %lld vertices.\n\n",
      settings.repeats, settings.onceAboveMs / 1000, static_cast<long long>(settings.cgalMaxVertices));
  std::printf("- CGAL ARAP: %s\n", verdict(rows, &FreeBorderRow::arap).c_str());
  std::printf("- CGAL LSCM: %s\n", verdict(rows, &FreeBorderRow::lscm).c_str());
  std::printf("- ours free: %s\n", verdict(rows, &FreeBorderRow::ours).c_str());
}

}  // namespace bench_cgal
