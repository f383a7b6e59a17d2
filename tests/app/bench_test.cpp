// atrium bench: a tiny sweep through the real command writes well-formed CSV,
// markdown and PNG; `atrium render` settles light lists under either view
// name; and the efficiency counters are exact on a hand-built
// scene where the answer is known.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "app/bench.hpp"
#include "app/world.hpp"
#include "assets/image.hpp"
#include "assets/mesh_builder.hpp"
#include "components/frame_resources.hpp"
#include "gfx/limits.hpp"
#include "systems/light_animation.hpp"
#include "support/gl_test.hpp"

namespace atrium {
namespace {
namespace fs = std::filesystem;

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream out;
  out << in.rdbuf();
  return out.str();
}

// Splits one CSV line, honouring double quotes.
std::vector<std::string> csv_fields(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (char c : line) {
    if (c == '"') quoted = !quoted;
    else if (c == ',' && !quoted) fields.emplace_back();
    else fields.back() += c;
  }
  return fields;
}

// The rows of a CSV file the bench wrote, its header left out.
std::vector<std::vector<std::string>> csv_rows(const fs::path& path) {
  std::istringstream csv(read_text(path));
  std::string line;
  std::getline(csv, line);
  std::vector<std::vector<std::string>> rows;
  while (std::getline(csv, line)) rows.push_back(csv_fields(line));
  return rows;
}

TEST(BenchCommand, TinySweepWritesWellFormedCsvMarkdownAndPlot) {
  const fs::path folder = fs::temp_directory_path() / ("atrium_bench_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  const std::string command = std::string(ATRIUM_BINARY) +
                              " bench --modes forward,deferred-radius --lights 3,6 --views 1,2 --size 32x18 --frames 2 --warmup 1"
                              " --csv " + (folder / "b.csv").string() + " --md " + (folder / "b.md").string() +
                              " --plot " + (folder / "b.png").string() + " > " + (folder / "stdout.txt").string();
  ASSERT_EQ(std::system(command.c_str()), 0) << read_text(folder / "stdout.txt");

  std::istringstream csv(read_text(folder / "b.csv"));
  std::string line;
  std::getline(csv, line);
  const std::vector<std::string> header = csv_fields(line);
  ASSERT_EQ(header.size(), 34u);
  EXPECT_EQ(header[0], "mode");
  EXPECT_EQ(header[7], "median_ms");
  EXPECT_EQ(header[17], "refused");
  EXPECT_EQ(header[18], "triangles_drawn");
  EXPECT_EQ(header[19], "draw_calls");
  EXPECT_EQ(header[20], "cpu_passes");
  EXPECT_EQ(header[21], "z_slicing");
  EXPECT_EQ(header[22], "shadows");
  EXPECT_EQ(header[23], "triangles_occluded");
  EXPECT_EQ(header[24], "gpu_ms");
  EXPECT_EQ(header[25], "gpu_waits");
  EXPECT_EQ(header[26], "skipped");
  EXPECT_EQ(header[27], "lighting_stage");
  EXPECT_EQ(header[28], "light_lists");
  EXPECT_EQ(header[29], "cpu_systems");
  EXPECT_EQ(header[30], "pipelined_ms");
  EXPECT_EQ(header[31], "technique_variant");
  EXPECT_EQ(header[32], "pass_steps");
  EXPECT_EQ(header[33], "paced_ms");
  int rows = 0;
  while (std::getline(csv, line)) {
    const std::vector<std::string> f = csv_fields(line);
    ASSERT_EQ(f.size(), header.size()) << line;
    EXPECT_TRUE(f[0] == "forward" || f[0] == "deferred-radius");
    EXPECT_GT(std::stod(f[7]), 0.0);
    EXPECT_LE(std::stod(f[8]), std::stod(f[7])) << "p5 <= median";
    EXPECT_GE(std::stod(f[9]), std::stod(f[7])) << "p95 >= median";
    EXPECT_NE(f[14].find("tonemap="), std::string::npos) << "per-pass medians";
    EXPECT_EQ(f[17], "") << "nothing refused";
    // The built-in scene: views 1 and 2 see most of its 251,144 triangles (the
    // gallery's walls hide two fifths of what it has in view), in one
    // multi-draw per texture set (10 materials).
    EXPECT_GT(std::stoul(f[18]), 60000u);
    EXPECT_LE(std::stoul(f[18]) + std::stoul(f[23]), 251144u);
    EXPECT_GT(std::stoul(f[18]) + std::stoul(f[23]), 100000u);
    EXPECT_GE(std::stoul(f[19]), 1u);
    EXPECT_LE(std::stoul(f[19]), 10u);
    EXPECT_NE(f[20].find("tonemap="), std::string::npos) << "per-pass CPU medians";
    EXPECT_EQ(f[21], "") << "neither mode slices depth";
    EXPECT_GT(std::stod(f[24]), 0.0) << "the passes' summed time";
    EXPECT_LE(std::stod(f[24]), std::stod(f[7]) * 1.05) << "the passes fit in the frame";
    EXPECT_EQ(f[26], "") << "nothing skipped";
    EXPECT_EQ(f[28], "") << "neither mode has light lists";
    EXPECT_EQ(f[32], "") << "steps are timed only with --pass-steps";
    // The frames back to back wait for the GPU only between frames, and for no
    // longer than they took.
    EXPECT_GE(std::stod(f[33]), 0.0);
    EXPECT_LE(std::stod(f[33]), std::stod(f[30])) << "paced within pipelined";
    ++rows;
  }
  EXPECT_EQ(rows, 2 * 2 * 2);

  const std::string md = read_text(folder / "b.md");
  EXPECT_NE(md.find("| lights | forward | deferred-radius |"), std::string::npos) << md;
  EXPECT_NE(md.find("| 3 |"), std::string::npos);
  EXPECT_NE(md.find("| 6 |"), std::string::npos);
  EXPECT_NE(md.find("Speed-up over forward"), std::string::npos);
  EXPECT_EQ(read_text(folder / "stdout.txt"), md) << "the table printed is the one written";

  const assets::Image plot = assets::read_png(folder / "b.png");
  EXPECT_GT(plot.width, 300);
  EXPECT_GT(plot.height, 200);
  fs::remove_all(folder);
}

// --lighting-stage LIST: each mode is measured in each stage, named with the
// stage asked for; the CSV's lighting_stage column says the stage it ran in (auto takes
// the fragment stage on llvmpipe), and a stage the frame cannot run is a
// refused row, not a failed sweep.
TEST(BenchCommand, EachModeIsMeasuredInEachLightingStage) {
  const fs::path folder = fs::temp_directory_path() / ("atrium_bench_stage_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  auto run = [&](const std::string& options) {
    const std::string command = std::string(ATRIUM_BINARY) + " bench --modes tiled-deferred --lights 40 --views 1 --size 32x18 --frames 1"
                                " --warmup 0 " + options + " --csv " + (folder / "s.csv").string() + " > " + (folder / "stdout.txt").string();
    EXPECT_EQ(std::system(command.c_str()), 0) << read_text(folder / "stdout.txt");
    std::istringstream csv(read_text(folder / "s.csv"));
    std::string line;
    std::getline(csv, line);
    EXPECT_TRUE(line.ends_with(",skipped,lighting_stage,light_lists,cpu_systems,pipelined_ms,technique_variant,pass_steps,paced_ms")) << line;
    std::vector<std::vector<std::string>> rows;
    while (std::getline(csv, line)) rows.push_back(csv_fields(line));
    return rows;
  };
  const auto rows = run("--lighting-stage fragment,compute,auto");
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0][27], "fragment");
  EXPECT_EQ(rows[1][27], "compute");
  EXPECT_EQ(rows[2][27], gfx::is_software_renderer() ? "fragment" : "compute");
  EXPECT_TRUE(rows[0][28].starts_with("2x2 tiles of 16 px, ")) << rows[0][28];
  // Each system's CPU time: the light buffer's and the renderer's are there, in execution order.
  EXPECT_NE(rows[0][29].find("Render/light_buffer="), std::string::npos) << rows[0][29];
  EXPECT_LT(rows[0][29].find("Render/light_buffer="), rows[0][29].find("Render/mesh_renderer=")) << rows[0][29];
  // The frames back to back: a time for a measured row, none for a refused one.
  EXPECT_GT(std::stod(rows[0][30]), 0.0) << rows[0][30];
  const std::string md = read_text(folder / "stdout.txt");
  EXPECT_NE(md.find("| lights | tiled-deferred/fragment | tiled-deferred/compute | tiled-deferred/auto |"), std::string::npos) << md;
  EXPECT_NE(md.find("| systems (CPU, median) |"), std::string::npos) << md;
  EXPECT_NE(md.find("mesh_renderer "), std::string::npos) << "the renderer takes over 0.05 ms: " << md;
  const auto refused = run("--no-compute --lighting-stage fragment,compute");
  ASSERT_EQ(refused.size(), 2u);
  EXPECT_EQ(refused[0][17], "");
  EXPECT_NE(refused[1][17].find("needs compute shaders and storage images, which the compute-free tier does not use"), std::string::npos)
      << refused[1][17];
  EXPECT_EQ(refused[1][27], "") << "a refused run has no stage";
  EXPECT_EQ(refused[1][30], "-") << "nor frames back to back";
  fs::remove_all(folder);
}

