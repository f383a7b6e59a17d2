// The page's main (the WebAssembly build, web/): the same World the window
// runs, on a WebGL2 canvas through GLFW. The page's state is a command line:
// its URL parameters become options (web/shell.html: ?mode=x&view=3 is --mode
// x --view 3), and every panel control sets one option of that list, which
// the command line's own parser reads again whole: the same values and the
// same one-line messages from the URL, the panel and the terminal. The panel
// itself is the table of rows below; the page reads it, with the world's
// state, from atrium_state() twice a second.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <emscripten/emscripten.h>
#include <nlohmann/json.hpp>

#include "gfx/gl.hpp"  // before GLFW, which would bring in GL/gl.h
#include <GLFW/glfw3.h>

#include "app/cli.hpp"
#include "app/demo_keys.hpp"
#include "app/world.hpp"
#include "assets/image.hpp"
#include "assets/model_import.hpp"
#include "assets/scene_file.hpp"
#include "components/demo.hpp"
#include "components/frame_resources.hpp"
#include "components/input.hpp"
#include "components/light.hpp"
#include "components/camera.hpp"
#include "components/system_options.hpp"
#include "components/transform.hpp"
#include "gfx/context.hpp"
#include "gfx/gl_object.hpp"
#include "gfx/limits.hpp"
#include "render/lighting/shading_model.hpp"
#include "render/shadows/shadow_selection.hpp"
#include "render/techniques/technique.hpp"
#include "systems/fly_camera.hpp"
#include "systems/input.hpp"
#include "systems/light_animation.hpp"

