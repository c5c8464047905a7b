#pragma once

// Every replay node AVC ships. New nodes add one Register call in builtin_nodes.cc.

#include "core/record/node_registry.h"

namespace avc::record {

void RegisterBuiltinNodes(NodeRegistry& registry);

}  // namespace avc::record
