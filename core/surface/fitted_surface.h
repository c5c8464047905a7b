#pragma once

// The local surface of a cell's points (moving least squares, one step): around a query, the
// points within a radius get a Gaussian-weighted tangent frame and a quadratic height field
// over it, and the query moves along the frame's normal onto that height field. A mesh whose
// vertices are the noisy samples themselves and whose faces are chords between them sits on
// neither: the fit averages the noise of a dozen samples and carries the leaf's curvature into
// the space between them (paper §4 Phase 2: grown boundary points are re-projected onto "the
// local surface fitted to the surrounding points").

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "core/cluster/point_grid.h"

namespace avc::surface {

struct FittedSurfaceOptions {
  // Neighbourhood radius, in point spacings, widened (doubling, up to max_radius_factor) until
  // it holds min_points: about the 12-20 nearest samples of an even sampling.
  double radius_factor = 2.0;
  double max_radius_factor = 4.0;
  int min_points = 10;
};

class FittedSurface {
 public:
  // points: the cell's samples (m); facing: the cell's normal, which the frames face along.
  // spacing > 0 (m).
  FittedSurface(std::vector<Eigen::Vector3f> points, const Eigen::Vector3d& facing, double spacing,
                const FittedSurfaceOptions& options = {});

  // query moved along the local normal onto the fitted surface; nullopt when fewer than 3
  // points are within the widest radius (nothing to fit: the caller keeps the vertex).
  std::optional<Eigen::Vector3f> Project(const Eigen::Vector3f& query) const;

 private:
  std::vector<Eigen::Vector3f> points_;
  Eigen::Vector3d facing_;
  double spacing_;
  FittedSurfaceOptions options_;
  cluster::PointGrid grid_;
};

}  // namespace avc::surface
