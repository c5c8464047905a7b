// avc-builder's node on an in-process bus with a small simulated scan: the proxy grows and is
// published as each image meets its camera (in either order, in any arrival order), bad images,
// cameras and commands are answered without stopping it, and RUN_MVS publishes exactly the
// points the offline builder::Reconstruct makes from the same images.

#include "services/builder/builder_node.h"

#include <gtest/gtest.h>
#include <octomap/OcTree.h>

#include <algorithm>
#include <avc/ack_t.hpp>
#include <avc/heartbeat_t.hpp>
#include <avc/image_t.hpp>
#include <avc/mvs_points_t.hpp>
#include <avc/voxel_map_t.hpp>
#include <sstream>

#include "core/bus/channels.h"
#include "core/dataset/dataset_reader.h"
#include "core/messages/camera_message.h"
#include "core/messages/mvs_points_message.h"
#include "core/products/product_receiver.h"
#include "core/products/product_sender.h"
#include "sim/dataset/render_dataset.h"
#include "tests/support/test_support.h"

namespace avc::builder {
namespace {

namespace fs = std::filesystem;
using std::chrono::milliseconds;

// 8 views of the broad-leaf plant at 320x240 on two rings: enough for three views per surface
// point, small enough that two MVS runs take seconds.
const fs::path& Scan() {
  static testing::TempDir dir("avc-builder-node");
  static const fs::path scan = [] {
    sim::RenderDatasetOptions options;
    options.preset = sim::PlantPreset::kBroadleaf;
    options.views = 8;
    options.rings = 2;
    options.width = 320;
    options.height = 240;
    options.output = dir / "scan";
    sim::RenderDataset(options);
    return options.output;
  }();
  return scan;
}

std::string IdOf(const dataset::View& view) { return fs::path(view.name).stem().string(); }

avc::image_t ImageMessage(const std::string& id, const std::string& png, int width, int height) {
  avc::image_t image{};
  image.image_id = id;
  image.camera_id = "cam0";
  image.width = width;
  image.height = height;
  image.pixel_format = avc::image_t::PIXEL_BGR8;
  image.encoding = avc::image_t::ENCODING_PNG;
  image.data.assign(png.begin(), png.end());
  image.size = static_cast<int32_t>(image.data.size());
  return image;
}

avc::image_t ImageMessage(const dataset::View& view) {
  return ImageMessage(IdOf(view), testing::ReadFile(Scan() / "images" / view.name), view.image.cols,
                      view.image.rows);
}

avc::camera_t CameraMessage(const std::string& id, const camera::Camera& camera) {
  return messages::CameraToMessage(camera, id, "cam0");
}

template <class T>
T Decode(const products::Product& product) {
  T message;
  EXPECT_GE(message.decode(product.payload.data(), 0, static_cast<int>(product.payload.size())), 0);
  return message;
}

void ExpectSamePoints(const mvs::MvsPoints& bus, const mvs::MvsPoints& offline) {
  ASSERT_EQ(bus.size(), offline.size());
  for (size_t i = 0; i < offline.size(); ++i) {
    ASSERT_EQ(bus.cloud.positions[i], offline.cloud.positions[i]) << i;
    ASSERT_EQ(bus.cloud.normals[i], offline.cloud.normals[i]) << i;
    ASSERT_EQ(bus.cloud.colors[i], offline.cloud.colors[i]) << i;
    ASSERT_EQ(bus.confidence[i], offline.confidence[i]) << i;
    ASSERT_EQ(bus.views[i], offline.views[i]) << i;
  }
}

struct Harness {
  explicit Harness(BuilderNodeOptions options = {})
      : bus(bus::InProcessBusOptions()),
        heartbeat(bus, loop, "avc-builder", milliseconds(50)),
        sender(bus, loop),
        receiver(bus, "test-receiver", "PRODUCT/(VOXEL_MAP|MVS_POINTS)",
                 [this](const products::Product& product, const bus::RxInfo& info) {
                   if (info.channel.ends_with("VOXEL_MAP")) {
                     voxel_maps.push_back(Decode<avc::voxel_map_t>(product));
                   } else {
                     mvs_points.push_back(Decode<avc::mvs_points_t>(product));
                   }
                 }) {
    bus.AttachTo(loop);
    bus.Subscribe<avc::ack_t>(channels::kAck, [this](const avc::ack_t& ack, const bus::RxInfo&) {
      if (ack.service == "avc-builder") acks.push_back(ack);
    });
    bus.Subscribe<avc::heartbeat_t>(channels::kHeartbeat,
                                    [this](const avc::heartbeat_t& beat, const bus::RxInfo&) {
                                      if (beat.state == avc::heartbeat_t::STATE_BUSY) {
                                        busy_details.push_back(beat.detail);
                                      }
                                    });
    node = std::make_unique<BuilderNode>(bus, loop, heartbeat, options);
  }

