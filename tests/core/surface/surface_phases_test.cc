// The surfacer's phases one by one on small meshes with known answers: boundary loops, hole
// filling, sliver and long-triangle removal, Laplacian smoothing, Phase 1 triangulation (incl.
// the fold split), boundary growth, stitching, subdivision and the fitted-surface projection.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <random>
#include <utility>

#include "core/surface/boundary_growth.h"
#include "core/surface/cell_islands.h"
#include "core/surface/cell_merging.h"
#include "core/surface/fitted_surface.h"
#include "core/surface/hole_filling.h"
#include "core/surface/laplacian_smoothing.h"
#include "core/surface/mesh_subdivision.h"
#include "core/surface/mesh_topology.h"
#include "core/surface/triangle_cleanup.h"
#include "core/surface/triangulate_cell.h"
#include "core/util/ordered_draws.h"
#include "tests/core/surface/surface_test_points.h"

namespace avc::surface {
namespace {

// An n x n grid of unit-pitch squares (pitch h) in z = 0, facing +z, label 0.
geometry::Mesh Grid(int n, float h = 1.0f) {
  geometry::Mesh mesh;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) mesh.vertices.emplace_back(h * i, h * j, 0.0f);
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      mesh.faces.emplace_back(a, b, d);
      mesh.faces.emplace_back(a, d, c);
    }
  }
  mesh.face_labels.assign(mesh.faces.size(), 0);
  return mesh;
}

// Phase 4's rule with this stitch distance and the defaults otherwise.
StitchRule Rule(double distance) {
  StitchRule rule;
  rule.distance = distance;
  return rule;
}

// Removes the two faces of each grid square (i, j) listed.
void Punch(geometry::Mesh& mesh, int n, const std::vector<std::pair<int, int>>& squares) {
  std::vector<bool> keep(mesh.faces.size(), true);
  for (const auto& [i, j] : squares) keep[2 * (j * n + i)] = keep[2 * (j * n + i) + 1] = false;
  KeepFaces(mesh, keep);
}

TEST(MeshTopology, GridHasOneCounterClockwiseOuterLoop) {
  const geometry::Mesh mesh = Grid(4);
  const std::vector<BoundaryLoop> loops = BoundaryLoops(mesh);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_TRUE(loops[0].closed);
  EXPECT_EQ(loops[0].vertices.size(), 16u);
  EXPECT_DOUBLE_EQ(loops[0].Perimeter(mesh), 16.0);
  // Counter-clockwise seen from +z: positive signed area.
  double twice_area = 0.0;
  for (size_t i = 0; i < loops[0].vertices.size(); ++i) {
    const Eigen::Vector3f& a = mesh.vertices[loops[0].vertices[i]];
    const Eigen::Vector3f& b = mesh.vertices[loops[0].vertices[(i + 1) % 16]];
    twice_area += a.x() * b.y() - b.x() * a.y();
  }
  EXPECT_NEAR(twice_area, 32.0, 1e-9);
  int components = 0;
  FaceComponents(mesh, &components);
  EXPECT_EQ(components, 1);
}

