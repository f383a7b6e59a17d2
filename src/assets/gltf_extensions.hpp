// Every glTF extension Atrium knows, with what it does with each: the one
// list behind the importer's refusals and warnings and docs/gltf-extensions.md
// (a test keeps the page and this table in step).
#pragma once

#include <span>
#include <string_view>

namespace atrium::assets {

struct GltfExtension {
  std::string_view name;
  bool supported;  // a file that requires it loads
  // Supported: what Atrium does with it. Unsupported: what a file that uses it
  // optionally loses (the warning says so); empty when nothing visible is lost.
  std::string_view effect;
};

[[nodiscard]] std::span<const GltfExtension> gltf_extensions();
// nullptr for an extension Atrium does not know.
[[nodiscard]] const GltfExtension* find_gltf_extension(std::string_view name);

}  // namespace atrium::assets