  void SendImage(const avc::image_t& image) {
    sender.SendMessage(channels::kProductImage, "images/" + image.image_id + ".png", image);
  }
  void SendCamera(avc::camera_t camera) { bus.Publish(channels::kCamera, camera); }
  void Command(const std::string& request_id, int8_t action,
               const std::vector<std::string>& image_ids = {}, const std::string& method = "") {
    avc::build_command_t command{};
    command.request_id = request_id;
    command.scan_id = "plant1";
    command.action = action;
    command.method = method;
    command.image_ids = image_ids;
    command.num_image_ids = static_cast<int32_t>(image_ids.size());
    bus.Publish(channels::kBuildCommand, command);
  }
  void Settle(milliseconds time = milliseconds(50)) {
    loop.RunUntil([] { return false; }, time);
  }
  bool WaitFor(const std::function<bool()>& done, milliseconds timeout = milliseconds(10000)) {
    return loop.RunUntil(done, timeout);
  }
  // The last answer other than ACCEPTED.
  std::optional<avc::ack_t> Final(const std::string& id) const {
    std::optional<avc::ack_t> last;
    for (const auto& ack : acks) {
      if (ack.request_id == id && ack.status != avc::ack_t::STATUS_ACCEPTED) last = ack;
    }
    return last;
  }
  // Runs the loop until every request has its final answer (the node answers asynchronously, and
  // a loaded machine can take far longer than any fixed pause).
  bool WaitForAnswers(const std::vector<std::string>& ids,
                      milliseconds timeout = milliseconds(10000)) {
    return WaitFor(
        [&] {
          return std::ranges::all_of(ids,
                                     [&](const std::string& id) { return Final(id).has_value(); });
        },
        timeout);
  }
  int Count(const std::string& id, int8_t status) const {
    int count = 0;
    for (const auto& ack : acks) count += ack.request_id == id && ack.status == status;
    return count;
  }
  // Feeds the views, half with the camera first, in the order given.
  void Feed(const dataset::ViewSet& set, const std::vector<size_t>& order) {
    for (size_t n = 0; n < order.size(); ++n) {
      const dataset::View& view = set.views[order[n]];
      if (n % 2 == 0) SendCamera(CameraMessage(IdOf(view), view.camera));
      SendImage(ImageMessage(view));
      Settle(milliseconds(20));
      if (n % 2 == 1) SendCamera(CameraMessage(IdOf(view), view.camera));
    }
  }

