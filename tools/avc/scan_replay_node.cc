#include "tools/avc/scan_replay_node.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <avc/config_t.hpp>
#include <avc/scan_cameras_t.hpp>
#include <exception>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/bus/channels.h"
#include "core/camera/camera_io.h"
#include "core/messages/camera_message.h"
#include "core/products/product_archive.h"
#include "core/products/product_receiver.h"
#include "core/stage/stage_names.h"
#include "core/util/file_io.h"
#include "core/util/log.h"
#include "services/builder/build_step.h"
#include "services/builder/builder_options.h"
#include "services/clusterer/cluster_step.h"
#include "services/clusterer/clusterer_options.h"
#include "services/surfacer/surface_step.h"
#include "services/surfacer/surfacer_options.h"

namespace avc::cli {
namespace {

namespace fs = std::filesystem;

class ScanReplayNode final : public record::ReplayNode {
 public:
  ScanReplayNode(bus::Bus& bus, const fs::path& output_dir)
      : bus_(bus),
        dir_(output_dir / "scan"),
        images_(bus, "avc-replay-scan", std::string(channels::kProductImage),
                [this](const products::Product& product, const bus::RxInfo&) { Keep(product); }) {
    cameras_subscription_ = bus.Subscribe<avc::scan_cameras_t>(
        channels::kScanCameras,
        [this](const avc::scan_cameras_t& message, const bus::RxInfo&) { cameras_ = message; });
    config_subscription_ = bus.Subscribe<avc::config_t>(
        channels::kConfig, [this](const avc::config_t& message, const bus::RxInfo&) {
          configs_[message.service] = message.text;
        });
  }
  ~ScanReplayNode() override {
    bus_.Unsubscribe(cameras_subscription_);
    bus_.Unsubscribe(config_subscription_);
  }

  void Finish() override {
    if (!cameras_) {
      outcome_ =
          "nothing rebuilt: the log holds no SCAN_CAMERAS (no scan reached BUILD while "
          "it was recorded)";
      return;
    }
    try {
      Rebuild();
    } catch (const std::exception& error) {
      outcome_ = fmt::format("scan {}: not rebuilt: {}", cameras_->scan_id, error.what());
      log::Error("replay: {}", outcome_);
    }
  }

  fs::path OutputDir() const override { return dir_; }
  std::string Describe() const override { return outcome_; }

 private:
  // Images by file name; a later product of the same name (a recapture) replaces the earlier.
  void Keep(const products::Product& product) {
    try {
      products::StoredFile file = products::ToStoredFile(product);
      images_by_name_[file.relative_path.filename().string()] = std::move(file.bytes);
    } catch (const std::invalid_argument& error) {
      log::Warn("replay: image product '{}' skipped: {}", product.name, error.what());
    }
  }

  void Rebuild() {
    std::vector<camera::NamedCamera> cameras;
    fs::create_directories(dir_ / "images");
    for (const avc::camera_t& message : cameras_->cameras) {
      const auto image = images_by_name_.find(message.image_id);
      if (image == images_by_name_.end()) {
        throw std::runtime_error(
            fmt::format("kept view {} has no image product in the log (recorded from later on?)",
                        message.image_id));
      }
      WriteFileAtomically(dir_ / "images" / message.image_id, image->second);
      cameras.push_back({message.image_id, messages::CameraFromMessage(message)});
    }
    camera::WriteCamerasJson(dir_ / "cameras.json", cameras);
    const fs::path model = dir_ / "model";
    std::vector<std::string> defaults;
    builder::BuildModel(dir_, model,
                        Configured(builder::BuilderOptionTable(), stage::kBuildService, &defaults));
    clusterer::ClusterModel(
        model, model,
        Configured(clusterer::ClustererOptionTable(), stage::kClusterService, &defaults));
    surfacer::SurfaceModel(
        model, model,
        Configured(surfacer::SurfacerOptionTable(), stage::kSurfaceService, &defaults));
    outcome_ = fmt::format("scan {}: {} kept views of {} images rebuilt into {}", cameras_->scan_id,
                           cameras.size(), images_by_name_.size(), (model / "mesh.ply").string());
    if (!defaults.empty()) {
      outcome_ +=
          fmt::format(" (no CONFIG of {} in the log: default options)", fmt::join(defaults, ", "));
    }
  }

  // The options `service` published on CONFIG while the log was recorded, so the rebuild runs
  // with the scan's own; the defaults (named in `defaults`) when the log holds none.
  template <typename Options>
  Options Configured(const config::OptionTable<Options>& table, const std::string& service,
                     std::vector<std::string>* defaults) const {
    Options options;
    const auto it = configs_.find(service);
    if (it == configs_.end()) {
      defaults->push_back(service);
      return options;
    }
    table.Apply(options, config::ReadTomlAssignments(it->second, "CONFIG of " + service));
    return options;
  }

  bus::Bus& bus_;
  fs::path dir_;
  products::ProductReceiver images_;
  bus::Bus::SubscriptionId cameras_subscription_ = 0;
  bus::Bus::SubscriptionId config_subscription_ = 0;
  std::optional<avc::scan_cameras_t> cameras_;
  std::map<std::string, std::string> configs_;  // by service: its latest CONFIG text
  std::map<std::string, std::string> images_by_name_;
  std::string outcome_;
};

}  // namespace

void RegisterScanReplayNode(record::NodeRegistry& registry) {
  registry.Register("scan",
                    "rebuilds the recorded scan's model from its images and kept cameras "
                    "(SCAN_CAMERAS) with avc scan's own steps, in <output>/scan",
                    [](bus::Bus& bus, const fs::path& output_dir) {
                      return std::make_unique<ScanReplayNode>(bus, output_dir);
                    });
}

}  // namespace avc::cli
