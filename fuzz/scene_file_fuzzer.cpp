// libFuzzer target: scene files (docs/scene-format.md). Any input must either
// load or be refused with SceneFileError or ImportError; anything else (a
// crash, a sanitizer report, another exception, a huge allocation) is a bug.
#include "assets/scene_file.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = atrium::fuzz::write_input(data, size, ".json");
  try {
    atrium::assets::AssetManager assets;
    atrium::assets::LoadReport report;
    (void)atrium::assets::load_scene_file(path, assets, report);
  } catch (const atrium::assets::SceneFileError&) {
  } catch (const atrium::assets::ImportError&) {
  }
  return 0;
}
