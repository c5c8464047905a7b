#pragma once

#include <avc/point_cloud_t.hpp>
#include <string>

namespace avc::products {

// A binary little-endian PLY file with one vertex property per field element, in record order;
// padding between fields becomes "uchar pad<N>" properties so records are copied unchanged.
// Throws std::invalid_argument naming the problem when fields overlap, leave the record, or
// the data size disagrees with num_points * point_step.
std::string PointCloudToPly(const avc::point_cloud_t& cloud);

}  // namespace avc::products
