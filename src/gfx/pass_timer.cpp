#include "gfx/pass_timer.hpp"

#include "gfx/gl_features.hpp"
#include "gfx/gpu_waits.hpp"
#include "gfx/limits.hpp"

namespace atrium::gfx {
namespace {
// The timer whose pass is open on this thread with steps timed (PassTimer::Step).
thread_local PassTimer* t_stepping = nullptr;
}  // namespace

// Software renderers are timed with glFinish and the clock (their queries
// add little and cost much), where glFinish waits; a browser's does not, so
// there queries are the one honest timing.
PassTimer::PassTimer()
    : PassTimer(gl_features().timer_queries && !(is_software_renderer() && gl_features().finish_waits) ? TimingMethod::GpuQueries
                                                                                                       : TimingMethod::CpuFinish) {}
PassTimer::PassTimer(TimingMethod method)
    : method_(method),
      counts_fragments_(gl_features().pipeline_statistics) {
  if (counts_fragments_) cpu_fragments_ = create_query(GL_FRAGMENT_SHADER_INVOCATIONS_ARB);
}

const char* PassTimer::method_name() const {
  if (method_ == TimingMethod::GpuQueries) return "GL_TIME_ELAPSED queries";
  return gl_features().finish_waits ? "glFinish + steady clock (software renderer, or no GL_TIME_ELAPSED)"
                                    : "steady clock: command submission only (no timer queries, and this glFinish does not wait)";
}

void PassTimer::begin_frame() {
  if (method_ == TimingMethod::CpuFinish) {
    current_.clear();
    return;
  }
  collect();
  FrameQueries& frame = frames_[frame_ % kQueryFrames];
  if (frame.pending) {
    // Still not available after kQueryFrames frames: wait rather than lose it.
    for (std::size_t i = 0; i < frame.used; ++i) {
      GLuint64 ignored = 0;
      count_gpu_wait();
      glGetQueryObjectui64v(frame.passes[i].query.id(), GL_QUERY_RESULT, &ignored);
    }
    collect();
  }
  frame.used = 0;
}

void PassTimer::end_frame() {
  if (method_ == TimingMethod::CpuFinish) {
    latest_ = current_;
    return;
  }
  frames_[frame_ % kQueryFrames].pending = frames_[frame_ % kQueryFrames].used > 0;
  ++frame_;
}

void PassTimer::begin_pass(const std::string& name) {
  t_stepping = time_steps_ ? this : nullptr;
  if (method_ == TimingMethod::CpuFinish) {
    glFinish();  // the previous work must not be charged to this pass
    current_.push_back({name, 0.0, 0, 0.0, {}});
    if (counts_fragments_) glBeginQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB, cpu_fragments_.id());
    pass_start_ = std::chrono::steady_clock::now();
    return;
  }
  FrameQueries& frame = frames_[frame_ % kQueryFrames];
  if (frame.used == frame.passes.size()) {
    frame.passes.push_back({name, create_query(GL_TIME_ELAPSED), counts_fragments_ ? create_query(GL_FRAGMENT_SHADER_INVOCATIONS_ARB) : Query{}, 0.0, {}, 0});
  }
  QueryPass& pass = frame.passes[frame.used++];
  pass.name = name;
  pass.steps_used = 0;
  glBeginQuery(GL_TIME_ELAPSED, pass.query.id());
  if (counts_fragments_) glBeginQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB, pass.fragments.id());
  pass_start_ = std::chrono::steady_clock::now();
}

void PassTimer::end_pass() {
  t_stepping = nullptr;
  const double cpu_milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - pass_start_).count();
  if (method_ == TimingMethod::CpuFinish) {
    current_.back().cpu_milliseconds = cpu_milliseconds;
    glFinish();
    current_.back().milliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - pass_start_).count();
    if (counts_fragments_) {
      glEndQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB);
      GLuint64 fragments = 0;
      glGetQueryObjectui64v(cpu_fragments_.id(), GL_QUERY_RESULT, &fragments);
      current_.back().fragments = fragments;
    }
    return;
  }
  FrameQueries& frame = frames_[frame_ % kQueryFrames];
  frame.passes[frame.used - 1].cpu_milliseconds = cpu_milliseconds;
  glEndQuery(GL_TIME_ELAPSED);
  if (counts_fragments_) glEndQuery(GL_FRAGMENT_SHADER_INVOCATIONS_ARB);
}

