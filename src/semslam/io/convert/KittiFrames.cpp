#include "semslam/io/convert/KittiFrames.h"

namespace semslam {

const SE3& kittiCameraToBody() {
  static const SE3 s = [] {
    Matrix3 r;
    r << 0.0, 0.0, 1.0,  //
        -1.0, 0.0, 0.0,  //
        0.0, -1.0, 0.0;
    return SE3(SO3(r), Point3::Zero());
  }();
  return s;
}

Point3 kittiBodyPoint(const Point3& cameraPoint) { return kittiCameraToBody().rotation().matrix() * cameraPoint; }

SE3 kittiBodyPose(const SE3& cameraToWorld) {
  const SE3& s = kittiCameraToBody();
  return s.compose(cameraToWorld).compose(s.inverse());
}

}  // namespace semslam
