#pragma once

// `avc replay`'s "scan" node: rebuilds a scan's model from its log. It keeps the image products
// and the scan's kept cameras (SCAN_CAMERAS), and after the last event writes them as a scan
// directory (<output>/scan: images/, cameras.json) and runs the code the stage services run for
// a scan (build_step.h, cluster_step.h, surface_step.h) with the options those services
// published on CONFIG during the recording, so model/mesh.ply comes out byte for byte as the
// scan's services wrote it.

#include "core/record/node_registry.h"

namespace avc::cli {

void RegisterScanReplayNode(record::NodeRegistry& registry);

}  // namespace avc::cli
