#include "services/clusterer/clusters_ply.h"

#include <fstream>
#include <stdexcept>

#include "core/products/point_cloud_ply.h"

namespace avc::clusterer {

void WriteClustersPly(const std::filesystem::path& path, const messages::ClustersContent& content) {
  const std::string ply = products::PointCloudToPly(messages::ClustersToMessage(content).points);
  std::ofstream out(path, std::ios::binary);
  out.write(ply.data(), static_cast<std::streamsize>(ply.size()));
  if (!out.flush()) throw std::runtime_error("cannot write " + path.string());
}

}  // namespace avc::clusterer
