#include "services/builder/build_step.h"

#include "core/dataset/dataset_reader.h"
#include "services/builder/build_report.h"
#include "services/builder/builder_options.h"
#include "services/builder/reconstruction_output.h"

namespace avc::builder {

namespace fs = std::filesystem;

void BuildModel(const fs::path& scan_dir, const fs::path& model_dir,
                const ReconstructOptions& options,
                const std::function<void(const std::string&)>& report) {
  dataset::ViewSet set = dataset::ReadDataset(scan_dir);
  const Reconstruction reconstruction =
      Reconstruct(set, options, [&](const std::string& stage, size_t done, size_t total) {
        if (report && done == total) {
          report(stage + " " + std::to_string(done) + "/" + std::to_string(total));
        }
      });
  const BuildReport build_report =
      MakeBuildReport(reconstruction, options.method, set.ground_truth_mesh, set.FileToWorld());
  WriteReconstruction(model_dir, set, reconstruction, build_report, /*overwrite=*/true);
}

stage::StageHandler BuildStageHandler(const ReconstructOptions& base) {
  return [base](const stage::StageWork& work) {
    ReconstructOptions options = base;
    BuilderOptionTable().ApplyTexts(options, work.settings, "the build job's settings");
    BuildModel(work.input_dir, work.output_dir, options, work.progress);
  };
}

}  // namespace avc::builder
