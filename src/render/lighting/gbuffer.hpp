// The G-buffer shared by the deferred techniques plus the renderer's
// depth-stencil target. Two layouts (--gbuffer): the reference's five targets
// (full), or two packed targets (compact); shaders/common/gbuffer.glsl writes
// and reads both, picked by the COMPACT_GBUFFER define the renderer sets. A
// third, thin, holds only what the light pre-pass lights with; programs that
// write or read it are built with defines(). Its targets are transient
// resources of the frame graph ("gbuffer.<target>"), made by the pass that
// fills them and shared with other targets once the last reader has run.
#pragma once

#include <array>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "gfx/gl_object.hpp"
#include "gfx/shader_library.hpp"
#include "gfx/shader_program.hpp"
#include "render/shader_globals.hpp"
#include "render/lighting/sample_rate.hpp"
#include "render/frame/frame_context.hpp"
#include "components/technique_options.hpp"

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

  // With MSAA, whether the geometry pass then marks the edges in the stencil
  // (deferred/edges.frag): fragment lighting passes and light volumes test
  // it; the compute lighting stage finds the edges itself (common/lighting_main.glsl).
  enum class EdgeMarks : std::uint8_t { Stencil, None };

  // `samples` > 1: multisampled targets (the renderer's --msaa), edges marked
  // after the geometry pass as `marks` says.
  GBuffer(gfx::ShaderLibrary& shaders, GBufferLayout layout, int samples, EdgeMarks marks = EdgeMarks::Stencil);

  // The frame's targets as "gbuffer.<target>" transients of `pass`, which
  // writes them first, `size` pixels with samples(); the scene depth
  // (`depth`) is the depth-stencil they are drawn with.
  void create_targets(render::PassBuilder& pass, glm::ivec2 size, render::ResourceId depth);
  // Declares a sampled read of every target (a pass that shades from them).
  void read_targets(render::PassBuilder& pass) const;
  // This frame's targets (after create_targets).
  [[nodiscard]] std::span<const render::ResourceId> resources() const { return {resources_.data(), targets().size()}; }

  // Fills the G-buffer with the opaque and masked draw items; with MSAA and
  // EdgeMarks::Stencil then sets kEdgeStencilBit on the pixels whose samples differ.
  void draw_geometry(const render::PassResources& res, gfx::ShaderProgram& program, const render::FrameContext& frame);
  // Binds the targets to texture units 0.. for lighting passes.
  void bind_textures(const render::PassResources& res) const;
  // A full-screen pass with `programs` reading the G-buffer into the lighting
  // targets (lighting_framebuffer in render/frame/frame_context.hpp), per pixel or per sample.
  void draw_fullscreen(const render::PassResources& res, const SampleRatePrograms& programs, const render::FrameContext& frame,
                       const render::FrameTargets& targets) const;

  [[nodiscard]] std::span<const Target> targets() const { return targets(layout_); }
  [[nodiscard]] GBufferLayout layout() const { return layout_; }
  // The defines a program that writes or reads this G-buffer is built with on
  // top of the renderer's globals (which carry COMPACT_GBUFFER).
  [[nodiscard]] std::vector<gfx::ShaderDefine> defines() const;
  [[nodiscard]] int samples() const { return samples_; }
  // Bytes per pixel of the targets plus the shared depth-stencil
  // (gfx::kDepthStencilFormat, 8 bytes), from their GL formats.
  [[nodiscard]] static std::size_t bytes_per_pixel(GBufferLayout layout);
  // The COMPACT_GBUFFER row of the shader globals (render/shader_globals.hpp).
  static void layout_defines(const render::GlobalDefineInputs& inputs, std::vector<gfx::ShaderDefine>& defines) {
    if (inputs.settings.technique_options.gbuffer_layout == GBufferLayout::Compact) defines.push_back({"COMPACT_GBUFFER"});
  }
  [[nodiscard]] static std::span<const Target> targets(GBufferLayout layout);

  // The G-buffer a frame's graph holds, whichever pass made it: its layout
  // (told by its target names) and its targets in layout order; nullopt when
  // the graph has none.
  struct Found {
    GBufferLayout layout;
    std::array<render::ResourceId, kMaxTargets> resources;
    std::size_t count;
  };
  [[nodiscard]] static std::optional<Found> find(const render::FrameGraph& graph);
  // The defines a program reading a G-buffer of `layout` is built with.
  [[nodiscard]] static std::vector<gfx::ShaderDefine> defines(GBufferLayout layout);
  // Binds the targets of `found` to texture units 0.. (a pass that declared reads of them).
  static void bind_textures(const render::PassResources& res, const Found& found);

 private:
  void mark_edges(const render::PassResources& res) const;

  GBufferLayout layout_;
  int samples_;
  gfx::ShaderProgram* edges_ = nullptr;  // with MSAA and stencil marks: shaders/deferred/edges.frag
  glm::ivec2 size_{0};
  std::array<render::ResourceId, kMaxTargets> resources_;  // this frame's, set by create_targets
  render::ResourceId depth_;
  render::FullscreenTriangle fullscreen_;
};

}  // namespace atrium::lighting
