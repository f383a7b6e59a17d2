// The full-screen lighting pass of the deferred techniques (deferred,
// deferred-radius, tiled-deferred, clustered-deferred), in the stage the frame
// runs it in (--lighting-stage). It reads the G-buffer and the light data and
// writes the lit HDR colour and, with the split on, the diffuse and specular
// light sums. The fragment stage draws a full-screen triangle per sample rate
// (sample_rate.hpp); the compute stage runs one invocation per pixel and
// stores each result with imageStore: on GPUs whose graphics pipeline reaches
// few of their cores (an H200's fragment shaders run on 4 of 132 SMs) the
// same shading runs on all of them. One GLSL file serves both stages
// (shaders/common/lighting_main.glsl).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "render/binding_slots.hpp"
#include "components/technique_options.hpp"
#include "gfx/shader_library.hpp"
#include "render/frame_graph.hpp"
#include "render/lighting/gbuffer.hpp"
#include "render/lighting/sample_rate.hpp"
#include "render/frame/frame_context.hpp"

namespace atrium::lighting {

using render::kDiffuseLightImageUnit, render::kDisplayImageUnit, render::kLitColorImageUnit, render::kSpecularLightImageUnit;

// The stage `options` ask for, Automatic resolved for the current context
// (never Automatic). Throws gfx::ResourceLimitError naming what is missing
// when the compute stage is asked for where it cannot run: the compute-free tier.
[[nodiscard]] LightingStage resolve_lighting_stage(const TechniqueOptions& options);
// The edge marks a G-buffer read only by full-screen lighting passes needs:
// none when those run in compute.
[[nodiscard]] GBuffer::EdgeMarks lighting_edge_marks(const TechniqueOptions& options);
[[nodiscard]] std::string_view lighting_stage_name(LightingStage stage);

// Runs a compute program over every pixel of `size` in the program's own work
// group size (ShaderProgram::work_group_size, read once at link): the shader's layout is the one fact.
void dispatch_per_pixel(gfx::ShaderProgram& program, glm::ivec2 size);

// A full-screen pass that sums every light is split into runs of this many
// lights (or fewer) over `size` in `stage`, so that no dispatch or draw
// runs longer than about 20 ms on an H200: kLightEvaluationsPerRun evaluations
// a run (the compute stage's 2^33 at 4.2e11 a second; the fragment stage's
// 2^28 at 1.3e10, its 4 SMs of 132), and never more than kMostLightsPerRun,
// which keeps a pixel's loop under llvmpipe's cap. With `msaa` samples every
// pixel counts as that many: an edge pixel shades each of them, and a frame
// may be edges throughout. At 2^20 lights and 1080p a single dispatch took
// 5.2 s (docs/benchmarks.md).
inline constexpr std::uint64_t kComputeEvaluationsPerRun = std::uint64_t{1} << 33;
inline constexpr std::uint64_t kFragmentEvaluationsPerRun = std::uint64_t{1} << 28;
inline constexpr std::uint32_t kMostLightsPerRun = 16384;
[[nodiscard]] std::uint32_t lights_per_run(glm::ivec2 size, int msaa, LightingStage stage);

// Binds the lit targets a compute lighting pass stores to (the HDR colour and,
// with the split on, the two light sums) at their image units with `access`.
void bind_lit_images(const render::PassResources& res, const render::FrameContext& frame, GLenum access);

class LightingPass {
 public:
  // How a run writes the lit targets: Store replaces them; Add (a later run
  // of a pass split by lights, its shaders built with ADD_LIGHTS) adds its
  // sums to what the runs before it wrote.
  enum class Write { Store, Add };
  // `file` names the pass's GLSL without its stage's extension
  // ("tiled/lighting": tiled/lighting.frag or tiled/lighting.comp).
  LightingPass(gfx::ShaderLibrary& shaders, const std::string& file, std::vector<gfx::ShaderDefine> defines,
               const TechniqueOptions& options, Write write = Write::Store);

  [[nodiscard]] LightingStage stage() const { return compute_ ? LightingStage::Compute : LightingStage::Fragment; }
  // Calls `f` with each program (to set the same uniforms on all).
  void each(const std::function<void(gfx::ShaderProgram&)>& f) const;
  // Declares what the pass reads (the G-buffer, the lights and the shadow
  // atlas; its light lists are the technique's) and the lit targets it
  // writes, as the stage reaches them.
  void declare(render::PassBuilder& pass, const GBuffer& gbuffer, const render::FrameContext& frame) const;
  // Shades every pixel of the lit targets from the G-buffer.
  void run(const render::PassResources& res, const GBuffer& gbuffer, const render::FrameContext& frame, const render::FrameTargets& targets) const;

 private:
  std::optional<SampleRatePrograms> fragment_;
  gfx::ShaderProgram* compute_ = nullptr;
  Write write_;
};

}  // namespace atrium::lighting
