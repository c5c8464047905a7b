#include "services/builder/option_overrides.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <charconv>
#include <functional>
#include <map>
#include <stdexcept>

namespace avc::builder {
namespace {

using Setter = std::function<void(ReconstructOptions*, const std::string&)>;

template <typename T>
T Parse(const std::string& text) {
  T value{};
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (error != std::errc() || stop != end) throw std::invalid_argument("not a number");
  return value;
}

template <typename T>
Setter Field(T ReconstructOptions::*section, auto field) {
  return [section, field](ReconstructOptions* options, const std::string& text) {
    auto& target = (options->*section).*field;
    target = Parse<std::remove_reference_t<decltype(target)>>(text);
  };
}

const std::map<std::string, Setter>& Setters() {
  using O = ReconstructOptions;
  using P = mvs::PatchMvsOptions;
  using S = mvs::PlaneSweepOptions;
  using X = ppr::ProxyOptions;
  using L = SoilLevelOptions;
  static const std::map<std::string, Setter> setters = {
      {"patch.level", Field(&O::patch, &P::level)},
      {"patch.cell_size", Field(&O::patch, &P::cell_size)},
      {"patch.window", Field(&O::patch, &P::window)},
      {"patch.ncc_threshold", Field(&O::patch, &P::ncc_threshold)},
      {"patch.ncc_threshold_before", Field(&O::patch, &P::ncc_threshold_before)},
      {"patch.min_images", Field(&O::patch, &P::min_images)},
      {"patch.max_view_angle", Field(&O::patch, &P::max_view_angle)},
      {"patch.features_per_block", Field(&O::patch, &P::features_per_block)},
      {"patch.feature_block", Field(&O::patch, &P::feature_block)},
      {"patch.epipolar_distance", Field(&O::patch, &P::epipolar_distance)},
      {"patch.seed_neighbours", Field(&O::patch, &P::seed_neighbours)},
      {"patch.rounds", Field(&O::patch, &P::rounds)},
      {"patch.max_iterations", Field(&O::patch, &P::max_iterations)},
      {"patch.max_refine_images", Field(&O::patch, &P::max_refine_images)},
      {"patch.min_texture", Field(&O::patch, &P::min_texture)},
      {"patch.occlusion_cells", Field(&O::patch, &P::occlusion_cells)},
      {"patch.regularity_threshold", Field(&O::patch, &P::regularity_threshold)},
      {"patch.min_group_size", Field(&O::patch, &P::min_group_size)},
      {"patch.bounds_dilation", Field(&O::patch, &P::bounds_dilation)},
      {"patch.whole_patch_in_mask", Field(&O::patch, &P::whole_patch_in_mask)},
      {"sweep.level", Field(&O::sweep, &S::level)},
      {"sweep.window", Field(&O::sweep, &S::window)},
      {"sweep.neighbours", Field(&O::sweep, &S::neighbours)},
      {"sweep.best_k", Field(&O::sweep, &S::best_k)},
      {"sweep.min_score", Field(&O::sweep, &S::min_score)},
      {"sweep.min_texture_std", Field(&O::sweep, &S::min_texture_std)},
      {"sweep.consistency_tolerance", Field(&O::sweep, &S::consistency_tolerance)},
      {"sweep.min_consistent_views", Field(&O::sweep, &S::min_consistent_views)},
      {"proxy.background_votes_allowed", Field(&O::proxy, &X::background_votes_allowed)},
      {"proxy.min_plant_views", Field(&O::proxy, &X::min_plant_views)},
      {"proxy.final_voxel_size", Field(&O::proxy, &X::final_voxel_size)},
      {"proxy.resolution_increases", Field(&O::proxy, &X::resolution_increases)},
      {"soil.inner_radius", Field(&O::soil, &L::inner_radius)},
      {"soil.outer_radius", Field(&O::soil, &L::outer_radius)},
      {"soil.search_below", Field(&O::soil, &L::search_below)},
      {"soil.search_above", Field(&O::soil, &L::search_above)},
      {"soil.min_views", Field(&O::soil, &L::min_views)},
      {"soil.min_elevation_deg", Field(&O::soil, &L::min_elevation_deg)},
      {"soil.max_contrast", Field(&O::soil, &L::max_contrast)},  // 0: never measure from soil
  };
  return setters;
}

}  // namespace

std::vector<std::string> OverrideNames() {
  std::vector<std::string> names;
  for (const auto& [name, setter] : Setters()) names.push_back(name);
  return names;
}

void ApplyOverride(const std::string& assignment, ReconstructOptions* options) {
  const size_t equals = assignment.find('=');
  if (equals == std::string::npos) {
    throw std::invalid_argument(
        fmt::format("override '{}': expected section.field=value", assignment));
  }
  const std::string name = assignment.substr(0, equals);
  const std::string value = assignment.substr(equals + 1);
  const auto it = Setters().find(name);
  if (it == Setters().end()) {
    throw std::invalid_argument(fmt::format("override '{}': unknown setting '{}' (known: {})",
                                            assignment, name, fmt::join(OverrideNames(), ", ")));
  }
  ReconstructOptions changed = *options;
  try {
    it->second(&changed, value);
    changed.patch.Validate();
    changed.sweep.Validate();
    changed.soil.Validate();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(fmt::format("override '{}': {}", assignment, e.what()));
  }
  *options = changed;
}

}  // namespace avc::builder
