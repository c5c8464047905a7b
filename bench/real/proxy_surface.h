#pragma once

// The plant proxy's own surface: the boundary between its occupied and empty voxels as a closed
// triangle mesh (two triangles per voxel face, corners shared), Taubin-smoothed. It is what a
// carving-based reconstruction (such as the ROMI scanner's own mesh) makes from the same
// silhouettes, so `avc bench real` scores it beside our mesh: a reference for how far a surface
// built on the proxy's thin parts (issue 35, item 4) could go on this scan.

#include "core/geometry/mesh.h"
#include "core/mvs/mvs_bounds.h"

namespace avc::bench {

// `inward_voxels`: the smoothed surface is then moved this many voxel sizes inwards along its
// normals (the carved hull stands about half a voxel outside a thin organ).
geometry::Mesh ProxyBoundaryMesh(const mvs::MvsBounds& proxy, int smoothing_iterations,
                                 double inward_voxels);

}  // namespace avc::bench
