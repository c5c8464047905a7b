#pragma once

// A small synthetic scan directory for the report tests: report.json, scan.json, cameras.json,
// model/mesh.ply and model/points.ply, written from the project's own writers.

#include <Eigen/Core>
#include <filesystem>
#include <string>

#include "core/camera/camera_io.h"
#include "core/geometry/mesh.h"

namespace avc::testing {

inline constexpr char kTestScanId[] = "synthetic-0042";

// A 640x480 camera at `eye` looking at the origin, z up.
camera::NamedCamera LookingAtOrigin(const std::string& name, const Eigen::Vector3d& eye);

// A tetrahedron whose four faces are each seen at a slant from the front, side and top.
geometry::Mesh Tetrahedron();
// A wavy leaf-like sheet of 2 * n * n faces in four clusters, about 10 cm across.
geometry::Mesh WavySheet(int n);

// Writes the scan around `mesh` into dir: three views (one dropped by pruning), two cameras
// kept, two clusters in the traits, ground-truth scores in the build section.
void WriteTestScan(const std::filesystem::path& dir, const geometry::Mesh& mesh);

}  // namespace avc::testing
