#pragma once

// avc-builder's options (the reconstruction: masks, proxy, MVS, soil), declared once for
// --config, --set, a stage job's settings, the configuration it publishes and --help
// (core/config/option_table.h). `avc reconstruct` takes the same names.

#include "core/config/option_table.h"
#include "services/builder/reconstruction.h"

namespace avc::builder {

const config::OptionTable<ReconstructOptions>& BuilderOptionTable();

}  // namespace avc::builder
