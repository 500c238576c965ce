// Name tables: every value has one name, every name parses back, and errors list the choices.
#include <set>

#include <gtest/gtest.h>

#include "straightest/base/names.hpp"
#include "straightest/geodesics/geodesic_distance.hpp"
#include "straightest/io/mesh_io.hpp"
#include "straightest/param/parameterize.hpp"
#include "straightest/paths/straightest_path.hpp"

namespace straightest {
namespace {

template <class E, size_t N>
void expectRoundTrip(const EnumName<E> (&table)[N]) {
  std::set<std::string> seen;
  for (const EnumName<E>& e : table) {
    EXPECT_TRUE(seen.insert(e.name).second) << "duplicate name " << e.name;
    EXPECT_STREQ(nameOf(table, e.value), e.name);
    EXPECT_EQ(valueOf(table, e.name), e.value);
  }
  EXPECT_EQ(namesOf(table).size(), N);
  EXPECT_FALSE(valueOf(table, "no such name"));
}

TEST(EnumNames, EveryTableRoundTrips) {
  expectRoundTrip(kTraceStatusNames);
  expectRoundTrip(kBoundaryKindNames);
  expectRoundTrip(kWeightKindNames);
  expectRoundTrip(kLinearSolverNames);
  expectRoundTrip(kDistanceMethodNames);
  expectRoundTrip(kMeshFormatNames);
  EXPECT_EQ(std::size(kTraceStatusNames), static_cast<size_t>(kTraceStatusCount));
}

TEST(EnumNames, TheNameFunctionsReadTheTables) {
  for (const auto& e : kTraceStatusNames) EXPECT_STREQ(traceStatusName(e.value), e.name);
  for (const auto& e : kBoundaryKindNames) EXPECT_STREQ(boundaryKindName(e.value), e.name);
  for (const auto& e : kWeightKindNames) EXPECT_STREQ(weightKindName(e.value), e.name);
  EXPECT_EQ(parseLinearSolver("lu").value(), LinearSolver::SparseLU);
  EXPECT_EQ(parseDistanceMethod("dijkstra").value(), DistanceMethod::Dijkstra);
}

TEST(EnumNames, AutoIsTheAbsentBoundaryAndErrorsListEveryChoice) {
  EXPECT_FALSE(parseBoundaryChoice("auto").value().has_value());
  EXPECT_EQ(parseBoundaryChoice("square").value(), BoundaryKind::Square);
  EXPECT_EQ(parseBoundaryChoice("free").value(), BoundaryKind::Free);
  const auto bad = parseBoundaryChoice("ellipse");
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.error().code, ErrorCode::InvalidArgument);
  EXPECT_EQ(bad.error().message, "unknown boundary 'ellipse' (use measured, circle, square, free or auto)");
  EXPECT_EQ(parseWeightKind("harmonic").error().message,
            "unknown weights 'harmonic' (use shape-preserving, mean-value, cotan or uniform)");
  EXPECT_EQ(choiceList({"a"}), "a");
  EXPECT_EQ(choiceList({"a", "b", "c"}, "|", "|"), "a|b|c");
}

}  // namespace
}  // namespace straightest
