// `avc surfacer` as a real process on the real LCM bus (in a private network namespace): it
// becomes READY, answers a clusters product with the same mesh as the offline run, writes its
// files, and stops cleanly on SIGTERM.

#include <gtest/gtest.h>
#include <signal.h>

#include <avc/heartbeat_t.hpp>
#include <avc/mesh_t.hpp>
#include <chrono>
#include <filesystem>
#include <optional>

#include "core/bus/bus.h"
#include "core/bus/channels.h"
#include "core/bus/event_loop.h"
#include "core/launch/child_process.h"
#include "core/messages/clusters_message.h"
#include "core/messages/mesh_message.h"
#include "core/products/product_receiver.h"
#include "core/products/product_sender.h"
#include "services/surfacer/surface_clusters.h"
#include "tests/support/test_support.h"
#include "tests/services/surfacer/two_leaf_clusters.h"

namespace avc::surfacer {
namespace {

using std::chrono::seconds;

TEST(SurfacerProcess, AnswersOverTheBusLikeTheOfflineRunAndStopsOnSigterm) {
  ::avc::testing::TempDir dir("avc-surfacer-mp");
  bus::Bus bus(bus::ResolveBusOptions({}, "surfacer-test"));
  bus::EventLoop loop;
  bus.AttachTo(loop);
  std::optional<avc::heartbeat_t> ready;
  bus.Subscribe<avc::heartbeat_t>(
      channels::kHeartbeat, [&](const avc::heartbeat_t& beat, const bus::RxInfo&) {
        if (beat.service == "avc-surfacer" && beat.state == avc::heartbeat_t::STATE_READY) {
          ready = beat;
        }
      });
  std::optional<avc::mesh_t> answer;
  products::ProductReceiver receiver(bus, "surfacer-test", std::string(channels::kProductMesh),
                                     [&](const products::Product& product, const bus::RxInfo&) {
                                       avc::mesh_t message;
                                       message.decode(product.payload.data(), 0,
                                                      static_cast<int>(product.payload.size()));
                                       answer = message;
                                     });
  products::ProductSender sender(bus, loop);

  const auto log = dir / "surfacer.log";
  launch::ChildProcess surfacer = launch::ChildProcess::Spawn(
      {{::avc::testing::Executable("avc").string(), "surfacer", "--output", dir.path().string()},
       {},
       "",
       log.string()});
  ASSERT_TRUE(loop.RunUntil([&] { return ready.has_value() || !surfacer.running(); }, seconds(10)));
  ASSERT_TRUE(ready.has_value()) << "avc surfacer never became READY:\n"
                                 << ::avc::testing::ReadFile(log);
  EXPECT_NE(ready->detail.find("waiting for clusters"), std::string::npos) << ready->detail;

  const messages::ClustersContent clusters = testing::TwoLeafClusters("plant-mvs-1");
  sender.SendMessage(channels::kProductClusters, "clusters/plant-mvs-1",
                     messages::ClustersToMessage(clusters));
  ASSERT_TRUE(loop.RunUntil([&] { return answer.has_value(); }, seconds(20)))
      << ::avc::testing::ReadFile(log);
  EXPECT_EQ(answer->mesh_id, "plant-mvs-1");
  const SurfacerResult offline = SurfaceClusters(clusters);
  EXPECT_EQ(answer->data, messages::MeshToMessage(offline.mesh, "plant-mvs-1").data);
  EXPECT_TRUE(std::filesystem::exists(dir / "plant-mvs-1/mesh.ply"));
  EXPECT_TRUE(std::filesystem::exists(dir / "plant-mvs-1/traits.csv"));

  surfacer.Signal(SIGTERM);
  const std::optional<int> stopped = surfacer.WaitFor(seconds(10));
  ASSERT_TRUE(stopped.has_value());
  EXPECT_TRUE(WIFEXITED(*stopped) && WEXITSTATUS(*stopped) == 0)
      << launch::DescribeWaitStatus(*stopped) << "\n"
      << ::avc::testing::ReadFile(log);
}

}  // namespace
}  // namespace avc::surfacer
