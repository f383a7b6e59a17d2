#include "gfx/shader_library.hpp"

namespace atrium::gfx {

ShaderProgram& ShaderLibrary::get(const std::vector<std::string>& files, const std::vector<ShaderDefine>& defines) {
  std::vector<ShaderDefine> all = globals_;
  all.insert(all.end(), defines.begin(), defines.end());
  std::string key;
  for (const auto& file : files) key += file + ";";
  for (const auto& define : all) key += "#" + define.name + "=" + define.value;
  auto it = programs_.find(key);
  if (it == programs_.end()) {
    auto program = std::make_unique<ShaderProgram>(ShaderProgram::load(files, all));
    it = programs_.emplace(key, Entry{files, std::move(all), std::move(program)}).first;
  }
  return *it->second.program;
}

std::vector<std::string> ShaderLibrary::reload() {
  std::vector<std::string> errors;
  for (auto& [key, entry] : programs_) {
    try {
      // Assigned in place: techniques hold references to the cached object.
      *entry.program = ShaderProgram::load(entry.files, entry.defines);
    } catch (const ShaderError& e) {
      errors.emplace_back(e.what());
    }
  }
  return errors;
}

}  // namespace atrium::gfx
