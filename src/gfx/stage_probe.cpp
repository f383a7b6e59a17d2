#include "gfx/stage_probe.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <string_view>

#include "gfx/depth.hpp"
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

void require_full_tier(std::string_view probe) {
  const GlFeatures& features = gl_features();
  if (!features.full_tier()) {
    throw std::runtime_error("the " + std::string(probe) + " needs compute shaders and storage buffers, and this context has " +
                             features.missing_for_full_tier());
  }
}

// `runs` runs of `run`, each timed on its own after `prepare` (untimed), after
// one warm-up: the median.
double median_time(PassTimer& timer, const char* name, std::uint32_t runs, const std::function<void()>& prepare,
                   const std::function<void()>& run) {
  prepare();
  run();
  std::vector<double> times;
  for (std::uint32_t i = 0; i < runs; ++i) {
    prepare();
    timer.begin_frame();
    timer.begin_pass(name);
    run();
    timer.end_pass();
    timer.end_frame();
    timer.wait_for_latest();
    if (!timer.latest().empty()) times.push_back(timer.latest().back().milliseconds);
  }
  return median(times);
}

// The raster probe's sheets: a grid of square cells `cell` pixels a side,
// two triangles each, per layer, in clip space. Vertices sit at a quarter and
// three eighths of a pixel off the grid, so that no edge passes through a
// pixel centre and the two sides' rules for ties never decide a pixel.
// Layers are planes tilted in x, their vertices bumped off them, the farthest
// (the smallest depth: gfx/depth.hpp) first.
struct Sheets {
  std::vector<float> positions;  // xyz a vertex
  std::vector<std::uint32_t> indices;
};

Sheets make_sheets(glm::ivec2 size, int cell, std::uint32_t layers) {
  const int cells_x = (size.x + cell - 1) / cell, cells_y = (size.y + cell - 1) / cell;
  const auto row = static_cast<std::uint32_t>(cells_x + 1);
  Sheets sheets;
  for (std::uint32_t layer = 0; layer < layers; ++layer) {
    const float base = 0.2f + 0.6f * static_cast<float>(layer) / static_cast<float>(std::max(layers, 2u) - 1u);
    const auto first = static_cast<std::uint32_t>(sheets.positions.size() / 3);
    for (int j = 0; j <= cells_y; ++j) {
      for (int i = 0; i <= cells_x; ++i) {
        const float x = (static_cast<float>(cell * i) + 0.25f) / static_cast<float>(size.x) * 2.0f - 1.0f;
        const float y = (static_cast<float>(cell * j) + 0.375f) / static_cast<float>(size.y) * 2.0f - 1.0f;
        // Each vertex a little off the plane, so that neighbouring triangles
        // lie in planes of their own: a pixel given to the wrong one shows in depth.
        const float bump = 0.02f * static_cast<float>((static_cast<unsigned>(i) * 73856093u ^ static_cast<unsigned>(j) * 19349663u) % 1024u) / 1024.0f;
        sheets.positions.insert(sheets.positions.end(), {x, y, base + 0.05f * x + bump});
      }
    }
    for (int j = 0; j < cells_y; ++j) {
      for (int i = 0; i < cells_x; ++i) {
        const std::uint32_t a = first + static_cast<std::uint32_t>(j) * row + static_cast<std::uint32_t>(i), b = a + 1, c = a + row, d = c + 1;
        sheets.indices.insert(sheets.indices.end(), {a, b, d, a, d, c});
      }
    }
  }
  return sheets;
}

template <typename T>
std::vector<T> read_texture(const Texture& texture, glm::ivec2 size, GLenum format, GLenum type) {
  std::vector<T> texels(static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y));
  glGetTextureImage(texture.id(), 0, format, type, static_cast<GLsizei>(texels.size() * sizeof(T)), texels.data());
  return texels;
}

}  // namespace

std::uint32_t StageReach::sms_reached() const {
  return static_cast<std::uint32_t>(std::count_if(invocations.begin(), invocations.end(), [](std::uint32_t n) { return n > 0; }));
}

double StageProbeResult::flops() const { return static_cast<double>(size.x) * size.y * iterations * 16.0; }

StageProbeResult run_stage_probe(glm::ivec2 size, std::uint32_t iterations, std::uint32_t runs) {
  require_full_tier("stage probe");
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
  for (const Stage& stage : stages) stage.reach->milliseconds = median_time(timer, stage.name, result.runs, [] {}, stage.run);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return result;
}

