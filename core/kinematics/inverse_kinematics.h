#pragma once

// Analytic inverse kinematics of UR-structured arms (UR3/5/10 CB3 and e-Series share it): three
// parallel shoulder/elbow/wrist-1 axes and a spherical-offset wrist give up to 8 closed-form
// branches (shoulder left/right x wrist flip x elbow up/down). A numerical refinement handles
// arms whose DH set departs from that structure (factory-calibrated or simulated "true" arms).

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "core/kinematics/dh_parameters.h"

namespace avc::kinematics {

// Empty when `dh` has the UR structure the analytic solver needs (a1 = a4 = a5 = a6 = 0,
// d2 = d3 = 0, alpha = (pi/2, 0, 0, pi/2, -pi/2, 0), a2, a3, d4, d6 non-zero); else which entry
// breaks it. Theta offsets and the lengths d1, a2, a3, d4, d5, d6 are free.
std::string UrStructureError(const DhParameters& dh);

// `dh` with the entries that break the UR structure reset to the structure's values: the
// closest arm the analytic solver can handle (a starting point for RefineInverseKinematics).
DhParameters NearestUrStructure(const DhParameters& dh);

// Every joint vector (wrapped to (-pi, pi]) whose flange pose is T_base_flange, at most 8,
// without duplicates, in a fixed branch order. Empty when the pose is out of reach. At the wrist
// singularity (joints 4 and 6 aligned) joint 6 is not determined: it is set to `singular_q6` and
// the remaining joints are solved for it. Throws std::invalid_argument when `dh` lacks the UR
// structure or the pose is not a finite rigid transform.
std::vector<JointVector> InverseKinematics(const DhParameters& dh,
                                           const Eigen::Isometry3d& T_base_flange,
                                           double singular_q6 = 0.0);

// Joint vectors (wrapped to (-pi, pi]) whose flange pose under `dh` is T_base_flange, for an arm
// close to the UR structure (a factory-calibrated or simulated "true" arm, millimetre and
// milliradian departures): the analytic branches of NearestUrStructure(dh), seeded two ways and
// refined by RefineInverseKinematics on `dh`. Every returned vector reproduces the pose; all
// branches are found away from singularities, while within a few degrees (or centimetres) of a
// wrist, elbow or shoulder singularity two nearby branches may come back as one. Equals
// InverseKinematics (to rounding) when `dh` has the structure. Throws like InverseKinematics.
std::vector<JointVector> InverseKinematicsRefined(const DhParameters& dh,
                                                  const Eigen::Isometry3d& T_base_flange,
                                                  double singular_q6 = 0.0);

// Of all solutions and their +-2 pi equivalents within the joint limits, the one nearest to
// `current` (Euclidean distance in joint space; the first such solution on ties). nullopt when
// `solutions` is empty. Throws std::invalid_argument when `current` is not finite.
std::optional<JointVector> ClosestSolution(const std::vector<JointVector>& solutions,
                                           const JointVector& current);

// Newton iterations on the full pose from `seed` for any DH set. Returns the joints (within the
// joint limits) whose flange pose matches T_base_flange to `tolerance` (metres and radians), or
// nullopt when the iteration does not get there.
std::optional<JointVector> RefineInverseKinematics(const DhParameters& dh,
                                                   const Eigen::Isometry3d& T_base_flange,
                                                   const JointVector& seed,
                                                   double tolerance = 1e-11);

}  // namespace avc::kinematics
