// The frame-graph passes most techniques share. "geometry" fills a G-buffer
// (its targets made as transients gbuffer.<target>) and the scene depth from the
// opaque and masked draw items; "transparency" shades the blended items
// forward over the lit HDR image, depth-tested against the opaque depth. Both
// exist so that each technique's file lists only the passes that are its own.
#pragma once

#include <functional>

#include "render/frame_graph.hpp"
#include "render/lighting/gbuffer.hpp"
#include "render/frame/frame_context.hpp"
#include "render/frame/frame_draws.hpp"

namespace atrium::render {

// Adds the "geometry" pass, which makes `gbuffer`'s targets for this frame
// (GBuffer::create_targets) and fills them and the scene depth; passes that
// shade from them declare GBuffer::read_targets.
void add_geometry_pass(FrameGraph& graph, lighting::GBuffer& gbuffer, gfx::ShaderProgram& program, const FrameContext& frame,
                       const FrameTargets& targets);

// The "transparency" pass, when the frame has blended items: `prepare` runs
// first (binding the light lists the program reads, say); `reads` declares
// what it reads beyond the scene's depth, colour and lights.
void add_transparency_pass(FrameGraph& graph, gfx::ShaderProgram& program, const FrameContext& frame, const FrameTargets& targets,
                           const std::function<void(PassBuilder&)>& reads = {}, std::function<void()> prepare = {});

}  // namespace atrium::render
