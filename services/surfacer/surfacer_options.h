#pragma once

// avc-surfacer's options (Algorithm 3's surface phases), declared once for --config, --set, the
// configuration it publishes and --help (core/config/option_table.h). The traits' ground is not
// an option: a scan's surface stage measures it from the soil the builder found.

#include "core/config/option_table.h"
#include "services/surfacer/surface_clusters.h"

namespace avc::surfacer {

const config::OptionTable<SurfacerOptions>& SurfacerOptionTable();

}  // namespace avc::surfacer
