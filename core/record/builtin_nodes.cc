#include "core/record/builtin_nodes.h"

#include "core/record/archive_node.h"

namespace avc::record {

void RegisterBuiltinNodes(NodeRegistry& registry) { RegisterArchiveNode(registry); }

}  // namespace avc::record
