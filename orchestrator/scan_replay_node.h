#pragma once

// `avc replay`'s "scan" node: rebuilds a scan's model from its log. It keeps the image products
// and the scan's kept cameras (SCAN_CAMERAS), and after the last event writes them as a scan
// directory (<output>/scan: images/, cameras.json) and runs the scan's own reconstruction steps
// (scan_processing.h) with the default options `avc scan` uses, so model/mesh.ply comes out
// byte for byte as the scan wrote it.

#include "core/record/node_registry.h"

namespace avc::orchestrator {

void RegisterScanReplayNode(record::NodeRegistry& registry);

}  // namespace avc::orchestrator
