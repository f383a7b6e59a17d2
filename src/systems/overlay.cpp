#include "systems/overlay.hpp"

#include <algorithm>
#include <array>
#include <cstdio>

#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include "components/demo.hpp"
#include "components/frame_resources.hpp"
#include "components/input.hpp"
#include "components/light.hpp"
#include "components/system_options.hpp"
#include "gfx/gl_object.hpp"
#include "gfx/limits.hpp"
#include "systems/light_radius.hpp"
#include "render/debug/debug_views.hpp"
#include "render/lighting/shading_model.hpp"
#include "render/techniques/technique.hpp"
#include "render/frame/frame_modules.hpp"
#include "render/mesh_renderer.hpp"

namespace atrium {

namespace {

// Owns the Dear ImGui context and backends for the window's lifetime.
class Overlay {
 public:
  explicit Overlay(GLFWwindow* window) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini next to the user's files
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 450 core");
  }
  ~Overlay() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
  Overlay(const Overlay&) = delete;
  Overlay& operator=(const Overlay&) = delete;

  void draw(ecs::Registry& registry);

 private:
  void statistics(ecs::Registry& registry);
  void controls(ecs::Registry& registry);
  void thumbnails(const render::MeshRenderer& renderer);

  double fps_ = 0.0, frame_ms_ = 0.0, window_seconds_ = 0.0;
  int window_frames_ = 0;
  double memory_age_ = 1e9;
  std::uint64_t memory_bytes_ = 0;
  float light_radius_ = 5.0f;
  // The MSAA sample counts the window's context can hold (four GL queries): a
  // larger one is not offered. The context lives as long as the overlay.
  int max_msaa_samples_ = std::min(8, gfx::max_msaa_samples());
};

bool combo(const char* label, const std::string& current, const std::vector<std::string>& items, std::string& chosen) {
  bool changed = false;
  if (ImGui::BeginCombo(label, current.c_str())) {
    for (const std::string& item : items) {
      if (ImGui::Selectable(item.c_str(), item == current)) {
        chosen = item;
        changed = item != current;
      }
    }
    ImGui::EndCombo();
  }
  return changed;
}

// A combo over an option's names (a k...Names table indexed by the enum).
template <typename Enum, std::size_t N>
void enum_combo(const char* label, const std::array<std::string_view, N>& names, Enum& value) {
  std::vector<std::string> items(names.begin(), names.end());
  std::string chosen;
  if (combo(label, items[static_cast<std::size_t>(value)], items, chosen)) {
    value = static_cast<Enum>(std::find(items.begin(), items.end(), chosen) - items.begin());
  }
}

void Overlay::statistics(ecs::Registry& registry) {
  const auto& clock = registry.resource<ecs::FrameClock>();
  window_seconds_ += clock.delta_seconds;
  ++window_frames_;
  memory_age_ += clock.delta_seconds;
  if (window_seconds_ >= 0.5) {
    fps_ = window_frames_ / window_seconds_;
    frame_ms_ = 1000.0 * window_seconds_ / window_frames_;
    window_seconds_ = 0.0;
    window_frames_ = 0;
  }
  // Asking the driver about every texture is not free: twice a second.
  if (memory_age_ >= 0.5) {
    memory_bytes_ = gfx::estimated_gpu_memory_bytes();
    memory_age_ = 0.0;
  }
  const render::MeshRenderer& renderer = registry.resource<render::MeshRenderer>();
  const render::FrameStats& stats = renderer.stats();
  const RendererSettings& settings = registry.resource<RendererSettings>();
  ImGui::Text("%.1f fps, %.2f ms per frame", fps_, frame_ms_);
  ImGui::Text("mode %s, shading %s", settings.mode.c_str(), settings.shading.c_str());
  ImGui::Text("%u lights; per geometry pass %zu of %zu triangles, %zu draw calls", stats.lights, stats.triangles_drawn,
              stats.triangles, stats.draw_calls);
  ImGui::Text("%zu of %zu objects in view%s", stats.objects_drawn, stats.objects, settings.frustum_culling ? "" : " (culling off)");
  if (settings.frustum_culling && settings.occlusion_culling) {
    ImGui::Text("%zu triangles in view hidden by depth, not drawn (tested on the %s)", stats.triangles_occluded,
                stats.culled_on_gpu ? "GPU" : "CPU");
  }
  ImGui::Text("full-screen passes in the %s stage", std::string(kLightingStageNames[static_cast<std::size_t>(stats.lighting_stage)]).c_str());
  if (!stats.technique_variant.empty()) ImGui::Text("%s", stats.technique_variant.c_str());
  if (stats.light_list_entries > 0) {
    ImGui::Text("light lists: %u entries (%s, density %.4f), %u overflowed frames", stats.light_list_entries,
                std::string(light_assignment_label(stats.light_assignment)).c_str(), stats.light_list_density,
                stats.light_list_overflows);
  }
  if (stats.shadows.atlas_size > 0) {
    ImGui::Text("shadows: %u lights, %u maps drawn, %u reused (%d^2 atlas)", stats.shadows.lights, stats.shadows.maps_rendered,
                stats.shadows.maps_reused, stats.shadows.atlas_size);
  }
  // Each is a stall on a GPU: the queue drains while the CPU waits (gfx/gpu_waits.hpp).
  ImGui::Text("GPU waits this frame: %u", stats.gpu_waits);
  // Not a stall: the GPU still has a frame queued (gfx/frame_pacer.hpp).
  if (stats.paced_ms > 0.0) ImGui::Text("GPU-bound: waited %.2f ms before the frame for the GPU", stats.paced_ms);
  ImGui::Text("GPU memory (estimate): %.1f MiB", static_cast<double>(memory_bytes_) / (1024.0 * 1024.0));
  const render::GraphMemory targets = renderer.graph().memory();
  ImGui::Text("render targets: %.1f MiB long-lived, %.1f MiB transient (%.1f unshared)", static_cast<double>(targets.imported_bytes) / (1024.0 * 1024.0),
              static_cast<double>(targets.aliased_bytes) / (1024.0 * 1024.0), static_cast<double>(targets.transient_bytes) / (1024.0 * 1024.0));
  // Fragments shaded per pixel tell a pass that draws too much (overdraw, a
  // camera inside foliage) from one that shades expensively.
  const bool fragments = renderer.timer().counts_fragments();
  const double pixels = std::max(1.0, static_cast<double>(renderer.size().x) * renderer.size().y);
  if (ImGui::BeginTable("passes", fragments ? 4 : 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) {
    ImGui::TableSetupColumn("pass");
    ImGui::TableSetupColumn("ms");
    ImGui::TableSetupColumn("CPU ms");
    if (fragments) ImGui::TableSetupColumn("fragments/px");
    ImGui::TableHeadersRow();
    for (const gfx::PassTime& pass : renderer.timer().latest()) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(pass.name.c_str());
      ImGui::TableNextColumn();
      ImGui::Text("%.2f", pass.milliseconds);
      ImGui::TableNextColumn();
      ImGui::Text("%.2f", pass.cpu_milliseconds);
      if (fragments) {
        ImGui::TableNextColumn();
        ImGui::Text("%.2f", static_cast<double>(pass.fragments) / pixels);
      }
    }
    ImGui::EndTable();
  }
  ImGui::Text("timing: %s", renderer.timer().method_name());
}

void Overlay::controls(ecs::Registry& registry) {
  auto& settings = registry.resource<RendererSettings>();
  auto& requests = registry.resource<DemoRequests>();
  const std::vector<std::string> modes = techniques::mode_names(settings.technique_options);
  std::vector<std::string> models, views{"(none)"};
  for (const auto name : lighting::kShadingModels) models.emplace_back(name);
  for (const render::OfferedView& view : registry.resource<render::MeshRenderer>().offered_views()) views.push_back(view.name);
  ImGui::PushItemWidth(220);
  std::string chosen;
  if (combo("mode", settings.mode, modes, chosen)) requests.mode = chosen;
  if (combo("shading", settings.shading, models, chosen)) settings.shading = chosen;
  if (combo("debug view", settings.debug_view.empty() ? views[0] : settings.debug_view, views, chosen)) {
    settings.debug_view = chosen == views[0] ? "" : chosen;
  }
  enum_combo("z slicing", kZSlicingNames, settings.technique_options.z_slicing);
  // Where the full-screen passes run, and how light lists are built: the same
  // pictures either way; the pass table shows what each costs.
  enum_combo("lighting stage", kLightingStageNames, settings.technique_options.lighting_stage);
  enum_combo("light assignment", kLightAssignmentNames, settings.technique_options.light_assignment);
  enum_combo("material binding", kMaterialBindingNames, settings.technique_options.material_binding);
  std::vector<std::string> sample_counts{"off"};
  for (int samples = 2; samples <= max_msaa_samples_; samples *= 2) sample_counts.push_back(std::to_string(samples) + "x");
  int& msaa = settings.technique_options.msaa;
  if (combo("MSAA", msaa > 1 ? std::to_string(msaa) + "x" : "off", sample_counts, chosen)) {
    msaa = chosen == "off" ? 1 : std::stoi(chosen);
  }
  // Costs two more target writes per pixel in the deferred modes; the thumbnails show the sums.
  ImGui::Checkbox("diffuse and specular apart", &settings.technique_options.split_lighting);
  // Off draws what is in view behind walls too: the same picture, for comparing costs.
  ImGui::Checkbox("occlusion culling", &settings.occlusion_culling);
  // Where it tests: the same pictures; the CPU reads the depth back, the GPU reads nothing back.
  std::vector<std::string> devices;
  std::string device_name;
  for (const CullingDeviceName& row : kCullingDevices) {
    devices.emplace_back(row.name);
    if (row.device == settings.culling_device) device_name = row.name;
  }
  if (combo("culling on", device_name, devices, chosen)) {
    for (const CullingDeviceName& row : kCullingDevices) {
      if (row.name == chosen) settings.culling_device = row.device;
    }
  }
  // K of --shadows: the lights that matter most get maps; 0 turns shadows off.
  ImGui::SliderInt("shadowed lights", &settings.shadows, 0, 256, "%d", ImGuiSliderFlags_Logarithmic);
  int lights = static_cast<int>(registry.resource<render::MeshRenderer>().stats().lights);
  if (ImGui::InputInt("lights", &lights, 16, 256, ImGuiInputTextFlags_EnterReturnsTrue)) {
    requests.light_count = static_cast<std::uint32_t>(std::clamp(lights, 0, static_cast<int>(kMaxLights)));
  }
  // One radius for every point and spot light, with the intensity that goes
  // with it, as --light-radius gives them.
  if (ImGui::SliderFloat("light radius (m)", &light_radius_, 0.5f, 40.0f, "%.1f", ImGuiSliderFlags_Logarithmic)) {
    set_every_light_radius(registry, light_radius_);
  }
  // The options systems declared (components/system_options.hpp): a slider each.
  if (auto* system_options = registry.try_resource<SystemOptions>()) {
    for (auto& [name, option] : system_options->options) {
      if (!option.declared) continue;
      if (option.step == SystemOption::Step::Fraction) {
        auto value = static_cast<float>(option.value);
        if (ImGui::SliderFloat(option.label.c_str(), &value, static_cast<float>(option.min), static_cast<float>(option.max), "%.3f")) {
          option.value = value;
        }
        continue;
      }
      int value = static_cast<int>(option.value);
      if (ImGui::SliderInt(option.label.c_str(), &value, static_cast<int>(option.min), static_cast<int>(option.max), "%d",
                           ImGuiSliderFlags_Logarithmic)) {
        option.value = value;
      }
    }
  }
  ImGui::PopItemWidth();
}

void Overlay::thumbnails(const render::MeshRenderer& renderer) {
  const GLuint texture = renderer.gbuffer_thumbnails();
  if (texture == 0) {
    ImGui::TextUnformatted("(this mode has no G-buffer)");
    return;
  }
  using render::DebugViews;
  const glm::ivec2 cell = renderer.thumbnail_size();
  constexpr int kRows = DebugViews::kThumbnailCount / DebugViews::kThumbnailColumns;
  // The cells share the panel's width, however many columns there are.
  const float spacing = ImGui::GetStyle().ItemSpacing.x;
  const float width = std::min(static_cast<float>(cell.x),
                               (ImGui::GetContentRegionAvail().x - spacing * (DebugViews::kThumbnailColumns - 1)) / DebugViews::kThumbnailColumns);
  const ImVec2 size(width, width * static_cast<float>(cell.y) / static_cast<float>(cell.x));
  for (int view = 0; view < DebugViews::kThumbnailCount; ++view) {
    // GL rows run bottom-up: the cell's top edge has the larger v.
    const int column = view % DebugViews::kThumbnailColumns, row = kRows - 1 - view / DebugViews::kThumbnailColumns;
    const ImVec2 uv0(static_cast<float>(column) / DebugViews::kThumbnailColumns, static_cast<float>(row + 1) / kRows);
    const ImVec2 uv1(static_cast<float>(column + 1) / DebugViews::kThumbnailColumns, static_cast<float>(row) / kRows);
    ImGui::BeginGroup();
    ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<std::uintptr_t>(texture)), size, uv0, uv1);
    ImGui::TextUnformatted(std::string(DebugViews::kThumbnailViews[static_cast<std::size_t>(view)]).c_str());
    ImGui::EndGroup();
    if (column + 1 < DebugViews::kThumbnailColumns) ImGui::SameLine();
  }
}

