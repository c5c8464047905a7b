#pragma once

// Laplacian smoothing of a triangulated sheet (paper §4, Phase 3 and the final smoothing;
// Algorithm 3 lines 4 and 16): first the interior vertices over their mesh neighbours, then the
// boundary vertices along their boundary loop only, so the outline is smoothed without being
// pulled into the sheet. Taubin's lambda|mu steps keep the sheet from shrinking.

#include "core/geometry/mesh.h"
#include "core/surface/surface_options.h"

namespace avc::surface {

void SmoothInterior(geometry::Mesh& mesh, const SmoothingOptions& options);
void SmoothBoundary(geometry::Mesh& mesh, const SmoothingOptions& options);

// Interior, then boundary.
void SmoothSheet(geometry::Mesh& mesh, const SmoothingOptions& options);

}  // namespace avc::surface
