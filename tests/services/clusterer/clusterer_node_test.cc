// avc-clusterer on an in-process bus: MVS points that arrive before the proxy wait for it, the
// answer equals the offline MergeAndCluster of the same inputs, and undecodable or empty clouds
// and bad voxel maps are answered or refused by name without stopping the node.

#include "services/clusterer/clusterer_node.h"

#include <gtest/gtest.h>

#include <avc/clusters_t.hpp>
#include <avc/mvs_points_t.hpp>
#include <avc/voxel_map_t.hpp>
#include <chrono>
#include <functional>
#include <memory>
#include <vector>

#include "core/bus/channels.h"
#include "core/messages/clusters_message.h"
#include "core/messages/mvs_points_message.h"
#include "core/ppr/octree_voxels.h"
#include "tests/services/clusterer/two_discs.h"
#include "tests/support/test_support.h"

namespace avc::clusterer {
namespace {

using std::chrono::milliseconds;
using testing::kVoxel;

avc::voxel_map_t VoxelMap(const std::string& id, const std::string& bytes) {
  avc::voxel_map_t map{};
  map.map_id = id;
  map.frame = "world";
  map.resolution = kVoxel;
  map.encoding = avc::voxel_map_t::ENCODING_OCTOMAP_BT;
  map.data.assign(bytes.begin(), bytes.end());
  map.data_size = static_cast<int32_t>(map.data.size());
  return map;
}

struct Harness {
  explicit Harness(ClustererNodeOptions options = {})
      : bus(bus::InProcessBusOptions()),
        heartbeat(bus, loop, "avc-clusterer", milliseconds(50)),
        sender(bus, loop),
        receiver(bus, "test-receiver", std::string(channels::kProductClusters),
                 [this](const products::Product& product, const bus::RxInfo&) {
                   avc::clusters_t message;
                   message.decode(product.payload.data(), 0,
                                  static_cast<int>(product.payload.size()));
                   answers.push_back(messages::ClustersFromMessage(message));
                 }) {
    bus.AttachTo(loop);
    node = std::make_unique<ClustererNode>(bus, loop, heartbeat, options);
  }
  void SendPoints(const mvs::MvsPoints& points, const std::string& id) {
    sender.SendMessage(channels::kProductMvsPoints, "mvs/" + id,
                       messages::MvsPointsToMessage(points, {"a", "b", "c"}, id));
  }
  bool WaitForAnswers(size_t count) {
    return loop.RunUntil([&] { return answers.size() >= count; }, milliseconds(10000));
  }
  bool WaitFor(const std::function<bool()>& done) {
    return loop.RunUntil(done, milliseconds(10000));
  }
  void Settle() {
    loop.RunUntil([] { return false; }, milliseconds(100));
  }

