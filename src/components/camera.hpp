// The camera: an entity with a Transform (position and orientation) and a Camera
// (projection). CameraAngles keeps yaw and pitch for controllers and stored views,
// which set the Transform's rotation from them.
#pragma once

namespace atrium {

struct Camera {
  float vertical_fov_degrees = 60.0f;
  float near_plane = 0.05f;
  float far_plane = 200.0f;
};

struct CameraAngles {
  float yaw_degrees = 0.0f;    // 0 looks along -Z, 90 along +X
  float pitch_degrees = 0.0f;  // positive looks up
};

}  // namespace atrium
