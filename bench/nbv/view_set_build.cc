#include "bench/nbv/view_set_build.h"

#include <fmt/format.h>

#include <chrono>
#include <optional>
#include <stdexcept>

#include "bench/nbv/simulated_capture.h"
#include "core/eval/metrics.h"
#include "services/builder/reconstruction.h"
#include "sim/render/renderer.h"

namespace avc::bench {

nlohmann::json BuildViewSet(const sim::Scene& scene, const std::vector<camera::Camera>& cameras,
                            double scale, const geometry::Mesh& organs) {
  dataset::ViewSet set;
  set.format = "live";
  sim::Renderer renderer;
  sim::RenderResult frame;
  for (size_t i = 0; i < cameras.size(); ++i) {
    dataset::View view;
    view.name = fmt::format("view_{:04d}.png", i);
    view.camera = ScaledCamera(cameras[i], scale);
    renderer.Render(scene, view.camera, sim::RenderOptions{}, &frame);
    view.image = frame.color.clone();
    set.views.push_back(std::move(view));
  }
  const auto start = std::chrono::steady_clock::now();
  std::optional<builder::Reconstruction> reconstruction;
  try {
    reconstruction.emplace(builder::Reconstruct(set, builder::ReconstructOptions{}));
  } catch (const std::exception& error) {
    return {{"build_error", error.what()}};
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const mvs::MvsPoints& points = reconstruction->points;
  nlohmann::json result = {
      {"points", points.size()},
      {"points_per_image", static_cast<double>(points.size()) / cameras.size()},
      {"build_s", seconds}};
  if (points.size() > 0) {
    const eval::EvalResult scores = eval::EvaluatePointCloud(organs, points.cloud, {});
    result["mean_distance_mm"] = 1e3 * scores.accuracy.mean;
  }
  return result;
}

}  // namespace avc::bench
