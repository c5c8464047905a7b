#pragma once

// What the plant masks say about a 3-D point: Phase 2 with images asks, for each grid node a
// cell could grow to, whether the views see plant or background there. A point on a leaf
// projects onto plant in every view that has it in frame (whatever occludes it is plant too);
// a point in the air beside a leaf projects onto background in the views that look past the
// leaf's edge. So background in a couple of views rules a node out (the visual hull, at the
// masks' full resolution), and plant in several views with no such veto lets the level set
// grow there, when the colours those views show agree with the growing cell's colour model
// (colour_model.h): a leaf does not grow over a plant part of another colour behind its edge.

#include <Eigen/Core>
#include <cstdint>
#include <opencv2/core/mat.hpp>
#include <string>
#include <vector>

#include "core/camera/pinhole_camera.h"
#include "core/surface/colour_model.h"
#include "core/surface/image_growth_options.h"

namespace avc::surface {

struct EvidenceView {
  std::string name;       // for messages
  camera::Camera camera;  // the camera the mask was made in (world -> camera)
  cv::Mat mask;           // CV_8UC1 of the camera's image size: 255 plant, 0 background
  // Optional, for colour agreement: CV_8UC3 (BGR) of the camera's size, or reduced 2, 4 or 8
  // times (sizes rounded up), as a large image is read to save memory.
  cv::Mat image;
};

struct SurfaceImages {
  std::vector<EvidenceView> views;
};

// How many times smaller than its camera's image a colour image is on both axes: 1, 2, 4 or 8
// (sizes rounded up, as a JPEG decoded reduced), or 0 when it is not a CV_8UC3 image of such a
// size.
int ColourImageReduction(const cv::Mat& image, const camera::Intrinsics& k);

enum class NodeVerdict { kPlant, kBackground, kUnknown, kOtherColour };

class ImageEvidence {
 public:
  // Throws std::invalid_argument naming the view whose mask is not CV_8UC1 of its camera's
  // size, or whose image is neither empty nor CV_8UC3 of that size (or reduced as above).
  ImageEvidence(const SurfaceImages& images, const ImageGrowthOptions& options);

  // kBackground when at least min_background_views views see background clearly at the
  // point's projection; else, when at least min_plant_views see plant: kPlant if `colour` is
  // null or at least min_plant_views of them, and at least half, show a colour it agrees with
  // (views without an image count as agreeing), kOtherColour if not; else kUnknown (too few
  // views have it in frame).
  NodeVerdict Judge(const Eigen::Vector3d& point, const ColourModel* colour = nullptr) const;

  size_t views() const { return views_.size(); }

 private:
  // What each pixel says, one byte a pixel (a real cell's 18-megapixel masks add up).
  static constexpr uint8_t kClearBackground = 0, kNearEdge = 128, kPlant = 255;
  struct PreparedView {
    camera::Camera camera;
    cv::Mat says;       // CV_8UC1 of kClearBackground, kNearEdge or kPlant
    cv::Mat image;      // CV_8UC3 or empty (shared with the caller's view)
    int reduction = 1;  // the camera's pixels per image pixel along each axis
  };
  std::vector<PreparedView> views_;
  int min_plant_views_;
  int min_background_views_;
};

}  // namespace avc::surface
