// The overlay: a pass of the frame graph after the frame is presented to the
// window (a module of the window stage), timed with the others: a Dear ImGui
// panel over the window with frame rate and time, the last frame's pass timings, the mode,
// shading model, light count, triangles, draw calls, light-list overflow,
// estimated GPU memory and G-buffer thumbnails; and controls for mode, light
// count, light radius, shading model and debug view. F1 hides it.
#pragma once

#include <string>

#include "ecs/registry.hpp"

struct GLFWwindow;

namespace atrium {


// Sets up Dear ImGui on `window` (after register_input: ImGui's GLFW backend
// chains to the input system's callbacks) and adds its pass. The ImGui
// context lives as long as the registry's Overlay resource.
void register_overlay(ecs::Registry& registry, GLFWwindow* window);

}  // namespace atrium
