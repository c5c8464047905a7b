// Turntable axis and centre: exact on noise-free captures from the simulated cell's turntable
// model, the sign convention, noisy accuracy against the paper's baseline, the per-angle offset
// model, order invariance and refusals of degenerate input.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "bench/calibration/turntable/turntable_scenario.h"
#include "bench/calibration/turntable/turntable_trials.h"
#include "core/calibration/turntable/circle_screw_axis.h"
#include "core/calibration/turntable/opposite_pairs_centre.h"
#include "core/calibration/turntable/turntable_axis_fit.h"

namespace avc::calibration {
namespace {

using bench::AxisError;
using bench::CentreError;
using bench::RandomTurntableScenario;
using bench::SimulateTurntableViews;
using bench::TurntableNoise;
using bench::TurntableScenario;

constexpr double kDeg = M_PI / 180;

std::vector<TurntableView> NoiseFreeViews(const TurntableScenario& scenario, int angles) {
  sim::DeterministicRandom random(1);
  return SimulateTurntableViews(scenario, angles, {}, random);
}

std::string ErrorMessage(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected std::invalid_argument";
  return {};
}

TEST(TurntableAxis, NoiseFreeCapturesGiveTheExactAxisAndCentre) {
  for (uint64_t seed : {1u, 2u, 3u, 4u, 5u}) {
    sim::DeterministicRandom random(seed);
    const TurntableScenario scenario = RandomTurntableScenario(random, 2 * kDeg, 0.1);
    const TurntableAxis truth = scenario.TruthInFixedFrame();
    for (int angles : {4, 10, 36}) {
      const auto views = NoiseFreeViews(scenario, angles);
      const TurntableAxis paper = OppositePairsCentre(views);
      const TurntableAxis closed = CircleScrewAxis(views);
      const TurntableFit fit = FitTurntableAxis(views);
      for (const auto& [name, estimate] :
           {std::pair{"line intersection", paper}, {"circle/screw", closed}, {"ceres", fit.axis}}) {
        EXPECT_LT(CentreError(estimate, truth), 1e-9)
            << name << " seed " << seed << " n " << angles;
        EXPECT_LT(AxisError(estimate, truth), 1e-9) << name << " seed " << seed << " n " << angles;
      }
      EXPECT_LT(fit.rms_position, 1e-9);
      EXPECT_LT(fit.rms_orientation, 1e-9);
      // The angle-0 board pose is recovered too (what T_table_board is built from).
      const Eigen::Isometry3d T0 = scenario.T_fixed_table * scenario.T_table_board0;
      EXPECT_LT((fit.T_fixed_board0.matrix() - T0.matrix()).norm(), 1e-9);
    }
  }
}

TEST(TurntableAxis, AxisPointsSoPositiveAnglesTurnRightHanded) {
  sim::DeterministicRandom random(8);
  const TurntableScenario scenario = RandomTurntableScenario(random, 1 * kDeg, 0.1);
  auto views = NoiseFreeViews(scenario, 10);
  const TurntableAxis truth = scenario.TruthInFixedFrame();
  // Commanding the opposite sense (angle -> -angle for the same poses) must flip every axis.
  for (auto& view : views) view.angle = -view.angle;
  EXPECT_NEAR(AxisError(OppositePairsCentre(views), truth), M_PI, 1e-9);
  EXPECT_NEAR(AxisError(CircleScrewAxis(views), truth), M_PI, 1e-9);
  EXPECT_NEAR(AxisError(FitTurntableAxis(views).axis, truth), M_PI, 1e-9);
}

TEST(TurntableAxis, NoisyCapturesMeetTheAccuracyTargetsAndBeatThePaper) {
  bench::TurntableTrialOptions options;  // 0.1 mm / 1 mrad pose noise, 0.1 deg table error
  options.trials = 40;
  const nlohmann::json result = bench::RunTurntableTrials(options);
  const auto& methods = result.at("methods");
  const auto median = [&](const char* m, const char* what) {
    return methods.at(m).at(what).at("median").get<double>();
  };
  for (const char* m : {"line_intersection", "circle_screw", "ceres_fit"})
    EXPECT_EQ(methods.at(m).at("failures").get<int>(), 0) << m;
  // The closed form at this noise with 10 angles: centre < 0.2 mm and axis < 0.1 deg (measured
  // 0.065 mm / 0.022 deg median, BENCHMARKS.md, calibration).
  EXPECT_LT(median("circle_screw", "centre_mm"), 0.2);
  EXPECT_LT(median("circle_screw", "axis_deg"), 0.1);
  // The acceptance for our method, and better than the paper's baseline.
  EXPECT_LT(median("ceres_fit", "centre_mm"), 0.1);
  EXPECT_LT(median("ceres_fit", "axis_deg"), 0.05);
  EXPECT_LT(median("ceres_fit", "centre_mm"), median("line_intersection", "centre_mm"));
  EXPECT_LT(median("ceres_fit", "axis_deg"), median("line_intersection", "axis_deg"));
  EXPECT_TRUE(result.at("acceptance").at("met").get<bool>());
  // Same options, same bytes.
  EXPECT_EQ(bench::RunTurntableTrials(options).dump(), result.dump());
  const std::string table = bench::FormatTurntableTrials(result);
  EXPECT_NE(table.find("line_intersection"), std::string::npos) << table;
  EXPECT_NE(table.find(": met"), std::string::npos) << table;

  bench::TurntableTrialOptions bad = options;
  bad.position_sigma = std::nan("");
  EXPECT_THROW(bench::RunTurntableTrials(bad), std::invalid_argument);
  bad = options;
  bad.angles = 2;
  EXPECT_THROW(bench::RunTurntableTrials(bad), std::invalid_argument);
}

TEST(TurntableAxis, AngleOffsetsAbsorbATableThatStopsOffItsCommand) {
  sim::DeterministicRandom random(12);
  const TurntableScenario scenario = RandomTurntableScenario(random, 1 * kDeg, 0.1);
  const TurntableAxis truth = scenario.TruthInFixedFrame();
  auto views = NoiseFreeViews(scenario, 10);
  // The table stopped 0.5 deg short at view 3 (the poses show it; the command does not).
  views[3].angle += 0.5 * kDeg;
  TurntableFitOptions with_offsets;
  with_offsets.angle_sigma = 0.5 * kDeg;
  TurntableFitOptions trusting = with_offsets;
  trusting.angle_sigma = 0;
  const TurntableFit absorbed = FitTurntableAxis(views, with_offsets);
  const TurntableFit pulled = FitTurntableAxis(views, trusting);
  std::cout << "offset model: centre " << CentreError(absorbed.axis, truth) * 1e3 << " mm axis "
            << AxisError(absorbed.axis, truth) / kDeg << " deg; fixed angles: centre "
            << CentreError(pulled.axis, truth) * 1e3 << " mm axis "
            << AxisError(pulled.axis, truth) / kDeg << " deg\n";
  EXPECT_LT(CentreError(absorbed.axis, truth), 5e-6);
  EXPECT_LT(AxisError(absorbed.axis, truth), 1e-3 * kDeg);
  EXPECT_GT(CentreError(pulled.axis, truth), 10 * CentreError(absorbed.axis, truth));
  // The offset estimate sees the 0.5 deg error, relative to the others.
  double others = 0;
  for (size_t k = 0; k < views.size(); ++k)
    if (k != 3) others += absorbed.angle_offsets[k] / 9;
  EXPECT_NEAR(absorbed.angle_offsets[3] - others, -0.5 * kDeg, 0.01 * kDeg);
}

TEST(TurntableAxis, ResultDoesNotDependOnViewOrder) {
  sim::DeterministicRandom random(21);
  const TurntableScenario scenario = RandomTurntableScenario(random, 1 * kDeg, 0.1);
  std::vector<TurntableView> views =
      SimulateTurntableViews(scenario, 10, TurntableNoise{1e-4, 1e-3, 0.1 * kDeg}, random);
  std::vector<TurntableView> shuffled = views;
  std::reverse(shuffled.begin(), shuffled.end());
  std::rotate(shuffled.begin(), shuffled.begin() + 3, shuffled.end());
  const TurntableAxis a = CircleScrewAxis(views), b = CircleScrewAxis(shuffled);
  EXPECT_LT(CentreError(a, b), 1e-12);
  EXPECT_LT(AxisError(a, b), 1e-12);
  const TurntableFit fa = FitTurntableAxis(views), fb = FitTurntableAxis(shuffled);
  EXPECT_LT(CentreError(fa.axis, fb.axis), 1e-9);
  EXPECT_LT(AxisError(fa.axis, fb.axis), 1e-9);
  const TurntableAxis pa = OppositePairsCentre(views), pb = OppositePairsCentre(shuffled);
  EXPECT_LT(CentreError(pa, pb), 1e-12);
}

TEST(TurntableAxis, RefusesDegenerateCapturesWithTheReason) {
  sim::DeterministicRandom random(3);
  const TurntableScenario scenario = RandomTurntableScenario(random, 1 * kDeg, 0.1);
  const auto views = NoiseFreeViews(scenario, 12);  // 30 deg steps

  const std::vector<TurntableView> two(views.begin(), views.begin() + 2);
  EXPECT_NE(ErrorMessage([&] { CircleScrewAxis(two); }).find("2 table angles given"),
            std::string::npos);
  EXPECT_NE(ErrorMessage([&] { FitTurntableAxis(two); }).find("Ceres"), std::string::npos);

  const std::vector<TurntableView> narrow(views.begin(), views.begin() + 3);  // 0, 30, 60 deg
  const std::string span = ErrorMessage([&] { CircleScrewAxis(narrow); });
  EXPECT_NE(span.find("span 60.0 deg"), std::string::npos) << span;

  std::vector<TurntableView> bad = views;
  bad[2].T_fixed_board.translation().x() = std::nan("");
  EXPECT_NE(ErrorMessage([&] { FitTurntableAxis(bad); }).find("view 2"), std::string::npos);
  bad = views;
  bad[4].angle = INFINITY;
  EXPECT_NE(ErrorMessage([&] { OppositePairsCentre(bad); }).find("view 4"), std::string::npos);
  bad = views;
  bad[5].T_fixed_board.linear() *= 1.1;
  EXPECT_NE(ErrorMessage([&] { CircleScrewAxis(bad); }).find("not a rigid transform"),
            std::string::npos);

  // Five angles 72 deg apart have no opposite pairs: the paper's method cannot run, ours can.
  const auto five = NoiseFreeViews(scenario, 5);
  EXPECT_NE(ErrorMessage([&] { OppositePairsCentre(five); }).find("opposite"), std::string::npos);
  EXPECT_LT(CentreError(FitTurntableAxis(five).axis, scenario.TruthInFixedFrame()), 1e-9);

  TurntableFitOptions no_weight;
  no_weight.position_sigma = 0;
  EXPECT_NE(ErrorMessage([&] { FitTurntableAxis(views, no_weight); }).find("sigma"),
            std::string::npos);

  // A board whose origin sits on the axis traces no circle.
  sim::DeterministicRandom again(3);
  const TurntableScenario on_axis = RandomTurntableScenario(again, 1 * kDeg, 1e-12);
  const std::string circle = ErrorMessage([&] { CircleScrewAxis(NoiseFreeViews(on_axis, 10)); });
  EXPECT_NE(circle.find("circle"), std::string::npos) << circle;

  // The same poses with no rotation between them (a table that never turned).
  std::vector<TurntableView> frozen = views;
  for (auto& view : frozen) view.T_fixed_board = views.front().T_fixed_board;
  EXPECT_NE(ErrorMessage([&] { CircleScrewAxis(frozen); }).find("do not rotate"),
            std::string::npos);
}

TEST(TurntableAxis, TableFrameHasZAlongTheAxisAndXTowardsTheBoard) {
  TurntableAxis axis;
  axis.axis = Eigen::Vector3d(0, 0.6, 0.8);
  axis.centre = Eigen::Vector3d(1, 2, 3);
  const Eigen::Vector3d board(1.5, 2, 3);
  const Eigen::Isometry3d T = TableFrame(axis, board);
  EXPECT_LT((T.linear().col(2) - axis.axis).norm(), 1e-12);
  EXPECT_LT((T.translation() - axis.centre).norm(), 1e-12);
  EXPECT_LT((T.linear().col(0) - Eigen::Vector3d::UnitX()).norm(), 1e-12);
  EXPECT_NEAR(T.linear().determinant(), 1, 1e-12);
  EXPECT_NEAR(AngularSpan({0, 0.1, 2 * M_PI - 0.1}), 0.2, 1e-12);
  EXPECT_NEAR(AngularSpan({0, M_PI / 2, M_PI}), M_PI, 1e-12);
}

}  // namespace
}  // namespace avc::calibration
