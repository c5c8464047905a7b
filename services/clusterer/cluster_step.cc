#include "services/clusterer/cluster_step.h"

#include <fmt/format.h>

#include <avc/clusters_t.hpp>
#include <stdexcept>

#include "core/bus/decode.h"
#include "core/stage/stage_names.h"
#include "core/util/file_io.h"
#include "services/clusterer/cluster_folder.h"
#include "services/clusterer/clusterer_options.h"
#include "services/clusterer/clusters_ply.h"

namespace avc::clusterer {

namespace fs = std::filesystem;

messages::ClustersContent ClusterModel(const fs::path& model_dir, const fs::path& output_dir,
                                       const ClustererOptions& options) {
  messages::ClustersContent clusters =
      ClusterFolderFiles(model_dir / "points.ply", model_dir / "ppr.bt", options);
  if (!clusters.problem.empty()) {
    throw std::runtime_error("the points could not be clustered: " + clusters.problem);
  }
  WriteClustersPly(output_dir / "clusters.ply", clusters);
  const avc::clusters_t message = messages::ClustersToMessage(clusters);
  std::string bytes(static_cast<size_t>(message.getEncodedSize()), '\0');
  message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  WriteFileAtomically(output_dir / stage::kClustersMessageFile, bytes);
  // What the surface stage will read: the message's own content (float fields), so the clusters
  // surfaced here and after a resume or over the bus are the same.
  return messages::ClustersFromMessage(message);
}

messages::ClustersContent ReadClustersMessage(const fs::path& file) {
  const std::string bytes = ReadFile(file);
  avc::clusters_t message;
  if (!bus::DecodeMessage(bytes.data(), bytes.size(), &message)) {
    throw std::runtime_error(fmt::format("{}: not a clusters_t message", file.string()));
  }
  try {
    return messages::ClustersFromMessage(message);
  } catch (const std::invalid_argument& error) {
    throw std::runtime_error(fmt::format("{}: {}", file.string(), error.what()));
  }
}

stage::StageHandler ClusterStageHandler(const ClustererOptions& base) {
  return [base](const stage::StageWork& work) {
    ClustererOptions options = base;
    ClustererOptionTable().ApplyTexts(options, work.settings, "the cluster job's settings");
    ClusterModel(work.input_dir, work.output_dir, options);
  };
}

}  // namespace avc::clusterer
