#include "gfx/sanitizer_support.hpp"

#ifdef ATRIUM_SANITIZE
#include <dlfcn.h>

#include <fstream>
#include <set>
#include <string>
#endif

namespace atrium::gfx {

void keep_gl_driver_loaded() {
#ifdef ATRIUM_SANITIZE
  std::ifstream maps("/proc/self/maps");
  std::set<std::string> modules;
  for (std::string line; std::getline(maps, line);) {
    const auto slash = line.find('/');
    if (slash == std::string::npos) continue;
    const std::string path = line.substr(slash);
    if (path.find("_dri.so") != std::string::npos || path.find("libgallium") != std::string::npos ||
        path.find("libLLVM") != std::string::npos) {
      modules.insert(path);
    }
  }
  for (const std::string& module : modules) dlopen(module.c_str(), RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
#endif
}

}  // namespace atrium::gfx
