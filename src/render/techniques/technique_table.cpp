// The technique table: one row per lighting mode, in the order `t` cycles them.
#include "render/techniques/clustered/clustered.hpp"
#include "render/techniques/deferred/deferred.hpp"
#include "render/techniques/forward/forward.hpp"
#include "render/techniques/light_prepass/light_prepass.hpp"
#include "render/techniques/light_volumes/light_volumes.hpp"
#include "render/techniques/tiled/tiled.hpp"
#include "render/techniques/visibility/visibility.hpp"
#include "render/techniques/technique.hpp"

namespace atrium::techniques {
namespace {

// Every technique is built from the GPU assets and the options; `variant`
// picks a row's flavour of a shared implementation (radius culling, instancing,
// deferred or forward+).
template <typename T, auto... variant>
std::unique_ptr<LightingTechnique> make(render::GpuAssets& gpu, const TechniqueOptions& options) {
  return std::make_unique<T>(gpu, options, variant...);
}

constexpr TechniqueInfo kTechniques[] = {
    {"forward", "one geometry pass; every fragment loops over every light (the baseline)", {true, true}, GBufferUse::None, {}, &make<ForwardTechnique>},
    {"deferred", "G-buffer, then one full-screen pass over every light", {true, true}, GBufferUse::Chosen, {}, &make<DeferredTechnique, false>},
    {"deferred-radius", "deferred, skipping lights whose radius does not reach the pixel", {true, true}, GBufferUse::Chosen, {}, &make<DeferredTechnique, true>},
    {"light-volumes", "deferred; per light a stencil pass and a lighting pass on a sphere of its radius", {false, true},
     GBufferUse::Chosen, {}, &make<LightVolumeTechnique, false>},
    {"tiled-deferred", "G-buffer, lights culled per 16x16 tile against its depth bounds, each pixel shades its tile's", {},
     GBufferUse::Chosen, {}, &make<TiledTechnique>},
    {"clustered-forward", "forward+: depth pre-pass, lights assigned to a 3D cluster grid, each fragment shades its cluster's", {},
     GBufferUse::None, {}, &make<ClusteredTechnique, false>},
    {"clustered-deferred", "G-buffer, lights assigned to a 3D cluster grid, each pixel shades its cluster's", {},
     GBufferUse::Chosen, {}, &make<ClusteredTechnique, true>},
    {"light-volumes-instanced", "deferred; all light spheres in one instanced draw, no stencil", {false, true},
     GBufferUse::Chosen, {}, &make<LightVolumeTechnique, true>},
    {"light-prepass", "thin G-buffer, light volumes sum BRDF factors into a light buffer, a second geometry pass applies materials",
     {false, true}, GBufferUse::Own, {}, &make<LightPrepassTechnique>},
    {"visibility-buffer", "depth and triangle identifiers only, then per material a compute pass rebuilds each pixel's surface and shades its cluster's lights",
     {}, GBufferUse::None, {.compute = true}, &make<VisibilityTechnique>},
};

}  // namespace

std::span<const TechniqueInfo> technique_table() { return kTechniques; }

const TechniqueInfo* find_technique(std::string_view name) {
  for (const TechniqueInfo& info : kTechniques) {
    if (info.name == name) return &info;
  }
  return nullptr;
}

std::vector<std::string> mode_names() {
  std::vector<std::string> names;
  for (const TechniqueInfo& info : kTechniques) names.emplace_back(info.name);
  return names;
}

std::vector<std::string> mode_names(const TechniqueOptions& options) {
  std::vector<std::string> names;
  for (const TechniqueInfo& info : kTechniques) {
    if (refusal(info, options).empty()) names.emplace_back(info.name);
  }
  return names;
}

std::string refusal(const TechniqueInfo& info, const TechniqueOptions& options) {
  if (info.needs.compute && options.compute_free) {
    return std::string(info.name) + " needs compute shaders and storage buffers, which this context's tier (OpenGL 4.1, ES 3.0, " +
           "WebGL2) lacks; use another mode";
  }
  return {};
}

std::string technique_names() {
  std::string names;
  for (const std::string& name : mode_names()) names += (names.empty() ? "" : ", ") + name;
  return names;
}

}  // namespace atrium::techniques
