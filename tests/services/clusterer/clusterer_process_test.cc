// `avc clusterer` as a real process on the real LCM bus (in a private network namespace): it
// becomes READY, answers an MVS points product sent before the proxy once the proxy arrives, with
// the same clusters as the offline run and its clusters_<cloud>.ply written, and stops cleanly on
// SIGTERM.

#include <gtest/gtest.h>
#include <signal.h>

#include <avc/clusters_t.hpp>
#include <avc/heartbeat_t.hpp>
#include <avc/voxel_map_t.hpp>
#include <chrono>
#include <filesystem>
#include <optional>

#include "core/bus/bus.h"
#include "core/bus/channels.h"
#include "core/bus/event_loop.h"
#include "core/launch/child_process.h"
#include "core/messages/clusters_message.h"
#include "core/messages/mvs_points_message.h"
#include "core/ppr/octree_voxels.h"
#include "core/products/product_receiver.h"
#include "core/products/product_sender.h"
#include "services/clusterer/merge_and_cluster.h"
#include "tests/services/clusterer/two_discs.h"
#include "tests/support/test_support.h"

namespace avc::clusterer {
namespace {

using std::chrono::seconds;

TEST(ClustererProcess, AnswersOverTheBusLikeTheOfflineRunAndStopsOnSigterm) {
  ::avc::testing::TempDir dir("avc-clusterer-mp");
  const testing::TwoDiscs scene = testing::MakeTwoDiscs();

  bus::Bus bus(bus::ResolveBusOptions({}, "clusterer-test"));
  bus::EventLoop loop;
  bus.AttachTo(loop);
  std::optional<avc::heartbeat_t> ready;
  bus.Subscribe<avc::heartbeat_t>(
      channels::kHeartbeat, [&](const avc::heartbeat_t& beat, const bus::RxInfo&) {
        if (beat.service == "avc-clusterer" && beat.state == avc::heartbeat_t::STATE_READY) {
          ready = beat;
        }
      });
  std::optional<messages::ClustersContent> answer;
  products::ProductReceiver receiver(bus, "clusterer-test", std::string(channels::kProductClusters),
                                     [&](const products::Product& product, const bus::RxInfo&) {
                                       avc::clusters_t message;
                                       message.decode(product.payload.data(), 0,
                                                      static_cast<int>(product.payload.size()));
                                       answer = messages::ClustersFromMessage(message);
                                     });
  products::ProductSender sender(bus, loop);

  const auto log = dir / "clusterer.log";
  launch::ChildProcess clusterer = launch::ChildProcess::Spawn(
      {{::avc::testing::Executable("avc").string(), "clusterer", "--output", dir.path().string()},
       {},
       "",
       log.string()});
  ASSERT_TRUE(
      loop.RunUntil([&] { return ready.has_value() || !clusterer.running(); }, seconds(10)));
  ASSERT_TRUE(ready.has_value()) << "avc clusterer never became READY:\n"
                                 << ::avc::testing::ReadFile(log);
  EXPECT_NE(ready->detail.find("waiting for a plant proxy"), std::string::npos) << ready->detail;

  sender.SendMessage(channels::kProductMvsPoints, "mvs/plant-mvs-1",
                     messages::MvsPointsToMessage(scene.points, {"a", "b", "c"}, "plant-mvs-1"));
  avc::voxel_map_t map{};
  map.map_id = "plant-ppr-0001";
  map.frame = "world";
  map.resolution = testing::kVoxel;
  map.encoding = avc::voxel_map_t::ENCODING_OCTOMAP_BT;
  map.data.assign(scene.proxy_bt.begin(), scene.proxy_bt.end());
  map.data_size = static_cast<int32_t>(map.data.size());
  // The points go first: the clusterer holds them until the proxy is in.
  ASSERT_TRUE(loop.RunUntil([&] { return sender.pending() == 0; }, seconds(10)));
  sender.SendMessage(channels::kProductVoxelMap, "ppr/plant-ppr-0001.bt", map);
  ASSERT_TRUE(loop.RunUntil([&] { return answer.has_value(); }, seconds(20)))
      << ::avc::testing::ReadFile(log);
  ASSERT_TRUE(answer->problem.empty()) << answer->problem;
  EXPECT_EQ(answer->cloud_id, "plant-mvs-1");
  EXPECT_EQ(answer->map_id, "plant-ppr-0001");
  EXPECT_EQ(answer->num_clusters, 2);
  const messages::ClustersContent offline = MergeAndCluster(
      scene.points, ppr::OccupiedVoxelsFromBinary(scene.proxy_bt, testing::kVoxel, "discs"), {},
      "plant-mvs-1", "plant-ppr-0001");
  EXPECT_EQ(answer->clusters, offline.clusters);
  EXPECT_EQ(answer->merged.cloud.positions, offline.merged.cloud.positions);
  EXPECT_TRUE(std::filesystem::exists(dir / "clusters_plant-mvs-1.ply"));

  clusterer.Signal(SIGTERM);
  const std::optional<int> stopped = clusterer.WaitFor(seconds(10));
  ASSERT_TRUE(stopped.has_value());
  EXPECT_TRUE(WIFEXITED(*stopped) && WEXITSTATUS(*stopped) == 0)
      << launch::DescribeWaitStatus(*stopped) << "\n"
      << ::avc::testing::ReadFile(log);
}

}  // namespace
}  // namespace avc::clusterer
