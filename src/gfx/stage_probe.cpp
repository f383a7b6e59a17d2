#include "gfx/stage_probe.hpp"

#include <algorithm>
#include <functional>
#include <stdexcept>
#include <string_view>

#include "gfx/gl_features.hpp"
#include "gfx/gl_object.hpp"
#include "gfx/pass_timer.hpp"
#include "gfx/shader_program.hpp"

namespace atrium::gfx {
namespace {

// GL_NV_shader_thread_group's queries (its header names are not in every epoxy).
constexpr GLenum kWarpSizeNv = 0x9339, kWarpsPerSmNv = 0x933A, kSmCountNv = 0x933B;
constexpr std::size_t kMaxSmIds = 256;  // the census buffer's length (shaders/probe/census.glsl)

bool has_gl_extension(std::string_view name) {
  GLint count = 0;
  glGetIntegerv(GL_NUM_EXTENSIONS, &count);
  for (GLint i = 0; i < count; ++i) {
    const auto* extension = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, static_cast<GLuint>(i)));
    if (extension && name == extension) return true;
  }
  return false;
}

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

std::vector<std::uint32_t> read_census(const Buffer& census) {
  std::vector<std::uint32_t> counts(kMaxSmIds);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(census.id(), 0, static_cast<GLsizeiptr>(counts.size() * sizeof(std::uint32_t)), counts.data());
  while (!counts.empty() && counts.back() == 0) counts.pop_back();
  return counts;
}

}  // namespace

std::uint32_t StageReach::sms_reached() const {
  return static_cast<std::uint32_t>(std::count_if(invocations.begin(), invocations.end(), [](std::uint32_t n) { return n > 0; }));
}

double StageProbeResult::flops() const { return static_cast<double>(size.x) * size.y * iterations * 16.0; }

StageProbeResult run_stage_probe(glm::ivec2 size, std::uint32_t iterations, std::uint32_t runs) {
  const GlFeatures& features = gl_features();
  if (!features.full_tier()) {
    throw std::runtime_error("the stage probe needs compute shaders and storage buffers, and this context has " +
                             features.missing_for_full_tier());
  }
  StageProbeResult result;
  result.size = size;
  result.iterations = iterations;
  result.runs = std::max(runs, 1u);
  result.sm_ids = has_gl_extension("GL_NV_shader_thread_group");
  std::vector<ShaderDefine> defines;
  if (result.sm_ids) {
    GLint value = 0;
    glGetIntegerv(kSmCountNv, &value);
    result.sm_count = static_cast<std::uint32_t>(std::max(value, 0));
    glGetIntegerv(kWarpSizeNv, &value);
    result.warp_size = static_cast<std::uint32_t>(std::max(value, 0));
    glGetIntegerv(kWarpsPerSmNv, &value);
    result.warps_per_sm = static_cast<std::uint32_t>(std::max(value, 0));
    defines.push_back({"HAS_SM_ID"});
  }
  ShaderProgram compute = ShaderProgram::load({"probe/census.comp"}, defines);
  ShaderProgram fragment = ShaderProgram::load({"post/fullscreen.vert", "probe/census.frag"}, defines);

  Texture target = create_render_target(GL_R32F, size.x, size.y);
  Framebuffer framebuffer = create_framebuffer();
  glNamedFramebufferTexture(framebuffer.id(), GL_COLOR_ATTACHMENT0, target.id(), 0);
  require_complete(framebuffer.id(), "stage probe");
  VertexArray triangle = create_vertex_array();
  Buffer census = create_buffer();
  glNamedBufferStorage(census.id(), kMaxSmIds * sizeof(std::uint32_t), nullptr, GL_DYNAMIC_STORAGE_BIT);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, census.id());
  for (ShaderProgram* program : {&compute, &fragment}) program->set("u_iterations", iterations);

  auto run_compute = [&] {
    compute.use();
    glBindImageTexture(0, target.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
    glDispatchCompute(static_cast<GLuint>((size.x + 7) / 8), static_cast<GLuint>((size.y + 7) / 8), 1);
  };
  auto run_fragment = [&] {
    fragment.use();
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
    glViewport(0, 0, size.x, size.y);
    glBindVertexArray(triangle.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
  };
  struct Stage {
    const char* name;
    ShaderProgram* program;
    std::function<void()> run;
    StageReach* reach;
  };
  const Stage stages[] = {{"compute", &compute, run_compute, &result.compute}, {"fragment", &fragment, run_fragment, &result.fragment}};

  // The census: each invocation counts itself once on its SM; no timing.
  for (const Stage& stage : stages) {
    if (!result.sm_ids) break;
    const std::uint32_t zero = 0;
    glClearNamedBufferData(census.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    stage.program->set("u_census", 1);
    stage.run();
    stage.reach->invocations = read_census(census);
    stage.program->set("u_census", 0);
  }
  // The timing: one warm-up, then `runs` passes each timed on its own.
  PassTimer timer;
  result.timing = timer.method_name();
  for (const Stage& stage : stages) {
    stage.run();
    std::vector<double> times;
    for (std::uint32_t run = 0; run < result.runs; ++run) {
      timer.begin_frame();
      timer.begin_pass(stage.name);
      stage.run();
      timer.end_pass();
      timer.end_frame();
      timer.wait_for_latest();
      if (!timer.latest().empty()) times.push_back(timer.latest().back().milliseconds);
    }
    stage.reach->milliseconds = median(times);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return result;
}

}  // namespace atrium::gfx
