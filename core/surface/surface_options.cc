#include "core/surface/surface_options.h"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "core/util/validation.h"

namespace avc::surface {
namespace {

void RequirePositive(FirstProblem& problem, double value, const char* field) {
  problem.Require(
      value > 0.0 && std::isfinite(value),
      fmt::format("surface options: {} must be positive and finite, got {}", field, value));
}

void RequireSmoothing(FirstProblem& problem, const SmoothingOptions& smoothing, const char* field) {
  problem.Require(smoothing.iterations >= 0,
                  fmt::format("surface options: {}.iterations must be >= 0, got {}", field,
                              smoothing.iterations));
  problem.Require(
      smoothing.lambda > 0.0 && smoothing.lambda < 1.0,
      fmt::format("surface options: {}.lambda must be in (0, 1), got {}", field, smoothing.lambda));
  problem.Require(
      smoothing.mu < -smoothing.lambda && smoothing.mu > -1.0,
      fmt::format("surface options: {}.mu must be in (-1, -lambda), got {}", field, smoothing.mu));
}

}  // namespace

std::string SurfaceOptions::Validate() const {
  FirstProblem problem;
  problem.Require(std::isfinite(spacing),
                  "surface options: spacing must be finite (<= 0 to measure it)");
  problem.Require(std::isfinite(noise),
                  "surface options: noise must be finite (< 0 to measure it)");
  RequirePositive(problem, piece_link_factor, "piece_link_factor");
  problem.Require(std::isfinite(growth_scale),
                  "surface options: growth_scale must be finite (<= 0: automatic)");
  RequirePositive(problem, alpha_factor, "alpha_factor");
  RequirePositive(problem, growth_clearance_factor, "growth_clearance_factor");
  RequirePositive(problem, long_edge_factor, "long_edge_factor");
  RequirePositive(problem, hole_perimeter_factor, "hole_perimeter_factor");
  RequirePositive(problem, stitch_factor, "stitch_factor");
  problem.Require(
      std::isfinite(own_cluster_stitch_factor),
      "surface options: own_cluster_stitch_factor must be finite (<= 0: stitch_factor)");
  problem.Require(
      std::isfinite(stitch_link_mean_slope),
      "surface options: stitch_link_mean_slope must be finite (< 0 turns the test off)");
  problem.Require(!(refine_subdivisions < 0 || refine_subdivisions > 3),
                  fmt::format("surface options: refine_subdivisions must be in [0, 3], got {}",
                              refine_subdivisions));
  RequirePositive(problem, fit.radius_factor, "fit.radius_factor");
  problem.Require(
      fit.max_radius_factor >= fit.radius_factor,
      fmt::format(
          "surface options: fit.max_radius_factor must be >= fit.radius_factor ({}), got {}",
          fit.radius_factor, fit.max_radius_factor));
  problem.Require(
      !(fit.min_points < 3),
      fmt::format("surface options: fit.min_points must be >= 3, got {}", fit.min_points));
  problem.Require(min_boundary_quality >= 0.0 && min_boundary_quality < 1.0,
                  fmt::format("surface options: min_boundary_quality must be in [0, 1), got {}",
                              min_boundary_quality));
  problem.Require(max_stitch_tilt_deg > 0.0 && max_stitch_tilt_deg <= 90.0,
                  fmt::format("surface options: max_stitch_tilt_deg must be in (0, 90], got {}",
                              max_stitch_tilt_deg));
  problem.Require(!(min_component_faces < 0),
                  fmt::format("surface options: min_component_faces must be >= 0, got {}",
                              min_component_faces));
  RequirePositive(problem, image_growth.max_growth_factor, "image_growth.max_growth_factor");
  RequirePositive(problem, image_growth.grid_factor, "image_growth.grid_factor");
  RequirePositive(problem, image_growth.smoothing_factor, "image_growth.smoothing_factor");
  problem.Require(
      image_growth.edge_tolerance_px >= 0.0 && std::isfinite(image_growth.edge_tolerance_px),
      fmt::format("surface options: image_growth.edge_tolerance_px must be >= 0, got {}",
                  image_growth.edge_tolerance_px));
  problem.Require(
      !(image_growth.min_plant_views < 1 || image_growth.min_background_views < 1),
      fmt::format(
          "surface options: image_growth.min_plant_views and min_background_views must be >= 1, "
          "got {} and {}",
          image_growth.min_plant_views, image_growth.min_background_views));
  RequireSmoothing(problem, cell_smoothing, "cell_smoothing");
  RequireSmoothing(problem, final_smoothing, "final_smoothing");
  return problem.text();
}

SurfaceThresholds ResolveThresholds(const SurfaceOptions& options, double spacing, double noise) {
  SurfaceThresholds t;
  t.spacing = spacing;
  t.noise = noise;
  t.piece_link = options.piece_link_factor * spacing;
  t.alpha = options.alpha_factor * spacing;
  t.long_edge = options.long_edge_factor * spacing;
  t.hole_perimeter = options.hole_perimeter_factor * spacing;
  t.stitch_distance = options.stitch_factor * spacing;
  t.own_cluster_stitch_distance =
      (options.own_cluster_stitch_factor > 0.0 ? options.own_cluster_stitch_factor
                                               : options.stitch_factor) *
      spacing;
  t.growth_clearance = options.growth_clearance_factor * spacing;
  return t;
}

}  // namespace avc::surface
