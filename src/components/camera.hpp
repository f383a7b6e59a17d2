// The camera: an entity with a Transform (position and orientation) and a Camera
// (projection). CameraAngles keeps yaw and pitch for controllers and stored views,
// which set the Transform's rotation from them. CameraCut marks a jump.
#pragma once

#include <optional>

namespace atrium {

struct Camera {
  float vertical_fov_degrees = 60.0f;
  // Metres. Absent, the camera system fits them each frame to the scene's
  // bounds and the camera's place in them (fit_depth_planes).
  std::optional<float> near_plane;
  std::optional<float> far_plane;
};

struct CameraAngles {
  float yaw_degrees = 0.0f;    // 0 looks along -Z, 90 along +X
  float pitch_degrees = 0.0f;  // positive looks up
};

// Put on a camera entity by whatever moves it somewhere new at once (apply_view:
// a stored view, --camera, the page's view switch), as engines flag a camera
// cut: what the last frame showed says little about the next, so what keeps
// history across frames (occlusion culling, the shadow maps' choice) learns
// anew. The camera system turns it into ViewState::cut for one frame and
// takes it off.
struct CameraCut {};

// Lets the fly-camera system steer a camera (systems/fly_camera.hpp).
struct FlyCamera {
  float speed = 3.0f;                   // metres per second; the scroll wheel scales it
  float fast_factor = 4.0f;             // with Shift held
  float look_degrees_per_pixel = 0.15f; // mouse drag
  float turn_degrees_per_second = 90.0f;// arrow keys
};

}  // namespace atrium
