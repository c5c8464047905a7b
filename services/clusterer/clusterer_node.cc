#include "services/clusterer/clusterer_node.h"

#include <fmt/format.h>

#include <avc/clusters_t.hpp>
#include <avc/mvs_points_t.hpp>
#include <avc/voxel_map_t.hpp>
#include <stdexcept>

#include "core/bus/channels.h"
#include "core/messages/mvs_points_message.h"
#include "core/ppr/octree_voxels.h"
#include "core/util/log.h"
#include "core/util/validation.h"
#include "services/clusterer/clusters_ply.h"

namespace avc::clusterer {
namespace {

// Decodes a product's payload as T; throws std::invalid_argument naming the product.
template <class T>
T DecodeProduct(const products::Product& product) {
  if (product.content_type != products::ContentTypeOf<T>()) {
    throw std::invalid_argument(fmt::format("product '{}' is {}, not {}", product.name,
                                            product.content_type, products::ContentTypeOf<T>()));
  }
  T message;
  if (message.decode(product.payload.data(), 0, static_cast<int>(product.payload.size())) < 0) {
    throw std::invalid_argument(
        fmt::format("product '{}' does not decode as {}", product.name, T::getTypeName()));
  }
  return message;
}

}  // namespace

std::string ClustererNodeOptions::Validate() const {
  if (service.empty()) return "service name is empty";
  if (max_waiting == 0) return "max_waiting must be at least 1";
  FirstProblem problem;
  problem.Include(clustering.Validate());
  problem.Include(products.Validate());
  return problem.text();
}

ClustererNode::ClustererNode(bus::Bus& bus, bus::EventLoop& loop,
                             bus::HeartbeatPublisher& heartbeat, ClustererNodeOptions options)
    : bus_(bus),
      heartbeat_(heartbeat),
      options_(std::move(options)),
      sender_(bus, loop, options_.products) {
  if (const std::string problem = options_.Validate(); !problem.empty()) {
    throw std::invalid_argument(options_.service + ": " + problem);
  }
  if (!options_.output_dir.empty()) std::filesystem::create_directories(options_.output_dir);
  voxel_maps_ = std::make_unique<products::ProductReceiver>(
      bus_, options_.service, std::string(channels::kProductVoxelMap),
      [this](const products::Product& product, const bus::RxInfo&) { OnVoxelMap(product); });
  mvs_points_ = std::make_unique<products::ProductReceiver>(
      bus_, options_.service, std::string(channels::kProductMvsPoints),
      [this](const products::Product& product, const bus::RxInfo&) { OnMvsPoints(product); });
  UpdateHeartbeat();
}

ClustererNode::~ClustererNode() {
  mvs_points_.reset();
  voxel_maps_.reset();
}

void ClustererNode::OnVoxelMap(const products::Product& product) {
  try {
    const avc::voxel_map_t map = DecodeProduct<avc::voxel_map_t>(product);
    if (map.encoding != avc::voxel_map_t::ENCODING_OCTOMAP_BT) {
      throw std::invalid_argument(
          fmt::format("voxel map '{}': encoding {} (only .bt is read)", map.map_id, map.encoding));
    }
    const std::string what = fmt::format("voxel map '{}'", map.map_id);
    proxy_ =
        Proxy{map.map_id, ppr::OccupiedVoxelsFromBinary(
                              std::string(map.data.begin(), map.data.end()), map.resolution, what)};
    proxy_problem_.clear();
  } catch (const std::invalid_argument& error) {
    proxy_problem_ = error.what();
    log::Warn("{}; the previous proxy stays in use", error.what());
  }
  while (proxy_ && !waiting_.empty()) {
    WaitingCloud cloud = std::move(waiting_.front());
    waiting_.pop_front();
    Answer(cloud.cloud_id, cloud.points);
  }
  UpdateHeartbeat();
}

void ClustererNode::OnMvsPoints(const products::Product& product) {
  avc::mvs_points_t message;
  try {
    message = DecodeProduct<avc::mvs_points_t>(product);
  } catch (const std::invalid_argument& error) {
    log::Warn("{}; ignored", error.what());
    return;
  }
  mvs::MvsPoints points;
  try {
    points = messages::MvsPointsFromMessage(message).points;
  } catch (const std::invalid_argument& error) {
    messages::ClustersContent refusal;
    refusal.cloud_id = message.cloud_id;
    refusal.problem = error.what();
    Publish(refusal);
    return;
  }
  if (proxy_) {
    Answer(message.cloud_id, points);
  } else {
    waiting_.push_back({message.cloud_id, std::move(points)});
    if (waiting_.size() > options_.max_waiting) {
      messages::ClustersContent refusal;
      refusal.cloud_id = waiting_.front().cloud_id;
      refusal.problem = fmt::format("no plant proxy arrived on {} while {} newer clouds waited",
                                    channels::kProductVoxelMap, options_.max_waiting);
      waiting_.pop_front();
      Publish(refusal);
    }
  }
  UpdateHeartbeat();
}

void ClustererNode::Answer(const std::string& cloud_id, const mvs::MvsPoints& points) {
  heartbeat_.Set(bus::ServiceState::kBusy, fmt::format("merging and clustering '{}'", cloud_id));
  Publish(MergeAndCluster(points, proxy_->bounds, options_.clustering, cloud_id, proxy_->map_id));
}

void ClustererNode::Publish(const messages::ClustersContent& content) {
  ++clouds_answered_;
  if (content.problem.empty()) {
    last_answer_ = fmt::format("'{}': {} points -> {} merged, {} clusters", content.cloud_id,
                               content.raw_points, content.merged.size(), content.num_clusters);
    log::Info("{}", last_answer_);
  } else {
    last_answer_ = fmt::format("'{}': {}", content.cloud_id, content.problem);
    log::Warn("no clusters for {}", last_answer_);
  }
  avc::clusters_t message;
  try {
    message = messages::ClustersToMessage(content);
  } catch (const std::invalid_argument& error) {
    // Our own content failing its check is a bug; answer rather than leave the sender waiting.
    messages::ClustersContent refusal;
    refusal.cloud_id = content.cloud_id;
    refusal.map_id = content.map_id;
    refusal.problem = error.what();
    message = messages::ClustersToMessage(refusal);
  }
  if (!options_.output_dir.empty() && content.merged.size() > 0) {
    // The product is what matters; a local copy that cannot be written is only reported.
    try {
      WriteClustersPly(options_.output_dir / ("clusters_" + content.cloud_id + ".ply"), content);
    } catch (const std::exception& error) {
      log::Warn("cannot write the clusters of '{}': {}", content.cloud_id, error.what());
    }
  }
  sender_.SendMessage(channels::kProductClusters, "clusters/" + content.cloud_id, message,
                      [cloud_id = content.cloud_id](const products::SendResult& result) {
                        if (!result.ok) {
                          log::Warn("clusters of '{}' not delivered: {}", cloud_id, result.error);
                        }
                      });
  UpdateHeartbeat();
}

void ClustererNode::UpdateHeartbeat() {
  std::string detail =
      proxy_ ? fmt::format("proxy '{}' ({} occupied voxels)", proxy_->map_id,
                           proxy_->bounds.occupied_centres.size())
             : "waiting for a plant proxy on " + std::string(channels::kProductVoxelMap);
  if (!proxy_problem_.empty()) detail += "; last map refused: " + proxy_problem_;
  if (!waiting_.empty()) detail += fmt::format("; {} clouds waiting", waiting_.size());
  if (!last_answer_.empty()) detail += "; last: " + last_answer_;
  heartbeat_.Set(bus::ServiceState::kReady, detail);
}

}  // namespace avc::clusterer
