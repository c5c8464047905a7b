#include "core/eval/metrics.h"

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <stdexcept>

#include "core/eval/nearest_point_index.h"
#include "core/eval/triangle_tree.h"
#include "core/util/validation.h"

namespace avc::eval {
namespace {

constexpr uint64_t kGroundTruthStream = 1;
constexpr uint64_t kReconstructionStream = 2;

using DistanceTo = std::function<double(const Eigen::Vector3d&)>;

// Fills out[i] = f(i) for every i in parallel; each slot is written by one task only.
template <class T, class F>
void ParallelFill(std::vector<T>& out, size_t n, F f) {
  out.resize(n);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 256),
                    [&](const tbb::blocked_range<size_t>& r) {
                      for (size_t i = r.begin(); i != r.end(); ++i) out[i] = f(i);
                    });
}

std::vector<ThresholdScore> Scores(const std::vector<double>& thresholds,
                                   const std::vector<double>& accuracy,
                                   const std::vector<double>& completeness) {
  std::vector<ThresholdScore> scores;
  for (double threshold : thresholds) {
    ThresholdScore score;
    score.threshold = threshold;
    score.precision = FractionWithin(accuracy, threshold);
    score.recall = FractionWithin(completeness, threshold);
    score.fscore = FScore(score.precision, score.recall);
    scores.push_back(score);
  }
  return scores;
}

double FaceArea(const geometry::Mesh& mesh, size_t f) {
  const Eigen::Vector3i& face = mesh.faces[f];
  const Eigen::Vector3d a = mesh.vertices[face[0]].cast<double>();
  const Eigen::Vector3d b = mesh.vertices[face[1]].cast<double>();
  const Eigen::Vector3d c = mesh.vertices[face[2]].cast<double>();
  return 0.5 * (b - a).cross(c - a).norm();
}

std::vector<OrganEval> OrganBreakdown(const geometry::Mesh& gt, const EvalResult& result) {
  if (gt.face_labels.empty()) return {};
  struct Gather {
    OrganEval organ;
    std::vector<double> completeness, accuracy;
  };
  std::map<int32_t, Gather> by_label;
  for (size_t f = 0; f < gt.num_faces(); ++f) {
    by_label[gt.face_labels[f]].organ.gt_area += FaceArea(gt, f);
  }
  const SurfaceSamples& samples = result.gt_samples;
  for (size_t i = 0; i < samples.size(); ++i) {
    by_label[gt.face_labels[static_cast<size_t>(samples.faces[i])]].completeness.push_back(
        result.completeness_distances[i]);
  }
  for (size_t i = 0; i < result.accuracy_distances.size(); ++i) {
    by_label[gt.face_labels[static_cast<size_t>(result.nearest_gt_face[i])]].accuracy.push_back(
        result.accuracy_distances[i]);
  }
  std::vector<OrganEval> organs;
  for (auto& [label, gather] : by_label) {
    OrganEval organ = gather.organ;
    organ.label = label;
    organ.name = geometry::labels::Name(label);
    organ.completeness = Summarize(gather.completeness);
    organ.accuracy = Summarize(gather.accuracy);
    organ.scores = Scores(result.thresholds, gather.accuracy, gather.completeness);
    if (result.reconstruction_area) {
      // Each mesh sample stands for an equal share of the reconstructed area.
      organ.reconstructed_area = *result.reconstruction_area *
                                 static_cast<double>(gather.accuracy.size()) /
                                 static_cast<double>(result.accuracy_distances.size());
    }
    organs.push_back(std::move(organ));
  }
  return organs;
}

std::string AreaNote(const EvalResult& result) {
  std::string note =
      "Areas are one-sided: the sum of the triangle areas of each mesh, every triangle counted "
      "once.";
  if (result.gt_closed) {
    note +=
        " The ground truth is closed (no boundary edges): a closed thin solid such as a leaf "
        "counts both of its faces, so its area is about twice the one-sided leaf area and the "
        "area ratio of a one-sided reconstruction about half of what it would be against a "
        "one-sided ground truth.";
  } else {
    note += fmt::format(
        " The ground truth is open ({} boundary edges): leaves as single sheets count their "
        "one-sided area.",
        result.gt_boundary_edges);
  }
  return note;
}

