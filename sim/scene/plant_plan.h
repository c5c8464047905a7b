#pragma once

// The plan of a plant: the organs a preset lays out, before they are meshed. Presets decide
// shape and placement (random per organ); organ_mesh turns a plan into triangles at any
// resolution. Coordinates are relative to the plant base (the soil surface on the z axis).

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "core/geometry/mesh.h"
#include "sim/scene/material.h"
#include "sim/scene/plant_random.h"

namespace avc::sim {

enum class LeafOutline {
  kLanceolate,  // broad base tapering to a point (bromeliad, aloe)
  kOvate,       // round, widest below the middle (pumpkin, brassica)
  kStrap,       // long, nearly parallel margins (maize, cordyline)
  kElliptic,    // small pointed ellipse (chilli)
};

struct LeafSpec {
  Eigen::Vector3f base = Eigen::Vector3f::Zero();  // where the midrib starts
  float azimuth = 0;         // heading of the midrib at the base, about z (radians)
  float elevation = 0;       // angle of the midrib above horizontal at the base (radians)
  float droop = 0;           // elevation lost from base to tip (radians; > 0 arches down)
  float droop_power = 1.5f;  // 1: even curvature; > 1: bending concentrated towards the tip
  float side_bend = 0;       // heading change from base to tip (radians)
  float length = 0.1f;       // midrib length (m)
  float half_width = 0.02f;  // greatest half-width (m)
  LeafOutline outline = LeafOutline::kElliptic;
  float fold = 0.2f;         // margin lift as a fraction of the local half-width (< 0 domed)
  float fold_power = 1.5f;   // cross-section: 1 = V about the midrib, 2 = U
  float twist = 0;           // rotation about the midrib from base to tip (radians)
  float wave_amplitude = 0;  // margin ruffle as a fraction of the local half-width
  float wave_count = 0;      // ruffle periods along the leaf
  float wave_phase = 0;
  float age = 0;  // 0 oldest .. 1 youngest: younger leaves are lighter
};

struct TubeSpec {
  std::vector<Eigen::Vector3f> points;  // centre line from the base; at least 2
  std::vector<float> radii;             // one per point
  int32_t label = geometry::labels::kStem;
};

struct PlantPlan {
  std::vector<TubeSpec> tubes;  // stems and petioles
  std::vector<LeafSpec> leaves;
  // Appearance of the species.
  Eigen::Vector3f leaf_rgb{0.05f, 0.15f, 0.03f};
  Eigen::Vector3f stem_rgb{0.07f, 0.13f, 0.035f};
  Venation venation = Venation::kPinnate;
  // Leaf mesh segments across per segment along (leaves of this shape stay well proportioned).
  float leaf_across_ratio = 0.5f;
};

PlantPlan PlanRosette(PlantRandom& random);
PlantPlan PlanBroadleaf(PlantRandom& random);
PlantPlan PlanStrap(PlantRandom& random);
PlantPlan PlanBushy(PlantRandom& random);

// Golden angle (radians): successive leaves of a spiral phyllotaxis.
inline constexpr float kGoldenAngle = 2.39996323f;
inline constexpr float kPi = 3.14159265358979f;
inline constexpr float Degrees(float degrees) { return degrees * kPi / 180.0f; }

// Direction with the given heading about z and elevation above horizontal.
Eigen::Vector3f Heading(float azimuth, float elevation);

// A curve that starts at start with the given heading and bends as a leaf midrib does
// (elevation falls by droop * (s/length)^droop_power, azimuth turns by side_bend * s/length).
// Fills segments + 1 points (and unit tangents when tangents is not null).
void ArcCurve(const Eigen::Vector3f& start, float azimuth, float elevation, float droop,
              float droop_power, float side_bend, float length, int segments,
              std::vector<Eigen::Vector3f>* points, std::vector<Eigen::Vector3f>* tangents);

}  // namespace avc::sim
