// The technique table: one row per lighting mode, in the order `t` cycles them.
#include "systems/lighting/clustered.hpp"
#include "systems/lighting/deferred.hpp"
#include "systems/lighting/forward.hpp"
#include "systems/lighting/light_volumes.hpp"
#include "systems/lighting/tiled.hpp"
#include "systems/lighting/technique.hpp"

namespace atrium::lighting {
namespace {

template <typename T>
std::unique_ptr<LightingTechnique> make(assets::GpuAssets& gpu, const TechniqueOptions&) {
  return std::make_unique<T>(gpu);
}

constexpr TechniqueInfo kTechniques[] = {
    {"forward", "one geometry pass; every fragment loops over every light (the baseline)", &make<ForwardTechnique>},
    {"deferred", "G-buffer, then one full-screen pass over every light", [](assets::GpuAssets& gpu, const TechniqueOptions&) -> std::unique_ptr<LightingTechnique> {
       return std::make_unique<DeferredTechnique>(gpu, false);
     }},
    {"deferred-radius", "deferred, skipping lights whose radius does not reach the pixel",
     [](assets::GpuAssets& gpu, const TechniqueOptions&) -> std::unique_ptr<LightingTechnique> { return std::make_unique<DeferredTechnique>(gpu, true); }},
    {"light-volumes", "deferred; per light a stencil pass and a lighting pass on a sphere of its radius",
     [](assets::GpuAssets& gpu, const TechniqueOptions&) -> std::unique_ptr<LightingTechnique> { return std::make_unique<LightVolumeTechnique>(gpu, false); }},
    {"tiled-deferred", "G-buffer, lights culled per 16x16 tile against its depth bounds, each pixel shades its tile's",
     &make<TiledTechnique>},
    {"clustered-forward", "forward+: depth pre-pass, lights assigned to a 3D cluster grid, each fragment shades its cluster's",
     [](assets::GpuAssets& gpu, const TechniqueOptions& options) -> std::unique_ptr<LightingTechnique> {
       return std::make_unique<ClusteredTechnique>(gpu, options, false);
     }},
    {"clustered-deferred", "G-buffer, lights assigned to a 3D cluster grid, each pixel shades its cluster's",
     [](assets::GpuAssets& gpu, const TechniqueOptions& options) -> std::unique_ptr<LightingTechnique> {
       return std::make_unique<ClusteredTechnique>(gpu, options, true);
     }},
    {"light-volumes-instanced", "deferred; all light spheres in one instanced draw, no stencil",
     [](assets::GpuAssets& gpu, const TechniqueOptions&) -> std::unique_ptr<LightingTechnique> { return std::make_unique<LightVolumeTechnique>(gpu, true); }},
};

}  // namespace

std::span<const TechniqueInfo> technique_table() { return kTechniques; }

const TechniqueInfo* find_technique(std::string_view name) {
  for (const TechniqueInfo& info : kTechniques) {
    if (info.name == name) return &info;
  }
  return nullptr;
}

std::string technique_names() {
  std::string names;
  for (const TechniqueInfo& info : kTechniques) names += (names.empty() ? "" : ", ") + std::string(info.name);
  return names;
}

}  // namespace atrium::lighting
