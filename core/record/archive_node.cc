#include "core/record/archive_node.h"

#include <fmt/format.h>

#include "core/products/product_archive.h"

namespace avc::record {
namespace {

class ArchiveNode final : public ReplayNode {
 public:
  ArchiveNode(bus::Bus& bus, const std::filesystem::path& output_dir)
      : archive_(bus, output_dir / "archive") {}

  std::filesystem::path OutputDir() const override { return archive_.dir(); }
  std::string Describe() const override {
    const products::ReceiverStats& stats = archive_.receiver_stats();
    return fmt::format("{} products stored ({} chunks, {} duplicate, {} corrupt, {} invalid)",
                       archive_.stored(), stats.chunks, stats.duplicates, stats.corrupt,
                       stats.invalid);
  }

 private:
  products::ProductArchive archive_;
};

}  // namespace

void RegisterArchiveNode(NodeRegistry& registry) {
  registry.Register("archive",
                    "stores every product as a file (PNG/JPEG, PLY, .bt, ...) plus "
                    "manifest.jsonl, in <output>/archive",
                    [](bus::Bus& bus, const std::filesystem::path& output_dir) {
                      return std::make_unique<ArchiveNode>(bus, output_dir);
                    });
}

}  // namespace avc::record