void Overlay::draw(ecs::Registry& registry) {
  auto& state = registry.resource<OverlayState>();
  auto& input = registry.resource<InputState>();
  registry.resource<RendererSettings>().gbuffer_thumbnails = state.visible;
  if (!state.visible) {
    input.ui_wants_mouse = input.ui_wants_keyboard = false;
    return;
  }
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(430, std::max(200.0f, ImGui::GetIO().DisplaySize.y - 16)), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(0.8f);
  if (ImGui::Begin("Atrium (F1 hides, h for keys)")) {
    statistics(registry);
    if (ImGui::CollapsingHeader("controls", ImGuiTreeNodeFlags_DefaultOpen)) controls(registry);
    if (ImGui::CollapsingHeader("G-buffer", ImGuiTreeNodeFlags_DefaultOpen)) thumbnails(registry.resource<render::MeshRenderer>());
    if (!state.message.empty() && ImGui::CollapsingHeader("messages", ImGuiTreeNodeFlags_DefaultOpen)) {
      ImGui::TextUnformatted(state.message.c_str());
    }
  }
  ImGui::End();
  if (state.show_help) {
    ImGui::Begin("keys", &state.show_help, ImGuiWindowFlags_AlwaysAutoResize);
    ImGui::TextUnformatted(state.key_help.c_str());
    ImGui::End();
  }
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  const ImGuiIO& io = ImGui::GetIO();
  input.ui_wants_mouse = io.WantCaptureMouse;
  input.ui_wants_keyboard = io.WantCaptureKeyboard;
}

}  // namespace

void register_overlay(ecs::Registry& registry, GLFWwindow* window) {
  registry.set_resource<DemoRequests>();
  registry.set_resource<OverlayState>();
  registry.set_resource<Overlay>(window);
  // A pass over the window's framebuffer after presenting: the frame graph
  // times it with the others.
  registry.resource<render::FrameModules>().add({render::FrameStage::Window, "overlay", [](render::FrameBuild& build) {
    build.graph.add_pass("overlay", [](render::PassBuilder& pass) { pass.keep(); }, [&r = build.registry](const render::PassResources&) {
      glBindFramebuffer(GL_FRAMEBUFFER, 0);  // the window's, not the renderer's output
      r.resource<Overlay>().draw(r);
    });
  }, {}});
}

}  // namespace atrium
