#pragma once

// Phase 1 of the paper's Algorithm 3 (line 2): a cluster's points are projected to their
// orthogonal regression plane (PCA), triangulated there (2-D Delaunay), and the triangles whose
// circumradius is at most alpha are lifted back onto the original 3-D points: a cell.

#include <cstdint>
#include <string>
#include <vector>

#include "core/surface/cell.h"
#include "core/surface/clustered_points.h"

namespace avc::surface {

// members: point indices into input.cloud (finite, ascending) of one cluster, or of one piece
// of it. Triangles with a circumradius over alpha on the plane are dropped, and so are those
// over alpha once lifted (steep: across a fold or between layers; counted in *steep_faces).
// Returns a cell with no faces and *problem saying why when the points cannot be triangulated
// (fewer than 3, all collinear or coincident, or no triangle within alpha).
Cell TriangulateCell(const ClusteredPoints& input, int32_t cluster,
                     const std::vector<uint32_t>& members, double alpha, std::string* problem,
                     size_t* steep_faces = nullptr);

// A piece of surface whose projection folds (more than kMaxSteepFraction of its triangles
// steep) is split in halves at the median across whichever of its principal axes, or of the
// spread of its normals, leaves the halves flattest, recursively (up to max_depth levels, halves
// of at least kMinSplitPoints points), until every part is a height field over its own plane:
// the clusterer's normal constraint, enforced where the triangulation needs it. Returns the
// cells that have triangles.
inline constexpr double kMaxSteepFraction = 0.03;
inline constexpr size_t kMinSplitPoints = 12;
std::vector<Cell> TriangulateSurfacePiece(const ClusteredPoints& input, int32_t cluster,
                                          const std::vector<uint32_t>& members, double alpha,
                                          std::string* problem, int max_depth = 5);

}  // namespace avc::surface
