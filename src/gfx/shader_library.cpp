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
    it = programs_.emplace(key, std::make_unique<ShaderProgram>(ShaderProgram::load(files, all))).first;
  }
  return *it->second;
}

}  // namespace atrium::gfx
