// The report's static renders: every face drawn however small it projects, the nearest face in
// front, faces with non-finite corners left out, an empty mesh a blank picture.

#include "report/mesh_render.h"

#include <gtest/gtest.h>

#include <limits>
#include <opencv2/core.hpp>

namespace avc::report {
namespace {

// A square of side 1 m in the plane y = `y` (facing the front view), split into n x n cells of
// two faces each.
void AppendFrontSquare(int n, float y, geometry::Mesh* mesh) {
  const int first = static_cast<int>(mesh->vertices.size());
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      mesh->vertices.emplace_back(static_cast<float>(j) / n, y, static_cast<float>(i) / n);
    }
  }
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const int a = first + i * (n + 1) + j, b = a + 1, c = a + n + 1, d = c + 1;
      mesh->faces.emplace_back(a, b, d);
      mesh->faces.emplace_back(a, d, c);
    }
  }
}

bool IsWhite(const cv::Vec3b& pixel) { return pixel == cv::Vec3b(255, 255, 255); }

TEST(MeshRender, FacesSmallerThanAPixelStillCoverTheSurface) {
  // 180,000 faces, each about a fifth of an output pixel across: a renderer that skips small
  // faces or keeps only the largest ones leaves holes.
  geometry::Mesh mesh;
  AppendFrontSquare(300, 0.0f, &mesh);
  const std::vector<std::array<uint8_t, 3>> green(mesh.num_faces(), {40, 160, 60});
  const int size = 200;
  const cv::Mat image = RenderMeshView(mesh, green, MeshView::kFront, size);
  ASSERT_EQ(image.rows, size);
  ASSERT_EQ(image.cols, size);
  // The square fills the picture but for the 8-pixel margin; the edge pixels are blended.
  int holes = 0;
  for (int y = 9; y < size - 9; ++y) {
    for (int x = 9; x < size - 9; ++x) {
      const cv::Vec3b pixel = image.at<cv::Vec3b>(y, x);  // BGR
      if (pixel != cv::Vec3b(60, 160, 40)) ++holes;
    }
  }
  EXPECT_EQ(holes, 0);
  EXPECT_TRUE(IsWhite(image.at<cv::Vec3b>(3, 3)));
  EXPECT_TRUE(IsWhite(image.at<cv::Vec3b>(size - 4, size - 4)));
}

TEST(MeshRender, TheNearestFaceIsSeenWhateverTheFaceOrder) {
  // Two squares one behind the other in the front view (which looks along +y): the one at
  // y = -1 is nearer. Listed first or last, it is the one seen; from the side both show.
  for (const bool nearer_first : {true, false}) {
    geometry::Mesh mesh;
    std::vector<std::array<uint8_t, 3>> colours;
    const auto add = [&](float y, std::array<uint8_t, 3> rgb) {
      const size_t before = mesh.num_faces();
      AppendFrontSquare(4, y, &mesh);
      colours.insert(colours.end(), mesh.num_faces() - before, rgb);
    };
    const std::array<uint8_t, 3> red = {200, 0, 0}, blue = {0, 0, 200};
    if (nearer_first) {
      add(-1.0f, red);
      add(0.0f, blue);
    } else {
      add(0.0f, blue);
      add(-1.0f, red);
    }
    const cv::Mat front = RenderMeshView(mesh, colours, MeshView::kFront, 100);
    EXPECT_EQ(front.at<cv::Vec3b>(50, 50), cv::Vec3b(0, 0, 200))
        << "nearer listed first: " << nearer_first;
    // From the side (along -x) the squares are edge-on: nothing but background.
    const cv::Mat side = RenderMeshView(mesh, colours, MeshView::kSide, 100);
    EXPECT_EQ(cv::countNonZero(side.reshape(1) != 255), 0);
  }
}

TEST(MeshRender, AFaceWithANonFiniteCornerIsLeftOut) {
  geometry::Mesh mesh;
  AppendFrontSquare(2, 0.0f, &mesh);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  mesh.vertices.emplace_back(nan, 0.0f, 0.5f);
  mesh.vertices.emplace_back(0.5f, std::numeric_limits<float>::infinity(), 0.5f);
  const int bad_nan = static_cast<int>(mesh.vertices.size()) - 2, bad_inf = bad_nan + 1;
  mesh.faces.emplace_back(0, 1, bad_nan);
  mesh.faces.emplace_back(0, bad_inf, 2);
  const std::vector<std::array<uint8_t, 3>> grey(mesh.num_faces(), {100, 100, 100});
  const cv::Mat image = RenderMeshView(mesh, grey, MeshView::kFront, 50);
  EXPECT_EQ(image.at<cv::Vec3b>(25, 25), cv::Vec3b(100, 100, 100));
}

TEST(MeshRender, AnEmptyMeshIsABlankPicture) {
  const cv::Mat image = RenderMeshView(geometry::Mesh{}, {}, MeshView::kTop, 64);
  ASSERT_EQ(image.size(), cv::Size(64, 64));
  EXPECT_EQ(cv::countNonZero(image.reshape(1) != 255), 0);
  EXPECT_STREQ(NameOf(MeshView::kTop), "top");
}

}  // namespace
}  // namespace avc::report
