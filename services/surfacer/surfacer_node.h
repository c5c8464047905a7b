#pragma once

// avc-surfacer on the bus (paper §4): every clusters product is surfaced and the mesh goes out.
//  - Input: clusters_t products on PRODUCT/CLUSTERS (the clusterer's answers).
//  - Output: mesh_t on PRODUCT/MESH named "mesh/<cloud id>" (mesh_id = the cloud id), one per
//    clusters product, binary PLY with per-face `label` = cluster id and per-vertex colours.
//    Also when nothing could be surfaced: then the mesh is empty and the reason is logged and
//    in the heartbeat (mesh_t has no field for it), so a waiting orchestrator always hears
//    back. A product that does not decode at all is logged and skipped.
//  - Determinism: the mesh is a pure function of the clusters and the options.
//  - Heartbeat: READY with the last answer.
// With output_dir set, each result is also written to output_dir/<cloud id>/ as mesh.ply,
// traits.csv and traits.json.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "core/bus/bus.h"
#include "core/bus/event_loop.h"
#include "core/bus/heartbeat.h"
#include "core/products/product_receiver.h"
#include "core/products/product_sender.h"
#include "services/surfacer/surface_clusters.h"

namespace avc::surfacer {

struct SurfacerNodeOptions {
  std::string service = "avc-surfacer";
  SurfacerOptions surfacing;
  std::filesystem::path output_dir;
  // A reconstruction folder whose masks drive Phase 2 (surface_images_io.h), read for every
  // clusters product; empty: the band growth. Unreadable masks are logged and not used.
  std::filesystem::path images_dir;
  products::SenderOptions products;

  // Empty when usable, else a sentence naming the bad option.
  std::string Validate() const;
};

class SurfacerNode {
 public:
  // Throws std::invalid_argument for bad options.
  SurfacerNode(bus::Bus& bus, bus::EventLoop& loop, bus::HeartbeatPublisher& heartbeat,
               SurfacerNodeOptions options);
  ~SurfacerNode();
  SurfacerNode(const SurfacerNode&) = delete;
  SurfacerNode& operator=(const SurfacerNode&) = delete;

  int64_t clusters_answered() const { return clusters_answered_; }

 private:
  void OnClusters(const products::Product& product);
  void Publish(const SurfacerResult& result);
  void UpdateHeartbeat();

  bus::HeartbeatPublisher& heartbeat_;
  SurfacerNodeOptions options_;
  products::ProductSender sender_;
  int64_t clusters_answered_ = 0;
  std::string last_answer_;
  // After what it feeds: destroyed first.
  std::unique_ptr<products::ProductReceiver> clusters_;
};

}  // namespace avc::surfacer
