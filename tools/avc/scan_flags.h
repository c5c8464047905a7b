#pragma once

// The scan's options (orchestrator/scan_options.h) on avc scan's and avc demo's command lines:
// --config, --set, and flags standing for the options most often changed. Planner settings
// given become plan job settings for avc-planner; the others keep the planner's own defaults,
// which it reports with its first answer and the scan records. Neither command links the
// planner's code (a configure-time check).

#include <CLI/CLI.hpp>

#include "tools/avc/config_flags.h"

namespace avc::cli {

// --max-views, --prune-face-loss, --views-per-height, --ready-timeout, --config and --set.
void AddScanOptionFlags(CLI::App* command, ConfigFlags* config);

}  // namespace avc::cli
