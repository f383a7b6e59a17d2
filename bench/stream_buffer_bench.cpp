// What a StreamBuffer upload (gfx/stream_buffer.hpp: a persistently mapped
// staging copy written by the CPU, then copied on the GPU) costs the CPU,
// against glNamedBufferSubData into the buffer, which it replaced. Sizes as the
// grid's draw list sends them with GPU culling (instances of the overview and
// the court, their commands) and a small one. The GPU is idle at each upload
// (finished outside the timing): what a busy GPU costs SubData is the driver's
// to say, and it is what the staging copies exist for.
#include <vector>

#include <benchmark/benchmark.h>

#include "gfx/context.hpp"
#include "gfx/gpu_waits.hpp"
#include "gfx/stream_buffer.hpp"

namespace atrium {
namespace {

const gfx::HeadlessContext& context() {
  static const auto made = gfx::HeadlessContext::create();
  return *made;
}

void BM_StreamBufferUpload(benchmark::State& state) {
  (void)context();
  const std::vector<char> data(static_cast<std::size_t>(state.range(0)), 3);
  gfx::StreamBuffer stream;
  for (auto _ : state) {
    state.PauseTiming();
    gfx::finish();
    state.ResumeTiming();
    stream.upload(data.data(), data.size());
  }
  gfx::finish();
}

void BM_BufferSubData(benchmark::State& state) {
  (void)context();
  const std::vector<char> data(static_cast<std::size_t>(state.range(0)), 3);
  const gfx::Buffer buffer = gfx::create_buffer();
  glNamedBufferStorage(buffer.id(), static_cast<GLsizeiptr>(data.size()), nullptr, GL_DYNAMIC_STORAGE_BIT);
  for (auto _ : state) {
    state.PauseTiming();
    gfx::finish();
    state.ResumeTiming();
    glNamedBufferSubData(buffer.id(), 0, static_cast<GLsizeiptr>(data.size()), data.data());
  }
  gfx::finish();
}

BENCHMARK(BM_StreamBufferUpload)->Arg(4096)->Arg(152'280)->Arg(1'096'416)->Arg(3'166'128)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_BufferSubData)->Arg(4096)->Arg(152'280)->Arg(1'096'416)->Arg(3'166'128)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace atrium

BENCHMARK_MAIN();
