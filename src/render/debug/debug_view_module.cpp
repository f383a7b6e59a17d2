#include "render/debug/debug_view_module.hpp"

#include "components/bounds.hpp"
#include "components/frame_resources.hpp"

namespace atrium::render {

DebugViewNeeds DebugViewModule::needs(std::string_view view) {
  const DebugView* named = find_debug_view(view);
  return named ? named->needs : DebugViewNeeds{};
}

DebugViews& DebugViewModule::views(const FrameBuild& build) {
  if (!views_) {
    views_ = std::make_unique<DebugViews>(gpu_, build.registry.resource<RendererSettings>().technique_options);
    views_->resize(build.targets);
  }
  return *views_;
}

std::vector<DebugViews::CountAverage> DebugViewModule::take_averages() { return views_ ? views_->take_averages() : std::vector<DebugViews::CountAverage>{}; }

FrameModule DebugViewModule::counters_module() {
  return {FrameStage::BeforeLighting, "counters", [this](FrameBuild& build) {
            const DebugViewNeeds shown = needs(build.registry.resource<RendererSettings>().debug_view);
            if (shown.count_lights || shown.count_fragments) views(build).add_counting_pass(build.graph, shown);
          }, [this] { invalidate(); }};
}

FrameModule DebugViewModule::view_module() {
  return {FrameStage::Output, "debug view", [this](FrameBuild& build) {
            const auto& settings = build.registry.resource<RendererSettings>();
            // What this frame's graph offers, before any debug view adds to it.
            offered_ = render::offered_views(build.graph, settings.technique_options);
            selected_.reset();
            if (!settings.debug_view.empty()) {
              selected_ = select_view(settings.debug_view, build.graph);
              if (!selected_) throw UnknownViewError("unknown debug view '" + settings.debug_view + "' (views: " + view_names(offered_) + ")");
            }
            const auto* extent = build.registry.try_resource<SceneBounds>();
            view_frame_.reset();
            view_frame_.emplace(DebugViewFrame{build.frame, build.targets, build.graph, extent ? extent->min : glm::vec3(0.0f),
                                               extent ? extent->max : glm::vec3(1.0f)});
            const bool technique_gbuffer = lighting::GBuffer::find(build.graph).has_value();
            thumbnails_drawn_ = settings.gbuffer_thumbnails && technique_gbuffer;
            if (thumbnails_drawn_) {
              build.graph.add_pass("thumbnails", [&](PassBuilder& pass) {
                pass.keep();
                DebugViews::declare_thumbnail_reads(pass, build.graph, build.frame);
              }, [this, &build](const PassResources& res) { views(build).draw_thumbnails(*view_frame_, res); }, false);
            }
            if (!selected_) return;
            const DebugViewNeeds shown = needs(settings.debug_view);
            // A G-buffer view in a mode without one fills the views' own.
            if (shown.gbuffer && !technique_gbuffer) views(build).add_gbuffer_pass(build.graph, build.frame, build.targets);
            const ResourceId output = build.output;
            build.graph.add_pass("debug view", [&](PassBuilder& pass) {
              DebugViews::declare_reads(*selected_, pass, build.graph, build.frame);
              pass.write(output, Access::Attachment);
            }, [this, &build, output, shown](const PassResources& res) {
              views(build).draw(*selected_, *view_frame_, res, res.framebuffer({output}));
              if (shown.count_lights || shown.count_fragments) views(build).send_counts(shown);
            });
          }, [this] { invalidate(); }};
}

}  // namespace atrium::render
