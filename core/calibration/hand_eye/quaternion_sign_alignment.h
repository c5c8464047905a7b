#pragma once

// The sign fix that makes Dornaika & Horaud's quaternion closed form reliable (OpenCV's Horaud
// and Daniilidis hand-eye needed the same fix, opencv/opencv#24897). Its objective
// sum |a_i (x) x - z (x) b_i|^2 changes when one a_i or b_i flips sign, and rotation-to-quaternion
// conversions return either sign. Relative motions are conjugate, A_j A_r^-1 = Z (B_j B_r^-1) Z^-1,
// so scalar(a_j (x) a_r*) = scalar(b_j (x) b_r*) exactly when the signs agree: b_j is flipped
// until they do.

#include <vector>

#include "core/calibration/hand_eye/quaternion_matrices.h"

namespace avc::calibration::hand_eye {

// The reference pose r whose relative rotations to all other poses stay furthest from 180 deg
// (maximises min_j |scalar(a_j (x) a_r*)|), so no sign decision is made on a near-zero scalar.
// The lowest index wins ties. Requires a non-empty `a`.
size_t ChooseSignReference(const std::vector<QuaternionVector>& a);

// `b` with each b_j's sign chosen so that scalar(a_j (x) a_r*) and scalar(b_j (x) b_r*) have the
// same sign, r = ChooseSignReference(a). The a_i are left as they are. Sizes must match.
std::vector<QuaternionVector> AlignQuaternionSigns(const std::vector<QuaternionVector>& a,
                                                   const std::vector<QuaternionVector>& b);

}  // namespace avc::calibration::hand_eye
