#include "bench/clustering/compared_methods.h"

namespace avc::bench {

std::vector<ComparedMethod> ComparedMethods(const ComparisonOptions& options, int clusters) {
  namespace cb = cluster::baselines;
  std::vector<ComparedMethod> methods;
  if (options.ours) methods.push_back({options.ours_name, options.ours, 0});
  cb::KMeansOptions kmeans = options.kmeans;
  kmeans.clusters = clusters;
  methods.push_back(
      {kKMeansName,
       [kmeans](const cluster::PointSet& s) { return cb::KMeansClustering(s, kmeans); }, 0});
  cb::IpddpOptions ipddp = options.ipddp;
  ipddp.max_clusters = clusters;
  methods.push_back({kIpddpName,
                     [ipddp](const cluster::PointSet& s) { return cb::IpddpClustering(s, ipddp); },
                     0});
  cb::DenseSpectralOptions dense = options.dense_spectral;
  dense.clusters = clusters;
  methods.push_back(
      {kDenseSpectralName,
       [dense](const cluster::PointSet& s) { return cb::DenseSpectralClustering(s, dense); },
       options.dense_spectral_max_points});
  cb::SparseSpectralOptions sparse = options.sparse_spectral;
  sparse.clusters = clusters;
  methods.push_back(
      {kSparseSpectralName,
       [sparse](const cluster::PointSet& s) { return cb::SparseSpectralClustering(s, sparse); },
       0});
  const cb::RegionGrowingOptions growing = options.region_growing;
  methods.push_back(
      {kRegionGrowingName,
       [growing](const cluster::PointSet& s) { return cb::RegionGrowingClustering(s, growing); },
       0});
  return methods;
}

}  // namespace avc::bench
