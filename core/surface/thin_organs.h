#pragma once

// Stems, pedicels and siliques as surfaces. Their merged points are too few for Algorithm 3's
// patches (an organ 1-4 px wide leaves fewer than 4 MVS points in most voxels), but the plant
// proxy holds them whole and connected. The thin parts of the proxy are the occupied voxels out
// of reach of any bulky core (a leaf's hull, a pot): their boundary against empty space, smoothed
// and moved half a voxel in (the carved hull stands about that far outside a thin organ),
// replaces Algorithm 3's faces there: for plants made of such organs (the real ROMI scan,
// BENCHMARKS.md, "Where the defaults come from"). Not yet for leafy plants: a leaf's hull in the
// proxy is a plate thinner than the core depth, so it is taken for an organ too;
// ThinOrganOptions.enabled is therefore off by default.

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "core/geometry/mesh.h"

namespace avc::surface {

struct ThinOrganOptions {
  bool enabled = false;
  // A voxel at least this many voxels deep inside the proxy (6-connected steps from empty space)
  // belongs to a bulky part.
  int core_depth = 3;
  // Thin parts are the occupied voxels more than this many voxels (26-connected) from a core.
  int core_reach = 2;
  // The surface is moved this many voxel sizes inwards after smoothing.
  double inward_voxels = 0.5;
  int smoothing_iterations = 10;  // Taubin pairs

  // Empty when valid; else a sentence naming the bad field (ThinOrganOptions.<field>).
  std::string Validate() const;
};

// Voxel indices (voxel i spans [i, i + 1) * voxel_size) of the proxy's thin parts, sorted.
std::vector<Eigen::Vector3i> ThinVoxels(const std::vector<Eigen::Vector3f>& occupied_centres,
                                        double voxel_size, const ThinOrganOptions& options);

// The boundary of `voxels` against voxels not in `occupied` (faces against other occupied
// voxels stay open, where a thin part meets a bulky one), two triangles per voxel face,
// counter-clockwise seen from outside, Taubin-smoothed and moved `inward_voxels` in.
geometry::Mesh VoxelSurface(const std::vector<Eigen::Vector3i>& voxels,
                            const std::vector<Eigen::Vector3i>& occupied, double voxel_size,
                            int smoothing_iterations, double inward_voxels);

// Replaces `mesh`'s faces whose centroid lies in or next to (26-neighbourhood) a thin voxel with
// the thin parts' surface,
// labelled `label` (face_labels; colours, when the mesh has them, grey). Returns the faces added.
size_t AddThinOrgans(geometry::Mesh& mesh, const std::vector<Eigen::Vector3f>& occupied_centres,
                     double voxel_size, const ThinOrganOptions& options, int32_t label);

}  // namespace avc::surface
