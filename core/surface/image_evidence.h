#pragma once

// What the plant masks say about a 3-D point: Phase 2 with images asks, for each grid node a
// cell could grow to, whether the views see plant or background there. A point on a leaf
// projects onto plant in every view that has it in frame (whatever occludes it is plant too);
// a point in the air beside a leaf projects onto background in the views that look past the
// leaf's edge. So background in a couple of views rules a node out (the visual hull, at the
// masks' full resolution), and plant in several views with no such veto lets the level set
// grow there.

#include <Eigen/Core>
#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <string>
#include <vector>

#include "core/camera/pinhole_camera.h"
#include "core/surface/image_growth_options.h"

namespace avc::surface {

struct EvidenceView {
  std::string name;       // for messages
  camera::Camera camera;  // the camera the mask was made in (world -> camera)
  cv::Mat mask;           // CV_8UC1 of the camera's image size: 255 plant, 0 background
};

struct SurfaceImages {
  std::vector<EvidenceView> views;
};

enum class NodeVerdict { kPlant, kBackground, kUnknown };

class ImageEvidence {
 public:
  // Throws std::invalid_argument naming the view whose mask is not CV_8UC1 of its camera's
  // size.
  ImageEvidence(const SurfaceImages& images, const ImageGrowthOptions& options);

  // kBackground when at least min_background_views views see background clearly at the
  // point's projection, else kPlant when at least min_plant_views see plant, else kUnknown
  // (too few views have it in frame).
  NodeVerdict Judge(const Eigen::Vector3d& point) const;

  size_t views() const { return views_.size(); }

 private:
  // What each pixel says, one byte a pixel (a real cell's 18-megapixel masks add up).
  static constexpr uint8_t kClearBackground = 0, kNearEdge = 128, kPlant = 255;
  struct PreparedView {
    camera::Camera camera;
    cv::Mat says;  // CV_8UC1 of kClearBackground, kNearEdge or kPlant
  };
  std::vector<PreparedView> views_;
  int min_plant_views_;
  int min_background_views_;
};

}  // namespace avc::surface
