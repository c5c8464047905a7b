#include "bench/clustering/baselines/region_growing.h"

#include <pcl/features/normal_3d.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/region_growing.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "bench/clustering/baselines/input_checks.h"
#include "bench/clustering/baselines/relabel.h"

namespace avc::cluster::baselines {
namespace {

float Quantile(std::vector<float> values, double q) {
  const size_t at = static_cast<size_t>(std::floor(q * static_cast<double>(values.size() - 1)));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(at), values.end());
  return values[at];
}

}  // namespace

Assignment RegionGrowingClustering(const PointSet& set, const RegionGrowingOptions& options) {
  CheckPoints(set, "region growing");
  CheckNormals(set, "region growing");
  if (!(options.smoothness_degrees > 0 && options.smoothness_degrees <= 180) ||
      options.neighbours < 1 || options.min_cluster_size < 1 ||
      !(options.curvature_quantile >= 0 && options.curvature_quantile <= 1) ||
      !std::isfinite(options.curvature_threshold)) {
    throw std::invalid_argument(
        "region growing: smoothness must be in (0, 180] degrees, neighbours and "
        "min_cluster_size >= 1, curvature_quantile in [0, 1], curvature_threshold finite");
  }
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
  cloud->reserve(set.points.size());
  for (const Eigen::Vector3f& p : set.points) cloud->push_back({p.x(), p.y(), p.z()});
  pcl::search::KdTree<pcl::PointXYZ>::Ptr tree(new pcl::search::KdTree<pcl::PointXYZ>);
  tree->setInputCloud(cloud);

  // PCA curvature (lambda_min / sum) over the same neighbourhood region growing uses; the
  // estimated normals are replaced by the set's (oriented, from the scan).
  pcl::PointCloud<pcl::Normal>::Ptr normals(new pcl::PointCloud<pcl::Normal>);
  pcl::NormalEstimation<pcl::PointXYZ, pcl::Normal> estimation;
  estimation.setInputCloud(cloud);
  estimation.setSearchMethod(tree);
  estimation.setKSearch(std::min<int>(options.neighbours, static_cast<int>(cloud->size())));
  estimation.compute(*normals);
  std::vector<float> curvatures;
  curvatures.reserve(set.points.size());
  for (size_t i = 0; i < set.points.size(); ++i) {
    const Eigen::Vector3f n = set.normals[i].normalized();
    pcl::Normal& normal = (*normals)[i];
    normal.normal_x = n.x(), normal.normal_y = n.y(), normal.normal_z = n.z();
    // Too few neighbours for PCA gives NaN: treat as an edge point (maximal curvature 1/3).
    if (!std::isfinite(normal.curvature)) normal.curvature = 1.0f / 3.0f;
    curvatures.push_back(normal.curvature);
  }
  const double curvature_threshold = options.curvature_threshold > 0
                                         ? options.curvature_threshold
                                         : Quantile(curvatures, options.curvature_quantile);

  pcl::RegionGrowing<pcl::PointXYZ, pcl::Normal> growing;
  growing.setInputCloud(cloud);
  growing.setInputNormals(normals);
  growing.setSearchMethod(tree);
  growing.setNumberOfNeighbours(options.neighbours);
  growing.setSmoothnessThreshold(
      static_cast<float>(options.smoothness_degrees * std::numbers::pi / 180.0));
  growing.setCurvatureTestFlag(true);
  // Strictly below the threshold grows on; nudge so the quantile point itself is a seed.
  growing.setCurvatureThreshold(static_cast<float>(curvature_threshold) * 1.0001f + 1e-9f);
  growing.setResidualTestFlag(false);
  growing.setMinClusterSize(options.min_cluster_size);
  growing.setMaxClusterSize(static_cast<pcl::uindex_t>(set.points.size()));
  std::vector<pcl::PointIndices> regions;
  growing.extract(regions);

  Assignment assignment(set.points.size(), kUnassigned);
  for (size_t r = 0; r < regions.size(); ++r) {
    for (pcl::index_t i : regions[r].indices) {
      assignment[static_cast<size_t>(i)] = static_cast<int32_t>(r);
    }
  }
  return RelabelByFirstAppearance(assignment);
}

}  // namespace avc::cluster::baselines
