// Atrium's depth convention, the one place C++ states it (GLSL twin: the
// constants and view_depth_from_depth in shaders/common/frame.glsl, compared by
// a test): reversed Z in a 32-bit float depth buffer, clip space z in [0, 1]
// (glClipControl GL_ZERO_TO_ONE), the near plane at depth 1 and the far plane
// at 0. Floats are densest near 0, and reversing puts that density on distant
// geometry, where a standard depth buffer runs out: a 1 cm near plane and a
// 10 km far plane still keep surfaces a few centimetres apart at 10 km.
#pragma once

#include <glm/glm.hpp>

#include "gfx/gl.hpp"

namespace atrium::gfx {

inline constexpr float kDepthFar = 0.0f;   // the clear value: no geometry
inline constexpr float kDepthNear = 1.0f;
inline constexpr GLenum kDepthCloser = GL_GREATER;
inline constexpr GLenum kDepthCloserOrEqual = GL_GEQUAL;
inline constexpr GLenum kDepthFartherOrEqual = GL_LEQUAL;
inline constexpr GLenum kDepthStencilFormat = GL_DEPTH32F_STENCIL8;

// Sets the clip convention above on the current context (GL state that
// outlives any one pass; the renderer sets it every frame).
void use_depth_convention();

// Right-handed perspective projection (camera looking down -Z) that maps view
// depth `near` to depth 1 and `far` to depth 0.
[[nodiscard]] glm::mat4 perspective(float vertical_fov_radians, float aspect, float near, float far);

// View depth (metres in front of the camera) of a depth-buffer value written
// with perspective(..., near, far); `far` for kDepthFar.
[[nodiscard]] float view_depth_from_depth(float depth, float near, float far);

}  // namespace atrium::gfx