TEST(HoleFilling, SmallHolesAreFilledTheOuterBoundaryNever) {
  geometry::Mesh mesh = Grid(6);
  Punch(mesh, 6, {{2, 2}, {4, 3}});
  ASSERT_EQ(BoundaryLoops(mesh).size(), 3u);
  EXPECT_EQ(FillSmallHoles(mesh, 3.9), 0u);  // holes have perimeter 4
  EXPECT_EQ(FillSmallHoles(mesh, 100.0), 2u);
  EXPECT_EQ(BoundaryLoops(mesh).size(), 1u);
  EXPECT_NEAR(geometry::SurfaceArea(mesh), 36.0, 1e-6);
  EXPECT_TRUE(mesh.Validate().empty());
  ASSERT_EQ(mesh.face_labels.size(), mesh.faces.size());
  // The fillings face the same way as the sheet.
  for (const Eigen::Vector3i& t : mesh.faces) {
    const Eigen::Vector3f n = (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                                  .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
    EXPECT_GT(n.z(), 0.0f);
  }
}

TEST(TriangleCleanup, LongTrianglesAndBoundarySliversGo) {
  geometry::Mesh mesh = Grid(2);
  // A sliver on the boundary: a far, nearly collinear vertex below the bottom edge.
  mesh.vertices.emplace_back(1.0f, -0.05f, 0.0f);
  const int sliver = static_cast<int>(mesh.vertices.size()) - 1;
  mesh.faces.emplace_back(0, sliver, 2);
  mesh.face_labels.push_back(0);
  EXPECT_EQ(PeelBoundarySlivers(mesh, 0.1), 1u);
  EXPECT_EQ(mesh.faces.size(), 8u);
  mesh.vertices[8] = Eigen::Vector3f(2.0f, 2.0f, 5.0f);  // lift a corner: its two faces
  EXPECT_EQ(RemoveLongTriangles(mesh, 3.0), 2u);
  EXPECT_EQ(mesh.faces.size(), 6u);
}

TEST(LaplacianSmoothing, NoiseGoesTheSheetKeepsItsSize) {
  geometry::Mesh mesh = Grid(20, 0.01f);
  std::mt19937_64 rng(4);
  for (Eigen::Vector3f& v : mesh.vertices) v.z() += static_cast<float>(0.002 * test::Gaussian(rng));
  const double noisy_area = geometry::SurfaceArea(mesh);
  SmoothSheet(mesh, SmoothingOptions{});
  double rms = 0.0;
  for (const Eigen::Vector3f& v : mesh.vertices) rms += v.z() * v.z();
  rms = std::sqrt(rms / static_cast<double>(mesh.vertices.size()));
  EXPECT_LT(rms, 0.0012);
  EXPECT_LT(geometry::SurfaceArea(mesh), noisy_area);
  EXPECT_NEAR(geometry::SurfaceArea(mesh), 0.04, 0.04 * 0.03);
  // Boundary vertices move only along the outline: it stays on the square.
  const std::vector<BoundaryLoop> loops = BoundaryLoops(mesh);
  for (int v : loops[0].vertices) {
    const Eigen::Vector3f& p = mesh.vertices[v];
    const float to_edge = std::min(
        {std::abs(p.x()), std::abs(p.y()), std::abs(p.x() - 0.2f), std::abs(p.y() - 0.2f)});
    EXPECT_LT(to_edge, 2.5e-3f);  // a quarter pitch: only the corners round off
  }
}

TEST(TriangulateCell, FlatClusterBecomesAnOrientedCell) {
  const ClusteredPoints points = test::SpiralDisc(0.02, 400);
  std::vector<uint32_t> members(points.cloud.size());
  for (uint32_t i = 0; i < members.size(); ++i) members[i] = i;
  std::string problem;
  const Cell cell = TriangulateCell(points, 0, members, 0.004, &problem);
  EXPECT_TRUE(problem.empty());
  EXPECT_NEAR(cell.plane.normal.z(), 1.0, 1e-9);
  EXPECT_GT(cell.mesh.faces.size(), 700u);
  EXPECT_EQ(BoundaryLoops(cell.mesh).size(), 1u);
  ASSERT_EQ(cell.source_points.size(), cell.mesh.vertices.size());
  EXPECT_EQ(cell.source_points[10], 10);
}

TEST(TriangulateCell, NormalsDecideTheFrontSide) {
  ClusteredPoints points = test::SpiralDisc(0.02, 100);
  for (Eigen::Vector3f& n : points.cloud.normals) n = -n;
  std::vector<uint32_t> members(points.cloud.size());
  for (uint32_t i = 0; i < members.size(); ++i) members[i] = i;
  const Cell cell = TriangulateCell(points, 0, members, 0.01, nullptr);
  EXPECT_NEAR(cell.plane.normal.z(), -1.0, 1e-9);
}

TEST(TriangulateSurfacePiece, ArchIsSplitUntilEachPartIsAHeightField) {
  // A sheet bent through 240 degrees: its projection on any plane folds over.
  const ClusteredPoints points =
      test::CylinderSheet(0.02, 4.0 * std::numbers::pi / 3.0, 0.04, 2000, 2);
  std::vector<uint32_t> members(points.cloud.size());
  for (uint32_t i = 0; i < members.size(); ++i) members[i] = i;
  std::string problem;
  const std::vector<Cell> cells = TriangulateSurfacePiece(points, 0, members, 0.004, &problem);
  EXPECT_GE(cells.size(), 2u);
  double area = 0.0;
  for (const Cell& cell : cells) area += geometry::SurfaceArea(cell.mesh);
  const double truth = 0.02 * 4.0 * std::numbers::pi / 3.0 * 0.04;
  EXPECT_GT(area / truth, 0.85);
  EXPECT_LT(area / truth, 1.01);
}

TEST(BoundaryGrowth, EvenGridGrowsByHalfAPitch) {
  Cell cell;
  cell.mesh = Grid(10, 0.001f);
  cell.source_points.assign(cell.mesh.vertices.size(), 0);
  const std::vector<Cell> cells = {cell};
  const double band = EstimateBoundaryBand(cells, 0.001, 1.0);
  EXPECT_NEAR(band, 0.0005, 1e-9);
  const GrowthStats stats = GrowOuterBoundary(cell, band, [](int) { return true; });
  EXPECT_EQ(stats.vertices, 40u);
  EXPECT_EQ(stats.faces, 80u);
  // The 10 x 10 mm square grew by 0.5 mm a side (corners cut: ~11 x 11 mm less a bit).
  const double area = geometry::SurfaceArea(cell.mesh);
  EXPECT_GT(area, 1.2e-4);
  EXPECT_LT(area, 1.21e-4);
  EXPECT_EQ(BoundaryLoops(cell.mesh).size(), 1u);
  ASSERT_EQ(cell.source_points.size(), cell.mesh.vertices.size());
  EXPECT_EQ(cell.source_points.back(), -1);
  // Vertices that are not free stay.
  Cell held;
  held.mesh = Grid(4);
  held.source_points.assign(held.mesh.vertices.size(), 0);
  EXPECT_EQ(GrowOuterBoundary(held, 0.5, [](int) { return false; }).vertices, 0u);
}

// Two cells: the first `rows` rows of an n x n grid, and a copy moved by `offset` in cluster
// `upper_label`, joined into one mesh.
struct TwoCells {
  geometry::Mesh mesh;
  std::vector<int> vertex_cell;
};
TwoCells JoinedStrips(int n, int rows, const Eigen::Vector3f& offset, int32_t upper_label) {
  Cell lower;
  lower.mesh = Grid(n);
  std::vector<bool> keep(lower.mesh.faces.size());
  for (size_t f = 0; f < keep.size(); ++f) keep[f] = f < static_cast<size_t>(2 * n * rows);
  KeepFaces(lower.mesh, keep);
  RemoveUnusedVertices(lower.mesh);
  Cell upper = lower;
  upper.cluster = upper_label;
  for (Eigen::Vector3f& v : upper.mesh.vertices) v += offset;
  upper.mesh.face_labels.assign(upper.mesh.faces.size(), upper_label);
  TwoCells joined;
  joined.mesh = JoinCells({lower, upper}, &joined.vertex_cell);
  return joined;
}

TEST(CellMerging, GapBetweenTwoHalvesIsTriangulated) {
  // Two 10 x 5 grids one pitch apart: the gap strip is 10 x 1.
  TwoCells cells = JoinedStrips(10, 5, Eigen::Vector3f(0.0f, 6.0f, 0.0f), 1);
  geometry::Mesh& mesh = cells.mesh;
  const StitchStats stats =
      StitchCells(mesh, cells.vertex_cell, {Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitZ()},
                  {0, 1}, Rule(1.6));
  EXPECT_EQ(stats.neighbour_pairs, 1u);
  EXPECT_EQ(stats.faces, 20u);
  EXPECT_NEAR(geometry::SurfaceArea(mesh), 110.0, 1e-6);
  int components = 0;
  FaceComponents(mesh, &components);
  EXPECT_EQ(components, 1);
  EXPECT_EQ(BoundaryLoops(mesh).size(), 1u);  // manifold, consistently oriented
}

TEST(CellMerging, StackedSheetsAreNotWalledTogether) {
  Cell lower;
  lower.mesh = Grid(6);
  Cell upper = lower;
  upper.cluster = 1;
  for (Eigen::Vector3f& v : upper.mesh.vertices) v.z() += 1.0f;
  std::vector<int> vertex_cell;
  geometry::Mesh mesh = JoinCells({lower, upper}, &vertex_cell);
  const StitchStats stats = StitchCells(
      mesh, vertex_cell, {Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitZ()}, {0, 1}, Rule(1.6));
  EXPECT_EQ(stats.faces, 0u);
}

// Two flat strips 1 apart along y, the second `rise` higher (a step, like one leaf's base
// lying above the next leaf's at a rosette's centre): stitched faces between them.
size_t StitchedAcrossStep(float rise, int32_t upper_label, const StitchRule& rule) {
  TwoCells cells = JoinedStrips(6, 2, Eigen::Vector3f(0.0f, 3.0f, rise), upper_label);
  return StitchCells(cells.mesh, cells.vertex_cell,
                     {Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitZ()}, {0, upper_label}, rule)
      .faces;
}

TEST(CellMerging, ClustersAreJoinedOnlyWhereTheyContinueOneSurface) {
  // Level: one surface whatever the clusters (six squares of gap, two faces each).
  EXPECT_EQ(StitchedAcrossStep(0.0f, 1, Rule(1.8)), 12u);
  // A step of 0.8 over the gap of 1: within the 60 degree tilt, but the gap's edges rise 39
  // degrees off both strips' planes: not one surface, so two clusters stay apart...
  EXPECT_EQ(StitchedAcrossStep(0.8f, 1, Rule(1.8)), 0u);
  // ...unless the link test is off, or both strips are one cluster.
  StitchRule no_link = Rule(1.8);
  no_link.link_slope = -1.0f;
  EXPECT_EQ(StitchedAcrossStep(0.8f, 1, no_link), 12u);
  EXPECT_EQ(StitchedAcrossStep(0.8f, 0, Rule(1.8)), 12u);
}

TEST(CellMerging, OneClusterIsStitchedAcrossWiderGaps) {
  // A level gap of 1 (1.41 along the diagonals) with the stitch distance 0.9: too wide between
  // clusters; within one cluster too while its own distance is unset (the same 0.9), bridged
  // once it is 1.5.
  StitchRule rule = Rule(0.9);
  EXPECT_EQ(StitchedAcrossStep(0.0f, 1, rule), 0u);
  EXPECT_EQ(StitchedAcrossStep(0.0f, 0, rule), 0u);
  rule.own_cluster_distance = 1.5;
  EXPECT_EQ(StitchedAcrossStep(0.0f, 1, rule), 0u);
  EXPECT_EQ(StitchedAcrossStep(0.0f, 0, rule), 12u);
}

TEST(CellMerging, BridgesDoNotPassOverAThirdCell) {
  // Two level strips with a gap of 1, and a third cell (a 6 x 1 strip of another cluster, at
  // half the pitch) lying 0.3 over the gap, like a leaf base over the gap between two others at
  // a rosette's centre.
  TwoCells cells = JoinedStrips(6, 2, Eigen::Vector3f(0.0f, 3.0f, 0.0f), 1);
  Cell over;
  over.cluster = 2;
  over.mesh = Grid(12, 0.5f);
  std::vector<bool> keep(over.mesh.faces.size());
  for (size_t f = 0; f < keep.size(); ++f) keep[f] = f < 48;
  KeepFaces(over.mesh, keep);
  RemoveUnusedVertices(over.mesh);
  for (Eigen::Vector3f& v : over.mesh.vertices) v += Eigen::Vector3f(0.25f, 2.0f, 0.3f);
  over.mesh.face_labels.assign(over.mesh.faces.size(), 2);
  const size_t first_over = cells.mesh.vertices.size();
  cells.mesh.Append(over.mesh);
  cells.vertex_cell.resize(cells.mesh.vertices.size(), 2);
  // Faces joining the two strips (a vertex of each, none of the third cell).
  const auto strip_to_strip = [&](const geometry::Mesh& mesh, size_t first_new) {
    size_t count = 0;
    for (size_t f = first_new; f < mesh.faces.size(); ++f) {
      bool lower = false, upper = false, third = false;
      for (int k = 0; k < 3; ++k) {
        const int cell = cells.vertex_cell[mesh.faces[f][k]];
        lower |= cell == 0;
        upper |= cell == 1;
        third |= static_cast<size_t>(mesh.faces[f][k]) >= first_over;
      }
      count += lower && upper && !third;
    }
    return count;
  };
  const std::vector<Eigen::Vector3d> normals(3, Eigen::Vector3d::UnitZ());
  StitchRule rule = Rule(1.8);
  rule.link_slope = -1.0f;
  for (const bool clear : {false, true}) {
    geometry::Mesh mesh = cells.mesh;
    rule.clear_of_other_cells = clear;
    StitchCells(mesh, cells.vertex_cell, normals, {0, 1, 2}, rule);
    // Without the rule the strips are bridged under the third cell (12 faces over the gap).
    EXPECT_EQ(strip_to_strip(mesh, cells.mesh.faces.size()), clear ? 0u : 12u) << clear;
  }
  // Away from the third cell the rule changes nothing.
  EXPECT_EQ(StitchedAcrossStep(0.0f, 1, rule), 12u);
}

TEST(CellIslands, APieceCutOffACellIsStitchedBackAsACellOfItsOwn) {
  // A 10 x 10 grid with its fourth row of squares removed (as Phase 3 may remove the long
  // triangles across a leaf's narrow neck): one cell in two pieces, a gap of 1 between them.
  Cell cell;
  cell.cluster = 7;
  cell.mesh = Grid(10);
  Punch(cell.mesh, 10,
        {{0, 3}, {1, 3}, {2, 3}, {3, 3}, {4, 3}, {5, 3}, {6, 3}, {7, 3}, {8, 3}, {9, 3}});
  for (size_t v = 0; v < cell.mesh.vertices.size(); ++v) {
    cell.source_points.push_back(static_cast<int32_t>(100 + v));
  }
  const Cell whole = cell;
  size_t islands = 0;
  std::vector<Cell> pieces = SplitCellsIntoPieces({cell}, &islands);
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_EQ(islands, 1u);
  EXPECT_EQ(pieces[0].mesh.faces.size(), 60u);   // rows 0-2
  EXPECT_EQ(pieces[1].mesh.faces.size(), 120u);  // rows 4-9
  for (const Cell& piece : pieces) {
    EXPECT_EQ(piece.cluster, 7);
    ASSERT_EQ(piece.source_points.size(), piece.mesh.vertices.size());
    for (size_t v = 0; v < piece.mesh.vertices.size(); ++v) {
      // Each vertex keeps its own input point: the grid's row-major index + 100.
      const Eigen::Vector3f& p = piece.mesh.vertices[v];
      EXPECT_EQ(piece.source_points[v], static_cast<int32_t>(100 + 11 * p.y() + p.x()));
    }
  }
  // Phase 4 then bridges the gap (20 faces), which it never does within one cell.
  const auto stitched_faces = [](const std::vector<Cell>& cells) {
    std::vector<int> vertex_cell;
    geometry::Mesh mesh = JoinCells(cells, &vertex_cell);
    const std::vector<Eigen::Vector3d> normals(cells.size(), Eigen::Vector3d::UnitZ());
    return StitchCells(mesh, vertex_cell, normals, std::vector<int32_t>(cells.size(), 7), Rule(1.6))
        .faces;
  };
  EXPECT_EQ(stitched_faces({whole}), 0u);
  EXPECT_EQ(stitched_faces(pieces), 20u);
  // A cell in one piece stays as it is.
  pieces = SplitCellsIntoPieces({pieces[0]}, &islands);
  EXPECT_EQ(pieces.size(), 1u);
  EXPECT_EQ(islands, 0u);
}

}  // namespace
}  // namespace avc::surface

