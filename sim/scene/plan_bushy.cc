// Bushy preset (chilli): a short main stem forking repeatedly into spreading branches, with small
// elliptic leaves on short petioles at the nodes and clusters of young leaves at the tips.

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "sim/scene/plant_plan.h"

namespace avc::sim {
namespace {

constexpr int kMaxDepth = 3;

struct Branch {
  Eigen::Vector3f start;
  Eigen::Vector3f direction;  // unit
  float length;
  float radius;
  int depth;
};

// Two unit vectors perpendicular to the unit vector d (and to each other).
void PerpendicularPair(const Eigen::Vector3f& d, Eigen::Vector3f* e1, Eigen::Vector3f* e2) {
  const Eigen::Vector3f axis =
      std::abs(d.z()) < 0.9f ? Eigen::Vector3f::UnitZ() : Eigen::Vector3f::UnitX();
  *e1 = d.cross(axis).normalized();
  *e2 = d.cross(*e1);
}

class BushBuilder {
 public:
  BushBuilder(PlantRandom& random, PlantPlan* plan) : random_(random), plan_(plan) {}

  void Grow(const Branch& branch) {
    // The branch bends gently upwards as it grows.
    TubeSpec tube;
    tube.label = geometry::labels::kStem;
    const int steps = 6;
    Eigen::Vector3f point = branch.start;
    Eigen::Vector3f direction = branch.direction;
    tube.points.push_back(point);
    tube.radii.push_back(branch.radius);
    std::vector<Eigen::Vector3f> directions = {direction};
    for (int k = 1; k <= steps; ++k) {
      direction = (direction + 0.06f * Eigen::Vector3f::UnitZ()).normalized();
      point += direction * (branch.length / steps);
      tube.points.push_back(point);
      tube.radii.push_back(branch.radius * (1.0f - 0.25f * k / steps));
      directions.push_back(direction);
    }
    plan_->tubes.push_back(tube);

    const float age = static_cast<float>(branch.depth) / kMaxDepth;
    // Leaves at two nodes of every branch (the upper half of the main stem).
    for (int node : {branch.depth == 0 ? 3 : 2, branch.depth == 0 ? 5 : 4}) {
      AddLeaf(tube.points[node], directions[node], age);
    }
    if (branch.depth == kMaxDepth) {
      const int cluster = random_.Int(2, 3);
      for (int i = 0; i < cluster; ++i) AddLeaf(point, direction, 1.0f);
      return;
    }
    const int children = branch.depth == 0 ? random_.Int(2, 3) : 2;
    const float spin = random_.Uniform(0.0f, 2.0f * kPi);
    Eigen::Vector3f e1;
    Eigen::Vector3f e2;
    PerpendicularPair(direction, &e1, &e2);
    for (int c = 0; c < children; ++c) {
      const float around = spin +
                           2.0f * kPi * static_cast<float>(c) / static_cast<float>(children) +
                           random_.Uniform(-0.3f, 0.3f);
      const float tilt = Degrees(random_.Uniform(25.0f, 45.0f));
      Branch child;
      child.start = point;
      child.direction = (std::cos(tilt) * direction +
                         std::sin(tilt) * (std::cos(around) * e1 + std::sin(around) * e2))
                            .normalized();
      child.length = branch.length * random_.Uniform(0.65f, 0.85f);
      child.radius = branch.radius * 0.7f;
      child.depth = branch.depth + 1;
      Grow(child);
    }
  }

 private:
  // A leaf on a short petiole at a node of a branch growing along axis.
  void AddLeaf(const Eigen::Vector3f& node, const Eigen::Vector3f& axis, float age) {
    Eigen::Vector3f e1;
    Eigen::Vector3f e2;
    PerpendicularPair(axis, &e1, &e2);
    phyllotaxis_ += kGoldenAngle;
    const float around = phyllotaxis_ + random_.Uniform(-0.2f, 0.2f);
    const float lean = Degrees(random_.Uniform(20.0f, 45.0f));  // towards the branch tip
    const Eigen::Vector3f out =
        (std::cos(lean) * (std::cos(around) * e1 + std::sin(around) * e2) + std::sin(lean) * axis)
            .normalized();
    const float azimuth = std::atan2(out.y(), out.x());
    const float elevation = std::asin(std::clamp(out.z(), -1.0f, 1.0f));
    std::vector<Eigen::Vector3f> points;
    std::vector<Eigen::Vector3f> tangents;
    const float petiole_droop = Degrees(random_.Uniform(10.0f, 30.0f));
    ArcCurve(node, azimuth, elevation, petiole_droop, 1.0f, 0.0f, random_.Uniform(0.01f, 0.025f), 4,
             &points, &tangents);
    TubeSpec petiole;
    petiole.label = geometry::labels::kPetiole;
    petiole.points = points;
    petiole.radii.assign(points.size(), 0.0012f);
    plan_->tubes.push_back(petiole);

    LeafSpec leaf;
    leaf.age = age;
    leaf.base = points.back();
    leaf.azimuth = azimuth + random_.Uniform(-0.2f, 0.2f);
    leaf.elevation = std::clamp(elevation - petiole_droop - Degrees(random_.Uniform(0.0f, 10.0f)),
                                Degrees(-30.0f), Degrees(45.0f));
    leaf.droop = Degrees(random_.Uniform(25.0f, 55.0f));
    leaf.droop_power = 1.3f;
    leaf.side_bend = random_.Uniform(-0.3f, 0.3f);
    leaf.length = random_.Uniform(0.045f, 0.08f) * (1.0f - 0.3f * age);
    leaf.half_width = leaf.length * random_.Uniform(0.2f, 0.27f);
    leaf.outline = LeafOutline::kElliptic;
    leaf.fold = random_.Uniform(0.1f, 0.3f);
    leaf.fold_power = 1.5f;
    leaf.twist = random_.Uniform(-0.6f, 0.6f);
    leaf.wave_amplitude = random_.Uniform(0.0f, 0.03f);
    leaf.wave_count = random_.Uniform(2.0f, 4.0f);
    leaf.wave_phase = random_.Uniform(0.0f, 1.0f);
    plan_->leaves.push_back(leaf);
  }

  PlantRandom& random_;
  PlantPlan* plan_;
  float phyllotaxis_ = 0;
};

}  // namespace

PlantPlan PlanBushy(PlantRandom& random) {
  PlantPlan plan;
  plan.leaf_rgb = {0.03f, 0.10f, 0.018f};  // dark green
  plan.stem_rgb = {0.07f, 0.12f, 0.035f};
  plan.venation = Venation::kPinnate;
  plan.leaf_across_ratio = 0.6f;
  const float lean_azimuth = random.Uniform(0.0f, 2.0f * kPi);
  const float lean = Degrees(random.Uniform(0.0f, 7.0f));
  Branch main;
  main.start = {0.0f, 0.0f, -0.01f};
  main.direction = Heading(lean_azimuth, kPi / 2.0f - lean);
  main.length = random.Uniform(0.06f, 0.09f);
  main.radius = 0.006f;
  main.depth = 0;
  BushBuilder(random, &plan).Grow(main);
  return plan;
}

}  // namespace avc::sim
