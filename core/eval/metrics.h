#pragma once

// Accuracy, completeness, precision / recall / F-score and area ratio of a reconstruction (a
// point cloud or a mesh) against a ground-truth mesh, overall and per organ: the figures of the
// paper's Tables 1 and 4 and of the Tanks & Temples style benchmarks.
//
// Conventions: metres. The ground truth is treated as one-sided: every triangle counts once,
// so an open leaf sheet has its leaf area, while a closed thin solid (the synthetic maize)
// counts both faces (≈ 2× the one-sided area); results say whether the ground truth is closed.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/eval/distance_stats.h"
#include "core/eval/surface_sampling.h"
#include "core/geometry/mesh.h"
#include "core/geometry/point_cloud.h"

namespace avc::eval {

struct EvalOptions {
  // Distance thresholds τ (metres) of precision, recall and F-score.
  std::vector<double> thresholds = {0.001, 0.002, 0.005, 0.01};
  // Density of the area-uniform samples of the ground truth (completeness) and of a
  // reconstructed mesh (accuracy); 1e6 per m^2 is one per mm^2.
  double samples_per_m2 = 1e6;
  uint64_t seed = 1;
  // Refuse to draw more samples than this (a millimetre file read as metres draws 1e6× more).
  size_t max_samples = 5'000'000;

  // Empty when valid; else a sentence naming the bad field.
  std::string Validate() const;
};

// P(τ): fraction of reconstruction points within τ of the ground truth; R(τ): fraction of
// ground-truth samples within τ of the reconstruction; F = 2PR / (P + R).
struct ThresholdScore {
  double threshold = 0;
  double precision = 0;
  double recall = 0;
  double fscore = 0;
};

// One ground-truth organ (face label). Reconstruction points belong to the organ of their
// nearest ground-truth face.
struct OrganEval {
  int32_t label = 0;
  std::string name;
  double gt_area = 0;                        // m^2, one-sided
  DistanceStats completeness;                // its ground-truth samples → reconstruction
  DistanceStats accuracy;                    // its reconstruction points → ground truth
  std::vector<ThresholdScore> scores;        // precision / recall restricted to the organ
  std::optional<double> reconstructed_area;  // mesh only: reconstruction area nearest to it
};

struct EvalResult {
  std::vector<double> thresholds;  // sorted, without duplicates
  double samples_per_m2 = 0;
  uint64_t seed = 0;
  uint64_t gt_sample_seed = 0;
  std::optional<uint64_t> reconstruction_sample_seed;  // mesh only

  // Ground truth.
  size_t gt_vertices = 0;
  size_t gt_faces = 0;
  double gt_area = 0;
  size_t gt_boundary_edges = 0;  // edges with one face; 0 → a closed surface
  bool gt_closed = false;

  // Reconstruction: a cloud is evaluated point by point, a mesh by its area samples.
  bool reconstruction_is_mesh = false;
  size_t reconstruction_vertices = 0;  // cloud: its points
  size_t reconstruction_faces = 0;
  size_t reconstruction_points = 0;           // points evaluated for accuracy
  std::optional<double> reconstruction_area;  // mesh only, m^2
  std::optional<double> area_ratio;           // mesh only: reconstruction / ground truth
  std::string area_note;

  DistanceStats accuracy;      // reconstruction → ground-truth surface
  DistanceStats completeness;  // ground-truth samples → reconstruction
  double chamfer = 0;          // (accuracy.mean + completeness.mean) / 2, DTU's "overall"
  std::vector<ThresholdScore> scores;
  std::vector<OrganEval> organs;  // by label; empty when the ground truth has no face labels

  // Per-point data for plots and callers.
  std::vector<double> accuracy_distances;  // per reconstruction point (or mesh sample)
  std::vector<int32_t> nearest_gt_face;    // per reconstruction point
  SurfaceSamples gt_samples;
  std::vector<double> completeness_distances;  // per ground-truth sample
};

// Both throw std::invalid_argument with a message naming the input at fault (inconsistent or
// empty meshes, non-finite points, bad options). Results are a pure function of the inputs and
// options: distances are computed in parallel into per-point slots and reduced serially.
EvalResult EvaluatePointCloud(const geometry::Mesh& ground_truth,
                              const geometry::PointCloud& reconstruction,
                              const EvalOptions& options);
EvalResult EvaluateMesh(const geometry::Mesh& ground_truth, const geometry::Mesh& reconstruction,
                        const EvalOptions& options);

// Number of edges used by exactly one face (0 for a closed surface).
size_t CountBoundaryEdges(const geometry::Mesh& mesh);

}  // namespace avc::eval
