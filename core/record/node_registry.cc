#include "core/record/node_registry.h"

#include <stdexcept>

namespace avc::record {

ReplayNode::~ReplayNode() = default;

void NodeRegistry::Register(std::string name, std::string description, NodeFactory factory) {
  if (name.empty()) throw std::invalid_argument("a replay node needs a name");
  if (!factory) throw std::invalid_argument("replay node '" + name + "' has no factory");
  if (entries_.contains(name)) {
    throw std::invalid_argument("replay node '" + name + "' is registered twice");
  }
  Entry entry{name, std::move(description), std::move(factory)};
  entries_.emplace(std::move(name), std::move(entry));
}

const NodeRegistry::Entry& NodeRegistry::Get(const std::string& name) const {
  auto it = entries_.find(name);
  if (it != entries_.end()) return it->second;
  std::string known;
  for (const auto& [key, entry] : entries_) known += (known.empty() ? "" : ", ") + key;
  throw std::invalid_argument("unknown replay node '" + name +
                              "' (known: " + (known.empty() ? "none" : known) + ")");
}

std::vector<const NodeRegistry::Entry*> NodeRegistry::List() const {
  std::vector<const Entry*> list;
  for (const auto& [name, entry] : entries_) list.push_back(&entry);
  return list;
}

}  // namespace avc::record
