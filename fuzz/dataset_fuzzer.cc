// A dataset directory as `avc reconstruct --dataset` reads it (dataset::ReadDataset). The first
// byte picks the layout by its value modulo 3 ('0' scan, '1' COLMAP, '2' Middlebury); the rest is
// the camera file(s), COLMAP's cameras.txt and images.txt separated by fuzz::kPartSeparator.
// Every directory also holds a 4x3 image "a.png" (in images/ too), so cameras naming it reach
// the checks that follow the parse.

#include <cstdint>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/dataset/dataset_reader.h"

#include "fuzz/fuzz_support.h"

namespace {

std::string TinyPng() {
  std::vector<uint8_t> png;
  cv::imencode(".png", cv::Mat(3, 4, CV_8UC3, cv::Scalar(40, 120, 200)), png);
  return {png.begin(), png.end()};
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  namespace fuzz = avc::fuzz;
  if (size == 0) return 0;
  static const std::string png = TinyPng();
  const auto dir = fuzz::FreshDir("dataset");
  const auto images = fuzz::FreshDir("dataset/images");
  fuzz::WriteFile(dir, "a.png", png);
  fuzz::WriteFile(images, "a.png", png);
  const std::string_view text = fuzz::AsText(data + 1, size - 1);
  switch (data[0] % 3) {
    case 0:
      fuzz::WriteFile(dir, "cameras.json", text);
      break;
    case 1: {
      const auto parts = fuzz::SplitParts(text, 2);
      fuzz::WriteFile(dir, "cameras.txt", parts[0]);
      fuzz::WriteFile(dir, "images.txt", parts[1]);
      break;
    }
    default:
      fuzz::WriteFile(dir, "set_par.txt", text);
  }
  try {
    avc::dataset::ReadDataset(dir);
  } catch (const std::runtime_error&) {  // names the file and the entry at fault
  }
  return 0;
}
