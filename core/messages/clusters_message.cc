#include "core/messages/clusters_message.h"

#include <fmt/format.h>

#include <limits>
#include <stdexcept>

#include "core/messages/point_records.h"

namespace avc::messages {
namespace {

constexpr int8_t kInt = avc::point_field_t::TYPE_INT32;

const std::vector<FieldSpec>& ClusterFields() {
  static const std::vector<FieldSpec> fields = {
      {"x", kFloat},     {"y", kFloat},          {"z", kFloat},        {"nx", kFloat},
      {"ny", kFloat},    {"nz", kFloat},         {"red", kByte},       {"green", kByte},
      {"blue", kByte},   {"confidence", kFloat}, {"cluster", kInt},    {"voxel_x", kInt},
      {"voxel_y", kInt}, {"voxel_z", kInt},      {"merged_from", kInt}};
  return fields;
}

// Offsets of every field, found by name (any sender's layout).
struct Offsets {
  int32_t position[3], normal[3], colour[3], confidence, cluster, voxel[3], merged_from;

  Offsets(const avc::point_cloud_t& cloud, const std::string& what)
      : position{FieldOffset(cloud, {"x"}, kFloat, what), FieldOffset(cloud, {"y"}, kFloat, what),
                 FieldOffset(cloud, {"z"}, kFloat, what)},
        normal{FieldOffset(cloud, {"nx"}, kFloat, what), FieldOffset(cloud, {"ny"}, kFloat, what),
               FieldOffset(cloud, {"nz"}, kFloat, what)},
        colour{FieldOffset(cloud, {"red", "r"}, kByte, what),
               FieldOffset(cloud, {"green", "g"}, kByte, what),
               FieldOffset(cloud, {"blue", "b"}, kByte, what)},
        confidence(FieldOffset(cloud, {"confidence"}, kFloat, what)),
        cluster(FieldOffset(cloud, {"cluster"}, kInt, what)),
        voxel{FieldOffset(cloud, {"voxel_x"}, kInt, what),
              FieldOffset(cloud, {"voxel_y"}, kInt, what),
              FieldOffset(cloud, {"voxel_z"}, kInt, what)},
        merged_from(FieldOffset(cloud, {"merged_from"}, kInt, what)) {}
};

void CheckContent(const ClustersContent& content, const std::string& what) {
  const merge::MergedPoints& merged = content.merged;
  const size_t n = merged.size();
  if (const std::string problem = merged.cloud.Validate(); !problem.empty()) {
    throw std::invalid_argument(fmt::format("{}: {}", what, problem));
  }
  if (merged.cloud.normals.size() != n || merged.cloud.colors.size() != n ||
      merged.confidence.size() != n || merged.point_counts.size() != n ||
      merged.voxels.size() != n || content.clusters.size() != n) {
    throw std::invalid_argument(fmt::format(
        "{}: {} points but {} normals, {} colours, {} confidences, {} counts, {} voxels, {} "
        "cluster ids",
        what, n, merged.cloud.normals.size(), merged.cloud.colors.size(), merged.confidence.size(),
        merged.point_counts.size(), merged.voxels.size(), content.clusters.size()));
  }
  for (size_t i = 0; i < n; ++i) {
    const int32_t id = content.clusters[i];
    if (id < cluster::kUnassigned || id >= content.num_clusters) {
      throw std::invalid_argument(
          fmt::format("{}: point {} has cluster {} of {}", what, i, id, content.num_clusters));
    }
  }
}

}  // namespace

avc::clusters_t ClustersToMessage(const ClustersContent& content) {
  const std::string what = fmt::format("clusters '{}'", content.cloud_id);
  CheckContent(content, what);
  const merge::MergedPoints& merged = content.merged;
  avc::clusters_t message{};
  message.cloud_id = content.cloud_id;
  message.map_id = content.map_id;
  message.problem = content.problem;
  message.voxel_size = merged.voxel_size;
  message.points = MakePointCloud(content.cloud_id, ClusterFields(), merged.size());
  avc::point_cloud_t& cloud = message.points;
  const Offsets at(cloud, what);
  for (size_t i = 0; i < merged.size(); ++i) {
    uint8_t* record = cloud.data.data() + i * static_cast<size_t>(cloud.point_step);
    for (int a = 0; a < 3; ++a) {
      PutFloat(record + at.position[a], merged.cloud.positions[i][a]);
      PutFloat(record + at.normal[a], merged.cloud.normals[i][a]);
      record[at.colour[a]] = merged.cloud.colors[i][a];
      PutInt32(record + at.voxel[a], merged.voxels[i][a]);
    }
    PutFloat(record + at.confidence, merged.confidence[i]);
    PutInt32(record + at.cluster, content.clusters[i]);
    if (merged.point_counts[i] > static_cast<uint32_t>(std::numeric_limits<int32_t>::max())) {
      throw std::invalid_argument(fmt::format("{}: point {} merges too many points", what, i));
    }
    PutInt32(record + at.merged_from, static_cast<int32_t>(merged.point_counts[i]));
  }
  message.num_clusters = content.num_clusters;
  message.raw_points = content.raw_points;
  message.outside_proxy = static_cast<int64_t>(merged.outside_proxy);
  message.in_sparse_voxels = static_cast<int64_t>(merged.in_sparse_voxels);
  int32_t outliers = 0;
  for (const int32_t id : content.clusters) outliers += id == cluster::kUnassigned;
  message.clustering_outliers = outliers;
  return message;
}

ClustersContent ClustersFromMessage(const avc::clusters_t& message) {
  const std::string what = fmt::format("clusters '{}'", message.cloud_id);
  const avc::point_cloud_t& cloud = message.points;
  CheckPointCloud(cloud, what);
  if (message.num_clusters < 0 || message.raw_points < 0 || message.outside_proxy < 0 ||
      message.in_sparse_voxels < 0) {
    throw std::invalid_argument(what + ": negative counts");
  }
  ClustersContent content;
  content.cloud_id = message.cloud_id;
  content.map_id = message.map_id;
  content.problem = message.problem;
  content.num_clusters = message.num_clusters;
  content.raw_points = message.raw_points;
  merge::MergedPoints& merged = content.merged;
  merged.voxel_size = message.voxel_size;
  merged.outside_proxy = static_cast<uint64_t>(message.outside_proxy);
  merged.in_sparse_voxels = static_cast<uint64_t>(message.in_sparse_voxels);
  const size_t n = static_cast<size_t>(cloud.num_points);
  if (n > 0) {
    if (!(merged.voxel_size > 0) || !std::isfinite(merged.voxel_size)) {
      throw std::invalid_argument(fmt::format("{}: voxel size {}", what, merged.voxel_size));
    }
    const Offsets at(cloud, what);
    merged.cloud.positions.resize(n);
    merged.cloud.normals.resize(n);
    merged.cloud.colors.resize(n);
    merged.confidence.resize(n);
    merged.point_counts.resize(n);
    merged.voxels.resize(n);
    content.clusters.resize(n);
    for (size_t i = 0; i < n; ++i) {
      const uint8_t* record = cloud.data.data() + i * static_cast<size_t>(cloud.point_step);
      for (int a = 0; a < 3; ++a) {
        merged.cloud.positions[i][a] = GetFloat(record + at.position[a]);
        merged.cloud.normals[i][a] = GetFloat(record + at.normal[a]);
        merged.cloud.colors[i][a] = record[at.colour[a]];
        merged.voxels[i][a] = GetInt32(record + at.voxel[a]);
      }
      merged.confidence[i] = GetFloat(record + at.confidence);
      content.clusters[i] = GetInt32(record + at.cluster);
      const int32_t count = GetInt32(record + at.merged_from);
      if (count < 1) {
        throw std::invalid_argument(fmt::format("{}: point {} merges {} points", what, i, count));
      }
      merged.point_counts[i] = static_cast<uint32_t>(count);
    }
  }
  CheckContent(content, what);
  return content;
}

}  // namespace avc::messages