// The shared half of both evaluations: `result` arrives with the reconstruction fields set.
EvalResult Evaluate(const geometry::Mesh& gt, const std::vector<Eigen::Vector3d>& points,
                    const DistanceTo& distance_to_reconstruction, const EvalOptions& options,
                    EvalResult result) {
  const TriangleTree gt_tree(gt, "ground truth mesh");
  result.thresholds = options.thresholds;
  std::sort(result.thresholds.begin(), result.thresholds.end());
  result.thresholds.erase(std::unique(result.thresholds.begin(), result.thresholds.end()),
                          result.thresholds.end());
  result.samples_per_m2 = options.samples_per_m2;
  result.seed = options.seed;
  result.gt_sample_seed = DeriveSeed(options.seed, kGroundTruthStream);
  result.gt_vertices = gt.num_vertices();
  result.gt_faces = gt.num_faces();
  result.gt_boundary_edges = CountBoundaryEdges(gt);
  result.gt_closed = result.gt_boundary_edges == 0;
  result.gt_samples =
      SampleSurface(gt, options.samples_per_m2, result.gt_sample_seed, options.max_samples);
  result.gt_area = result.gt_samples.area;
  if (result.gt_samples.size() == 0) {
    throw std::invalid_argument(fmt::format(
        "ground truth mesh: {:.3g} m^2 at {:.3g} samples per m^2 gave no samples; raise the "
        "density",
        result.gt_area, options.samples_per_m2));
  }
  if (result.reconstruction_area) result.area_ratio = *result.reconstruction_area / result.gt_area;
  result.area_note = AreaNote(result);

  result.reconstruction_points = points.size();
  std::vector<TriangleTree::Nearest> nearest;
  ParallelFill(nearest, points.size(), [&](size_t i) { return gt_tree.Closest(points[i]); });
  result.accuracy_distances.resize(points.size());
  result.nearest_gt_face.resize(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    result.accuracy_distances[i] = nearest[i].distance;
    result.nearest_gt_face[i] = nearest[i].face;
  }
  const std::vector<Eigen::Vector3d>& gt_points = result.gt_samples.points;
  ParallelFill(result.completeness_distances, gt_points.size(),
               [&](size_t i) { return distance_to_reconstruction(gt_points[i]); });

  result.accuracy = Summarize(result.accuracy_distances);
  result.completeness = Summarize(result.completeness_distances);
  result.chamfer = 0.5 * (result.accuracy.mean + result.completeness.mean);
  result.scores =
      Scores(result.thresholds, result.accuracy_distances, result.completeness_distances);
  result.organs = OrganBreakdown(gt, result);
  return result;
}

}  // namespace

std::string EvalOptions::Validate() const {
  if (thresholds.empty()) return "evaluation: no distance thresholds given";
  for (double threshold : thresholds) {
    if (!(threshold > 0) || !std::isfinite(threshold)) {
      return fmt::format("evaluation: threshold {} must be positive and finite (metres)",
                         threshold);
    }
  }
  if (!(samples_per_m2 > 0) || !std::isfinite(samples_per_m2)) {
    return fmt::format("evaluation: samples per m^2 {} must be positive and finite",
                       samples_per_m2);
  }
  if (max_samples == 0) return "evaluation: max_samples must be positive";
  return {};
}

EvalResult EvaluatePointCloud(const geometry::Mesh& ground_truth,
                              const geometry::PointCloud& reconstruction,
                              const EvalOptions& options) {
  RequireValid(options);
  if (const std::string problem = reconstruction.Validate(); !problem.empty()) {
    throw std::invalid_argument("reconstruction point cloud: " + problem);
  }
  if (reconstruction.empty()) {
    throw std::invalid_argument("reconstruction point cloud: no points to evaluate");
  }
  std::vector<Eigen::Vector3d> points(reconstruction.size());
  for (size_t i = 0; i < points.size(); ++i) points[i] = reconstruction.positions[i].cast<double>();
  const NearestPointIndex index(points);
  EvalResult result;
  result.reconstruction_vertices = reconstruction.size();
  return Evaluate(
      ground_truth, points, [&](const Eigen::Vector3d& p) { return index.Distance(p); }, options,
      std::move(result));
}

EvalResult EvaluateMesh(const geometry::Mesh& ground_truth, const geometry::Mesh& reconstruction,
                        const EvalOptions& options) {
  RequireValid(options);
  const TriangleTree tree(reconstruction, "reconstruction mesh");
  EvalResult result;
  result.reconstruction_is_mesh = true;
  result.reconstruction_vertices = reconstruction.num_vertices();
  result.reconstruction_faces = reconstruction.num_faces();
  result.reconstruction_sample_seed = DeriveSeed(options.seed, kReconstructionStream);
  const SurfaceSamples samples =
      SampleSurface(reconstruction, options.samples_per_m2, *result.reconstruction_sample_seed,
                    options.max_samples);
  if (samples.size() == 0) {
    throw std::invalid_argument(fmt::format(
        "reconstruction mesh: {:.3g} m^2 at {:.3g} samples per m^2 gave no samples; raise the "
        "density",
        samples.area, options.samples_per_m2));
  }
  result.reconstruction_area = samples.area;
  return Evaluate(
      ground_truth, samples.points,
      [&](const Eigen::Vector3d& p) { return tree.Closest(p).distance; }, options,
      std::move(result));
}

size_t CountBoundaryEdges(const geometry::Mesh& mesh) {
  std::vector<uint64_t> edges;
  edges.reserve(3 * mesh.num_faces());
  for (const Eigen::Vector3i& face : mesh.faces) {
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = static_cast<uint32_t>(face[k]);
      const uint32_t b = static_cast<uint32_t>(face[(k + 1) % 3]);
      edges.push_back((uint64_t{std::min(a, b)} << 32) | std::max(a, b));
    }
  }
  std::sort(edges.begin(), edges.end());
  size_t boundary = 0;
  for (size_t i = 0; i < edges.size();) {
    size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    if (j - i == 1) ++boundary;
    i = j;
  }
  return boundary;
}

}  // namespace avc::eval
