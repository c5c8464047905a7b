#pragma once

// The plant masks' options (MaskOptions, plant_mask.h) declared once for every option table that
// holds them: avc-builder's masks for the reconstruction and avc scan's masks for the planner.

#include <stdexcept>
#include <string>
#include <string_view>

#include "core/config/option_table.h"
#include "core/segmentation/plant_mask.h"

namespace avc::segmentation {

// Adds PREFIX.method and PREFIX.<tuning> to `table`; `masks` is a generic lambda returning the
// MaskOptions inside Options: [](auto& o) -> auto& { return o.masks; }.
template <typename Options, typename Access>
void AddMaskOptions(config::OptionTable<Options>& table, const std::string& prefix, Access masks) {
  const auto field = [masks](auto member) {
    return [ masks, member ](auto& o) -> auto& { return masks(o).*member; };
  };
  table.AddText(
      prefix + ".method", [masks](const Options& o) { return MaskMethodName(masks(o).method); },
      [masks](Options& o, std::string_view text) {
        for (auto method :
             {MaskMethod::kAuto, MaskMethod::kExcessGreen, MaskMethod::kBackgroundDistance}) {
          if (text == MaskMethodName(method)) {
            masks(o).method = method;
            return;
          }
        }
        throw std::invalid_argument("not auto, excess_green or background_distance");
      },
      {"", "plant masks: auto picks excess_green for green plants, else background_distance"});
  table
      .Add(prefix + ".histogram_bins", field(&MaskOptions::histogram_bins),
           {"bins", "of the feature histogram Otsu searches", 2, 65536})
      .Add(prefix + ".dark_fraction", field(&MaskOptions::dark_fraction),
           {"", "excess green: R+G+B floor as a fraction of the bright level", 0, 1})
      .Add(prefix + ".border_fraction", field(&MaskOptions::border_fraction),
           {"", "background model: border strip width / min(width, height)", 0, 1})
      .Add(prefix + ".background_min_scale", field(&MaskOptions::background_min_scale),
           {"L*a*b*", "background model: smallest per-channel spread", 1e-6, 1000})
      .Add(prefix + ".hysteresis", field(&MaskOptions::hysteresis),
           {"", "pixels this far below the threshold join plant they touch (0: none)", 0, 1})
      .Add(prefix + ".green_min_exg", field(&MaskOptions::green_min_exg),
           {"", "auto: excess green is a candidate when its plant class is this green", -1, 2})
      .Add(prefix + ".green_preference", field(&MaskOptions::green_preference),
           {"", "auto: excess green wins at this fraction of the background's separability", 1e-6,
            1000})
      .Add(prefix + ".close_radius_px", field(&MaskOptions::close_radius_px),
           {"px", "closing disc radius (-1: min(width, height) / 400; 0: no closing)", -1, 1000})
      .Add(prefix + ".min_component_fraction", field(&MaskOptions::min_component_fraction),
           {"", "components smaller than this fraction of the largest are dropped", 0, 1})
      .Add(prefix + ".min_component_image_fraction",
           field(&MaskOptions::min_component_image_fraction),
           {"", "... and those smaller than this fraction of the image", 0, 1});
}

}  // namespace avc::segmentation
