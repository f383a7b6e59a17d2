// The frame-graph passes most techniques share. "geometry" fills a G-buffer
// (its targets imported as gbuffer.<target>) and the scene depth from the
// opaque and masked draw items; "transparency" shades the blended items
// forward over the lit HDR image, depth-tested against the opaque depth. Both
// exist so that each technique's file lists only the passes that are its own.
#pragma once

#include <functional>
#include <vector>

#include "render/frame_graph.hpp"
#include "systems/lighting/gbuffer.hpp"
#include "systems/lighting/technique.hpp"

namespace atrium::lighting {

// Imports `gbuffer`'s targets into the graph as "gbuffer.<target name>" and
// adds the "geometry" pass that writes them and the scene depth; returns the
// targets' resources, for the passes that read them.
std::vector<render::ResourceId> add_geometry_pass(render::FrameGraph& graph, GBuffer& gbuffer, gfx::ShaderProgram& program,
                                                  const FrameContext& frame);

// Reads of every G-buffer target, for a pass that samples them.
void read_gbuffer(render::PassBuilder& pass, const std::vector<render::ResourceId>& gbuffer);

// The "transparency" pass, when the frame has blended items: `prepare` runs
// first (binding the light lists the program reads, say); `reads` declares
// what it reads beyond the scene's depth, colour and lights.
void add_transparency_pass(render::FrameGraph& graph, gfx::ShaderProgram& program, const FrameContext& frame, const FrameTargets& targets,
                           const std::function<void(render::PassBuilder&)>& reads = {}, std::function<void()> prepare = {});

}  // namespace atrium::lighting