namespace atrium {
namespace {

struct Page {
  std::unique_ptr<gfx::WindowContext> context;
  std::unique_ptr<World> world;
  // The scene, then the options the world runs with: the URL's, with the
  // panel's changes (and, synced before each change, what keys changed).
  std::vector<std::string> args;
  std::string confirm;  // a change refused as too slow once: asked again, it is carried out
  // The light count the user chose (the URL's --lights, or any count the panel
  // or + and - set since): a scene file opened next keeps it; otherwise it
  // comes with its own lights, as on the command line.
  bool lights_given = false;     // the world started with --lights
  std::uint32_t scene_lights = 0;  // its light count then
  // A panel change on trial for its first frames (check_trial), with the
  // arguments to return to.
  struct Trial {
    std::vector<std::string> before;
    std::string change;
    int frames = 0;
  };
  std::optional<Trial> trial;
  double last_seconds = 0.0;
  double stats_seconds = 0.0;
  int frames_since_stats = 0;
  double fps = 0.0, frame_ms = 0.0;  // over the last half second
  double last_frame_ms = 0.0;         // the latest frame's, before the first half second has passed
  std::uint64_t memory_bytes = 0;    // estimated, twice a second (asking the driver is not free)
  std::string reply;       // what the last atrium_* call returns to the page
  std::string last_error;  // what the last frame failed with
};
Page* g_page = nullptr;

// A change that would make one frame take longer than this, judged by the
// last frames' cost per light, is refused until asked for again: a frame is
// not interruptible, and a software renderer at 2^20 lights takes minutes.
// Changes whose cost cannot be judged beforehand (a mode, MSAA, shadows) are
// undone when one of their first kTrialFrames frames took longer (fewer
// lights never are).
constexpr double kSlowFrameMs = 5000.0;
constexpr int kTrialFrames = 3;

void show_error(const std::string& message) {
  std::fprintf(stderr, "atrium: %s\n", message.c_str());
  EM_ASM({ atriumShowError(UTF8ToString($0)); }, message.c_str());
}

CliOptions parse_args(const std::vector<std::string>& args) {
  const std::vector<std::string_view> views(args.begin(), args.end());
  return parse_cli(views);
}

// Where `option` stands in `args` (after the scene), or args.size().
std::size_t find_option(const std::vector<std::string>& args, std::string_view option) {
  for (std::size_t i = 1; i < args.size(); ++i) {
    if (args[i] == option) return i;
  }
  return args.size();
}

// `args` without `option` (and its value, when it has one: an argument after
// it that is not an option; "-5" is a value).
std::vector<std::string> without(std::vector<std::string> args, std::string_view option) {
  const std::size_t at = find_option(args, option);
  if (at == args.size()) return args;
  const bool has_value = at + 1 < args.size() && args[at + 1].rfind("--", 0) != 0;
  args.erase(args.begin() + static_cast<std::ptrdiff_t>(at), args.begin() + static_cast<std::ptrdiff_t>(at + (has_value ? 2 : 1)));
  return args;
}

std::vector<std::string> with(std::vector<std::string> args, const std::string& option, const std::string& value) {
  args = without(std::move(args), option);
  args.push_back(option);
  args.push_back(value);
  return args;
}

std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// The page's controls: each row is one option of the command line, shown as a
// choice, a number or a check box, with what the world runs now in the
// option's own words. Keys and refusals change the world; the panel shows it.
enum class Control { Choice, Number, Flag, FlagOff };  // FlagOff: checked while the option is absent
struct PanelRow {
  std::string_view option, label;
  Control control;
  double min, max, step;                             // Number rows
  std::vector<std::string> (*choices)(World& world);  // Choice rows
  std::string (*value)(World& world);
  // The value (or an empty one) that means the option is left out: no debug
  // view, each light's own radius. nullptr: every value is given to the option.
  const char* absent = nullptr;
};

RendererSettings& settings(World& world) { return world.registry().resource<RendererSettings>(); }
template <std::size_t N>
std::vector<std::string> names(const std::array<std::string_view, N>& table) {
  return {table.begin(), table.end()};
}

const std::array kPanel{
    PanelRow{"--mode", "mode", Control::Choice, 0, 0, 0, [](World& w) { return w.modes(); }, [](World& w) { return w.mode(); }},
    PanelRow{"--view", "view", Control::Choice, 0, 0, 0,
             [](World& w) {
               std::vector<std::string> views;
               for (std::size_t i = 1; i <= w.scene().views.size(); ++i) views.push_back(std::to_string(i));
               return views;
             },
             [](World& w) { return std::to_string(w.view()); }},
    PanelRow{"--lights", "lights", Control::Number, 0, kMaxLights, 1, nullptr, [](World& w) { return std::to_string(w.light_count()); }},
    PanelRow{"--light-radius", "light radius (m; 0: each light's own)", Control::Number, 0, 1000, 0.5, nullptr,
             [](World& w) { return number_text(w.light_radius().value_or(0.0f)); }, "0"},
    PanelRow{"--debug-view", "debug view", Control::Choice, 0, 0, 0,
             [](World& w) {
               std::vector<std::string> views{""};
               for (const render::OfferedView& view : w.renderer().offered_views()) views.push_back(view.name);
               // A view the frame refused is listed too: the list shows what was asked.
               if (std::find(views.begin(), views.end(), settings(w).debug_view) == views.end()) views.push_back(settings(w).debug_view);
               return views;
             },
             [](World& w) { return settings(w).debug_view; }, ""},
    PanelRow{"--shading", "shading", Control::Choice, 0, 0, 0, [](World&) { return names(lighting::kShadingModels); },
             [](World& w) { return settings(w).shading; }},
    PanelRow{"--msaa", "MSAA samples", Control::Choice, 0, 0, 0,
             [](World&) {
               std::vector<std::string> counts{"1"};
               for (int samples = 2; samples <= std::min(8, gfx::max_msaa_samples()); samples *= 2) counts.push_back(std::to_string(samples));
               return counts;
             },
             [](World& w) { return std::to_string(settings(w).technique_options.msaa); }},
    PanelRow{"--shadows", "shadowed lights", Control::Number, 0, shadows::kMaxShadowedLights, 1, nullptr,
             [](World& w) { return std::to_string(settings(w).shadows); }},
    PanelRow{"--no-occlusion-culling", "occlusion culling", Control::FlagOff, 0, 0, 0, nullptr,
             [](World& w) { return std::string(settings(w).occlusion_culling ? "on" : "off"); }},
    PanelRow{"--z-slicing", "depth slicing (clustered modes)", Control::Choice, 0, 0, 0, [](World&) { return names(kZSlicingNames); },
             [](World& w) { return std::string(kZSlicingNames[static_cast<std::size_t>(settings(w).technique_options.z_slicing)]); }},
    PanelRow{"--split-lighting", "diffuse and specular apart", Control::Flag, 0, 0, 0, nullptr,
             [](World& w) { return std::string(settings(w).technique_options.split_lighting ? "on" : "off"); }},
};

// A control as the page shows it now: a row of kPanel evaluated on the
// world, or a slider of an optional system (components/system_options.hpp:
// each system declares its own, as the overlay shows them; its command-line
// option is its name with two dashes).
struct PanelControl {
  std::string option, label;
  Control control;
  double min = 0.0, max = 0.0, step = 0.0;
  std::vector<std::string> choices;
  std::string value;
  const char* absent = nullptr;

