#pragma once

// Reading and writing point clouds. Every error is a std::runtime_error whose message starts
// with the file name and names the line or element at fault, as in mesh_io.h.

#include <filesystem>

#include "core/geometry/point_cloud.h"

namespace avc::geometry {

// Reads a point cloud, choosing the format from the extension (any case):
//  .ply  the vertex element (ascii, binary little or big endian): x y z, optional nx ny nz,
//        optional red green blue (uchar, or float 0..1). Other elements (faces of a mesh file)
//        and properties are skipped, so a mesh PLY reads as its vertices.
//  .xyz  text, one point a line: "x y z" or "x y z nx ny nz" (the same column count on every
//        line); blank lines and lines starting with '#' are skipped.
//  .obj, .off  a mesh file: its vertices (with colours when present), faces ignored.
PointCloud ReadPointCloud(const std::filesystem::path& path);

// True when a PLY file's header declares a face element with at least one face, i.e. it holds a
// mesh rather than a bare cloud. Reads the header only.
bool PlyHasFaces(const std::filesystem::path& path);

// Writes PLY with float x y z, float nx ny nz when normals are present, uchar red green blue
// when colours are present. Same cloud → same bytes; reading back gives the same cloud exactly.
void WritePointCloudPly(const std::filesystem::path& path, const PointCloud& cloud,
                        bool binary = true);

}  // namespace avc::geometry
