// The seed's camera: on the line from the solid's centre through the player, looking at the centre,
// turned so that the player's floor reads level: the screen's right is the way the player walks
// (along the face, across its gravity), its up then against the gravity. (Seen from the centre's
// line the face is often oblique, as on a tetrahedron: taking "up" straight from the gravity would
// show floors tilted.) When the player changes
// face the wanted orientation turns at once; the camera follows it by quaternion slerp, at a rate
// set in seconds (so the same at any frame rate) and never faster than a top angular speed, so an
// edge never flips, jumps or rolls the view.
//
// Deterministic: step it with the simulation (lerp once per fixed step) and draw between the last
// two poses (CameraPose::between), so a screenshot of frame N is the same on every machine.
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace platon::camera {

// What the camera follows, in the stage's 3D units.
struct CameraTarget {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();   // the solid's centre
  Eigen::Vector3d player = Eigen::Vector3d::UnitZ();  // the player, on a face
  Eigen::Vector3d down = -Eigen::Vector3d::UnitY();   // the player's down (need not be unit length)
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // out of the player's face
  double viewHeight = 1;                              // how far above the player the eye sits (see CameraSettings)
};

struct CameraSettings {
  double verticalFov = 0.785398;  // radians (45 degrees)
  double settleSeconds = 0.25;    // time constant: 63% of a turn after this long
  double topSpeed = 3.5;          // radians per second, the fastest the view ever turns
  double zoomSeconds = 0.25;      // the distance eases the same way
};

// Where the eye is and how it is turned: the eye looks along orientation * (0, 0, -1) with up
// orientation * (0, 1, 0) (OpenGL's convention).
struct CameraPose {
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double distance = 1;  // from the centre to the eye

  Eigen::Vector3d eye() const { return centre + orientation * Eigen::Vector3d(0, 0, distance); }
  Eigen::Vector3d forward() const { return orientation * Eigen::Vector3d(0, 0, -1); }
  Eigen::Vector3d up() const { return orientation * Eigen::Vector3d::UnitY(); }
  // The pose a fraction t in [0, 1] of the way from a to b (slerp, the short way).
  static CameraPose between(const CameraPose& a, const CameraPose& b, double t);
};

class Camera {
 public:
  explicit Camera(CameraSettings settings = {}) : settings_(settings) {}

  // Places the camera on the target at once (the seed's set(); width and height give the aspect).
  void set(const CameraTarget& target, int width, int height);
  // Moves toward the target by `seconds` of time (the seed's lerp()).
  void lerp(const CameraTarget& target, double seconds);
  void resize(int width, int height);

  const CameraPose& pose() const { return pose_; }
  const CameraSettings& settings() const { return settings_; }
  double aspect() const { return aspect_; }

  // The pose the camera turns toward for this target.
  static CameraPose wanted(const CameraTarget& target);

 private:
  CameraSettings settings_;
  CameraPose pose_;
  double aspect_ = 16.0 / 9.0;
};

// Column-major 4x4 matrices for OpenGL: the view of a pose and a perspective projection whose near
// and far planes hold a solid of radius `radius` around the pose's centre.
Eigen::Matrix4f viewMatrix(const CameraPose& pose);
Eigen::Matrix4f projectionMatrix(const CameraPose& pose, double verticalFov, double aspect, double radius);

}  // namespace platon::camera
