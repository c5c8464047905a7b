#include "services/surfacer/surfacer_node.h"

#include <fmt/format.h>

#include <avc/clusters_t.hpp>
#include <stdexcept>

#include "core/bus/channels.h"
#include "core/messages/mesh_message.h"
#include "core/surface/surface_images_io.h"
#include "core/util/log.h"
#include "core/util/validation.h"

namespace avc::surfacer {

std::string SurfacerNodeOptions::Validate() const {
  if (service.empty()) return "service name is empty";
  FirstProblem problem;
  problem.Include(surfacing.Validate());
  problem.Include(products.Validate());
  return problem.text();
}

SurfacerNode::SurfacerNode(bus::Bus& bus, bus::EventLoop& loop, bus::HeartbeatPublisher& heartbeat,
                           SurfacerNodeOptions options)
    : heartbeat_(heartbeat), options_(std::move(options)), sender_(bus, loop, options_.products) {
  if (const std::string problem = options_.Validate(); !problem.empty()) {
    throw std::invalid_argument(options_.service + ": " + problem);
  }
  if (!options_.output_dir.empty()) std::filesystem::create_directories(options_.output_dir);
  clusters_ = std::make_unique<products::ProductReceiver>(
      bus, options_.service, std::string(channels::kProductClusters),
      [this](const products::Product& product, const bus::RxInfo&) { OnClusters(product); });
  UpdateHeartbeat();
}

SurfacerNode::~SurfacerNode() { clusters_.reset(); }

void SurfacerNode::OnClusters(const products::Product& product) {
  avc::clusters_t message;
  if (product.content_type != products::ContentTypeOf<avc::clusters_t>() ||
      message.decode(product.payload.data(), 0, static_cast<int>(product.payload.size())) < 0) {
    log::Warn("product '{}' ({}) is not a clusters_t; ignored", product.name, product.content_type);
    return;
  }
  heartbeat_.Set(bus::ServiceState::kBusy, fmt::format("surfacing '{}'", message.cloud_id));
  surface::SurfaceImages images;
  if (!options_.images_dir.empty()) {
    try {
      images = surface::ReadSurfaceImages(options_.images_dir);
    } catch (const std::exception& error) {
      log::Warn("surfacing '{}' without images: {}", message.cloud_id, error.what());
    }
  }
  SurfacerResult result;
  try {
    result = SurfaceClusters(messages::ClustersFromMessage(message), options_.surfacing, &images);
  } catch (const std::invalid_argument& error) {  // the message's records are inconsistent
    result.cloud_id = message.cloud_id;
    result.problem = error.what();
  }
  Publish(result);
}

void SurfacerNode::Publish(const SurfacerResult& result) {
  ++clusters_answered_;
  if (result.problem.empty()) {
    last_answer_ = fmt::format("'{}': {} faces, {} components, area {:.1f} cm^2", result.cloud_id,
                               result.mesh.faces.size(), result.report.components,
                               1e4 * result.traits.total_area);
    log::Info("{}", last_answer_);
    for (const std::string& warning : result.report.warnings) {
      log::Warn("surfacing '{}': {}", result.cloud_id, warning);
    }
  } else {
    last_answer_ = fmt::format("'{}': {}", result.cloud_id, result.problem);
    log::Warn("no surface for {}", last_answer_);
  }
  if (!options_.output_dir.empty() && !result.mesh.faces.empty()) {
    // The product is what matters; a local copy that cannot be written is only reported.
    try {
      WriteSurfacerFiles(result, options_.output_dir / result.cloud_id);
    } catch (const std::exception& error) {
      log::Warn("cannot write the surface of '{}': {}", result.cloud_id, error.what());
    }
  }
  avc::mesh_t message;
  try {
    message = messages::MeshToMessage(result.mesh, result.cloud_id);
  } catch (const std::exception& error) {
    // Our own mesh failing its check is a bug; answer with an empty mesh rather than not at all.
    log::Warn("mesh of '{}' cannot be encoded ({}); an empty one is sent", result.cloud_id,
              error.what());
    message = messages::MeshToMessage(geometry::Mesh{}, result.cloud_id);
  }
  sender_.SendMessage(channels::kProductMesh, "mesh/" + result.cloud_id, message,
                      [cloud_id = result.cloud_id](const products::SendResult& sent) {
                        if (!sent.ok)
                          log::Warn("mesh of '{}' not delivered: {}", cloud_id, sent.error);
                      });
  UpdateHeartbeat();
}

void SurfacerNode::UpdateHeartbeat() {
  std::string detail = "waiting for clusters on " + std::string(channels::kProductClusters);
  if (!last_answer_.empty()) {
    detail = fmt::format("{} answered; last: {}", clusters_answered_, last_answer_);
  }
  heartbeat_.Set(bus::ServiceState::kReady, detail);
}

}  // namespace avc::surfacer
