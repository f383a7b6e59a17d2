// `atrium probe [--size WxH] [--json]`: which SMs a compute dispatch and a
// full-screen fragment pass reach, and the same arithmetic timed in each
// (gfx/stage_probe.hpp). The GPU kit runs it first.
#pragma once

#include <string>

#include "gfx/stage_probe.hpp"

namespace atrium {

[[nodiscard]] std::string format_probe_text(const gfx::StageProbeResult& result, const std::string& renderer);
[[nodiscard]] std::string format_probe_json(const gfx::StageProbeResult& result, const std::string& renderer);

}  // namespace atrium
