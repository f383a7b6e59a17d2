// `atrium probe [--size WxH] [--json]`: which SMs a compute dispatch and a
// full-screen fragment pass reach, the same arithmetic timed in each, and
// small triangles rasterised by the raster pipeline and by compute
// (gfx/stage_probe.hpp). The GPU kit runs it first.
#pragma once

#include <string>

#include "gfx/stage_probe.hpp"

namespace atrium {

[[nodiscard]] std::string format_probe_text(const gfx::StageProbeResult& stages, const std::string& renderer);
[[nodiscard]] std::string format_raster_probe_text(const gfx::RasterProbeResult& raster);
[[nodiscard]] std::string format_probe_json(const gfx::StageProbeResult& stages, const gfx::RasterProbeResult& raster,
                                            const std::string& renderer);

}  // namespace atrium
