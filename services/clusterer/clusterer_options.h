#pragma once

// avc-clusterer's options (merging into the proxy, Algorithm 2), declared once for --config,
// --set, the configuration it publishes and --help (core/config/option_table.h).

#include "core/config/option_table.h"
#include "services/clusterer/merge_and_cluster.h"

namespace avc::clusterer {

const config::OptionTable<ClustererOptions>& ClustererOptionTable();

}  // namespace avc::clusterer
