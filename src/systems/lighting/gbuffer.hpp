// The G-buffer shared by the deferred techniques plus the renderer's
// depth-stencil target. Two layouts (--gbuffer): the reference's five targets
// (full), or two packed targets (compact); shaders/common/gbuffer.glsl writes
// and reads both, picked by the COMPACT_GBUFFER define the renderer sets. A
// third, thin, holds only what the light pre-pass lights with; programs that
// write or read it are built with defines().
#pragma once

#include <array>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "gfx/gl_object.hpp"
#include "gfx/shader_library.hpp"
#include "gfx/shader_program.hpp"
#include "render/shader_globals.hpp"
#include "systems/lighting/sample_rate.hpp"
#include "systems/lighting/technique.hpp"
#include "systems/lighting/technique_options.hpp"

namespace atrium::lighting {

class GBuffer {
 public:
  struct Target {
    const char* name;
    GLenum format;
  };
  static constexpr std::size_t kMaxTargets = 5;
  // Full: formats chosen so that deferred matches forward shading: 32-bit float
  // positions, 16-bit unorm normals, 16-bit float emission, sRGB albedo.
  static constexpr std::array<Target, 5> kFullLayout{{{"position", GL_RGBA32F},
                                                      {"albedo", GL_SRGB8_ALPHA8},
                                                      {"normal", GL_RGBA16},
                                                      {"metallic-roughness", GL_RGBA8},
                                                      {"emissive", GL_RGBA16F}}};
  // Compact: albedo as above; normal (octahedral, 2x16 bits), emission (3 half
  // floats), metallic and roughness (8 bits each) and the distance to the camera
  // (32-bit float) packed into the four words of one integer target.
  static constexpr std::array<Target, 2> kCompactLayout{{{"albedo", GL_SRGB8_ALPHA8}, {"packed", GL_RGBA32UI}}};
  // Thin: the light pre-pass's normal and roughness (16-bit unorm each) and the
  // distance to the camera.
  static constexpr std::array<Target, 2> kThinLayout{{{"normal-roughness", GL_RGBA16}, {"distance", GL_R32F}}};

  // `samples` > 1: multisampled targets (the renderer's --msaa), edges marked
  // after the geometry pass.
  GBuffer(gfx::ShaderLibrary& shaders, GBufferLayout layout, int samples);

  // (Re)allocates the colour targets; depth and stencil are the renderer's.
  void resize(glm::ivec2 size, GLuint depth_stencil);

  // Fills the G-buffer with the opaque and masked draw items; with MSAA then
  // sets kEdgeStencilBit on the pixels whose samples differ.
  void draw_geometry(gfx::ShaderProgram& program, const FrameContext& frame);
  // Binds the targets to texture units 0.. for lighting passes.
  void bind_textures() const;
  // A full-screen pass with `programs` reading the G-buffer into the lighting
  // targets (FrameTargets::lighting_framebuffer), per pixel or per sample.
  void draw_fullscreen(const SampleRatePrograms& programs, const FrameTargets& targets) const;

  [[nodiscard]] std::span<const Target> targets() const { return targets(layout_); }
  [[nodiscard]] GBufferLayout layout() const { return layout_; }
  // The defines a program that writes or reads this G-buffer is built with on
  // top of the renderer's globals (which carry COMPACT_GBUFFER).
  [[nodiscard]] std::vector<gfx::ShaderDefine> defines() const;
  [[nodiscard]] GLuint texture(std::size_t index) const { return textures_[index].id(); }
  [[nodiscard]] glm::ivec2 size() const { return size_; }
  [[nodiscard]] int samples() const { return samples_; }
  // Bytes per pixel of the targets plus the shared depth-stencil
  // (gfx::kDepthStencilFormat, 8 bytes), from their GL formats.
  [[nodiscard]] static std::size_t bytes_per_pixel(GBufferLayout layout);
  // The COMPACT_GBUFFER row of the shader globals (render/shader_globals.hpp).
  static void layout_defines(const render::GlobalDefineInputs& inputs, std::vector<gfx::ShaderDefine>& defines) {
    if (inputs.settings.technique_options.gbuffer_layout == GBufferLayout::Compact) defines.push_back({"COMPACT_GBUFFER"});
  }
  [[nodiscard]] static std::span<const Target> targets(GBufferLayout layout);

 private:
  void mark_edges() const;

  GBufferLayout layout_;
  int samples_;
  gfx::ShaderProgram* edges_ = nullptr;  // with MSAA: shaders/deferred/edges.frag
  glm::ivec2 size_{0};
  std::array<gfx::Texture, kMaxTargets> textures_;
  gfx::Framebuffer framebuffer_;
  FullscreenTriangle fullscreen_;
};

}  // namespace atrium::lighting