namespace avc::surface {
namespace {

TEST(MeshSubdivision, EveryFaceBecomesFourSharingEdgeMidpoints) {
  geometry::Mesh mesh = Grid(1);  // 4 vertices, 2 faces, 5 edges
  mesh.colors.assign(4, {10, 20, 30});
  mesh.colors[1] = {11, 21, 31};
  std::vector<int32_t> sources = {0, 1, 2, 3};
  const double area = geometry::SurfaceArea(mesh);
  EXPECT_EQ(SubdivideMidpoints(mesh, &sources), 5u);
  EXPECT_EQ(mesh.Validate(), "");
  ASSERT_EQ(mesh.vertices.size(), 9u);
  EXPECT_EQ(mesh.faces.size(), 8u);
  EXPECT_EQ(mesh.face_labels, std::vector<int32_t>(8, 0));
  EXPECT_EQ(sources, (std::vector<int32_t>{0, 1, 2, 3, -1, -1, -1, -1, -1}));
  EXPECT_NEAR(geometry::SurfaceArea(mesh), area, 1e-6);
  // The shared diagonal's midpoint is one vertex: still one outer loop, no holes, all faces up.
  EXPECT_EQ(BoundaryLoops(mesh).size(), 1u);
  for (const Eigen::Vector3i& t : mesh.faces) {
    const Eigen::Vector3f n = (mesh.vertices[t[1]] - mesh.vertices[t[0]])
                                  .cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]);
    EXPECT_GT(n.z(), 0.0f);
  }
  EXPECT_EQ(mesh.colors[4], (Eigen::Matrix<uint8_t, 3, 1>(11, 21, 31)));  // (10+11+1)/2 ...
}

