#pragma once

// Coverage of a ground-truth surface by a set of views: a surface
// sample is covered when at least min_views cameras see it, i.e. it projects inside the image,
// nothing lies between it and the camera centre, and the view is no more grazing than
// max_grazing_deg (angle between the surface normal, either side — leaves are two-sided — and
// the direction to the camera). The NBV planner uses the per-sample view counts.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/camera/pinhole_camera.h"
#include "core/eval/surface_sampling.h"
#include "core/geometry/mesh.h"

namespace avc::eval {

class TriangleTree;

struct CoverageOptions {
  int min_views = 3;  // PMVS's γ: a point needs three photo-consistent views
  double max_grazing_deg = 75;
  // The line of sight stops this far (metres) short of the sample, so the sample's own triangle
  // never counts as an occluder; far below any leaf thickness.
  double occlusion_epsilon = 1e-5;

  // Empty when valid; else a sentence naming the bad field.
  std::string Validate() const;
};

struct OrganCoverage {
  int32_t label = 0;
  std::string name;
  size_t samples = 0;
  size_t covered = 0;
  double fraction = 0;
};

struct CoverageResult {
  CoverageOptions options;
  size_t cameras = 0;
  size_t samples = 0;
  size_t covered = 0;
  double fraction = 0;  // covered / samples
  // histogram[k] = samples seen by exactly k views, k = 0 .. min_views (the last bin: >= ).
  std::vector<size_t> view_count_histogram;
  std::vector<OrganCoverage> organs;  // by label; empty without face labels
  std::vector<int> view_counts;       // per sample of CoverageModel::samples()
};

// Holds the ground truth (an AABB tree) and its samples, so many camera sets can be scored.
class CoverageModel {
 public:
  // Samples the mesh (area-uniform, seeded; see SampleSurface). Throws std::invalid_argument
  // for an inconsistent or empty mesh and bad options.
  CoverageModel(const geometry::Mesh& ground_truth, double samples_per_m2, uint64_t seed,
                const CoverageOptions& options = {}, size_t max_samples = 5'000'000);
  // Uses given samples of ground_truth (e.g. EvalResult::gt_samples, so both agree).
  CoverageModel(const geometry::Mesh& ground_truth, SurfaceSamples samples,
                const CoverageOptions& options = {});
  ~CoverageModel();
  CoverageModel(const CoverageModel&) = delete;
  CoverageModel& operator=(const CoverageModel&) = delete;

  const SurfaceSamples& samples() const { return samples_; }
  const CoverageOptions& options() const { return options_; }

  // Per sample: 1 when this camera sees it (inside the image, unoccluded, not too grazing).
  // Throws std::invalid_argument when the camera is unusable (bad intrinsics, non-finite pose).
  std::vector<uint8_t> SeenBy(const camera::Camera& camera) const;
  // Per sample: how many of the cameras see it.
  std::vector<int> ViewCounts(const std::vector<camera::Camera>& cameras) const;
  CoverageResult Evaluate(const std::vector<camera::Camera>& cameras) const;

 private:
  std::vector<int32_t> face_labels_;
  SurfaceSamples samples_;
  CoverageOptions options_;
  std::unique_ptr<TriangleTree> tree_;
};

// Throws std::invalid_argument naming `what` when the camera is unusable.
void ValidateCamera(const camera::Camera& camera, const std::string& what);

}  // namespace avc::eval
