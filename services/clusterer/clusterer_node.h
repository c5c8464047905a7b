#pragma once

// avc-clusterer on the bus (paper §3): every MVS points product is merged into the latest plant
// proxy and clustered, and the result goes out as one clusters_t product.
//  - Inputs: voxel_map_t products on PRODUCT/VOXEL_MAP (the proxy; the latest one is kept) and
//    mvs_points_t products on PRODUCT/MVS_POINTS. Points that arrive before any proxy wait for it
//    (a bounded number, oldest answered first with a problem).
//  - Output: clusters_t on PRODUCT/CLUSTERS named "clusters/<cloud id>", one per MVS points
//    product, also when nothing could be clustered (its `problem` says why), so a waiting
//    orchestrator always hears back. A product that does not decode is answered the same way
//    when its cloud id can be read, else logged.
//  - Determinism: the result is a pure function of the points, the proxy and the options.
//  - Heartbeat: READY with the proxy in hand and the clouds answered.
// With output_dir set, each result is also written there as clusters_<cloud id>.ply.

#include <cstdint>
#include <deque>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/bus/bus.h"
#include "core/bus/event_loop.h"
#include "core/bus/heartbeat.h"
#include "core/mvs/mvs_bounds.h"
#include "core/products/product_receiver.h"
#include "core/products/product_sender.h"
#include "services/clusterer/merge_and_cluster.h"

namespace avc::clusterer {

struct ClustererNodeOptions {
  std::string service = "avc-clusterer";
  ClustererOptions clustering;
  // MVS clouds waiting for a first proxy; the oldest is answered with a problem beyond this.
  size_t max_waiting = 4;
  std::filesystem::path output_dir;
  products::SenderOptions products;

  // Empty when usable, else a sentence naming the bad option.
  std::string Validate() const;
};

class ClustererNode {
 public:
  // Throws std::invalid_argument for bad options.
  ClustererNode(bus::Bus& bus, bus::EventLoop& loop, bus::HeartbeatPublisher& heartbeat,
                ClustererNodeOptions options);
  ~ClustererNode();
  ClustererNode(const ClustererNode&) = delete;
  ClustererNode& operator=(const ClustererNode&) = delete;

  bool has_proxy() const { return proxy_.has_value(); }
  int64_t clouds_answered() const { return clouds_answered_; }

 private:
  struct Proxy {
    std::string map_id;
    mvs::MvsBounds bounds;
  };
  struct WaitingCloud {
    std::string cloud_id;
    mvs::MvsPoints points;
  };

  void OnVoxelMap(const products::Product& product);
  void OnMvsPoints(const products::Product& product);
  void Answer(const std::string& cloud_id, const mvs::MvsPoints& points);
  void Publish(const messages::ClustersContent& content);
  void UpdateHeartbeat();

  bus::Bus& bus_;
  bus::HeartbeatPublisher& heartbeat_;
  ClustererNodeOptions options_;
  products::ProductSender sender_;
  std::optional<Proxy> proxy_;
  std::string proxy_problem_;  // why the last voxel map was not usable
  std::deque<WaitingCloud> waiting_;
  int64_t clouds_answered_ = 0;
  std::string last_answer_;
  // After what they feed: destroyed first.
  std::unique_ptr<products::ProductReceiver> voxel_maps_;
  std::unique_ptr<products::ProductReceiver> mvs_points_;
};

}  // namespace avc::clusterer
