#include "bench/clustering/baselines/knn_graph.h"

#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_types.h>

namespace avc::cluster::baselines {

KnnGraph BuildKnnGraph(const PointSet& set, int k) {
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
  cloud->reserve(set.points.size());
  for (const Eigen::Vector3f& p : set.points) cloud->push_back({p.x(), p.y(), p.z()});
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud(cloud);
  KnnGraph graph;
  graph.neighbours.resize(set.points.size());
  graph.squared_distances.resize(set.points.size());
  const int wanted = std::min<int>(k + 1, static_cast<int>(set.points.size()));
  std::vector<int> found;
  std::vector<float> distances;
  for (size_t i = 0; i < set.points.size(); ++i) {
    tree.nearestKSearch(static_cast<int>(i), wanted, found, distances);
    for (size_t j = 0; j < found.size(); ++j) {
      if (found[j] == static_cast<int>(i)) continue;  // the query point itself
      if (static_cast<int>(graph.neighbours[i].size()) == k) break;
      graph.neighbours[i].push_back(found[j]);
      graph.squared_distances[i].push_back(distances[j]);
    }
  }
  return graph;
}

}  // namespace avc::cluster::baselines
