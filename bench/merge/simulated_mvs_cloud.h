#pragma once

// Raw clouds for the merging benchmark: what multi-view stereo hands to model merging, made
// from a scan's ground truth so that the truth of every point is known. Points are drawn
// uniformly by area on the plant's organs and displaced by Gaussian noise (MVS's depth error);
// outliers are spread uniformly over a box around the plant (MVS's mismatches), and either
// kind can be added to a real MVS run's points.

#include <Eigen/Geometry>
#include <cstddef>
#include <cstdint>

#include "core/geometry/mesh.h"
#include "core/mvs/mvs_points.h"

namespace avc::bench {

struct SimulatedCloudOptions {
  size_t surface_points = 285'000;  // with 5 % outliers: 300,000 points in all
  double noise_sigma = 0.0004;      // metres per axis (our patch MVS: 0.2-0.4 mm mean error)
  uint64_t seed = 1;
};

// Surface samples of `truth` with noise, their face normals and a mid-grey colour; every point
// seen by no view and at confidence 1 (merging reads neither).
mvs::MvsPoints SimulatedMvsCloud(const geometry::Mesh& truth, const SimulatedCloudOptions& options);

// Appends round(n * fraction / (1 - fraction)) points uniform in `box`, with random normals, so
// that `fraction` of the result are outliers; returns how many were added. The originals keep
// their indices [0, n).
size_t InjectOutliers(mvs::MvsPoints& points, double fraction, const Eigen::AlignedBox3d& box,
                      uint64_t seed);

}  // namespace avc::bench