RasterProbeResult run_raster_probe(glm::ivec2 size, std::span<const int> cells, std::uint32_t layers, std::uint32_t runs) {
  require_full_tier("raster probe");
  RasterProbeResult result;
  result.size = size;
  result.layers = std::max(layers, 1u);
  result.runs = std::max(runs, 1u);
  result.identifiers = epoxy_has_gl_extension("GL_NV_shader_atomic_int64") && epoxy_has_gl_extension("GL_ARB_gpu_shader_int64");

  ShaderProgram raster = ShaderProgram::load({"probe/raster.vert", "probe/raster.frag"});
  ShaderProgram compute = ShaderProgram::load({"probe/raster.comp"}, result.identifiers ? std::vector<ShaderDefine>{{"IDENTIFIERS"}} : std::vector<ShaderDefine>{});
  glProgramUniform2i(compute.id(), glGetUniformLocation(compute.id(), "u_size"), size.x, size.y);
  // The geometry pass's depth convention: reversed, nearer is larger.
  static_assert(kDepthCloser == GL_GREATER && kDepthFar == 0.0f, "raster.comp keeps the largest depth, over texels cleared to 0");
  use_depth_convention();
  Texture ids = create_render_target(GL_R32UI, size.x, size.y);
  Texture depth = create_render_target(GL_DEPTH_COMPONENT32F, size.x, size.y);
  Framebuffer framebuffer = create_framebuffer();
  glNamedFramebufferTexture(framebuffer.id(), GL_COLOR_ATTACHMENT0, ids.id(), 0);
  glNamedFramebufferTexture(framebuffer.id(), GL_DEPTH_ATTACHMENT, depth.id(), 0);
  require_complete(framebuffer.id(), "raster probe");
  const std::size_t pixels = static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y);
  const std::size_t texel_bytes = result.identifiers ? sizeof(std::uint64_t) : sizeof(std::uint32_t);
  Buffer texels = create_buffer();
  glNamedBufferStorage(texels.id(), static_cast<GLsizeiptr>(pixels * texel_bytes), nullptr, GL_DYNAMIC_STORAGE_BIT);
  PassTimer timer;
  result.timing = timer.method_name();

  for (const int cell : cells) {
    RasterProbeRow row;
    row.cell = std::max(cell, 1);
    const std::uint64_t triangles = std::uint64_t{result.layers} * 2u * static_cast<std::uint64_t>((size.x + row.cell - 1) / row.cell) *
                                    static_cast<std::uint64_t>((size.y + row.cell - 1) / row.cell);
    row.triangles = static_cast<std::uint32_t>(std::min<std::uint64_t>(triangles, 0xffffffffu));
    if (triangles > kRasterProbeMaxTriangles) {
      row.skipped = true;
      result.rows.push_back(row);
      continue;
    }
    const Sheets sheets = make_sheets(size, row.cell, result.layers);
    compute.set("u_triangles", row.triangles);
    Buffer positions = create_buffer();
    glNamedBufferStorage(positions.id(), static_cast<GLsizeiptr>(sheets.positions.size() * sizeof(float)), sheets.positions.data(), 0);
    Buffer indices = create_index_buffer();
    glNamedBufferStorage(indices.id(), static_cast<GLsizeiptr>(sheets.indices.size() * sizeof(std::uint32_t)), sheets.indices.data(), 0);
    VertexArray vertices = create_vertex_array();
    glVertexArrayVertexBuffer(vertices.id(), 0, positions.id(), 0, 3 * sizeof(float));
    glVertexArrayElementBuffer(vertices.id(), indices.id());
    glEnableVertexArrayAttrib(vertices.id(), 0);
    glVertexArrayAttribFormat(vertices.id(), 0, 3, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(vertices.id(), 0, 0);

    auto clear_raster = [&] {
      const GLuint no_id = 0;
      const GLfloat far = kDepthFar;
      glClearNamedFramebufferuiv(framebuffer.id(), GL_COLOR, 0, &no_id);
      glClearNamedFramebufferfv(framebuffer.id(), GL_DEPTH, 0, &far);
    };
    auto run_raster = [&] {
      raster.use();
      glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.id());
      glViewport(0, 0, size.x, size.y);
      glEnable(GL_DEPTH_TEST);
      glDepthFunc(kDepthCloser);
      glDepthMask(GL_TRUE);
      glDisable(GL_CULL_FACE);
      glBindVertexArray(vertices.id());
      glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(sheets.indices.size()), GL_UNSIGNED_INT, nullptr);
    };
    // Every texel 0: kDepthFar's bits, farther than any depth.
    auto clear_compute = [&] {
      const std::uint32_t far = 0;
      glClearNamedBufferData(texels.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &far);
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    };
    auto run_compute = [&] {
      compute.use();
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, positions.id());
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, indices.id());
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, texels.id());
      const GLuint groups = (row.triangles + 63u) / 64u;
      // A dispatch's x count is capped at 65,535 groups: the rest in y.
      const GLuint x = std::min(groups, 65535u);
      glDispatchCompute(x, (groups + x - 1u) / x, 1);
    };
    row.raster_ms = median_time(timer, "raster", result.runs, clear_raster, run_raster);
    row.compute_ms = median_time(timer, "compute", result.runs, clear_compute, run_compute);
    glDisable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    // The last run of each, pixel by pixel.
    const auto raster_depth = read_texture<float>(depth, size, GL_DEPTH_COMPONENT, GL_FLOAT);
    const auto raster_ids = read_texture<std::uint32_t>(ids, size, GL_RED_INTEGER, GL_UNSIGNED_INT);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<std::uint32_t> words(pixels * texel_bytes / sizeof(std::uint32_t));
    glGetNamedBufferSubData(texels.id(), 0, static_cast<GLsizeiptr>(words.size() * sizeof(std::uint32_t)), words.data());
    for (std::size_t i = 0; i < pixels; ++i) {
      // A 64-bit texel in little-endian words: the identifier low, the depth's bits high.
      const std::uint32_t depth_bits = result.identifiers ? words[2 * i + 1] : words[i];
      float compute_depth = kDepthFar;
      std::memcpy(&compute_depth, &depth_bits, sizeof compute_depth);
      const bool raster_covered = raster_depth[i] != kDepthFar, compute_covered = compute_depth != kDepthFar;
      if (raster_covered) ++row.covered;
      if (raster_covered != compute_covered || std::abs(raster_depth[i] - compute_depth) > 1e-5f) ++row.depth_mismatches;
      if (result.identifiers && raster_covered && compute_covered && raster_ids[i] != words[2 * i]) ++row.identifier_mismatches;
    }
    result.rows.push_back(row);
  }
  return result;
}

}  // namespace atrium::gfx
