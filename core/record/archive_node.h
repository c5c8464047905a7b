#pragma once

// Replay node "archive": stores every product of the log as files (products::ProductArchive)
// under <output_dir>/archive.

#include "core/record/node_registry.h"

namespace avc::record {

void RegisterArchiveNode(NodeRegistry& registry);

}  // namespace avc::record
