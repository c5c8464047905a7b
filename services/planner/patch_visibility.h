#pragma once

// How well the views so far see the proxy's surface (paper §2.2, the utility of Algorithm 1
// line 17: "the angle at which each image sees the cluster, and the percentage that has been
// seen"). A face of a patch is seen by a view when it projects inside the image, the view is no
// more grazing than max_grazing_deg on either side (leaves are two-sided, as in the coverage
// metric of core/eval/coverage.h), and the ray from the camera reaches it: OctoMap ray casting
// through the proxy finds no occupied voxel before the face's own. A view sees a patch when it
// sees at least min_seen_fraction of its faces; a patch scores the number of views that see it
// over min_views, and passes at 1.

#include <cstdint>
#include <vector>

#include "core/camera/pinhole_camera.h"
#include "core/ppr/plant_proxy.h"
#include "services/planner/proxy_patches.h"

namespace avc::planner {

struct VisibilityOptions {
  int min_views = 3;  // PMVS's gamma, as the coverage metric
  double max_grazing_deg = 75;
  double min_seen_fraction = 0.5;
  size_t max_sampled_faces = 32;  // faces of a patch tested per view (evenly strided)
};

// Per patch: 1 when the view sees it.
using PatchesSeen = std::vector<uint8_t>;
// Per patch: the number of views that see it.
using PatchViewCounts = std::vector<uint16_t>;

// The fraction of `patch`'s faces `camera` sees.
double SeenFraction(const ppr::PlantProxy& proxy, const SurfacePatch& patch,
                    const camera::Camera& camera, const VisibilityOptions& options = {});

PatchesSeen PatchesSeenBy(const ppr::PlantProxy& proxy, const std::vector<SurfacePatch>& patches,
                          const camera::Camera& camera, const VisibilityOptions& options = {});

// Per sampled face of every patch (the faces SeenFraction tests, patch after patch): 1 when the
// view sees it.
PatchesSeen FacesSeenBy(const ppr::PlantProxy& proxy, const std::vector<SurfacePatch>& patches,
                        const camera::Camera& camera, const VisibilityOptions& options = {});

// How many of the patch's faces SeenFraction tests (every stride-th, at most max_sampled_faces).
size_t SampledFaceCount(const SurfacePatch& patch, const VisibilityOptions& options = {});

// PatchesSeenBy from a view's FacesSeenBy, without casting the rays again. Throws
// std::invalid_argument when `faces` is shorter than the patches' sampled faces.
PatchesSeen PatchesSeenFromFaces(const std::vector<SurfacePatch>& patches, const PatchesSeen& faces,
                                 const VisibilityOptions& options = {});

// Adds one view's PatchesSeenBy to the counts (sized on the first call), or takes it away.
void AddView(const PatchesSeen& seen, PatchViewCounts* counts);
void RemoveView(const PatchesSeen& seen, PatchViewCounts* counts);

// Per patch: views that see it over min_views.
std::vector<double> PatchScores(const PatchViewCounts& counts,
                                const VisibilityOptions& options = {});

}  // namespace avc::planner
