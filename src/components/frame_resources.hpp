// Registry resources (one per world) that systems share each frame. Plain data.
#pragma once

#include <string>
#include <string_view>

#include <glm/glm.hpp>

#include "components/technique_options.hpp"

namespace atrium {

// Size of the image the renderer produces, in pixels.
struct Viewport {
  glm::ivec2 size{1280, 720};
};

// Camera matrices for the frame, written by the camera system (PostUpdate).
struct ViewState {
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};
  glm::mat4 view_projection{1.0f};
  glm::vec3 camera_position{0.0f};
  float near_plane = 0.05f;
  float far_plane = 200.0f;
  bool cut = false;  // the camera jumped this frame (CameraCut): the last frame's history does not hold
};

// Scene-wide lighting settings.
struct SceneSettings {
  glm::vec3 ambient{0.03f};
  glm::vec3 background{0.0f};
  float exposure = 1.0f;
};

// Where occlusion culling tests what the depth hides (--culling): on the CPU,
// from the depth read back once or twice a frame (where a read-back costs
// nothing, as on a software renderer, measured faster), or on the GPU with
// nothing read back (render/culling/gpu_occlusion_culling.hpp). Automatic
// picks the CPU on a software renderer and the GPU elsewhere.
enum class CullingDevice { Automatic, Cpu, Gpu };
struct CullingDeviceName {
  std::string_view name;
  CullingDevice device;
};
inline constexpr CullingDeviceName kCullingDevices[] = {{"auto", CullingDevice::Automatic}, {"cpu", CullingDevice::Cpu}, {"gpu", CullingDevice::Gpu}};

// What the MeshRenderer draws with: a mode name from the technique table and a
// shading model name from render/lighting/shading_model.hpp.
struct RendererSettings {
  std::string mode = "forward";
  std::string shading = "pbr";  // pbr, blinn-phong or phong
  std::string debug_view;       // empty, or a name from render/debug/debug_views.hpp
  TechniqueOptions technique_options;
  bool present_to_window = false;  // blit the final image to the default framebuffer
  bool gbuffer_thumbnails = false; // render the overlay's G-buffer thumbnails (G-buffer modes)
  bool frustum_culling = true;     // off: every pass draws the whole scene (--no-culling, for comparisons)
  bool occlusion_culling = true;   // with frustum culling: leave out what the depth buffer hides (--no-occlusion-culling)
  CullingDevice culling_device = CullingDevice::Automatic;  // where occlusion culling runs (--culling)
  int shadows = 0;                 // lights given shadow maps each frame (--shadows K); 0 is off
  bool redraw_shadows = false;     // draw every map every frame, cached or not (bench --shadow-redraw)
  bool poison_targets = false;     // mark each target before its first write, so unwritten texels show (--poison-targets)
};

}  // namespace atrium
