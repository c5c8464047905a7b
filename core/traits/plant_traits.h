#pragma once

// Plant traits measured on a reconstructed surface (the surfacer's mesh, face_labels = cluster
// ids): size, hull volume, leaf area, per-cluster orientation and a curvature summary. Metres,
// square metres, cubic metres and radians inside; degrees only in the writer's output.

#include <cstdint>
#include <map>
#include <optional>
#include <vector>

#include "core/geometry/mesh.h"
#include "core/traits/curvature.h"

namespace avc::traits {

struct TraitOptions {
  // Height is measured from here (m, world z up); unset: the mesh's lowest point.
  std::optional<double> ground_z;
  // Groups of clusters (e.g. the clusters of one leaf): cluster id -> group id. Clusters not
  // listed form a group of their own with the cluster's id.
  std::map<int32_t, int32_t> group_of_cluster;
};

struct ClusterTraits {
  int32_t cluster = 0;
  double area = 0;                                    // m^2, one-sided
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // area-weighted mean, unit
  double inclination = 0;  // rad: angle between that normal and +z (0 = facing up, flat)
  double azimuth = 0;      // rad in [0, 2 pi): direction of the normal's horizontal part,
                           // counter-clockwise from +x; 0 when the normal is vertical
};

struct GroupTraits {
  int32_t group = 0;
  double area = 0;  // m^2
  std::vector<int32_t> clusters;
};

struct PlantTraits {
  double height = 0;         // m: highest point above ground_z (or the lowest point)
  double height_base_z = 0;  // m, world z the height is measured from
  double width = 0;          // m: largest horizontal distance between two vertices
  double hull_volume = 0;    // m^3: convex hull of the vertices
  double total_area = 0;     // m^2: the whole surface, one-sided (the leaf area)
  size_t faces = 0;
  std::vector<ClusterTraits> clusters;  // by cluster id
  std::vector<GroupTraits> groups;      // by group id
  CurvatureSummary curvature;
};

// Throws std::invalid_argument naming the problem for an inconsistent mesh (Mesh::Validate) or
// a non-finite ground_z. An empty mesh gives zeros.
PlantTraits MeasureTraits(const geometry::Mesh& mesh, const TraitOptions& options = {});

}  // namespace avc::traits
