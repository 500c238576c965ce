// PLACEHOLDER on branch wave2 only, so the layers above can be built against the interface while the
// refinement is written: returns the start unchanged. Replaced by the implementation before main.
#include "straightest/free_boundary.hpp"

namespace straightest {

Expected<FreeBoundaryResult> refineFreeBoundary(const TriMesh& mesh, const std::vector<Vec2>& start,
                                                const FreeBoundaryOptions&, const Progress&) {
  if (static_cast<int32_t>(start.size()) != mesh.numVertices())
    return Error{ErrorCode::InvalidArgument, "the start map needs one uv per vertex"};
  FreeBoundaryResult result;
  result.uv = start;
  return result;
}

}  // namespace straightest
