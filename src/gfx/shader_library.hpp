// Shader programs cached by their files and defines: a technique that is
// switched away from and back, or two passes that share a program, compile once.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "gfx/shader_program.hpp"

namespace atrium::gfx {

class ShaderLibrary {
 public:
  // The program for `files` with `defines`, compiled on first use. The reference
  // stays valid as long as the library. Throws ShaderError.
  ShaderProgram& get(const std::vector<std::string>& files, const std::vector<ShaderDefine>& defines = {});

  [[nodiscard]] std::size_t size() const { return programs_.size(); }
  // Calls visit(files, defines, program) for every cached program, globals
  // among its defines (what a tier's programs declare, for tests).
  template <typename Visit>
  void for_each(Visit visit) const {
    for (const auto& [key, entry] : programs_) visit(entry.files, entry.defines, *entry.program);
  }

  // Recompiles every cached program from its files (`r` in the window). A
  // program that fails keeps its old version; the errors come back, one per
  // failing program. Uniforms set on a replaced program are gone: its owner
  // must set them again (the renderer recreates its technique).
  std::vector<std::string> reload();

  // Defines added to every program fetched from now on (the shading model);
  // programs made with other globals stay cached under their own key.
  void set_global_defines(std::vector<ShaderDefine> defines) { globals_ = std::move(defines); }

 private:
  struct Entry {
    std::vector<std::string> files;
    std::vector<ShaderDefine> defines;
    std::unique_ptr<ShaderProgram> program;
  };
  std::map<std::string, Entry> programs_;
  std::vector<ShaderDefine> globals_;
};

}  // namespace atrium::gfx
