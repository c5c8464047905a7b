#include "core/eval/nearest_point_index.h"

#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Simple_cartesian.h>

#include <cmath>
#include <stdexcept>

namespace avc::eval {
namespace {

using SimpleKernel = CGAL::Simple_cartesian<double>;
using Search = CGAL::Orthogonal_k_neighbor_search<CGAL::Search_traits_3<SimpleKernel>>;

}  // namespace

struct NearestPointIndex::Impl {
  Search::Tree tree;
};

NearestPointIndex::NearestPointIndex(const std::vector<Eigen::Vector3d>& points)
    : impl_(std::make_unique<Impl>()) {
  if (points.empty()) throw std::invalid_argument("nearest point index: no points");
  for (const Eigen::Vector3d& p : points)
    impl_->tree.insert(SimpleKernel::Point_3(p.x(), p.y(), p.z()));
  // Build now: concurrent const queries then never trigger a lazy build.
  impl_->tree.build();
}

NearestPointIndex::~NearestPointIndex() = default;

double NearestPointIndex::Distance(const Eigen::Vector3d& query) const {
  const Search search(impl_->tree, SimpleKernel::Point_3(query.x(), query.y(), query.z()), 1);
  // The default distance reports squared Euclidean distances.
  return std::sqrt(search.begin()->second);
}

}  // namespace avc::eval