  [[nodiscard]] bool leaves_out(const std::string& given) const { return absent && (given.empty() || given == absent); }
};

std::vector<PanelControl> panel(World& world) {
  std::vector<PanelControl> controls;
  for (const PanelRow& row : kPanel) {
    controls.push_back({std::string(row.option), std::string(row.label), row.control, row.min, row.max, row.step,
                        row.choices ? row.choices(world) : std::vector<std::string>{}, row.value(world), row.absent});
  }
  for (const auto& [name, option] : world.registry().resource<SystemOptions>().options) {
    if (!option.declared) continue;
    controls.push_back({"--" + name, option.label, Control::Number, option.min, option.max,
                        option.step == SystemOption::Step::Whole ? 1.0 : 0.01, {}, number_text(option.value)});
  }
  return controls;
}

const PanelControl* find_control(const std::vector<PanelControl>& controls, std::string_view option) {
  for (const PanelControl& control : controls) {
    if (control.option == option) return &control;
  }
  return nullptr;
}

// The keys change mode, view, lights and debug view without the panel: the
// arguments take them from the world (`controls`, the panel now) before a
// change is made to them.
void sync_args(Page& page, const std::vector<PanelControl>& controls) {
  for (const char* option : {"--mode", "--view", "--lights", "--debug-view"}) {
    const PanelControl& control = *find_control(controls, option);
    page.args = control.leaves_out(control.value) ? without(page.args, option) : with(page.args, option, control.value);
  }
}

std::string duration_text(double ms) {
  if (ms < 120'000.0) return number_text(std::round(ms / 1000.0)) + " s";
  return number_text(std::round(ms / 60'000.0)) + " minutes";
}

// Refuses, once, a light count whose frames the last frames' cost per light
// says would take over kSlowFrameMs.
void refuse_slow_lights(Page& page, std::uint32_t lights, const std::string& change) {
  World& world = *page.world;
  const double frame_ms = page.frame_ms > 0.0 ? page.frame_ms : page.last_frame_ms;
  const double per_light = frame_ms / std::max(world.light_count(), 1u);
  const double estimate = per_light * lights;
  if (frame_ms <= 0.0 || lights <= world.light_count() || estimate <= kSlowFrameMs || page.confirm == change) {
    page.confirm.clear();
    return;
  }
  page.confirm = change;
  throw InputError("--lights " + std::to_string(lights) + ": a frame would take about " + duration_text(estimate) + " on this renderer (" +
                   number_text(std::round(frame_ms)) + " ms a frame now, with " + std::to_string(world.light_count()) +
                   " lights); set it again to draw it anyway");
}

// Runs the world with `args`, carrying out what differs from the page's.
void carry_out(Page& page, std::vector<std::string> args) {
  World& world = *page.world;
  const WorldOptions before = world_options(parse_args(page.args));
  const WorldOptions after = world_options(parse_args(args));
  world.apply_settings(after);
  if (after.lights && after.lights != before.lights) world.set_light_count(*after.lights);
  if (after.light_radius != before.light_radius) world.set_light_radius(after.light_radius);
  if (after.view != before.view) world.set_view(after.view);
  page.args = std::move(args);
}

// Sets `option` to `value` (a flag: "on" or "off") in the page's arguments,
// checks the whole list with the command line's parser and carries out what
// changed. Throws UsageError or InputError with the one-line message.
void set_option(Page& page, const std::string& option, const std::string& value) {
  World& world = *page.world;
  const std::vector<PanelControl> controls = panel(world);
  const PanelControl* row = find_control(controls, option);
  if (!row) throw InputError("the panel has no option " + option);
  sync_args(page, controls);
  std::vector<std::string> args = without(page.args, option);
  const bool flag = row->control == Control::Flag || row->control == Control::FlagOff;
  if (flag) {
    if (value != "on" && value != "off") throw InputError(option + " expects on or off, got '" + value + "'");
    if ((value == "on") == (row->control == Control::Flag)) args.push_back(option);
  } else if (!row->leaves_out(value)) {
    args = with(args, option, value);
  }
  const std::string change = option + " " + value;
  const bool insisted = !page.confirm.empty() && page.confirm == change;
  const WorldOptions before = world_options(parse_args(page.args));
  const WorldOptions after = world_options(parse_args(args));
  if (after.lights && after.lights != before.lights) refuse_slow_lights(page, *after.lights, change);
  // Fewer lights cannot have made a frame slow: on a page whose frames already
  // take over kSlowFrameMs a trial would undo the change meant to speed it up.
  const bool fewer_lights = after.lights && *after.lights < world.light_count();
  std::vector<std::string> previous = page.args;
  carry_out(page, std::move(args));
  page.confirm.clear();
  if (insisted || fewer_lights) {
    page.trial.reset();
  } else {
    page.trial = Page::Trial{std::move(previous), change};
  }
}

// A change on trial whose frame took over kSlowFrameMs is undone, with the
// reason, and carried out when asked again (the light count's estimate
// cannot judge a mode or MSAA); after kTrialFrames quick frames it stays.
void check_trial(Page& page, double frame_ms) {
  Page::Trial& trial = *page.trial;
  if (frame_ms <= kSlowFrameMs) {
    if (++trial.frames >= kTrialFrames) page.trial.reset();
    return;
  }
  const std::string change = trial.change;
  carry_out(page, std::move(trial.before));
  page.trial.reset();
  page.confirm = change;
  show_error(change + ": a frame took " + duration_text(frame_ms) + " on this renderer, over " + duration_text(kSlowFrameMs) +
             "; it is undone (set it again to draw it anyway)");
}

// A new World for `args` (the scene first), with the systems a window has;
// it replaces the page's only once it has loaded.
void start_world(Page& page, std::vector<std::string> args) {
  const CliOptions options = parse_args(args);
  auto world = std::make_unique<World>(world_options(options));
  world->registry().resource<RendererSettings>().present_to_window = true;
  register_input(world->scheduler(), world->registry(), page.context->window());
  register_fly_camera(world->scheduler());
  register_light_animation(world->scheduler(), world->registry());
  world->registry().set_resource<DemoRequests>();
  page.lights_given = options.lights.has_value();
  page.scene_lights = world->light_count();
  page.world = std::move(world);
  page.args = std::move(args);
  page.last_error.clear();
  page.confirm.clear();
  page.trial.reset();
  page.frame_ms = page.last_frame_ms = 0.0;
}

// What the panel shows, as JSON: fps, the latest frame's pass times and counts,
// memory, the camera, and each panel row with its choices and value now.
std::string state_json(Page& page) {
  World& world = *page.world;
  const gfx::PassTimer& timer = world.renderer().timer();
  nlohmann::ordered_json passes = nlohmann::ordered_json::array(), controls = nlohmann::ordered_json::array();
  double total = 0.0;
  for (const gfx::PassTime& pass : timer.latest()) {
    passes.push_back({{"name", pass.name}, {"ms", pass.milliseconds}});
    total += pass.milliseconds;
  }
  for (const PanelControl& control : panel(world)) {
    static constexpr const char* kControls[] = {"choice", "number", "flag", "flag"};
    nlohmann::ordered_json json{{"option", control.option}, {"label", control.label}, {"control", kControls[static_cast<int>(control.control)]},
                                {"value", control.value}};
    if (control.control == Control::Choice) json["choices"] = control.choices;
    if (control.control == Control::Number) json["range"] = {control.min, control.max, control.step};
    controls.push_back(std::move(json));
  }
  const render::FrameStats& stats = world.renderer().stats();
  const std::optional<assets::NamedView> here = camera_here(world);
  const nlohmann::ordered_json state{
      {"fps", page.fps},
      {"frame_ms", page.frame_ms},
      {"refused", page.last_error},  // why the latest frame drew nothing; empty when it drew
      {"mode", world.mode()},
      {"lights", world.light_count()},
      {"paused", world.registry().resource<LightAnimationSettings>().paused},
      {"timing", timer.method_name()},
      {"passes_ms", total},
      {"passes", passes},
      {"counts",
       {{"triangles", stats.triangles},
        {"triangles_drawn", stats.triangles_drawn},
        {"draw_calls", stats.draw_calls},
        {"objects", stats.objects},
        {"objects_drawn", stats.objects_drawn}}},
      {"memory_bytes", page.memory_bytes},
      {"camera", here ? assets::camera_argument(*here) : std::string()},
      {"args", page.args},
      {"panel", controls}};
  return state.dump();
}

void frame() {
  Page& page = *g_page;
  if (!page.world) return;
  World& world = *page.world;
  const double now = emscripten_get_now() / 1000.0;
  int width = 0, height = 0;
  glfwGetFramebufferSize(page.context->window(), &width, &height);
  if (width > 0 && height > 0) world.set_size({width, height});
  try {
    world.frame(page.last_seconds > 0.0 ? now - page.last_seconds : 0.0);
    apply_demo_keys(world);
    carry_out_demo_requests(world);
    page.last_error.clear();
  } catch (const std::exception& e) {
    // Once, not every frame: the panel's next change may cure it.
    if (page.last_error != e.what()) show_error(e.what());
    page.last_error = e.what();
  }
  // The first frame's time is what a newcomer waits for: the page shows it.
  if (page.last_seconds == 0.0) EM_ASM({ atriumFirstFrame(); });
  if (page.last_seconds > 0.0) page.last_frame_ms = (now - page.last_seconds) * 1000.0;
  if (page.trial && page.last_seconds > 0.0) check_trial(page, page.last_frame_ms);
  page.last_seconds = now;
  ++page.frames_since_stats;
  if (now - page.stats_seconds >= 0.5) {
    page.fps = page.frames_since_stats / (now - page.stats_seconds);
    page.frame_ms = 1000.0 / page.fps;
    page.memory_bytes = gfx::estimated_gpu_memory_bytes();
    const std::string json = state_json(page);
    EM_ASM({ atriumShowStats(UTF8ToString($0)); }, json.c_str());
    page.stats_seconds = now;
    page.frames_since_stats = 0;
  }
}

// Waits until the GPU has drawn the frame: reading back a pixel of the canvas
// (which the frame's last pass writes) is a round trip to the GPU process.
void wait_for_frame() {
  std::uint8_t pixel[4];
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixel);
}

// Runs `change` on the world; the reply is empty or the one-line error.
template <typename Change>
const char* apply(Change change) {
  g_page->reply.clear();
  if (!g_page->world) return "";  // it failed to start, and said why
  try {
    change(*g_page->world);
  } catch (const std::exception& e) {
    g_page->reply = e.what();
  }
  return g_page->reply.c_str();
}

// The page's default arguments (web/shell.html's atriumDefaults: the built-in
// scene in clustered-deferred at a size that fits the window).
std::vector<std::string> page_defaults() {
  // wasm32: a pointer is an int.
  char* json = reinterpret_cast<char*>(EM_ASM_INT({ return stringToNewUTF8(JSON.stringify(atriumDefaults())); }));
  std::vector<std::string> args = nlohmann::json::parse(json).get<std::vector<std::string>>();
  std::free(json);
  return args;
}

}  // namespace
}  // namespace atrium

extern "C" {

EMSCRIPTEN_KEEPALIVE const char* atrium_state() {
  atrium::g_page->reply = atrium::g_page->world ? atrium::state_json(*atrium::g_page) : "{}";
  return atrium::g_page->reply.c_str();
}

// One panel row's option set to `value` ("on"/"off" for a check box).
EMSCRIPTEN_KEEPALIVE const char* atrium_set(const char* option, const char* value) {
  return atrium::apply([&](atrium::World&) { atrium::set_option(*atrium::g_page, option, value); });
}

EMSCRIPTEN_KEEPALIVE const char* atrium_set_paused(int paused) {
  return atrium::apply([&](atrium::World& world) {
    world.registry().resource<atrium::LightAnimationSettings>().paused = paused != 0;
  });
}

// Loads `scene` (the built-in scene, a scene file or a model in the page's
// file system: fetched or dropped files) with the page's options, less the
// view and camera of the scene before (a model with no lights of its own is
// lit by the light count the page has); the old world runs on until the new
// one has loaded, and stays if it fails.
EMSCRIPTEN_KEEPALIVE const char* atrium_open_scene(const char* scene) {
  atrium::Page& page = *atrium::g_page;
  page.reply.clear();
  try {
    if (page.world) atrium::sync_args(page, atrium::panel(*page.world));
    std::vector<std::string> args = page.args.empty() ? atrium::page_defaults() : page.args;
    for (const char* option : {"--view", "--camera"}) args = atrium::without(std::move(args), option);
    // A dropped model, which brings few lights or none, is lit by the page's.
    const bool keep_lights = atrium::assets::is_model_file(scene) || page.lights_given ||
                             (page.world && page.world->light_count() != page.scene_lights);
    if (!keep_lights) args = atrium::without(std::move(args), "--lights");
    args[0] = scene;
    const bool paused = page.world && page.world->registry().resource<atrium::LightAnimationSettings>().paused;
    atrium::start_world(page, std::move(args));
    page.world->registry().resource<atrium::LightAnimationSettings>().paused = paused;
  } catch (const std::exception& e) {
    page.reply = e.what();
  }
  return page.reply.c_str();
}

// The frame as the canvas shows it, as a PNG in the page's file system at
// `path` (the page offers it as a download).
EMSCRIPTEN_KEEPALIVE const char* atrium_screenshot(const char* path) {
  return atrium::apply([&](atrium::World& world) { atrium::assets::write_png(path, world.renderer().read_output()); });
}

// The help lines of the keys the canvas takes.
EMSCRIPTEN_KEEPALIVE const char* atrium_key_help() {
  atrium::g_page->reply = atrium::demo_key_help() + atrium::key_help_line("F12", "screenshot (a PNG download)") +
                          atrium::key_help_line("h", "key help");
  return atrium::g_page->reply.c_str();
}

// Draws every mode once from the current view and writes each picture to
// `folder`/MODE.png in the page's file system (the browser tests read them);
// the reply names the first failure, and any WebGL error.
EMSCRIPTEN_KEEPALIVE const char* atrium_capture_modes(const char* folder) {
  return atrium::apply([&](atrium::World& world) {
    std::filesystem::create_directories(folder);
    for (const std::string& mode : world.modes()) {
      world.set_mode(mode);
      world.frame(0.0);
      atrium::assets::write_png(std::filesystem::path(folder) / (mode + ".png"), world.renderer().read_output());
      if (const GLenum error = glGetError(); error != GL_NO_ERROR) {
        throw std::runtime_error("WebGL error 0x" + std::to_string(error) + " drawing " + mode);
      }
    }
  });
}

// Frame times of every mode from the current view, as JSON ({"forward":
// 12.3, ...}: the median of `frames` after `warmup`, in milliseconds, as atrium
// bench reports them). A browser's glFinish does not wait for its GPU
// process; reading a pixel of the canvas does, so each frame's time is what
// it cost the GPU as well as the CPU.
EMSCRIPTEN_KEEPALIVE const char* atrium_bench_modes(int frames, int warmup) {
  nlohmann::ordered_json medians = nlohmann::ordered_json::object();
  const char* error = atrium::apply([&](atrium::World& world) {
    for (const std::string& mode : world.modes()) {
      world.set_mode(mode);
      for (int i = 0; i < warmup; ++i) world.frame(0.0);
      atrium::wait_for_frame();
      std::vector<double> times;
      for (int i = 0; i < std::max(frames, 1); ++i) {
        const double start = emscripten_get_now();
        world.frame(0.0);
        atrium::wait_for_frame();
        times.push_back(emscripten_get_now() - start);
      }
      std::nth_element(times.begin(), times.begin() + static_cast<std::ptrdiff_t>(times.size() / 2), times.end());
      medians[mode] = times[times.size() / 2];
    }
  });
  if (*error) return error;
  atrium::g_page->reply = medians.dump();
  return atrium::g_page->reply.c_str();
}

}  // extern "C"

int main(int argc, char** argv) {
  using namespace atrium;
  g_page = new Page();
  std::vector<std::string> args(argv + 1, argv + argc);
  try {
    const CliOptions options = parse_args(args);
    g_page->context = gfx::WindowContext::create("Atrium", options.size.x, options.size.y, {.api = options.gl_api});
    start_world(*g_page, std::move(args));
  } catch (const std::exception& e) {
    // A bad URL parameter: the message stays on the page, which runs its defaults.
    show_error(e.what());
    try {
      std::vector<std::string> defaults = page_defaults();
      const CliOptions options = parse_args(defaults);
      if (!g_page->context) g_page->context = gfx::WindowContext::create("Atrium", options.size.x, options.size.y, {.api = options.gl_api});
      start_world(*g_page, std::move(defaults));
    } catch (const std::exception& fallback) {
      show_error(fallback.what());
      EM_ASM({ atriumShowRefused(UTF8ToString($0)); }, fallback.what());
      g_page->world.reset();
      return kExitUsage;
    }
  }
  std::printf("Atrium on %s (%s), %s, %u lights\n", g_page->context->info().api.c_str(), g_page->context->info().renderer.c_str(),
              g_page->world->mode().c_str(), g_page->world->light_count());
  g_page->stats_seconds = emscripten_get_now() / 1000.0;
  emscripten_set_main_loop(frame, 0, false);
  return kExitOk;
}
