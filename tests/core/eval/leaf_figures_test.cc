#include "core/eval/leaf_figures.h"

#include <gtest/gtest.h>

namespace avc::eval {
namespace {

using Json = nlohmann::json;

// One organ of an evaluation report, scored at 1 and 2 mm.
Json Organ(int label, double gt_area, double area, int points, int samples, double accuracy,
           double precision, double recall) {
  return {{"label", label},
          {"gt_area_m2", gt_area},
          {"reconstructed_area_m2", area},
          {"reconstruction_points", points},
          {"gt_samples", samples},
          {"accuracy", {{"mean", accuracy}}},
          {"scores",
           {{{"threshold", 0.001}, {"precision", 0.0}, {"recall", 0.0}},
            {{"threshold", 0.002}, {"precision", precision}, {"recall", recall}}}}};
}

TEST(LeafFigures, LeavesOnlyAreasSummedScoresWeightedBySamples) {
  const Json evaluation = {{"organs",
                            {Organ(1, 0.05, 0.0, 0, 5000, 0.0, 0.0, 0.0),  // the pot: left out
                             Organ(100, 0.01, 0.009, 100, 1000, 0.0002, 1.0, 0.9),
                             Organ(101, 0.03, 0.030, 300, 3000, 0.0004, 0.9, 1.0)}}};
  const Json figures = LeafFigures(evaluation);
  EXPECT_NEAR(figures["area_ratio"].get<double>(), 0.039 / 0.04, 1e-12);
  EXPECT_NEAR(figures["accuracy_mean_mm"].get<double>(), 0.35, 1e-12);
  EXPECT_NEAR(figures["precision_2mm"].get<double>(), 0.925, 1e-12);
  EXPECT_NEAR(figures["recall_2mm"].get<double>(), 0.975, 1e-12);
  EXPECT_EQ(FormatLeafFigures(figures),
            "the leaves: 97.5 % of their area, precision 92.5 % and recall 97.5 % at 2 mm, mean "
            "error 0.35 mm\n");
}

}  // namespace
}  // namespace avc::eval
