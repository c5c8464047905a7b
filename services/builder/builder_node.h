#pragma once

// avc-builder on the bus (paper §2.2–3): the plant proxy grows as the scan's images arrive, and
// multi-view stereo runs on command.
//  - Inputs: image_t products on PRODUCT/IMAGE and camera_t on CAMERA, paired by image_id in
//    either order (unmatched ones wait, a bounded number, oldest dropped first). Each pair is
//    decoded, undistorted and masked (segmentation::SegmentPlant) exactly as builder::Reconstruct
//    does, then carved into the proxy.
//  - The proxy is created once `views_for_bounds` views are in, over ppr::BoundsFromViews of
//    those views (or the configured box); every later view is carved into it as it arrives.
//    After each change the proxy goes out as a voxel_map_t (.bt) product on PRODUCT/VOXEL_MAP;
//    while one is unacknowledged only the newest waits behind it.
//  - BUILD_COMMAND (acks via AckBook; a repeated request id gets its last answer again):
//    RESET forgets everything, INCREASE_RESOLUTION halves the proxy's voxels and republishes,
//    RUN_MVS runs builder::Reconstruct on a worker thread over the chosen integrated views
//    sorted by image_id (so the points depend neither on arrival order nor on the live proxy's
//    first views: they equal the offline `avc reconstruct` of the same images), publishes
//    mvs_points_t on PRODUCT/MVS_POINTS and acks DONE once that product is acknowledged.
//  - Heartbeat: READY with what is integrated, BUSY with the MVS stage while it runs; progress
//    also on PROGRESS (task "mvs").
// Bad input (corrupt image, bad camera, size mismatch, bad command) is logged or REFUSED with a
// message naming the image or field; the node carries on.

#include <Eigen/Geometry>
#include <atomic>
#include <avc/build_command_t.hpp>
#include <avc/camera_t.hpp>
#include <deque>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "core/bus/ack_book.h"
#include "core/bus/bus.h"
#include "core/bus/event_loop.h"
#include "core/bus/heartbeat.h"
#include "core/products/product_receiver.h"
#include "core/products/product_sender.h"
#include "services/builder/reconstruction.h"

namespace avc::builder {

struct BuilderNodeOptions {
  std::string service = "avc-builder";
  std::string scan_id = "scan";  // names products until a command names another scan
  // Views whose BoundsFromViews box the proxy is created over (at least 2).
  int views_for_bounds = 3;
  // Set: the proxy covers this box (world frame, metres) from the first view on.
  std::optional<Eigen::AlignedBox3d> box;
  // Masks, proxy and MVS settings; `reconstruct.method` is RUN_MVS's default method.
  ReconstructOptions reconstruct;
  // Images and cameras waiting for their partner, each; the oldest is dropped beyond this.
  size_t max_unmatched = 64;
  // Set: the latest proxy is also written there as ppr.bt and each MVS result as
  // mvs_<cloud id>.ply.
  std::filesystem::path output_dir;
  products::SenderOptions products;

  // Empty when usable, else a sentence naming the bad option.
  std::string Validate() const;
};

class BuilderNode {
 public:
  // Throws std::invalid_argument for bad options.
  BuilderNode(bus::Bus& bus, bus::EventLoop& loop, bus::HeartbeatPublisher& heartbeat,
              BuilderNodeOptions options);
  // Stops a running MVS and waits for the worker; MVS requests not yet DONE are FAILED.
  ~BuilderNode();
  BuilderNode(const BuilderNode&) = delete;
  BuilderNode& operator=(const BuilderNode&) = delete;

  int views_integrated() const { return static_cast<int>(views_.size()); }
  bool has_proxy() const { return proxy_.has_value(); }
  const ppr::PlantProxy& proxy() const { return *proxy_; }
  bool mvs_running() const { return worker_.joinable(); }
  int64_t voxel_maps_published() const { return voxel_maps_published_; }

 private:
  struct MvsJob;
  struct MvsOutcome;

  void OnImageProduct(const products::Product& product);
  void OnCamera(const avc::camera_t& message);
  void TryIntegrate(const std::string& image_id);
  void Integrate(const std::string& image_id, cv::Mat image, const camera::Camera& camera);
  void CreateProxyIfReady();
  void PublishVoxelMap();
  void SendLatestVoxelMap();

  void OnCommand(const avc::build_command_t& command);
  void Reset(const avc::build_command_t& command);
  void IncreaseResolution(const avc::build_command_t& command);
  void StartMvs(const avc::build_command_t& command);
  void OnMvsProgress(const std::string& stage, size_t done, size_t total);
  void OnMvsFinished(MvsOutcome outcome);
  void JoinWorker();

  void UpdateHeartbeat();
  // Runs fn on the loop thread later, unless the node is gone by then.
  void PostToLoop(std::function<void()> fn);

  bus::Bus& bus_;
  bus::EventLoop& loop_;
  bus::HeartbeatPublisher& heartbeat_;
  BuilderNodeOptions options_;
  std::string scan_id_;
  bus::AckBook acks_;
  products::ProductSender sender_;

  // Waiting for their partner, with arrival order for the bound.
  std::map<std::string, cv::Mat> unmatched_images_;
  std::deque<std::string> image_order_;
  std::map<std::string, camera::Camera> unmatched_cameras_;
  std::deque<std::string> camera_order_;

  // Integrated views (undistorted, masked), sorted by image_id; and their arrival order.
  std::map<std::string, dataset::View> views_;
  std::vector<std::string> arrival_;
  std::optional<ppr::PlantProxy> proxy_;
  std::string proxy_problem_;  // why the proxy could not be created yet, for the heartbeat

  int64_t voxel_maps_published_ = 0;
  bool voxel_map_in_flight_ = false;
  bool voxel_map_stale_ = false;  // changed since the product in flight was made

  // The running MVS: its request, and progress shown on the heartbeat.
  std::string mvs_request_;
  std::string mvs_progress_;
  std::shared_ptr<std::atomic<bool>> mvs_cancel_;
  std::thread worker_;
  // Finished runs whose points product is not acknowledged yet.
  std::set<std::string> mvs_sending_;

  std::vector<bus::Bus::SubscriptionId> subscriptions_;
  std::shared_ptr<int> alive_ = std::make_shared<int>(0);
  // After the subscriptions it feeds: destroyed first.
  std::unique_ptr<products::ProductReceiver> receiver_;
};

}  // namespace avc::builder
