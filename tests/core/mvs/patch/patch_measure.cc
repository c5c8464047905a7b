// Measures the patch MVS on the report's inputs: the Middlebury dino (points, points per
// image, time, fraction inside all silhouettes) and a simulated scan (precision / recall).
// Usage: avc_patch_mvs_measure dino <dir> [level]
//        avc_patch_mvs_measure sim <scratch dir> <preset 0..3> <views> <width> <height> [level]
//        avc_patch_mvs_measure plane

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "core/dataset/dataset_reader.h"
#include "core/eval/metrics.h"
#include "core/mvs/patch/patch_mvs.h"
#include "tests/core/mvs/patch/patch_test_scenes.h"

namespace {

using Clock = std::chrono::steady_clock;

double Seconds(Clock::time_point since) {
  return std::chrono::duration<double>(Clock::now() - since).count();
}

avc::mvs::MvsPoints Run(const std::vector<avc::dataset::View>& views,
                        const avc::mvs::MvsBounds& bounds, const avc::mvs::PatchMvsOptions& o) {
  const auto start = Clock::now();
  auto last = start;
  auto points = avc::mvs::RunPatchMvs(
      views, bounds, o, [&](const std::string& stage, size_t done, size_t total) {
        if (stage == "expand" && Seconds(last) < 1.0) return;
        last = Clock::now();
        std::cerr << fmt::format("  [{:6.2f} s] {} {}/{}\n", Seconds(start), stage, done, total);
      });
  std::cout << fmt::format("points {} in {:.2f} s\n", points.size(), Seconds(start));
  return points;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: see the comment at the top of patch_measure.cc\n";
    return 2;
  }
  const std::string mode = argv[1];
  avc::mvs::PatchMvsOptions options;
  // Overrides for exploring parameters: PATCH_ITER, PATCH_REFINE, PATCH_CELL, PATCH_ROUNDS,
  // PATCH_WHOLE, PATCH_WINDOW.
  if (const char* e = std::getenv("PATCH_ITER")) options.max_iterations = std::atoi(e);
  if (const char* e = std::getenv("PATCH_REFINE")) options.max_refine_images = std::atoi(e);
  if (const char* e = std::getenv("PATCH_CELL")) options.cell_size = std::atoi(e);
  if (const char* e = std::getenv("PATCH_ROUNDS")) options.rounds = std::atoi(e);
  if (const char* e = std::getenv("PATCH_WHOLE")) options.whole_patch_in_mask = std::atoi(e);
  if (const char* e = std::getenv("PATCH_WINDOW")) options.window = std::atoi(e);
  if (mode == "dino" && argc >= 3) {
    if (argc >= 4) options.level = std::atoi(argv[3]);
    auto set = avc::dataset::ReadDataset(argv[2]);
    std::vector<cv::Mat> silhouettes;
    for (auto& v : set.views) silhouettes.push_back(avc::mvs::testing::DinoSilhouette(v.image));
    const bool masked = std::getenv("PATCH_NO_MASK") == nullptr;
    for (size_t i = 0; i < set.views.size(); ++i) {
      if (masked) set.views[i].mask = silhouettes[i];
    }
    avc::mvs::MvsBounds bounds;
    if (masked && std::getenv("PATCH_NO_BOUNDS") == nullptr) {
      bounds = avc::mvs::testing::VisualHull(set.views, {-0.07, -0.025, -0.065},
                                             {0.02, 0.075, 0.025}, 0.002);
      std::cout << fmt::format("hull voxels {}\n", bounds.occupied_centres.size());
    }
    const auto points = Run(set.views, bounds, options);
    std::cout << fmt::format("per image {:.0f}, inside all silhouettes {:.4f}\n",
                             double(points.size()) / set.views.size(),
                             avc::mvs::testing::InsideFraction(points, set.views, silhouettes));
    return 0;
  }
  if (mode == "sim" && argc >= 7) {
    if (argc >= 8) options.level = std::atoi(argv[7]);
    const auto t0 = Clock::now();
    const auto scan = avc::mvs::testing::RenderScan(argv[2], std::atoi(argv[3]), std::atoi(argv[4]),
                                                    std::atoi(argv[5]), std::atoi(argv[6]));
    std::cout << fmt::format("rendered in {:.1f} s\n", Seconds(t0));
    const auto bounds = avc::mvs::testing::VisualHull(scan.views, scan.lo, scan.hi, 0.004);
    std::cout << fmt::format("hull voxels {}\n", bounds.occupied_centres.size());
    const auto points = Run(scan.views, bounds, options);
    const auto result =
        avc::eval::EvaluatePointCloud(scan.ground_truth, points.cloud, avc::eval::EvalOptions{});
    for (const auto& s : result.scores) {
      std::cout << fmt::format("tau {:.3f}: precision {:.4f} recall {:.4f}\n", s.threshold,
                               s.precision, s.recall);
    }
    // Depth error against the renderer's depth maps, in each point's first view.
    {
      std::vector<double> errors;
      std::vector<cv::Mat> depth(scan.views.size());
      for (size_t i = 0; i < points.size(); ++i) {
        const uint32_t j = points.views[i][0];
        if (depth[j].empty()) {
          const auto stem = std::filesystem::path(scan.views[j].name).stem().string();
          depth[j] =
              cv::imread(std::string(argv[2]) + "/depth/" + stem + ".tiff", cv::IMREAD_UNCHANGED);
        }
        // The depth maps are of the raw (distorted) images: project with the raw camera.
        avc::camera::Camera raw = scan.views[j].camera;
        raw.intrinsics.distortion = scan.raw_distortion[j];
        const auto px = raw.Project(points.cloud.positions[i].cast<double>());
        if (!px) continue;
        const int u = int(std::lround(px->x())), v = int(std::lround(px->y()));
        if (u < 0 || v < 0 || u >= depth[j].cols || v >= depth[j].rows) continue;
        const float d = depth[j].at<float>(v, u);
        if (d <= 0) continue;
        errors.push_back((raw.T_cam_world * points.cloud.positions[i].cast<double>()).z() - d);
      }
      std::sort(errors.begin(), errors.end());
      for (double q : {0.1, 0.25, 0.5, 0.75, 0.9}) {
        std::cout << fmt::format("depth error q{:.2f}: {:+.5f} m\n", q,
                                 errors[size_t(q * errors.size())]);
      }
    }
    // Precision of the most confident points: is the error noise (falls) or bias (stays)?
    for (size_t min_views : {4, 6}) {
      avc::geometry::PointCloud strong;
      for (size_t i = 0; i < points.size(); ++i) {
        if (points.views[i].size() >= min_views && points.confidence[i] > 0.85f) {
          strong.positions.push_back(points.cloud.positions[i]);
        }
      }
      if (strong.empty()) continue;
      const auto r = avc::eval::EvaluatePointCloud(scan.ground_truth, strong, {});
      std::cout << fmt::format("views>={} conf>0.85: {} points, P(1mm) {:.4f} P(2mm) {:.4f}\n",
                               min_views, strong.size(), r.scores[0].precision,
                               r.scores[1].precision);
    }
    return 0;
  }
  if (mode == "gtcheck" && argc >= 3) {
    // Do the ground truth's vertices project inside the (undistorted) masks?
    const auto scan = avc::mvs::testing::RenderScan(argv[2], 0, 6, 640, 480);
    for (const auto& v : scan.views) {
      size_t inside = 0, seen = 0;
      for (const auto& p : scan.ground_truth.vertices) {
        const auto px = v.camera.Project(p.cast<double>());
        if (!px) continue;
        const int u = int(std::lround(px->x())), w = int(std::lround(px->y()));
        if (u < 0 || w < 0 || u >= v.mask.cols || w >= v.mask.rows) continue;
        ++seen;
        inside += v.mask.at<uint8_t>(w, u) != 0;
      }
      std::cout << fmt::format("{}: {:.4f} of {} vertices inside the mask\n", v.name,
                               double(inside) / seen, seen);
    }
    return 0;
  }
  if (mode == "plane") {
    const auto views = avc::mvs::testing::TexturedPlaneViews(5, 320, 240, 0.5, 0.3, 7);
    const auto points = Run(views, {}, options);
    std::vector<double> z, angle;
    for (size_t i = 0; i < points.size(); ++i) {
      z.push_back(std::abs(points.cloud.positions[i].z()));
      angle.push_back(std::acos(std::min(1.0, double(points.cloud.normals[i].z()))) * 180 / M_PI);
    }
    std::sort(z.begin(), z.end());
    std::sort(angle.begin(), angle.end());
    for (double q : {0.5, 0.9, 0.99, 1.0}) {
      const size_t k = std::min(z.size() - 1, size_t(q * z.size()));
      std::cout << fmt::format("q{:.2f}: |z| {:.6f} m, normal {:.2f} deg\n", q, z[k], angle[k]);
    }
    return 0;
  }
  std::cerr << "usage: see the comment at the top of patch_measure.cc\n";
  return 2;
}