// Samples 3 mm apart on a cylinder of radius 15 mm (a curled leaf): between samples the chords
// sag by 0.075-0.15 mm, the fitted surface follows the cylinder; with 0.2 mm noise per axis the
// projection stays within the noise of one sample. Queries move along the local normal.
double WorstOffCylinder(double noise, double* rms) {
  const double r = 0.015;
  std::mt19937_64 rng(11);
  std::vector<Eigen::Vector3f> points;
  for (int i = -8; i <= 8; ++i) {
    for (int j = -8; j <= 8; ++j) {
      const double phi = 0.003 * i / r;
      const Eigen::Vector3d p(r * std::sin(phi), 0.003 * j, r * std::cos(phi));
      const Eigen::Vector3d jitter =
          util::DrawVector3<Eigen::Vector3d>([&] { return test::Gaussian(rng); });
      points.push_back((p + noise * jitter).cast<float>());
    }
  }
  const FittedSurface surface(points, Eigen::Vector3d(0.3, 0.0, 1.0), 0.003);
  double worst = 0.0, sum = 0.0;
  int n = 0;
  for (const double phi : {-0.5, -0.1, 0.0137, 0.1, 0.3}) {  // midway between sample columns too
    for (const double y : {-0.0045, 0.0015, 0.0041}) {
      for (const double offset : {-0.002, 0.0, 0.0015}) {  // off the sheet along its normal
        const Eigen::Vector3f query =
            Eigen::Vector3d((r + offset) * std::sin(phi), y, (r + offset) * std::cos(phi))
                .cast<float>();
        const auto projected = surface.Project(query);
        EXPECT_TRUE(projected.has_value());
        if (!projected) continue;
        const double off = std::abs(std::hypot(projected->x(), projected->z()) - r);
        worst = std::max(worst, off);
        sum += off * off;
        ++n;
        EXPECT_NEAR(std::atan2(projected->x(), projected->z()), phi, 0.02);
      }
    }
  }
  *rms = std::sqrt(sum / n);
  return worst;
}

TEST(FittedSurface, FollowsACurledSheetBetweenItsSamples) {
  double rms = 0.0;
  EXPECT_LT(WorstOffCylinder(0.0, &rms), 0.00002);  // 0.02 mm, against chords sagging 0.075+
  EXPECT_LT(WorstOffCylinder(0.0002, &rms), 0.0004);
  EXPECT_LT(rms, 0.0002);  // within one sample's noise
}

TEST(FittedSurface, TooFewSamplesNearLeaveTheVertexAlone) {
  const std::vector<Eigen::Vector3f> points = {{0, 0, 0}, {0.003f, 0, 0}, {0, 0.003f, 0}};
  const FittedSurface surface(points, Eigen::Vector3d::UnitZ(), 0.003);
  EXPECT_FALSE(surface.Project({1.0f, 1.0f, 1.0f}).has_value());  // nothing within reach
  const auto flat = surface.Project({0.001f, 0.001f, 0.002f});    // three: the plane
  ASSERT_TRUE(flat.has_value());
  EXPECT_NEAR(flat->z(), 0.0f, 1e-6f);
  EXPECT_NEAR(flat->x(), 0.001f, 1e-6f);
}

}  // namespace
}  // namespace avc::surface
