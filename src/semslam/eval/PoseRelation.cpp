#include "semslam/eval/PoseRelation.h"

#include <cmath>
#include <numbers>

#include "semslam/core/InputError.h"

namespace semslam {

PoseRelation parsePoseRelation(const std::string& name) {
  if (name == "trans_part") return PoseRelation::TranslationPart;
  if (name == "angle_deg") return PoseRelation::AngleDeg;
  if (name == "angle_rad") return PoseRelation::AngleRad;
  if (name == "rot_part") return PoseRelation::RotationPart;
  if (name == "full") return PoseRelation::Full;
  throw InputError("unknown pose relation '" + name + "' (expected trans_part, angle_deg, angle_rad, rot_part or full)");
}

std::string toString(PoseRelation relation) {
  switch (relation) {
    case PoseRelation::TranslationPart: return "trans_part";
    case PoseRelation::AngleRad: return "angle_rad";
    case PoseRelation::AngleDeg: return "angle_deg";
    case PoseRelation::RotationPart: return "rot_part";
    case PoseRelation::Full: return "full";
  }
  return "unknown";
}

std::string unitOf(PoseRelation relation) {
  switch (relation) {
    case PoseRelation::TranslationPart: return "m";
    case PoseRelation::AngleRad: return "rad";
    case PoseRelation::AngleDeg: return "deg";
    case PoseRelation::RotationPart:
    case PoseRelation::Full: return "";
  }
  return "";
}

double rotationAngle(const Matrix3& m) {
  // scipy Rotation.from_matrix: pick the largest of (m00, m11, m22, trace) for a well-conditioned quaternion.
  const double trace = m.trace();
  const double decision[4] = {m(0, 0), m(1, 1), m(2, 2), trace};
  int choice = 0;  // numpy argmax: the first of equal maxima
  for (int i = 1; i < 4; ++i) {
    if (decision[i] > decision[choice]) choice = i;
  }
  double q[4];  // x, y, z, w
  if (choice == 3) {
    q[0] = m(2, 1) - m(1, 2);
    q[1] = m(0, 2) - m(2, 0);
    q[2] = m(1, 0) - m(0, 1);
    q[3] = 1.0 + trace;
  } else {
    const int i = choice, j = (i + 1) % 3, k = (j + 1) % 3;
    q[i] = 1.0 - trace + 2.0 * m(i, i);
    q[j] = m(j, i) + m(i, j);
    q[k] = m(k, i) + m(i, k);
    q[3] = m(k, j) - m(j, k);
  }
  const double norm = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  const double vector = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]) / norm;
  const double w = std::abs(q[3]) / norm;
  return 2.0 * std::atan2(vector, w);
}

double poseErrorValue(const Matrix4& e, PoseRelation relation) {
  switch (relation) {
    case PoseRelation::TranslationPart: return e.block<3, 1>(0, 3).norm();
    case PoseRelation::AngleRad: return rotationAngle(e.block<3, 3>(0, 0));
    case PoseRelation::AngleDeg: return rotationAngle(e.block<3, 3>(0, 0)) * (180.0 / std::numbers::pi);
    case PoseRelation::RotationPart: return (e.block<3, 3>(0, 0) - Matrix3::Identity()).norm();
    case PoseRelation::Full: return (e - Matrix4::Identity()).norm();
  }
  return 0.0;
}

}  // namespace semslam
