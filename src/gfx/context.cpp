#include <algorithm>

#include "gfx/context.hpp"
#include "gfx/debug_output.hpp"
#include "gfx/gl.hpp"
#include "gfx/gl_features.hpp"
#include "gfx/sanitizer_support.hpp"

namespace atrium::gfx {

std::optional<GlApi> gl_api_from_name(std::string_view name) {
  const auto it = std::find_if(kGlApiNames.begin(), kGlApiNames.end(), [&](const GlApiName& n) { return n.name == name; });
  if (it == kGlApiNames.end()) return std::nullopt;
  return it->api;
}

std::string_view gl_api_name(GlApi api) {
  const auto it = std::find_if(kGlApiNames.begin(), kGlApiNames.end(), [&](const GlApiName& n) { return n.api == api; });
  return it == kGlApiNames.end() ? "?" : it->name;
}

std::vector<GlVersionRequest> gl_version_requests(GlApi api) {
  constexpr GlVersionRequest kGl45{false, 4, 5}, kGl41{false, 4, 1}, kEs30{true, 3, 0};
  switch (api) {
    case GlApi::Gl45: return {kGl45};
    case GlApi::Gl41: return {kGl41};
    case GlApi::Es30: return {kEs30};
    case GlApi::Auto: break;
  }
  return {kGl45, kGl41, kEs30};
}

std::string describe_requests(GlApi api) {
  std::string out;
  for (const GlVersionRequest& r : gl_version_requests(api)) {
    out += std::string(out.empty() ? "" : ", ") + (r.es ? "OpenGL ES " : "OpenGL ") + std::to_string(r.major) + "." +
           std::to_string(r.minor) + (r.es ? "" : " core");
  }
  return out;
}

ContextInfo current_context_info(std::string platform) {
  auto text = [](GLenum name) {
    const auto* s = reinterpret_cast<const char*>(glGetString(name));
    return std::string(s ? s : "?");
  };
  return {text(GL_VENDOR), text(GL_RENDERER), text(GL_VERSION), std::move(platform), gl_features().api_name()};
}

namespace detail {
void prepare_current_context(const ContextOptions& options) {
  keep_gl_driver_loaded();
  load_entry_points();
  adopt_current_context();
  if (options.debug && gl_features().debug_output) enable_debug_output();
}
}  // namespace detail

}  // namespace atrium::gfx
