#include "core/calibration/hand_eye/quaternion_sign_alignment.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace avc::calibration::hand_eye {
namespace {

// scalar(p (x) q*) = p . q for quaternions as 4-vectors.
double RelativeScalar(const QuaternionVector& p, const QuaternionVector& q) { return p.dot(q); }

}  // namespace

size_t ChooseSignReference(const std::vector<QuaternionVector>& a) {
  if (a.empty()) throw std::invalid_argument("ChooseSignReference: no quaternions");
  size_t best = 0;
  double best_margin = -1;
  for (size_t r = 0; r < a.size(); ++r) {
    double margin = std::numeric_limits<double>::infinity();
    for (size_t j = 0; j < a.size(); ++j) {
      margin = std::min(margin, std::abs(RelativeScalar(a[j], a[r])));
    }
    if (margin > best_margin) {
      best_margin = margin;
      best = r;
    }
  }
  return best;
}

std::vector<QuaternionVector> AlignQuaternionSigns(const std::vector<QuaternionVector>& a,
                                                   const std::vector<QuaternionVector>& b) {
  if (a.size() != b.size()) {
    throw std::invalid_argument("AlignQuaternionSigns: a and b differ in size");
  }
  if (a.empty()) return {};
  const size_t r = ChooseSignReference(a);
  std::vector<QuaternionVector> aligned = b;
  for (size_t j = 0; j < a.size(); ++j) {
    const bool a_positive = RelativeScalar(a[j], a[r]) >= 0;
    const bool b_positive = RelativeScalar(b[j], b[r]) >= 0;
    if (a_positive != b_positive) aligned[j] = -b[j];
  }
  return aligned;
}

}  // namespace avc::calibration::hand_eye