// --z-slicing LIST: each clustered mode is measured once per scheme and named
// with it; a mode without a cluster grid is measured once.
TEST(BenchCommand, SlicingSchemesAreMeasuredForTheClusteredModesOnly) {
  const fs::path folder = fs::temp_directory_path() / ("atrium_bench_z_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  const std::string command = std::string(ATRIUM_BINARY) +
                              " bench --modes forward,clustered-forward --z-slicing log,uniform,plain-log --lights 40 --views 1"
                              " --size 32x18 --frames 1 --warmup 0 --csv " + (folder / "z.csv").string() +
                              " --plot " + (folder / "z.png").string() + " > " + (folder / "stdout.txt").string();
  ASSERT_EQ(std::system(command.c_str()), 0) << read_text(folder / "stdout.txt");
  std::istringstream csv(read_text(folder / "z.csv"));
  std::string line;
  std::getline(csv, line);
  std::vector<std::string> measured;
  while (std::getline(csv, line)) {
    const std::vector<std::string> f = csv_fields(line);
    ASSERT_EQ(f.size(), 34u) << line;
    measured.push_back(f[0] + (f[21].empty() ? "" : "/" + f[21]));
    // A pixel grid never has fewer tiles than 16x9 (32x18 pixels: 2-pixel tiles), each cut into 32 slices.
    if (f[0] == "clustered-forward") EXPECT_TRUE(f[28].starts_with("16x9x32 clusters, ")) << f[28];
    else EXPECT_EQ(f[28], "");
    EXPECT_NE(f[11], "-") << "lights evaluated per pixel, counted under each scheme";
  }
  EXPECT_EQ(measured, (std::vector<std::string>{"forward", "clustered-forward/log", "clustered-forward/uniform",
                                                "clustered-forward/plain-log"}));
  const std::string md = read_text(folder / "stdout.txt");
  EXPECT_NE(md.find("| lights | forward | clustered-forward/log | clustered-forward/uniform | clustered-forward/plain-log |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| clustered-forward/plain-log | 40 | 1 "), std::string::npos) << md;
  EXPECT_GT(assets::read_png(folder / "z.png").width, 300);
  fs::remove_all(folder);
}

// --frame-limit: a run stops after a frame over the limit and says so, and the
// mode is skipped at the larger counts with the reason, so a sweep keeps to its time.
TEST(BenchCommand, AModeOverTheFrameLimitStopsAndIsSkippedAtLargerCounts) {
  const fs::path folder = fs::temp_directory_path() / ("atrium_bench_limit_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  const std::string command = std::string(ATRIUM_BINARY) +
                              " bench --modes forward --lights 8,4,16 --views 1 --size 32x18 --frames 5 --warmup 2 --frame-limit 1"
                              " --csv " + (folder / "l.csv").string() + " > " + (folder / "stdout.txt").string() + " 2> " +
                              (folder / "stderr.txt").string();
  ASSERT_EQ(std::system(command.c_str()), 0) << read_text(folder / "stderr.txt");
  const auto rows = csv_rows(folder / "l.csv");
  ASSERT_EQ(rows.size(), 3u);
  // Counts run smallest first; llvmpipe draws no frame of the built-in scene in 1 ms.
  EXPECT_EQ(rows[0][1], "4");
  EXPECT_GT(std::stod(rows[0][7]), 1.0);
  EXPECT_NE(rows[0][26].find("one frame took"), std::string::npos) << rows[0][26];
  EXPECT_NE(rows[0][26].find("over the 1 ms limit"), std::string::npos) << rows[0][26];
  for (std::size_t i = 1; i < 3; ++i) {
    EXPECT_EQ(rows[i][7], "-") << "a skipped run has no time";
    EXPECT_NE(rows[i][26].find("at 4 lights, over the 1 ms limit"), std::string::npos) << rows[i][26];
  }
  const std::string progress = read_text(folder / "stderr.txt");
  EXPECT_NE(progress.find("bench 1/3: forward, 4 lights, view 1: "), std::string::npos) << progress;
  EXPECT_NE(progress.find("bench 3/3: forward, 16 lights, view 1: skipped: "), std::string::npos) << progress;
  EXPECT_NE(read_text(folder / "stdout.txt").find("skipped: a frame took"), std::string::npos);
  fs::remove_all(folder);
}

// --moving-lights: the lights move while each mode is measured, and every
// mode meets them in the same places. The two clustered modes evaluate the
// same lists, so they count the same evaluations per pixel only when that
// holds (before the clock went back for each mode, 80.8517 and 80.8224).
TEST(BenchCommand, MovingLightsAreWhereTheyWereForEveryMode) {
  const fs::path folder = fs::temp_directory_path() / ("atrium_bench_moving_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  const std::string command = std::string(ATRIUM_BINARY) +
                              " bench --moving-lights --modes clustered-forward,clustered-deferred --lights 1024 --views 1"
                              " --size 160x90 --frames 2 --warmup 1 --csv " + (folder / "m.csv").string() + " > " +
                              (folder / "stdout.txt").string() + " 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0) << read_text(folder / "stdout.txt");
  const auto rows = csv_rows(folder / "m.csv");
  ASSERT_EQ(rows.size(), 2u);
  for (const auto& row : rows) EXPECT_NE(row[14].find("light motion"), std::string::npos) << "the lights move: " << row[14];
  EXPECT_GT(std::stod(rows[0][11]), 0.0);
  EXPECT_EQ(rows[0][11], rows[1][11]) << "evaluations per pixel of " << rows[0][0] << " and " << rows[1][0];
  fs::remove_all(folder);
}

// The window's b measures every mode from the same light positions too
// (without the clock going back, 22.0079 and 21.974 here).
using WindowBench = testing::GlTest;

TEST_F(WindowBench, EveryModeMeetsTheMovingLightsInTheSamePlaces) {
  World world({.lights = 256u, .size = {96, 54}});
  register_light_animation(world.scheduler(), world.registry());
  world.frame(0.5);
  const BenchResult result = bench_current_view(world, 2, 1);
  const BenchRow* forward_plus = nullptr;
  const BenchRow* deferred = nullptr;
  for (const BenchRow& row : result.rows) {
    if (row.mode == "clustered-forward") forward_plus = &row;
    if (row.mode == "clustered-deferred") deferred = &row;
  }
  ASSERT_TRUE(forward_plus && deferred);
  EXPECT_GT(forward_plus->evaluated_per_pixel, 0.0);
  EXPECT_EQ(forward_plus->evaluated_per_pixel, deferred->evaluated_per_pixel);
  EXPECT_EQ(world.mode(), "forward") << "the mode the window had";
}

// --pass-steps: the steps a pass names are timed inside it, listed after it
// in the table and as pass/step in the CSV, and never add up to more than the
// pass; occlusion culling names the same steps on the GPU and on the CPU (whose
// revealed draws run only in a frame that reveals something).
TEST(BenchCommand, PassStepsAreTimedInsideTheirPasses) {
  const fs::path folder = fs::temp_directory_path() / ("atrium_bench_steps_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  for (const std::string device : {"gpu", "cpu"}) {
    SCOPED_TRACE(device);
    const std::string command = std::string(ATRIUM_BINARY) +
                                " bench --modes clustered-deferred,tiled-deferred --lights 40 --views 1 --size 32x18 --frames 1"
                                " --warmup 1 --culling " + device + " --pass-steps --csv " + (folder / "s.csv").string() + " > " +
                                (folder / "stdout.txt").string();
    ASSERT_EQ(std::system(command.c_str()), 0) << read_text(folder / "stdout.txt");
    std::istringstream csv(read_text(folder / "s.csv"));
    std::string line;
    std::getline(csv, line);
    int rows = 0;
    while (std::getline(csv, line)) {
      const std::vector<std::string> f = csv_fields(line);
      ASSERT_EQ(f.size(), 34u) << line;
      std::map<std::string, double> passes, step_sums;
      std::istringstream pass_list(f[14]), step_list(f[32]);
      for (std::string item; std::getline(pass_list, item, ';');) passes[item.substr(0, item.find('='))] = std::stod(item.substr(item.find('=') + 1));
      std::set<std::string> steps;
      for (std::string item; std::getline(step_list, item, ';');) {
        const std::string name = item.substr(0, item.find('='));
        steps.insert(name);
        step_sums[name.substr(0, name.find('/'))] += std::stod(item.substr(item.find('=') + 1));
      }
      const std::string assignment = f[0] == "tiled-deferred" ? "light culling" : "light assignment";
      for (const char* step : {"/count", "/scan", "/write"}) EXPECT_TRUE(steps.contains(assignment + step)) << f[32];
      EXPECT_TRUE(steps.contains(f[0] == "tiled-deferred" ? "light culling/bounds" : "light assignment/mark")) << f[32];
      EXPECT_TRUE(steps.contains("geometry/first draws")) << f[32];
      EXPECT_TRUE(steps.contains("geometry/reveal")) << f[32];
      if (device == "gpu") EXPECT_TRUE(steps.contains("geometry/revealed draws")) << f[32];
      EXPECT_FALSE(steps.contains("geometry/remember")) << "one depth pyramid a frame, two only in the frame of a camera cut: " << f[32];
      for (const auto& [pass, sum] : step_sums) {
        ASSERT_TRUE(passes.contains(pass)) << pass;
        EXPECT_LE(sum, passes[pass] * 1.001 + 1e-3) << pass << ": its steps run inside it";
      }
      ++rows;
    }
    EXPECT_EQ(rows, 2);
    const std::string md = read_text(folder / "stdout.txt");
    EXPECT_NE(md.find("light assignment "), std::string::npos);
    EXPECT_NE(md.find(" [mark "), std::string::npos) << md;
  }
  fs::remove_all(folder);
}

// A step that ran in some of the measured frames only (the sort of a frame
// whose lists were scattered, when auto chose gather for the others) is its
// median over those frames, and the table and the CSV say how many.
TEST(BenchTables, AStepThatRanInSomeFramesSaysInHowMany) {
  BenchResult result;
  result.options.frames = 3;
  BenchRow& row = result.rows.emplace_back();
  row.mode = "tiled-deferred";
  row.lights = 1024;
  gfx::PassTime& pass = row.pass_medians.emplace_back();
  pass.name = "light culling";
  pass.milliseconds = 82.5;
  pass.steps = {{"count", 17.5, 3, 3}, {"sort", 264.0, 1, 3}};
  const std::string md = bench_markdown(result);
  EXPECT_NE(md.find("light culling 82.50 [count 17.50, sort 264.00 (1 of 3 frames)]"), std::string::npos) << md;
  const std::string csv = bench_csv(result);
  EXPECT_NE(csv.find("\"light culling/count=17.5000;light culling/sort=264.0000@1/3\""), std::string::npos) << csv;
}

using EfficiencyCounters = testing::GlTest;

// A plane that fills the whole view from above, two lights whose radius covers
// all of it and four whose radius reaches none of it.
TEST_F(EfficiencyCounters, AreExactOnAHandBuiltScene) {
  assets::AssetManager manager;
  assets::MeshAsset plane;
  assets::Material material;
  material.metallic_factor = 0.0f;
  plane.materials.push_back(material);
  plane.meshes.push_back(
      {"plane", {assets::add_geometry(plane, assets::shapes::grid(glm::vec3(-50, 0, 50), glm::vec3(100, 0, 0), glm::vec3(0, 0, -100), 4, 4, 1.0f), 0)}});
  assets::SceneDescription scene;
  scene.instances.push_back({manager.add_mesh_asset(std::move(plane)), 0, Transform{}});
  scene.lights.push_back({glm::vec3(0, 1, 0), glm::vec3(1.0f), 1.0f, 100.0f});
  scene.lights.push_back({glm::vec3(2, 2, 0), glm::vec3(1.0f), 1.0f, 100.0f});
  for (int i = 0; i < 4; ++i) scene.lights.push_back({glm::vec3(static_cast<float>(i), 60.0f, 0.0f), glm::vec3(1.0f), 1.0f, 5.0f});
  scene.views.push_back({"down", glm::vec3(0, 10, 0), 0.0f, -89.9f});
  World world(std::move(manager), std::move(scene), {.scene = "", .mode = "forward", .size = {64, 36}});
  auto& settings = world.registry().resource<RendererSettings>();
  settings.debug_view = "heatmap";
  auto evaluated = [&](const char* mode) {
    world.set_mode(mode);
    world.frame(0.0);
    world.renderer().settle();
    return world.renderer().stats().light_evaluations_per_pixel;
  };
  EXPECT_DOUBLE_EQ(evaluated("forward"), 6.0);
  EXPECT_DOUBLE_EQ(evaluated("deferred"), 6.0);
  EXPECT_DOUBLE_EQ(evaluated("deferred-radius"), 2.0);
  EXPECT_DOUBLE_EQ(evaluated("light-volumes"), 2.0);
  EXPECT_DOUBLE_EQ(evaluated("light-volumes-instanced"), 2.0);
  EXPECT_DOUBLE_EQ(evaluated("light-prepass"), 2.0);
  BenchRow row;
  row.evaluated_per_pixel = 6.0;
  row.reaching_per_pixel = 2.0;
  EXPECT_DOUBLE_EQ(row.efficiency(), 1.0 / 3.0);
}

// `atrium render` shows whole light lists in its one frame (a list's first
// frame sizes itself) whether the view is named light-lists or is the list
// resource by its own name: the two pictures are the same, and neither shows
// lights that overflowed (magenta).
TEST(RenderCommand, ALightListViewByEitherNameShowsWholeLists) {
  const fs::path folder = fs::temp_directory_path() / ("atrium_lists_" + std::to_string(::getpid()));
  fs::create_directories(folder);
  std::vector<assets::Image> images;
  for (const std::string view : {"light-lists", "cluster-light-lists"}) {
    const fs::path out = folder / (view + ".png");
    const std::string command = std::string(ATRIUM_BINARY) + " render --mode clustered-deferred --size 96x54 --debug-view " + view +
                                " --out " + out.string() + " > " + (folder / "stdout.txt").string();
    ASSERT_EQ(std::system(command.c_str()), 0) << read_text(folder / "stdout.txt");
    images.push_back(assets::read_png(out));
  }
  ASSERT_EQ(images[0].rgba, images[1].rgba) << "one picture under both names";
  int magenta = 0;
  for (std::size_t i = 0; i + 3 < images[0].rgba.size(); i += 4) {
    magenta += images[0].rgba[i] > 200 && images[0].rgba[i + 1] < 60 && images[0].rgba[i + 2] > 200;
  }
  EXPECT_EQ(magenta, 0) << "no light overflowed the lists";
  fs::remove_all(folder);
}

}  // namespace
}  // namespace atrium
