// Per-pass timings. On real GPUs each pass is bracketed by GL_TIME_ELAPSED
// queries that are read back a few frames later, so timing never stalls the
// pipeline. Mesa's software rasterisers return wrong query values (measured
// 30-300x too small on llvmpipe), so there each pass ends with glFinish and is
// timed with a steady clock; method() says which is in use. Where the driver
// counts pipeline statistics (GL 4.6 or ARB_pipeline_statistics_query, llvmpipe
// included), each pass also counts its fragment shader invocations: the
// fragments it shaded, overdraw and helper invocations included. Either way
// each pass also reports the CPU time spent issuing its commands. With
// time_steps() on, the steps a pass names inside itself (PassTimer::Step:
// the light lists' count, scan and write, the occlusion culling's pyramid)
// are timed too, by GL_TIMESTAMP queries or glFinish and the clock.
#pragma once

#include <array>
#include <chrono>
#include <string>
#include <string_view>
#include <vector>

#include "gfx/frame_pacer.hpp"
#include "gfx/gl_object.hpp"

namespace atrium::gfx {

enum class TimingMethod { GpuQueries, CpuFinish };

// A named part of a pass (PassTimer::Step), timed where time_steps() is on.
struct StepTime {
  std::string name;
  double milliseconds = 0.0;
  // Where this is a median over frames (bench): how many of them ran the step,
  // of how many ran its pass. A step that runs in some frames only (the sort
  // of a frame whose lists were scattered) is its median over those.
  std::size_t frames = 1, pass_frames = 1;
};

struct PassTime {
  std::string name;
  double milliseconds = 0.0;
  std::uint64_t fragments = 0;  // fragment shader invocations; 0 without pipeline statistics
  // What the pass cost the CPU: from its start until its last command was
  // issued (before any wait for the GPU). On llvmpipe this includes vertex
  // processing and binning, which run in the calling thread.
  double cpu_milliseconds = 0.0;
  std::vector<StepTime> steps;  // in the order they ran; empty unless time_steps() is on
};

class PassTimer {
 public:
  // Chooses the method from the current context's renderer string.
  PassTimer();
  explicit PassTimer(TimingMethod method);

  [[nodiscard]] TimingMethod method() const { return method_; }
  // Whether passes count their fragment shader invocations.
  [[nodiscard]] bool counts_fragments() const { return counts_fragments_; }
  [[nodiscard]] const char* method_name() const;

  void begin_frame();
  void end_frame();
  void begin_pass(const std::string& name);
  void end_pass();

  // Whether steps are timed (off by default: with glFinish timing each step
  // adds two waits inside its pass).
  void time_steps(bool on) { time_steps_ = on; }
  [[nodiscard]] bool times_steps() const { return time_steps_; }

  // A step of the pass running on this thread, timed for its scope where that
  // pass's timer times steps (else nothing): code deep inside a pass names its
  // parts without being handed the timer. Steps do not nest: one begun inside
  // another is not timed apart.
  class Step {
   public:
    explicit Step(std::string_view name);
    ~Step();
    Step(const Step&) = delete;
    Step& operator=(const Step&) = delete;

   private:
    PassTimer* timer_ = nullptr;
  };

  // The most recent frame whose timings are complete (with queries, a few
  // frames old), in pass order; empty until one is.
  [[nodiscard]] const std::vector<PassTime>& latest() const { return latest_; }

  // Waits until the latest frame's timings are complete and makes them
  // latest(): for one-shot commands after their last frame (a counted GPU
  // wait, outside any frame).
  void wait_for_latest();

  // RAII helper: times a pass for the enclosing scope.
  class Scope {
   public:
    Scope(PassTimer& timer, const std::string& name) : timer_(timer) { timer_.begin_pass(name); }
    ~Scope() { timer_.end_pass(); }
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    PassTimer& timer_;
  };
  [[nodiscard]] Scope scope(const std::string& name) { return Scope(*this, name); }

 private:
  // The frames whose queries are kept: one more than FramePacer lets the CPU
  // run ahead, so the slot a frame reuses held a frame the GPU has finished.
  static constexpr std::size_t kQueryFrames = FramePacer::kFramesInFlight + 1;
  struct QueryStep {
    std::string name;
    Query begin, end;  // GL_TIMESTAMP
  };
  struct QueryPass {
    std::string name;
    Query query;
    Query fragments;  // empty without pipeline statistics
    double cpu_milliseconds = 0.0;
    std::vector<QueryStep> steps;
    std::size_t steps_used = 0;
  };
  struct FrameQueries {
    std::vector<QueryPass> passes;
    std::size_t used = 0;
    bool pending = false;
  };

  void collect();
  // GpuQueries: the pass begun last in the frame being recorded (a step's).
  QueryPass& open_pass();
  void begin_step(std::string_view name);
  void end_step();

  TimingMethod method_;
  bool counts_fragments_;
  Query cpu_fragments_;  // CpuFinish: the running pass's invocation count
  std::array<FrameQueries, kQueryFrames> frames_;
  std::size_t frame_ = 0;
  std::vector<PassTime> current_;  // CpuFinish: the frame being timed
  std::chrono::steady_clock::time_point pass_start_;  // after the GPU went idle (CpuFinish) or the pass began
  std::vector<PassTime> latest_;
  bool time_steps_ = false;
  std::chrono::steady_clock::time_point step_start_;  // CpuFinish: after the GPU went idle
};

}  // namespace atrium::gfx
