// Per-pass timings. On real GPUs each pass is bracketed by GL_TIME_ELAPSED
// queries that are read back a few frames later, so timing never stalls the
// pipeline. Mesa's software rasterisers return wrong query values (measured
// 30-300x too small on llvmpipe), so there each pass ends with glFinish and is
// timed with a steady clock; method() says which is in use. Where the driver
// counts pipeline statistics (GL 4.6 or ARB_pipeline_statistics_query, llvmpipe
// included), each pass also counts its fragment shader invocations: the
// fragments it shaded, overdraw and helper invocations included. Either way
// each pass also reports the CPU time spent issuing its commands.
#pragma once

#include <array>
#include <chrono>
#include <string>
#include <vector>

#include "gfx/gl_object.hpp"

namespace atrium::gfx {

enum class TimingMethod { GpuQueries, CpuFinish };

struct PassTime {
  std::string name;
  double milliseconds = 0.0;
  std::uint64_t fragments = 0;  // fragment shader invocations; 0 without pipeline statistics
  // What the pass cost the CPU: from its start until its last command was
  // issued (before any wait for the GPU). On llvmpipe this includes vertex
  // processing and binning, which run in the calling thread.
  double cpu_milliseconds = 0.0;
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
  static constexpr std::size_t kFramesInFlight = 4;
  struct QueryPass {
    std::string name;
    Query query;
    Query fragments;  // empty without pipeline statistics
    double cpu_milliseconds = 0.0;
  };
  struct FrameQueries {
    std::vector<QueryPass> passes;
    std::size_t used = 0;
    bool pending = false;
  };

  void collect();

  TimingMethod method_;
  bool counts_fragments_;
  Query cpu_fragments_;  // CpuFinish: the running pass's invocation count
  std::array<FrameQueries, kFramesInFlight> frames_;
  std::size_t frame_ = 0;
  std::vector<PassTime> current_;  // CpuFinish: the frame being timed
  std::chrono::steady_clock::time_point pass_start_;  // after the GPU went idle (CpuFinish) or the pass began
  std::vector<PassTime> latest_;
};

}  // namespace atrium::gfx
