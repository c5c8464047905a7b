// avc-surfacer on an in-process bus: each clusters product is answered with one mesh equal to
// the offline SurfaceClusters of the same clusters (same bytes), with its files written; refused
// or broken clusters are answered with an empty mesh, and the node keeps going.

#include "services/surfacer/surfacer_node.h"

#include <gtest/gtest.h>

#include <avc/clusters_t.hpp>
#include <avc/mesh_t.hpp>
#include <chrono>
#include <memory>
#include <numbers>
#include <vector>

#include "core/bus/channels.h"
#include "core/messages/clusters_message.h"
#include "core/messages/mesh_message.h"
#include "core/surface/surface_images_io.h"
#include "tests/support/test_support.h"
#include "tests/core/surface/disc_views.h"
#include "tests/services/surfacer/two_leaf_clusters.h"

namespace avc::surfacer {
namespace {

using std::chrono::milliseconds;

struct Harness {
  explicit Harness(SurfacerNodeOptions options = {})
      : bus(bus::InProcessBusOptions()),
        heartbeat(bus, loop, "avc-surfacer", milliseconds(50)),
        sender(bus, loop),
        receiver(bus, "test-receiver", std::string(channels::kProductMesh),
                 [this](const products::Product& product, const bus::RxInfo&) {
                   avc::mesh_t message;
                   message.decode(product.payload.data(), 0,
                                  static_cast<int>(product.payload.size()));
                   names.push_back(product.name);
                   answers.push_back(message);
                 }) {
    bus.AttachTo(loop);
    node = std::make_unique<SurfacerNode>(bus, loop, heartbeat, options);
  }
  void Send(const avc::clusters_t& message) {
    sender.SendMessage(channels::kProductClusters, "clusters/" + message.cloud_id, message);
  }
  bool WaitForAnswers(size_t count) {
    return loop.RunUntil([&] { return answers.size() >= count; }, milliseconds(20000));
  }

  bus::Bus bus;
  bus::EventLoop loop;
  bus::HeartbeatPublisher heartbeat;
  products::ProductSender sender;
  products::ProductReceiver receiver;
  std::unique_ptr<SurfacerNode> node;
  std::vector<std::string> names;
  std::vector<avc::mesh_t> answers;
};

TEST(SurfacerNode, AnswersEachClustersProductWithTheOfflineMesh) {
  ::avc::testing::TempDir dir("avc-surfacer-node");
  SurfacerNodeOptions options;
  options.output_dir = dir.path();
  Harness h(options);
  const messages::ClustersContent clusters = testing::TwoLeafClusters("plant-mvs-1");
  h.Send(messages::ClustersToMessage(clusters));
  ASSERT_TRUE(h.WaitForAnswers(1));
  EXPECT_EQ(h.names[0], "mesh/plant-mvs-1");
  const avc::mesh_t& answer = h.answers[0];
  EXPECT_EQ(answer.mesh_id, "plant-mvs-1");
  EXPECT_EQ(answer.frame, "world");
  const SurfacerResult offline = SurfaceClusters(clusters);
  ASSERT_EQ(offline.problem, "");
  EXPECT_EQ(answer.data, messages::MeshToMessage(offline.mesh, "plant-mvs-1").data);
  const geometry::Mesh mesh = messages::MeshFromMessage(answer);
  EXPECT_EQ(mesh.face_labels, offline.mesh.face_labels);
  EXPECT_EQ(mesh.colors.size(), mesh.vertices.size());
  EXPECT_TRUE(std::filesystem::exists(dir / "plant-mvs-1/mesh.ply"));
  EXPECT_TRUE(std::filesystem::exists(dir / "plant-mvs-1/traits.csv"));
  EXPECT_TRUE(std::filesystem::exists(dir / "plant-mvs-1/traits.json"));
  EXPECT_EQ(h.node->clusters_answered(), 1);
}

TEST(SurfacerNode, GrowsOverTheMasksOfItsReconstructionFolder) {
  ::avc::testing::TempDir dir("avc-surfacer-masks");
  // The upper leaf (3 cm of points at z = 0.09) is 4 cm wide in the masks.
  surface::WriteSurfaceImages(dir.path(), surface::ViewsOfDisc(0.04, 0.09));
  SurfacerNodeOptions options;
  options.images_dir = dir.path();
  Harness h(options);
  const messages::ClustersContent clusters = testing::TwoLeafClusters("masks-1");
  h.Send(messages::ClustersToMessage(clusters));
  ASSERT_TRUE(h.WaitForAnswers(1));
  const surface::SurfaceImages images = surface::ReadSurfaceImages(dir.path());
  ASSERT_EQ(images.views.size(), 16u);
  const SurfacerResult offline = SurfaceClusters(clusters, {}, &images);
  ASSERT_EQ(offline.problem, "");
  EXPECT_EQ(h.answers[0].data, messages::MeshToMessage(offline.mesh, "masks-1").data);
  // The upper leaf gained the 7 pi cm^2 ring between 3 and 4 cm.
  const double ring = std::numbers::pi * (0.04 * 0.04 - 0.03 * 0.03);
  const double without = geometry::SurfaceArea(SurfaceClusters(clusters).mesh);
  EXPECT_NEAR(geometry::SurfaceArea(offline.mesh) - without, ring, 0.15 * ring);
}

TEST(SurfacerNode, RefusedAndBrokenClustersGetAnEmptyMeshAndTheNodeGoesOn) {
  Harness h;
  messages::ClustersContent refused;
  refused.cloud_id = "refused";
  refused.problem = "too few merged points";
  h.Send(messages::ClustersToMessage(refused));
  avc::clusters_t broken = messages::ClustersToMessage(testing::TwoLeafClusters("broken"));
  broken.points.fields.erase(broken.points.fields.begin());  // no "x"
  broken.points.num_fields = static_cast<int32_t>(broken.points.fields.size());
  h.Send(broken);
  h.Send(messages::ClustersToMessage(testing::TwoLeafClusters("good")));
  ASSERT_TRUE(h.WaitForAnswers(3));
  EXPECT_EQ(h.answers[0].mesh_id, "refused");
  EXPECT_EQ(h.answers[0].num_faces, 0);
  EXPECT_EQ(h.answers[1].mesh_id, "broken");
  EXPECT_EQ(h.answers[1].num_faces, 0);
  EXPECT_EQ(h.answers[2].mesh_id, "good");
  EXPECT_GT(h.answers[2].num_faces, 500);
  EXPECT_EQ(h.node->clusters_answered(), 3);
}

TEST(SurfacerNode, BadOptionsAreRefusedByName) {
  SurfacerNodeOptions bad;
  bad.surfacing.surface.stitch_factor = -1;
  try {
    Harness refused(bad);
    ADD_FAILURE() << "bad options accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("avc-surfacer"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("stitch"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace avc::surfacer
