#include "services/builder/builder_node.h"

#include <fmt/format.h>

#include <algorithm>
#include <avc/image_t.hpp>
#include <avc/progress_t.hpp>
#include <avc/voxel_map_t.hpp>
#include <chrono>
#include <mutex>
#include <opencv2/core.hpp>
#include <set>
#include <stdexcept>

#include "core/bus/channels.h"
#include "core/dataset/view_transforms.h"
#include "core/messages/camera_message.h"
#include "core/messages/mvs_points_message.h"
#include "core/mvs/mvs_points_io.h"
#include "core/ppr/proxy_bounds.h"
#include "core/segmentation/plant_mask.h"
#include "core/util/log.h"
#include "core/util/validation.h"
#include "services/builder/node_inputs.h"

namespace avc::builder {
namespace {

// Thrown from the progress callback to stop Reconstruct when the node goes away.
struct MvsCancelled {};

// How often a running MVS may update the heartbeat and PROGRESS (a stage change always does).
constexpr auto kProgressPeriod = std::chrono::milliseconds(250);

const char* ActionName(int8_t action) {
  switch (action) {
    case avc::build_command_t::ACTION_RESET:
      return "RESET";
    case avc::build_command_t::ACTION_INCREASE_RESOLUTION:
      return "INCREASE_RESOLUTION";
    case avc::build_command_t::ACTION_RUN_MVS:
      return "RUN_MVS";
    default:
      return "unknown";
  }
}

// Forgets `id` from a bounded waiting list's arrival order.
void Forget(std::deque<std::string>& order, const std::string& id) {
  const auto it = std::find(order.begin(), order.end(), id);
  if (it != order.end()) order.erase(it);
}

}  // namespace

struct BuilderNode::MvsOutcome {
  std::string request_id;
  std::string cloud_id;
  std::vector<std::string> image_ids;  // sorted: what the points' view indices refer to
  mvs::MvsPoints points;
  std::string error;  // empty on success
};

std::string BuilderNodeOptions::Validate() const {
  if (service.empty()) return "service name is empty";
  if (views_for_bounds < 2) {
    return fmt::format("views_for_bounds is {}; the automatic box needs at least 2 views",
                       views_for_bounds);
  }
  if (box && (box->isEmpty() || !box->min().allFinite() || !box->max().allFinite() ||
              (box->sizes().array() <= 0).any())) {
    return "the proxy box is empty or not finite";
  }
  if (max_unmatched == 0) return "max_unmatched must be at least 1";
  if (reconstruct.method == MvsMethod::kNone) return "the default MVS method cannot be 'none'";
  FirstProblem problem;
  problem.Include(reconstruct.Validate());
  problem.Include(products.Validate());
  return problem.text();
}

BuilderNode::BuilderNode(bus::Bus& bus, bus::EventLoop& loop, bus::HeartbeatPublisher& heartbeat,
                         BuilderNodeOptions options)
    : bus_(bus),
      loop_(loop),
      heartbeat_(heartbeat),
      options_(std::move(options)),
      scan_id_(options_.scan_id.empty() ? "scan" : options_.scan_id),
      acks_(bus, options_.service),
      sender_(bus, loop, options_.products) {
  if (const std::string problem = options_.Validate(); !problem.empty()) {
    throw std::invalid_argument(options_.service + ": " + problem);
  }
  if (!options_.output_dir.empty()) std::filesystem::create_directories(options_.output_dir);
  subscriptions_.push_back(bus_.Subscribe<avc::camera_t>(
      channels::kCamera,
      [this](const avc::camera_t& camera, const bus::RxInfo&) { OnCamera(camera); }));
  subscriptions_.push_back(bus_.Subscribe<avc::build_command_t>(
      channels::kBuildCommand,
      [this](const avc::build_command_t& command, const bus::RxInfo&) { OnCommand(command); }));
  receiver_ = std::make_unique<products::ProductReceiver>(
      bus_, options_.service, std::string(channels::kProductImage),
      [this](const products::Product& product, const bus::RxInfo&) { OnImageProduct(product); });
  UpdateHeartbeat();
}

BuilderNode::~BuilderNode() {
  receiver_.reset();
  for (const auto id : subscriptions_) bus_.Unsubscribe(id);
  if (worker_.joinable()) {
    *mvs_cancel_ = true;
    worker_.join();
    acks_.Send(mvs_request_, avc::ack_t::STATUS_FAILED,
               options_.service + " stopped before the MVS run finished");
  }
  for (const std::string& request_id : mvs_sending_) {
    acks_.Send(request_id, avc::ack_t::STATUS_FAILED,
               options_.service + " stopped before its MVS points were acknowledged");
  }
}

void BuilderNode::PostToLoop(std::function<void()> fn) {
  loop_.Post([alive = std::weak_ptr<int>(alive_), fn = std::move(fn)] {
    if (!alive.expired()) fn();
  });
}

// ---- Inputs ------------------------------------------------------------------------------------

void BuilderNode::OnImageProduct(const products::Product& product) {
  if (product.content_type != products::ContentTypeOf<avc::image_t>()) {
    log::Warn("product '{}' on {} is {}, not an image; ignored", product.name,
              channels::kProductImage, product.content_type);
    return;
  }
  avc::image_t message;
  if (message.decode(product.payload.data(), 0, static_cast<int>(product.payload.size())) < 0) {
    log::Warn("product '{}' does not decode as image_t; ignored", product.name);
    return;
  }
  const std::string& id = message.image_id;
  if (id.empty()) {
    log::Warn("image product '{}' has no image_id; ignored", product.name);
    return;
  }
  if (views_.count(id) != 0) {
    log::Warn("image '{}' is already integrated; the new copy is ignored (RESET starts a new scan)",
              id);
    return;
  }
  cv::Mat image;
  try {
    image = DecodeImage(message);
  } catch (const std::exception& error) {
    log::Warn("{}; ignored", error.what());
    return;
  }
  if (unmatched_images_.count(id) == 0) image_order_.push_back(id);
  unmatched_images_[id] = std::move(image);
  while (unmatched_images_.size() > options_.max_unmatched) {
    const std::string oldest = image_order_.front();
    image_order_.pop_front();
    unmatched_images_.erase(oldest);
    log::Warn("image '{}' dropped: no camera came for it while {} newer images waited", oldest,
              options_.max_unmatched);
  }
  TryIntegrate(id);
}

void BuilderNode::OnCamera(const avc::camera_t& message) {
  const std::string& id = message.image_id;
  if (id.empty() || views_.count(id) != 0) return;
  camera::Camera camera;
  try {
    camera = messages::CameraFromMessage(message);
  } catch (const std::exception& error) {
    log::Warn("{}; ignored", error.what());
    return;
  }
  if (unmatched_cameras_.count(id) == 0) camera_order_.push_back(id);
  unmatched_cameras_[id] = camera;
  // Cameras answering queries (no image ever follows) end here: dropping them is routine.
  while (unmatched_cameras_.size() > options_.max_unmatched) {
    unmatched_cameras_.erase(camera_order_.front());
    camera_order_.pop_front();
  }
  TryIntegrate(id);
}

void BuilderNode::TryIntegrate(const std::string& image_id) {
  const auto image = unmatched_images_.find(image_id);
  const auto camera = unmatched_cameras_.find(image_id);
  if (image == unmatched_images_.end() || camera == unmatched_cameras_.end()) return;
  cv::Mat pixels = std::move(image->second);
  const camera::Camera pose = camera->second;
  unmatched_images_.erase(image);
  unmatched_cameras_.erase(camera);
  Forget(image_order_, image_id);
  Forget(camera_order_, image_id);
  Integrate(image_id, std::move(pixels), pose);
  UpdateHeartbeat();
}

void BuilderNode::Integrate(const std::string& image_id, cv::Mat image,
                            const camera::Camera& camera) {
  if (camera.intrinsics.width != image.cols || camera.intrinsics.height != image.rows) {
    log::Warn("image '{}' is {}x{} but its camera is {}x{}; ignored", image_id, image.cols,
              image.rows, camera.intrinsics.width, camera.intrinsics.height);
    return;
  }
  // The same steps, in the same order, as builder::Reconstruct: undistort, then mask.
  dataset::View view{image_id, camera, std::move(image), cv::Mat()};
  try {
    dataset::Undistort(view);
    view.mask = segmentation::SegmentPlant(view.image, options_.reconstruct.masks).mask;
  } catch (const std::exception& error) {
    log::Warn("image '{}': {}; ignored", image_id, error.what());
    return;
  }
  if (cv::countNonZero(view.mask) == 0) {
    log::Warn("no plant found in image '{}': it votes background everywhere it sees", image_id);
  }
  if (proxy_) {
    try {
      proxy_->AddView(view);
    } catch (const std::exception& error) {
      log::Warn("image '{}' not carved: {}", image_id, error.what());
      return;
    }
  }
  views_[image_id] = std::move(view);
  arrival_.push_back(image_id);
  if (proxy_) {
    PublishVoxelMap();
  } else {
    CreateProxyIfReady();
  }
}

void BuilderNode::CreateProxyIfReady() {
  if (proxy_) return;
  const size_t needed = options_.box ? 1 : static_cast<size_t>(options_.views_for_bounds);
  if (arrival_.size() < needed) return;
  Eigen::AlignedBox3d box;
  if (options_.box) {
    box = *options_.box;
  } else {
    // The first views_for_bounds views; when they cannot bound the plant, each later attempt
    // uses every view so far.
    std::vector<dataset::View> first;
    for (const std::string& id : arrival_) first.push_back(views_.at(id));
    try {
      box = ppr::BoundsFromViews(first);
    } catch (const std::exception& error) {
      proxy_problem_ = error.what();
      log::Warn("no proxy box from {} views yet: {}", first.size(), error.what());
      return;
    }
  }
  try {
    proxy_.emplace(box, options_.reconstruct.proxy);
  } catch (const std::exception& error) {
    proxy_problem_ = error.what();
    log::Warn("cannot create the proxy: {}", error.what());
    return;
  }
  proxy_problem_.clear();
  log::Info(
      "proxy box [{:.3f} {:.3f} {:.3f}] .. [{:.3f} {:.3f} {:.3f}] m from {} views, voxel {:.4f} m",
      box.min().x(), box.min().y(), box.min().z(), box.max().x(), box.max().y(), box.max().z(),
      arrival_.size(), proxy_->voxel_size());
  std::vector<std::string> carved;
  for (const std::string& id : arrival_) {
    try {
      proxy_->AddView(views_.at(id));
      carved.push_back(id);
    } catch (const std::exception& error) {
      log::Warn("image '{}' not carved: {}", id, error.what());
      views_.erase(id);
    }
  }
  arrival_ = std::move(carved);
  PublishVoxelMap();
}

// ---- Voxel map ---------------------------------------------------------------------------------

void BuilderNode::PublishVoxelMap() {
  if (!proxy_) return;
  if (!options_.output_dir.empty()) {
    try {
      proxy_->WriteBinary(options_.output_dir / "ppr.bt");
    } catch (const std::exception& error) {
      log::Warn("cannot write the proxy: {}", error.what());
    }
  }
  // One map in flight at a time; the newest waits behind it and older ones are never sent.
  if (voxel_map_in_flight_) {
    voxel_map_stale_ = true;
    return;
  }
  SendLatestVoxelMap();
}

void BuilderNode::SendLatestVoxelMap() {
  avc::voxel_map_t map{};
  map.map_id = fmt::format("{}-ppr-{:04}", scan_id_, voxel_maps_published_ + 1);
  map.frame = "world";
  map.resolution = proxy_->voxel_size();
  map.views_integrated = proxy_->view_count();
  map.encoding = avc::voxel_map_t::ENCODING_OCTOMAP_BT;
  const std::string bytes = proxy_->BinaryBytes();
  map.data.assign(bytes.begin(), bytes.end());
  map.data_size = static_cast<int32_t>(map.data.size());
  ++voxel_maps_published_;
  voxel_map_in_flight_ = true;
  voxel_map_stale_ = false;
  sender_.SendMessage(channels::kProductVoxelMap, "ppr/" + map.map_id + ".bt", map,
                      [this](const products::SendResult& result) {
                        voxel_map_in_flight_ = false;
                        if (!result.ok) log::Warn("voxel map not delivered: {}", result.error);
                        if (voxel_map_stale_ && proxy_) SendLatestVoxelMap();
                      });
}

// ---- Commands ----------------------------------------------------------------------------------

void BuilderNode::OnCommand(const avc::build_command_t& command) {
  if (acks_.Repeat(command.request_id)) return;
  try {
    if (command.request_id.empty()) throw std::invalid_argument("empty request_id");
    switch (command.action) {
      case avc::build_command_t::ACTION_RESET:
        Reset(command);
        break;
      case avc::build_command_t::ACTION_INCREASE_RESOLUTION:
        IncreaseResolution(command);
        break;
      case avc::build_command_t::ACTION_RUN_MVS:
        StartMvs(command);
        break;
      default:
        throw std::invalid_argument(fmt::format(
            "unknown action {} (RESET {}, INCREASE_RESOLUTION {}, RUN_MVS {})", command.action,
            avc::build_command_t::ACTION_RESET, avc::build_command_t::ACTION_INCREASE_RESOLUTION,
            avc::build_command_t::ACTION_RUN_MVS));
    }
  } catch (const std::exception& error) {
    log::Warn("build command '{}' ({}) refused: {}", command.request_id, ActionName(command.action),
              error.what());
    acks_.Send(command.request_id, avc::ack_t::STATUS_REFUSED, error.what());
  }
  UpdateHeartbeat();
}

void BuilderNode::Reset(const avc::build_command_t& command) {
  if (worker_.joinable()) {
    throw std::invalid_argument(
        fmt::format("MVS request '{}' is running; RESET after it finishes", mvs_request_));
  }
  unmatched_images_.clear();
  image_order_.clear();
  unmatched_cameras_.clear();
  camera_order_.clear();
  views_.clear();
  arrival_.clear();
  proxy_.reset();
  proxy_problem_.clear();
  voxel_map_stale_ = false;
  if (!command.scan_id.empty()) scan_id_ = command.scan_id;
  log::Info("reset: scan '{}' starts with no views", scan_id_);
  acks_.Send(command.request_id, avc::ack_t::STATUS_DONE,
             fmt::format("scan '{}' starts with no views", scan_id_));
}

void BuilderNode::IncreaseResolution(const avc::build_command_t& command) {
  if (!proxy_) {
    throw std::invalid_argument(
        fmt::format("no proxy yet ({} of {} views for its box integrated{}{})", views_.size(),
                    options_.views_for_bounds, proxy_problem_.empty() ? "" : "; ", proxy_problem_));
  }
  acks_.Send(command.request_id, avc::ack_t::STATUS_ACCEPTED, "carving at half the voxel size");
  proxy_->IncreaseResolution();
  PublishVoxelMap();
  acks_.Send(command.request_id, avc::ack_t::STATUS_DONE,
             fmt::format("voxel size now {:.5f} m over {} views", proxy_->voxel_size(),
                         proxy_->view_count()));
}

void BuilderNode::StartMvs(const avc::build_command_t& command) {
  if (worker_.joinable()) {
    throw std::invalid_argument(fmt::format("MVS request '{}' is still running", mvs_request_));
  }
  const MvsMethod method =
      command.method.empty() ? options_.reconstruct.method : ParseMvsMethod(command.method);
  if (method == MvsMethod::kNone) throw std::invalid_argument("method 'none' makes no points");
  std::set<std::string> chosen(command.image_ids.begin(), command.image_ids.end());
  if (chosen.empty()) {
    for (const auto& [id, view] : views_) chosen.insert(id);
  }
  std::vector<std::string> unknown;
  for (const std::string& id : chosen) {
    if (views_.count(id) == 0) unknown.push_back(id);
  }
  if (!unknown.empty()) {
    throw std::invalid_argument(
        fmt::format("image(s) {} not integrated", fmt::join(unknown, ", ")));
  }
  if (chosen.size() < 2) {
    throw std::invalid_argument(
        fmt::format("MVS needs at least 2 integrated views, {} chosen", chosen.size()));
  }

  // Sorted by image_id (std::set), so the result does not depend on arrival order.
  dataset::ViewSet set;
  set.format = "live";
  MvsOutcome outcome;
  outcome.request_id = command.request_id;
  outcome.cloud_id = fmt::format("{}-mvs-{}", command.scan_id.empty() ? scan_id_ : command.scan_id,
                                 command.request_id);
  for (const std::string& id : chosen) {
    set.views.push_back(views_.at(id));
    outcome.image_ids.push_back(id);
  }
  ReconstructOptions reconstruct = options_.reconstruct;
  reconstruct.method = method;

  acks_.Send(command.request_id, avc::ack_t::STATUS_ACCEPTED,
             fmt::format("{} MVS over {} views", MvsMethodName(method), set.views.size()));
  log::Info("MVS request '{}': {} over {} views", command.request_id, MvsMethodName(method),
            set.views.size());
  mvs_request_ = command.request_id;
  mvs_progress_ = "starting";
  mvs_cancel_ = std::make_shared<std::atomic<bool>>(false);
  worker_ = std::thread([this, set = std::move(set), reconstruct, outcome = std::move(outcome),
                         cancel = mvs_cancel_]() mutable {
    struct Gate {
      std::mutex mutex;
      std::string stage;
      std::chrono::steady_clock::time_point last;
    } gate;
    // May be called from TBB threads (plane sweep): serialised, and thinned out.
    const ReconstructProgress progress = [&](const std::string& stage, size_t done, size_t total) {
      if (*cancel) throw MvsCancelled{};
      const std::lock_guard<std::mutex> lock(gate.mutex);
      const auto now = std::chrono::steady_clock::now();
      if (stage == gate.stage && done != total && now - gate.last < kProgressPeriod) return;
      gate.stage = stage;
      gate.last = now;
      PostToLoop([this, stage, done, total] { OnMvsProgress(stage, done, total); });
    };
    try {
      outcome.points = Reconstruct(set, reconstruct, progress).points;
    } catch (const MvsCancelled&) {
      outcome.error = "cancelled";
    } catch (const std::exception& error) {
      outcome.error = error.what();
    }
    PostToLoop(
        [this, outcome = std::move(outcome)]() mutable { OnMvsFinished(std::move(outcome)); });
  });
}

void BuilderNode::OnMvsProgress(const std::string& stage, size_t done, size_t total) {
  if (!worker_.joinable()) return;
  mvs_progress_ = fmt::format("{} {}/{}", stage, done, total);
  avc::progress_t progress{};
  progress.task = "mvs";
  progress.phase = stage;
  progress.done = static_cast<int32_t>(done);
  progress.total = static_cast<int32_t>(total);
  progress.fraction = total > 0 ? static_cast<double>(done) / static_cast<double>(total) : 0;
  progress.eta_us = -1;
  progress.detail = mvs_request_;
  bus_.Publish(channels::kProgress, progress);
  UpdateHeartbeat();
}

void BuilderNode::OnMvsFinished(MvsOutcome outcome) {
  JoinWorker();
  const std::string request_id = outcome.request_id;
  if (outcome.error.empty()) {
    try {
      const avc::mvs_points_t message =
          messages::MvsPointsToMessage(outcome.points, outcome.image_ids, outcome.cloud_id);
      if (!options_.output_dir.empty()) {
        // The product is what matters; a local copy that cannot be written is only reported.
        try {
          mvs::WriteMvsPointsPly(options_.output_dir / ("mvs_" + outcome.cloud_id + ".ply"),
                                 outcome.points);
        } catch (const std::exception& error) {
          log::Warn("MVS request '{}': {}", request_id, error.what());
        }
      }
      const size_t count = outcome.points.size();
      log::Info("MVS request '{}': {} points; sending {}", request_id, count, outcome.cloud_id);
      mvs_sending_.insert(request_id);
      sender_.SendMessage(channels::kProductMvsPoints, "mvs/" + outcome.cloud_id, message,
                          [this, request_id, count,
                           cloud_id = outcome.cloud_id](const products::SendResult& result) {
                            mvs_sending_.erase(request_id);
                            if (result.ok) {
                              acks_.Send(request_id, avc::ack_t::STATUS_DONE,
                                         fmt::format("{} points on {} as '{}'", count,
                                                     channels::kProductMvsPoints, cloud_id));
                            } else {
                              acks_.Send(request_id, avc::ack_t::STATUS_FAILED, result.error);
                            }
                          });
    } catch (const std::exception& error) {
      outcome.error = error.what();
    }
  }
  if (!outcome.error.empty()) {
    log::Warn("MVS request '{}' failed: {}", request_id, outcome.error);
    acks_.Send(request_id, avc::ack_t::STATUS_FAILED, outcome.error);
  }
  mvs_request_.clear();
  mvs_progress_.clear();
  UpdateHeartbeat();
}

void BuilderNode::JoinWorker() {
  if (worker_.joinable()) worker_.join();
}

void BuilderNode::UpdateHeartbeat() {
  std::string views;
  if (proxy_) {
    views = fmt::format("{} views integrated, proxy voxel {:.1f} mm", views_.size(),
                        1000 * proxy_->voxel_size());
  } else {
    views = fmt::format("{} views, the proxy's box waits for {}{}{}", views_.size(),
                        options_.box ? 1 : options_.views_for_bounds,
                        proxy_problem_.empty() ? "" : ": ", proxy_problem_);
  }
  if (worker_.joinable()) {
    heartbeat_.Set(bus::ServiceState::kBusy,
                   fmt::format("MVS '{}': {}; {}", mvs_request_, mvs_progress_, views));
  } else {
    heartbeat_.Set(bus::ServiceState::kReady, views);
  }
}

}  // namespace avc::builder