void PassTimer::wait_for_latest() {
  if (method_ == TimingMethod::CpuFinish || frame_ == 0) return;
  const FrameQueries& newest = frames_[(frame_ - 1) % kQueryFrames];
  if (!newest.pending) return;
  // Queries finish in submission order: once the newest frame's last one has
  // its result, every pending frame's queries have theirs.
  count_gpu_wait();
  GLuint64 ignored = 0;
  glGetQueryObjectui64v(newest.passes[newest.used - 1].query.id(), GL_QUERY_RESULT, &ignored);
  collect();
}

// Reads back the oldest pending frame whose queries are all available.
void PassTimer::collect() {
  for (std::size_t age = kQueryFrames; age > 0; --age) {
    if (frame_ < age) continue;
    FrameQueries& frame = frames_[(frame_ - age) % kQueryFrames];
    if (!frame.pending) continue;
    GLint available = GL_FALSE;
    glGetQueryObjectiv(frame.passes[frame.used - 1].query.id(), GL_QUERY_RESULT_AVAILABLE, &available);
    if (!available) return;
    std::vector<PassTime> times;
    for (std::size_t i = 0; i < frame.used; ++i) {
      GLuint64 nanoseconds = 0, fragments = 0;
      glGetQueryObjectui64v(frame.passes[i].query.id(), GL_QUERY_RESULT, &nanoseconds);
      if (counts_fragments_) glGetQueryObjectui64v(frame.passes[i].fragments.id(), GL_QUERY_RESULT, &fragments);
      times.push_back({frame.passes[i].name, static_cast<double>(nanoseconds) / 1e6, fragments, frame.passes[i].cpu_milliseconds, {}});
      for (std::size_t k = 0; k < frame.passes[i].steps_used; ++k) {
        const QueryStep& step = frame.passes[i].steps[k];
        GLuint64 begin = 0, end = 0;
        glGetQueryObjectui64v(step.begin.id(), GL_QUERY_RESULT, &begin);
        glGetQueryObjectui64v(step.end.id(), GL_QUERY_RESULT, &end);
        times.back().steps.push_back({step.name, static_cast<double>(end - begin) / 1e6});
      }
    }
    latest_ = std::move(times);
    frame.pending = false;
  }
}

PassTimer::QueryPass& PassTimer::open_pass() {
  FrameQueries& frame = frames_[frame_ % kQueryFrames];
  return frame.passes[frame.used - 1];
}

void PassTimer::begin_step(std::string_view name) {
  if (method_ == TimingMethod::CpuFinish) {
    glFinish();
    current_.back().steps.push_back({std::string(name), 0.0});
    step_start_ = std::chrono::steady_clock::now();
    return;
  }
  QueryPass& pass = open_pass();
  if (pass.steps_used == pass.steps.size()) pass.steps.push_back({{}, create_query(GL_TIMESTAMP), create_query(GL_TIMESTAMP)});
  QueryStep& step = pass.steps[pass.steps_used++];
  step.name = name;
  glQueryCounter(step.begin.id(), GL_TIMESTAMP);
}

void PassTimer::end_step() {
  if (method_ == TimingMethod::CpuFinish) {
    glFinish();
    current_.back().steps.back().milliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - step_start_).count();
    return;
  }
  const QueryPass& pass = open_pass();
  glQueryCounter(pass.steps[pass.steps_used - 1].end.id(), GL_TIMESTAMP);
}

PassTimer::Step::Step(std::string_view name) : timer_(t_stepping) {
  if (!timer_) return;
  t_stepping = nullptr;  // a step inside this one is not timed apart
  timer_->begin_step(name);
}

PassTimer::Step::~Step() {
  if (!timer_) return;
  timer_->end_step();
  t_stepping = timer_;
}

}  // namespace atrium::gfx
