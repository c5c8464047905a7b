#pragma once

// Baseline: Pound et al. 2014's canopy reconstruction as the paper compares with (Table 4;
// Plant Physiology 166:1688), without its image term: the points are cut into patches of a fixed
// radius (the input's clusters are ignored), each patch is a planar section (its points
// projected onto their regression plane and triangulated there), its outline grows in that
// plane until it nears another patch, and patches are never merged: a set of flat pieces with
// gaps between them. Built from the surfacer's own Phase 1 and Phase 2 pieces.

#include <cstdint>
#include <vector>

#include "core/geometry/mesh.h"
#include "core/geometry/point_cloud.h"

namespace avc::surface::baselines {

struct PoundOptions {
  double spacing = 0;  // m; <= 0: measured (median nearest-neighbour distance)
  // Patch radius in spacings (Pound's user-set size). 8 spacings holds ~45 points of a random
  // sampling (density ~0.22 / spacing^2), enough for a stable plane, while a patch stays
  // nearly flat on a curved leaf; the paper's comparison also chose a small radius (§4.2).
  double patch_radius_factor = 8.0;
  // Triangles on the plane kept up to this circumradius in spacings: the surfacer's alpha.
  double alpha_factor = 4.0;
  // Outline vertices with a point of another patch this close (spacings) stop growing.
  double growth_clearance_factor = 2.0;
};

// The patch of each point (0..P-1): seeds taken in point order, each gathering the points not
// yet taken within the radius. Deterministic.
std::vector<int32_t> FixedRadiusPatches(const std::vector<Eigen::Vector3f>& points, double radius);

// face_labels = patch id. Throws std::invalid_argument naming the problem for bad input
// (fewer than 3 points, non-finite points or normals).
geometry::Mesh PoundPatches(const geometry::PointCloud& cloud, const PoundOptions& options = {});

}  // namespace avc::surface::baselines
