#pragma once

// The images Phase 2 grows with: read from a reconstruction folder as the builder writes it
// (services/builder/reconstruction_output.h: cameras.json, the undistorted cameras, and
// masks/<image stem>.png for each), or taken from a view set the builder has just masked.

#include <filesystem>

#include "core/dataset/view.h"
#include "core/surface/image_evidence.h"

namespace avc::surface {

// The views of folder/cameras.json that have a mask in folder/masks, in cameras.json order, with
// their undistorted colour image from folder/images/<stem>.jpg when there is one (for colour
// agreement); views without a mask are left out. No cameras.json or no masks folder: no views.
// Throws std::runtime_error naming the file when cameras.json, a mask or an image cannot be read,
// or its size is not its camera's.
SurfaceImages ReadSurfaceImages(const std::filesystem::path& folder);

// The views of a set that have a mask, with their images (shared, not copied).
SurfaceImages SurfaceImagesOf(const dataset::ViewSet& set);

}  // namespace avc::surface
