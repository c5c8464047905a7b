#pragma once

// The processing nodes `avc replay` can run, by name. Each node is built on the replay's
// in-process bus and writes its files under the replay output directory. Registration is an
// explicit call (RegisterBuiltinNodes), never static initialisation, so what a binary can
// replay is visible in its main.

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/bus/bus.h"

namespace avc::record {

struct ReplayNode {
  virtual ~ReplayNode();
  // Called once after the last event: write out anything held back.
  virtual void Finish() {}
  // The directory this node writes into (empty if it writes no files); listed in the summary.
  virtual std::filesystem::path OutputDir() const { return {}; }
  // One line on what the node did, e.g. "3 products stored".
  virtual std::string Describe() const { return {}; }
};

using NodeFactory = std::function<std::unique_ptr<ReplayNode>(
    bus::Bus& bus, const std::filesystem::path& output_dir)>;

class NodeRegistry {
 public:
  struct Entry {
    std::string name;
    std::string description;
    NodeFactory factory;
  };

  // Throws std::invalid_argument for an empty or already registered name.
  void Register(std::string name, std::string description, NodeFactory factory);
  bool Contains(const std::string& name) const { return entries_.contains(name); }
  // Throws std::invalid_argument listing the known names when name is unknown.
  const Entry& Get(const std::string& name) const;
  // Sorted by name.
  std::vector<const Entry*> List() const;

 private:
  std::map<std::string, Entry> entries_;
};

}  // namespace avc::record
