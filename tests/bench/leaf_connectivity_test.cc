// The surface benchmark's per-leaf connectivity (bench/surface/leaf_connectivity.h) on flat
// sheets whose answer is known: a copy of the truth, a leaf cut in two, and a neighbour's sheet
// passing within the noise of a leaf.

#include "bench/surface/leaf_connectivity.h"

#include <gtest/gtest.h>

namespace avc::bench {
namespace {

constexpr float kMm = 1e-3f;

// A flat grid sheet over [x0, x1] x [0, 10] mm at height z mm, 0.5 mm pitch, every face labelled.
geometry::Mesh Sheet(float x0, float x1, float z, int32_t label) {
  constexpr float kPitch = 0.5f;
  const int nx = static_cast<int>((x1 - x0) / kPitch + 0.5f);
  const int ny = static_cast<int>(10.0f / kPitch + 0.5f);
  geometry::Mesh sheet;
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) {
      sheet.vertices.emplace_back((x0 + i * kPitch) * kMm, j * kPitch * kMm, z * kMm);
    }
  }
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const int a = j * (nx + 1) + i;
      sheet.faces.emplace_back(a, a + 1, a + nx + 2);
      sheet.faces.emplace_back(a, a + nx + 2, a + nx + 1);
    }
  }
  sheet.face_labels.assign(sheet.faces.size(), label);
  return sheet;
}

geometry::Mesh Join(const geometry::Mesh& a, const geometry::Mesh& b) {
  geometry::Mesh joined = a;
  joined.Append(b);
  return joined;
}

// Two leaves side by side, 1 mm apart: leaf 1 over x 0-10 mm, leaf 2 over x 11-20 mm.
geometry::Mesh TwoLeaves() { return Join(Sheet(0, 10, 0, 1), Sheet(11, 20, 0, 2)); }

TEST(LeafConnectivity, ACopyOfTheTruthHasEveryLeafInOnePiece) {
  const LeafConnectivity result = CountConnectedLeaves(TwoLeaves(), TwoLeaves());
  EXPECT_EQ(result.leaves, 2);
  EXPECT_EQ(result.one_component, 2);
  EXPECT_EQ(result.one_component_strict, 2);
  EXPECT_EQ(result.mostly_one, 2);
  EXPECT_DOUBLE_EQ(result.Fraction(), 1.0);
}

TEST(LeafConnectivity, OnlyLeafLabelsCountWhenAsked) {
  // A stem (label 1, not a leaf) cut in two beside a whole leaf (a leaf label).
  const int32_t leaf = geometry::labels::kLeafBase;
  const geometry::Mesh truth = Join(Sheet(0, 10, 0, 1), Sheet(11, 20, 0, leaf));
  const geometry::Mesh mesh =
      Join(Join(Sheet(0, 4, 0, 0), Sheet(6, 10, 0, 0)), Sheet(11, 20, 0, 0));
  const LeafConnectivity all = CountConnectedLeaves(truth, mesh);
  EXPECT_EQ(all.leaves, 2);
  EXPECT_EQ(all.one_component, 1);  // the stem's two pieces count against it
  const LeafConnectivity leaves = CountConnectedLeaves(truth, mesh, true);
  EXPECT_EQ(leaves.leaves, 1);
  EXPECT_EQ(leaves.one_component, 1);
  EXPECT_DOUBLE_EQ(leaves.Fraction(), 1.0);
}

TEST(LeafConnectivity, ALeafCutAcrossIsTwoPieces) {
  // Leaf 1 reconstructed as two halves 2 mm apart, leaf 2 whole.
  const geometry::Mesh mesh =
      Join(Join(Sheet(0, 4, 0, 0), Sheet(6, 10, 0, 0)), Sheet(11, 20, 0, 0));
  const LeafConnectivity result = CountConnectedLeaves(TwoLeaves(), mesh);
  EXPECT_EQ(result.one_component, 1);
  EXPECT_EQ(result.one_component_strict, 1);
  EXPECT_EQ(result.mostly_one, 1);  // each half holds 50 % of the leaf's area
}

TEST(LeafConnectivity, AMissingLeafIsNotConnected) {
  const LeafConnectivity result = CountConnectedLeaves(TwoLeaves(), Sheet(0, 10, 0, 0));
  EXPECT_EQ(result.leaves, 2);
  EXPECT_EQ(result.one_component, 1);
}

TEST(LeafConnectivity, ANeighboursSheetWithinTheNoiseIsNotAStrayPiece) {
  // Leaf 2 lies 0.5 mm above leaf 1 where they overlap (x 9-10 mm). Its reconstruction runs
  // 0.3 mm below it, so over the overlap it is nearer leaf 1 (0.2 mm) than leaf 2 (0.3 mm).
  const geometry::Mesh truth = Join(Sheet(0, 10, 0, 1), Sheet(9, 20, 0.5f, 2));
  const geometry::Mesh mesh = Join(Sheet(0, 10, 0, 0), Sheet(9, 20, 0.2f, 0));
  const LeafConnectivity result = CountConnectedLeaves(truth, mesh);
  EXPECT_EQ(result.one_component_strict, 1);  // the overlap strip counts as a piece of leaf 1
  EXPECT_EQ(result.one_component, 2);         // settled on leaf 2's sheet, which it belongs to
}

TEST(LeafConnectivity, AnUnambiguousStrayPieceStillCounts) {
  // A separate 2 mm wide patch 2.5 mm above leaf 1, nearer to it than to leaf 2 by more than the
  // ambiguity: a piece of leaf 1 the mesh leaves apart, 20 mm^2 beside its 100 mm^2.
  const geometry::Mesh mesh = Join(TwoLeaves(), Sheet(2, 4, 2.5f, 0));
  const LeafConnectivity result = CountConnectedLeaves(TwoLeaves(), mesh);
  EXPECT_EQ(result.one_component, 1);
  EXPECT_EQ(result.mostly_one, 1);  // leaf 1's largest piece holds 83 % of its area
}

}  // namespace
}  // namespace avc::bench