  bus::Bus bus;
  bus::EventLoop loop;
  bus::HeartbeatPublisher heartbeat;
  products::ProductSender sender;
  products::ProductReceiver receiver;
  std::unique_ptr<ClustererNode> node;
  std::vector<messages::ClustersContent> answers;
};

TEST(ClustererNode, PointsWaitForTheProxyAndTheAnswerEqualsTheOfflineRun) {
  const testing::TwoDiscs scene = testing::MakeTwoDiscs();
  Harness h;
  h.SendPoints(scene.points, "plant1-mvs-1");
  h.Settle();
  EXPECT_TRUE(h.answers.empty());  // no proxy yet: it waits
  EXPECT_FALSE(h.node->has_proxy());
  h.sender.SendMessage(channels::kProductVoxelMap, "ppr/plant1-ppr-0001.bt",
                       VoxelMap("plant1-ppr-0001", scene.proxy_bt));
  ASSERT_TRUE(h.WaitForAnswers(1));
  const messages::ClustersContent answer = h.answers[0];  // a copy: answers grows below
  ASSERT_TRUE(answer.problem.empty()) << answer.problem;
  EXPECT_EQ(answer.cloud_id, "plant1-mvs-1");
  EXPECT_EQ(answer.map_id, "plant1-ppr-0001");
  EXPECT_EQ(answer.num_clusters, 2);

  const messages::ClustersContent offline =
      MergeAndCluster(scene.points, ppr::OccupiedVoxelsFromBinary(scene.proxy_bt, kVoxel, "discs"),
                      {}, "plant1-mvs-1", "plant1-ppr-0001");
  EXPECT_EQ(::avc::testing::Encode(messages::ClustersToMessage(answer)),
            ::avc::testing::Encode(messages::ClustersToMessage(offline)));

  // Later clouds use the proxy in hand at once.
  h.SendPoints(scene.points, "plant1-mvs-2");
  ASSERT_TRUE(h.WaitForAnswers(2));
  EXPECT_EQ(h.answers[1].cloud_id, "plant1-mvs-2");
  EXPECT_EQ(h.answers[1].clusters, answer.clusters);
  EXPECT_EQ(h.node->clouds_answered(), 2);
}

TEST(ClustererNode, BadCloudsAreAnsweredWithTheirProblemAndBadMapsKeepTheOldProxy) {
  const testing::TwoDiscs scene = testing::MakeTwoDiscs();
  Harness h;
  h.sender.SendMessage(channels::kProductVoxelMap, "ppr/m1.bt", VoxelMap("m1", scene.proxy_bt));
  ASSERT_TRUE(h.WaitFor([&] { return h.node->has_proxy(); }));
  // A corrupt map is refused; the proxy in hand stays.
  h.sender.SendMessage(channels::kProductVoxelMap, "ppr/m2.bt", VoxelMap("m2", "not a tree"));
  h.Settle();
  EXPECT_TRUE(h.node->has_proxy());

  h.SendPoints({}, "empty");
  avc::mvs_points_t broken = messages::MvsPointsToMessage(scene.points, {"a", "b", "c"}, "broken");
  broken.points.fields.erase(broken.points.fields.begin());  // no "x"
  broken.points.num_fields = static_cast<int32_t>(broken.points.fields.size());
  h.sender.SendMessage(channels::kProductMvsPoints, "mvs/broken", broken);
  h.SendPoints(scene.points, "good");
  ASSERT_TRUE(h.WaitForAnswers(3));
  EXPECT_EQ(h.answers[0].cloud_id, "empty");
  EXPECT_NE(h.answers[0].problem.find("are empty"), std::string::npos) << h.answers[0].problem;
  EXPECT_EQ(h.answers[1].cloud_id, "broken");
  EXPECT_NE(h.answers[1].problem.find("no field 'x'"), std::string::npos) << h.answers[1].problem;
  EXPECT_EQ(h.answers[2].cloud_id, "good");
  EXPECT_TRUE(h.answers[2].problem.empty()) << h.answers[2].problem;
  EXPECT_EQ(h.answers[2].map_id, "m1");
  EXPECT_EQ(h.answers[2].num_clusters, 2);
}

TEST(ClustererNode, CloudsWaitingTooLongForAProxyAreAnswered) {
  const testing::TwoDiscs scene = testing::MakeTwoDiscs(100);
  ClustererNodeOptions options;
  options.max_waiting = 2;
  Harness h(options);
  for (const char* id : {"c1", "c2", "c3"}) h.SendPoints(scene.points, id);
  ASSERT_TRUE(h.WaitForAnswers(1));
  EXPECT_EQ(h.answers[0].cloud_id, "c1");
  EXPECT_NE(h.answers[0].problem.find("no plant proxy arrived"), std::string::npos);
  EXPECT_THROW(
      {
        ClustererNodeOptions bad;
        bad.max_waiting = 0;
        Harness refused(bad);
      },
      std::invalid_argument);
}

}  // namespace
}  // namespace avc::clusterer
