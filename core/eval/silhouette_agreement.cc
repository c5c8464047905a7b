#include "core/eval/silhouette_agreement.h"

#include <cmath>
#include <stdexcept>

namespace avc::eval {

double InsideAllSilhouettesFraction(const mvs::MvsPoints& points,
                                    const std::vector<dataset::View>& views,
                                    const std::vector<cv::Mat>& silhouettes) {
  if (silhouettes.size() != views.size()) {
    throw std::invalid_argument("one silhouette per view is needed");
  }
  if (points.size() == 0) return 0;
  size_t inside = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d p = points.cloud.positions[i].cast<double>();
    bool all_inside = !points.views[i].empty();
    for (uint32_t v : points.views[i]) {
      const auto pixel = views.at(v).camera.Project(p);
      const cv::Mat& silhouette = silhouettes[v];
      const int u = pixel ? static_cast<int>(std::lround(pixel->x())) : -1;
      const int w = pixel ? static_cast<int>(std::lround(pixel->y())) : -1;
      if (u < 0 || w < 0 || u >= silhouette.cols || w >= silhouette.rows ||
          silhouette.at<uint8_t>(w, u) == 0) {
        all_inside = false;
        break;
      }
    }
    inside += all_inside;
  }
  return static_cast<double>(inside) / static_cast<double>(points.size());
}

}  // namespace avc::eval
