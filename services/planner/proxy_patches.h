#pragma once

// What the planner must see (paper §2.2, Algorithm 1 lines 13-14): the plant proxy's surface,
// clustered into patches. The surface is made of the open faces of occupied voxels: faces whose
// neighbour is not occupied (free, or unknown: space no view has carved yet, e.g. under a leaf),
// each with the face's outward normal. A thin leaf, one voxel thick, thus has both its sides.
// Patches group open faces by place (cubic cells of the plant's box) and by direction (the six
// face normals), so each patch is small and faces one way: one good view direction exists for
// it. Deterministic: voxels in index order, patches ordered by (cell, direction).

#include <Eigen/Core>
#include <vector>

#include "core/ppr/plant_proxy.h"

namespace avc::planner {

struct SurfacePatch {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();   // mean of its voxel centres
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // outward, unit
  std::vector<Eigen::Vector3d> points;                // centres of its open faces
  int unknown_faces = 0;  // of them, faces towards unknown space (still unseen)
};

struct PatchOptions {
  // Cells per axis along the occupied box's longest edge.
  int cells_across = 8;
  // Patches with fewer faces are dropped (noise of the carving).
  int min_faces = 3;
};

std::vector<SurfacePatch> ProxySurfacePatches(const ppr::PlantProxy& proxy,
                                              const PatchOptions& options = {});

}  // namespace avc::planner
