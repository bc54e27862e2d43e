#include "semslam/models/Viewpoint.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace semslam {

namespace {

// atan2 in (−π, π]: atan2(−0.0, x < 0) gives −π, which is the same angle as +π.
double bearing(double y, double x) {
  const double t = std::atan2(y, x);
  return t == -std::numbers::pi ? std::numbers::pi : t;
}

}  // namespace

double viewpointAngle(const SE2& camera, const SE2& object, MatrixN<1, 3>* Hcamera, MatrixN<1, 3>* Hobject) {
  Matrix23 pWrtObject;
  Matrix2 pWrtPosition;  // R_oᵀ
  const Point2 p = object.transformTo(camera.translation(), Hobject ? &pWrtObject : nullptr,
                                      Hcamera ? &pWrtPosition : nullptr);
  const double rho2 = p.squaredNorm();
  if (rho2 == 0.0) throw std::domain_error("viewpointAngle: the camera is at the object's position");
  const MatrixN<1, 2> thetaWrtP(-p.y() / rho2, p.x() / rho2);
  if (Hcamera) {
    Hcamera->leftCols<2>() = thetaWrtP * pWrtPosition * camera.rotation().matrix();
    (*Hcamera)(0, 2) = 0.0;
  }
  if (Hobject) *Hobject = thetaWrtP * pWrtObject;
  return bearing(p.y(), p.x());
}

double viewpointAngle(const SE3& camera, const SE3& object, MatrixN<1, 6>* Hcamera, MatrixN<1, 6>* Hobject) {
  Matrix36 pWrtObject;
  Matrix3 pWrtPosition;  // R_oᵀ
  const Point3 p = object.transformTo(camera.translation(), Hobject ? &pWrtObject : nullptr,
                                      Hcamera ? &pWrtPosition : nullptr);
  const double rho2 = p.x() * p.x() + p.y() * p.y();
  if (rho2 == 0.0) throw std::domain_error("viewpointAngle: the camera is on the object's z axis");
  const MatrixN<1, 3> thetaWrtP(-p.y() / rho2, p.x() / rho2, 0.0);
  if (Hcamera) {
    Hcamera->leftCols<3>() = thetaWrtP * pWrtPosition * camera.rotation().matrix();
    Hcamera->rightCols<3>().setZero();
  }
  if (Hobject) *Hobject = thetaWrtP * pWrtObject;
  return bearing(p.y(), p.x());
}

}  // namespace semslam
