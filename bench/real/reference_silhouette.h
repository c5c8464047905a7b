#pragma once

// Where a reference mesh lies in a view: its triangles projected and filled, so a plant mask can
// be checked against a reconstruction that is not ours (ROMI's own mesh of its scan).

#include <opencv2/core/mat.hpp>

#include "core/camera/pinhole_camera.h"
#include "core/geometry/mesh.h"

namespace avc::bench {

// CV_8UC1 of the camera's image size, 255 where a triangle in front of the camera projects.
cv::Mat ReferenceSilhouette(const geometry::Mesh& mesh, const camera::Camera& camera);

struct MaskAgainstReference {
  double plant_fraction = 0;     // of the image's pixels, in the mask
  double off_reference = 0;      // of the mask's pixels, farther than the tolerance from the
                                 // reference (stage, board, cloth or pot called plant)
  double reference_covered = 0;  // of the reference's pixels, within the tolerance of the mask
};

// Both CV_8UC1 of one size (non-zero = plant). `tolerance_px` absorbs the reference's own error.
MaskAgainstReference CompareMask(const cv::Mat& mask, const cv::Mat& reference,
                                 double tolerance_px);

}  // namespace avc::bench