  bus::Bus bus;
  bus::EventLoop loop;
  bus::HeartbeatPublisher heartbeat;
  products::ProductSender sender;
  products::ProductReceiver receiver;
  std::unique_ptr<BuilderNode> node;
  std::vector<avc::ack_t> acks;
  std::vector<avc::voxel_map_t> voxel_maps;
  std::vector<avc::mvs_points_t> mvs_points;
  std::vector<std::string> busy_details;
};

std::string RefusalOf(const Harness& h, const std::string& id) {
  const auto ack = h.Final(id);
  if (!ack) return "<no answer>";
  if (ack->status != avc::ack_t::STATUS_REFUSED) return "<not refused: " + ack->reason + ">";
  return ack->reason;
}

TEST(BuilderNode, GrowsTheProxyAsViewsArriveAndRunsMvsLikeTheOfflineBuild) {
  const dataset::ViewSet set = dataset::ReadDataset(Scan());
  ASSERT_EQ(set.views.size(), 8u);
  Harness h;

  // Bad inputs first: each is logged and dropped, none stops the node.
  const dataset::View& first = set.views[0];
  avc::image_t corrupt = ImageMessage("corrupt", std::string(4000, 'x'), 320, 240);
  h.SendImage(corrupt);
  h.SendCamera(CameraMessage("corrupt", first.camera));
  avc::camera_t nan_camera = CameraMessage("nan_camera", first.camera);
  nan_camera.fx = std::nan("");
  h.SendCamera(nan_camera);
  h.SendImage(
      ImageMessage("nan_camera", testing::ReadFile(Scan() / "images" / first.name), 320, 240));
  camera::Camera small = first.camera;
  small.intrinsics.width = 160;
  small.intrinsics.height = 120;
  h.SendCamera(CameraMessage("wrong_size", small));
  h.SendImage(
      ImageMessage("wrong_size", testing::ReadFile(Scan() / "images" / first.name), 320, 240));
  h.Settle(milliseconds(200));
  EXPECT_EQ(h.node->views_integrated(), 0);

  // The good views in a scrambled arrival order.
  h.Feed(set, {5, 2, 7, 0, 3, 6, 1, 4});
  ASSERT_TRUE(h.WaitFor([&] {
    return !h.voxel_maps.empty() && h.voxel_maps.back().views_integrated == 8;
  })) << h.voxel_maps.size()
      << " voxel maps, node has " << h.node->views_integrated();
  EXPECT_EQ(h.node->views_integrated(), 8);
  // Created once views_for_bounds (3) views were in, then one more view each time (maps made
  // while one was in flight may be skipped, never reordered).
  EXPECT_EQ(h.voxel_maps.front().views_integrated, 3);
  for (size_t i = 1; i < h.voxel_maps.size(); ++i) {
    EXPECT_GT(h.voxel_maps[i].views_integrated, h.voxel_maps[i - 1].views_integrated);
  }
  const avc::voxel_map_t& map = h.voxel_maps.back();
  EXPECT_EQ(map.encoding, avc::voxel_map_t::ENCODING_OCTOMAP_BT);
  EXPECT_EQ(map.frame, "world");
  EXPECT_EQ(map.resolution, h.node->proxy().voxel_size());
  EXPECT_EQ(std::string(map.data.begin(), map.data.end()), h.node->proxy().BinaryBytes());
  std::istringstream stream(std::string(map.data.begin(), map.data.end()));
  octomap::OcTree tree(0.1);
  ASSERT_TRUE(tree.readBinary(stream));
  // .bt stores the resolution as text with 6 significant digits.
  EXPECT_NEAR(tree.getResolution(), map.resolution, 1e-6 * map.resolution);
  // OctoMap prunes 8 occupied children into their parent: count voxels by volume.
  uint64_t occupied_voxels = 0;
  for (auto it = tree.begin_leafs(); it != tree.end_leafs(); ++it) {
    if (tree.isNodeOccupied(*it)) {
      occupied_voxels += uint64_t{1} << (3 * (tree.getTreeDepth() - it.getDepth()));
    }
  }
  EXPECT_GT(occupied_voxels, 1000u);
  EXPECT_EQ(h.node->proxy().Counts().occupied, occupied_voxels);

  // MVS over every integrated view (sorted by image_id), compared with the offline build.
  h.Command("mvs-1", avc::build_command_t::ACTION_RUN_MVS, {}, "plane-sweep");
  h.Command("reset-while-busy", avc::build_command_t::ACTION_RESET);
  ASSERT_TRUE(h.WaitFor([&] { return h.Final("mvs-1").has_value(); }, milliseconds(60000)));
  EXPECT_EQ(h.Final("mvs-1")->status, avc::ack_t::STATUS_DONE) << h.Final("mvs-1")->reason;
  EXPECT_EQ(h.Count("mvs-1", avc::ack_t::STATUS_ACCEPTED), 1);
  EXPECT_NE(RefusalOf(h, "reset-while-busy").find("'mvs-1' is running"), std::string::npos);
  ASSERT_EQ(h.mvs_points.size(), 1u);
  EXPECT_FALSE(h.busy_details.empty());
  EXPECT_NE(h.busy_details.back().find("MVS 'mvs-1'"), std::string::npos);

  const messages::MvsPointsMessageContent bus = messages::MvsPointsFromMessage(h.mvs_points[0]);
  EXPECT_EQ(h.mvs_points[0].cloud_id, "plant1-mvs-mvs-1");
  std::vector<std::string> sorted_ids;
  for (const dataset::View& view : set.views) sorted_ids.push_back(IdOf(view));
  EXPECT_EQ(bus.image_ids, sorted_ids);
  dataset::ViewSet offline_set = dataset::ReadDataset(Scan());
  ReconstructOptions offline_options;
  offline_options.method = MvsMethod::kPlaneSweep;
  const Reconstruction offline = Reconstruct(offline_set, offline_options);
  ASSERT_GT(offline.points.size(), 500u);
  ExpectSamePoints(bus.points, offline.points);

  // The default method (patch) over chosen images, listed in any order: the offline build of
  // those images in image_id order.
  h.Command("mvs-2", avc::build_command_t::ACTION_RUN_MVS,
            {"view_0006", "view_0001", "view_0004", "view_0003", "view_0000"});
  ASSERT_TRUE(h.WaitFor([&] { return h.Final("mvs-2").has_value(); }, milliseconds(60000)));
  EXPECT_EQ(h.Final("mvs-2")->status, avc::ack_t::STATUS_DONE) << h.Final("mvs-2")->reason;
  ASSERT_EQ(h.mvs_points.size(), 2u);
  const messages::MvsPointsMessageContent chosen = messages::MvsPointsFromMessage(h.mvs_points[1]);
  EXPECT_EQ(chosen.image_ids, (std::vector<std::string>{"view_0000", "view_0001", "view_0003",
                                                        "view_0004", "view_0006"}));
  dataset::ViewSet chosen_set = dataset::ReadDataset(Scan());
  std::erase_if(chosen_set.views, [](const dataset::View& view) {
    const std::string id = IdOf(view);
    return id == "view_0002" || id == "view_0005" || id == "view_0007";
  });
  const Reconstruction chosen_offline = Reconstruct(chosen_set, {});
  // Enough points for the comparison to mean something (the patch back end's own tests judge
  // how many it should find; 5 views of 320x240 give 28 today).
  EXPECT_GT(chosen_offline.points.size(), 20u);
  ExpectSamePoints(chosen.points, chosen_offline.points);

  // A repeated request gets its answer again and runs nothing.
  const size_t acks_before = h.acks.size();
  h.Command("mvs-1", avc::build_command_t::ACTION_RUN_MVS);
  ASSERT_TRUE(h.WaitFor([&] { return h.acks.size() > acks_before; }));
  h.Settle(milliseconds(200));  // room for a second answer or a run, which must not come
  EXPECT_FALSE(h.node->mvs_running());
  ASSERT_EQ(h.acks.size(), acks_before + 1);
  EXPECT_EQ(h.acks.back().status, avc::ack_t::STATUS_DONE);
  EXPECT_EQ(h.mvs_points.size(), 2u);

  // INCREASE_RESOLUTION halves the voxels and republishes.
  const double voxel = h.node->proxy().voxel_size();
  h.Command("finer", avc::build_command_t::ACTION_INCREASE_RESOLUTION);
  ASSERT_TRUE(h.WaitFor([&] { return h.voxel_maps.back().resolution < voxel; }));
  EXPECT_EQ(h.Final("finer")->status, avc::ack_t::STATUS_DONE);
  EXPECT_NEAR(h.voxel_maps.back().resolution, voxel / 2, 1e-12);
  EXPECT_EQ(h.voxel_maps.back().views_integrated, 8);

  // RESET starts a new scan: the same images are welcome again.
  h.Command("reset", avc::build_command_t::ACTION_RESET);
  ASSERT_TRUE(h.WaitForAnswers({"reset"}));
  EXPECT_EQ(h.Final("reset")->status, avc::ack_t::STATUS_DONE);
  EXPECT_EQ(h.node->views_integrated(), 0);
  EXPECT_FALSE(h.node->has_proxy());
  h.Feed(set, {1, 0});
  ASSERT_TRUE(h.WaitFor([&] { return h.node->views_integrated() == 2; }));
}

TEST(BuilderNode, RefusesBadCommandsNamingWhatIsWrong) {
  const dataset::ViewSet set = dataset::ReadDataset(Scan());
  Harness h;
  h.Feed(set, {0, 1});
  ASSERT_TRUE(h.WaitFor([&] { return h.node->views_integrated() == 2; }));
  EXPECT_FALSE(h.node->has_proxy());  // 2 of 3 views for the box

  h.Command("finer", avc::build_command_t::ACTION_INCREASE_RESOLUTION);
  h.Command("one-view", avc::build_command_t::ACTION_RUN_MVS, {"view_0001"});
  h.Command("unknown-ids", avc::build_command_t::ACTION_RUN_MVS,
            {"view_0000", "view_0099", "nope"});
  h.Command("bad-method", avc::build_command_t::ACTION_RUN_MVS, {}, "pmvs");
  h.Command("none-method", avc::build_command_t::ACTION_RUN_MVS, {}, "none");
  h.Command("bad-action", 7);
  h.Command("", avc::build_command_t::ACTION_RESET);
  ASSERT_TRUE(h.WaitForAnswers(
      {"finer", "one-view", "unknown-ids", "bad-method", "none-method", "bad-action", ""}));
  EXPECT_NE(RefusalOf(h, "finer").find("no proxy yet (2 of 3 views"), std::string::npos)
      << RefusalOf(h, "finer");
  EXPECT_NE(RefusalOf(h, "one-view").find("at least 2 integrated views, 1 chosen"),
            std::string::npos)
      << RefusalOf(h, "one-view");
  EXPECT_NE(RefusalOf(h, "unknown-ids").find("image(s) nope, view_0099 not integrated"),
            std::string::npos)
      << RefusalOf(h, "unknown-ids");
  EXPECT_NE(RefusalOf(h, "bad-method").find("unknown MVS method 'pmvs'"), std::string::npos);
  EXPECT_NE(RefusalOf(h, "none-method").find("'none' makes no points"), std::string::npos);
  EXPECT_NE(RefusalOf(h, "bad-action").find("unknown action 7"), std::string::npos);
  EXPECT_NE(RefusalOf(h, "").find("empty request_id"), std::string::npos);
  EXPECT_FALSE(h.node->mvs_running());
  EXPECT_EQ(h.node->views_integrated(), 2);  // nothing was reset by the refused commands
  EXPECT_TRUE(h.mvs_points.empty());
}

TEST(BuilderNode, ABoxOverrideStartsTheProxyAtTheFirstView) {
  const dataset::ViewSet set = dataset::ReadDataset(Scan());
  BuilderNodeOptions options;
  options.box =
      Eigen::AlignedBox3d(Eigen::Vector3d(-0.2, -0.2, -0.05), Eigen::Vector3d(0.2, 0.2, 0.35));
  testing::TempDir output("avc-builder-output");
  options.output_dir = output.path();
  Harness h(options);
  h.Feed(set, {4});
  ASSERT_TRUE(h.WaitFor([&] { return !h.voxel_maps.empty(); }));
  EXPECT_EQ(h.voxel_maps[0].views_integrated, 1);
  EXPECT_TRUE(h.node->proxy().box().contains(*options.box));
  EXPECT_EQ(testing::ReadFile(output / "ppr.bt"), h.node->proxy().BinaryBytes());

  options.views_for_bounds = 1;
  EXPECT_THROW(BuilderNode(h.bus, h.loop, h.heartbeat, options), std::invalid_argument);
}

TEST(BuilderNode, KeepsABoundedNumberOfImagesWaitingForCameras) {
  const dataset::ViewSet set = dataset::ReadDataset(Scan());
  BuilderNodeOptions options;
  options.max_unmatched = 2;
  Harness h(options);
  for (size_t i : {0, 1, 2}) h.SendImage(ImageMessage(set.views[i]));
  h.Settle(milliseconds(200));
  // view_0000 waited longest and was dropped; the others pair when their cameras come.
  for (size_t i : {0, 1, 2}) h.SendCamera(CameraMessage(IdOf(set.views[i]), set.views[i].camera));
  ASSERT_TRUE(h.WaitFor([&] { return h.node->views_integrated() == 2; }));
  h.Settle(milliseconds(100));
  EXPECT_EQ(h.node->views_integrated(), 2);
  h.Command("mvs-without-0", avc::build_command_t::ACTION_RUN_MVS, {"view_0000", "view_0001"});
  ASSERT_TRUE(h.WaitForAnswers({"mvs-without-0"}));
  EXPECT_NE(RefusalOf(h, "mvs-without-0").find("view_0000 not integrated"), std::string::npos);
  // Sent again, it is welcome.
  h.SendImage(ImageMessage(set.views[0]));
  h.SendCamera(CameraMessage(IdOf(set.views[0]), set.views[0].camera));
  ASSERT_TRUE(h.WaitFor([&] { return h.node->views_integrated() == 3; }));
}

TEST(BuilderNode, StoppingDuringMvsFailsTheRunningRequest) {
  const dataset::ViewSet set = dataset::ReadDataset(Scan());
  Harness h;
  h.Feed(set, {0, 1, 2, 3});
  ASSERT_TRUE(h.WaitFor([&] { return h.node->views_integrated() == 4; }));
  h.Command("mvs", avc::build_command_t::ACTION_RUN_MVS, {}, "plane-sweep");
  ASSERT_TRUE(h.WaitFor([&] { return h.node->mvs_running(); }));
  h.node.reset();
  ASSERT_TRUE(h.WaitForAnswers({"mvs"}));
  EXPECT_EQ(h.Final("mvs")->status, avc::ack_t::STATUS_FAILED);
  EXPECT_NE(h.Final("mvs")->reason.find("stopped before the MVS run finished"), std::string::npos);
}

}  // namespace
}  // namespace avc::builder
