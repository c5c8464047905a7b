#include "bench/merge/simulated_mvs_cloud.h"

#include <cmath>
#include <stdexcept>

#include "core/eval/surface_sampling.h"
#include "core/util/ordered_draws.h"
#include "sim/cell/random.h"

namespace avc::bench {
namespace {

void AppendPoint(mvs::MvsPoints& points, const Eigen::Vector3f& position,
                 const Eigen::Vector3f& normal) {
  points.cloud.positions.push_back(position);
  points.cloud.normals.push_back(normal);
  points.cloud.colors.push_back(Eigen::Matrix<uint8_t, 3, 1>::Constant(128));
  points.confidence.push_back(1.0f);
  points.views.emplace_back();
}

}  // namespace

mvs::MvsPoints SimulatedMvsCloud(const geometry::Mesh& truth,
                                 const SimulatedCloudOptions& options) {
  if (options.surface_points == 0 || !(options.noise_sigma >= 0)) {
    throw std::invalid_argument("SimulatedMvsCloud: need surface points and a noise sigma >= 0");
  }
  const double area = geometry::SurfaceArea(truth);
  if (!(area > 0)) throw std::invalid_argument("SimulatedMvsCloud: the truth has no area");
  const eval::SurfaceSamples samples =
      eval::SampleSurface(truth, static_cast<double>(options.surface_points) / area, options.seed,
                          10 * options.surface_points);
  sim::DeterministicRandom random(eval::DeriveSeed(options.seed, 1));
  mvs::MvsPoints points;
  for (size_t i = 0; i < samples.size(); ++i) {
    const Eigen::Vector3d noise =
        util::DrawVector3<Eigen::Vector3d>([&] { return random.Normal(); });
    AppendPoint(points, (samples.points[i] + options.noise_sigma * noise).cast<float>(),
                samples.normals[i]);
  }
  return points;
}

size_t InjectOutliers(mvs::MvsPoints& points, double fraction, const Eigen::AlignedBox3d& box,
                      uint64_t seed) {
  if (!(fraction >= 0 && fraction < 1) || box.isEmpty()) {
    throw std::invalid_argument("InjectOutliers: need a fraction in [0, 1) and a box");
  }
  const double n = static_cast<double>(points.size());
  const auto count = static_cast<size_t>(std::llround(n * fraction / (1 - fraction)));
  sim::DeterministicRandom random(eval::DeriveSeed(seed, 2));
  for (size_t i = 0; i < count; ++i) {
    // z drawn first, as in util::DrawVector3.
    Eigen::Vector3d p;
    for (int axis = 2; axis >= 0; --axis) {
      p[axis] = random.Uniform(box.min()[axis], box.max()[axis]);
    }
    AppendPoint(points, p.cast<float>(), random.UnitVector().cast<float>());
  }
  return count;
}

}  // namespace avc::bench
