#pragma once

// Distance from a query to the nearest of a fixed set of points (a CGAL kd-tree): how far a
// ground-truth sample is from a reconstructed point cloud. Built once; const queries are safe
// from many threads at once.

#include <Eigen/Core>
#include <memory>
#include <vector>

namespace avc::eval {

class NearestPointIndex {
 public:
  // Throws std::invalid_argument when points is empty.
  explicit NearestPointIndex(const std::vector<Eigen::Vector3d>& points);
  ~NearestPointIndex();
  NearestPointIndex(const NearestPointIndex&) = delete;
  NearestPointIndex& operator=(const NearestPointIndex&) = delete;

  // Euclidean distance (metres) to the nearest point.
  double Distance(const Eigen::Vector3d& query) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace avc::eval
