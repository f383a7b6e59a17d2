#include "render/binding_slots.hpp"
#include "render/culling/occlusion_culling.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "assets/asset_manager.hpp"
#include "components/bounds.hpp"
#include "components/visibility.hpp"
#include "gfx/gpu_waits.hpp"

namespace atrium::render {
namespace {

// culling/depth_tiles.comp's bindings.
constexpr GLuint kTileStorageBinding = kDepthTilesBinding;

}  // namespace

DepthPyramid::DepthPyramid(std::vector<float> tiles, glm::ivec2 tile_count, glm::ivec2 viewport) : viewport_(viewport) {
  if (tile_count.x <= 0 || tile_count.y <= 0 || tiles.size() != static_cast<std::size_t>(tile_count.x) * tile_count.y) return;
  levels_.push_back({tile_count, std::move(tiles)});
  while (levels_.back().size.x > 1 || levels_.back().size.y > 1) {
    const Level& below = levels_.back();
    Level level{(below.size + 1) / 2, {}};
    level.farthest.resize(static_cast<std::size_t>(level.size.x) * level.size.y);
    for (int y = 0; y < level.size.y; ++y) {
      for (int x = 0; x < level.size.x; ++x) {
        float farthest = 0.0f;
        for (int dy = 0; dy < 2; ++dy) {
          for (int dx = 0; dx < 2; ++dx) {
            const int bx = std::min(2 * x + dx, below.size.x - 1), by = std::min(2 * y + dy, below.size.y - 1);
            farthest = std::max(farthest, below.farthest[static_cast<std::size_t>(by) * below.size.x + bx]);
          }
        }
        level.farthest[static_cast<std::size_t>(y) * level.size.x + x] = farthest;
      }
    }
    levels_.push_back(std::move(level));
  }
}

bool DepthPyramid::hides(const glm::mat4& view, const glm::mat4& projection, float near_plane, glm::vec3 min, glm::vec3 max) const {
  if (levels_.empty()) return false;
  // The box's screen rectangle (normalised device coordinates) and its
  // nearest view depth, from its eight corners.
  glm::vec2 low(std::numeric_limits<float>::max()), high(std::numeric_limits<float>::lowest());
  float nearest = std::numeric_limits<float>::max();
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec4 world((corner & 1) ? max.x : min.x, (corner & 2) ? max.y : min.y, (corner & 4) ? max.z : min.z, 1.0f);
    const glm::vec4 eye = view * world;
    const float depth = -eye.z;
    // A corner at or behind the near plane has no place on screen: the box may
    // cover any pixel.
    if (!(depth > near_plane)) return false;
    const glm::vec4 clip = projection * eye;
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    low = glm::min(low, ndc);
    high = glm::max(high, ndc);
    nearest = std::min(nearest, depth);
  }
  // Tiles under the rectangle, clamped to the viewport (a box partly off
  // screen is judged by its part on it; frustum culling drops the rest).
  const glm::vec2 pixels_low = (low * 0.5f + 0.5f) * glm::vec2(viewport_);
  const glm::vec2 pixels_high = (high * 0.5f + 0.5f) * glm::vec2(viewport_);
  if (!(pixels_low.x < viewport_.x && pixels_low.y < viewport_.y && pixels_high.x > 0.0f && pixels_high.y > 0.0f)) return false;
  const glm::ivec2 last_tile = levels_[0].size - 1;
  glm::ivec2 first = glm::clamp(glm::ivec2(glm::floor(pixels_low / float(kTileSize))), glm::ivec2(0), last_tile);
  glm::ivec2 last = glm::clamp(glm::ivec2(glm::floor(pixels_high / float(kTileSize))), glm::ivec2(0), last_tile);
  // The level where the rectangle spans at most two texels each way: at most
  // four reads, each the farthest depth of what it covers.
  std::size_t l = 0;
  while (l + 1 < levels_.size() && (last.x - first.x > 1 || last.y - first.y > 1)) {
    first /= 2;
    last /= 2;
    ++l;
  }
  const Level& level = levels_[l];
  float farthest = 0.0f;
  for (int y = first.y; y <= last.y; ++y) {
    for (int x = first.x; x <= last.x; ++x) farthest = std::max(farthest, level.farthest[static_cast<std::size_t>(y) * level.size.x + x]);
  }
  // A relative margin keeps a surface at the very depth it drew (a wall facing
  // the camera) from counting as behind itself by a rounding error.
  return nearest > farthest * 1.001f;
}

namespace {

// Calls test(state, min, max, triangles) for every opaque primitive in view
// that is not cut into meshlets, and for every meshlet in view of those that are.
template <typename Test>
void for_each_opaque_in_view(ecs::Registry& registry, Test test) {
  const auto& assets = registry.resource<assets::AssetManager>();
  registry.view<WorldBounds, Visibility>().each([&](const WorldBounds& bounds, Visibility& visibility) {
    if (!visibility.any || visibility.primitives.size() != bounds.primitives.size() ||
        visibility.meshlets.size() != bounds.meshlets.size()) {
      return;
    }
    const assets::MeshAsset& asset = assets.mesh_asset(bounds.asset);
    if (bounds.mesh >= asset.meshes.size()) return;
    const auto& primitives = asset.meshes[bounds.mesh].primitives;
    for (std::size_t p = 0; p < bounds.primitives.size() && p < primitives.size(); ++p) {
      if (!(visibility.primitives[p] & seen::kInView)) continue;
      const assets::Primitive& primitive = primitives[p];
      if (primitive.material >= asset.materials.size() || asset.materials[primitive.material].alpha_mode == assets::AlphaMode::Blend) continue;
      const std::uint32_t first = bounds.meshlet_offsets[p], last = bounds.meshlet_offsets[p + 1];
      if (first == last || last - first != primitive.meshlets.size()) {
        test(visibility.primitives[p], bounds.primitives[p].min, bounds.primitives[p].max, primitive.indices.size() / 3);
        continue;
      }
      for (std::uint32_t m = first; m < last; ++m) {
        if (!(visibility.meshlets[m] & seen::kInView)) continue;
        const MeshletBounds& sphere = bounds.meshlets[m];
        test(visibility.meshlets[m], sphere.center - sphere.radius, sphere.center + sphere.radius,
             primitive.meshlets[m - first].index_count / 3);
      }
    }
  });
}

}  // namespace

std::size_t reveal_unhidden(ecs::Registry& registry, const DepthPyramid& depth, const ViewState& view) {
  std::size_t revealed = 0;
  for_each_opaque_in_view(registry, [&](std::uint8_t& state, glm::vec3 min, glm::vec3 max, std::size_t) {
    if (depth.hides(view.view, view.projection, view.near_plane, min, max)) {
      state |= seen::kHidden;
    } else if (!(state & seen::kLastFrame)) {
      state |= seen::kRevealed;
      ++revealed;
    }
  });
  return revealed;
}

std::size_t remember_shown(ecs::Registry& registry, const ViewState& view, const DepthPyramid* full_depth) {
  std::size_t not_drawn = 0;
  for_each_opaque_in_view(registry, [&](std::uint8_t& state, glm::vec3 min, glm::vec3 max, std::size_t triangles) {
    const bool drawn = !(state & seen::kHidden) || (state & seen::kLastFrame);
    if (!drawn) not_drawn += triangles;
    const bool hidden = full_depth ? full_depth->hides(view.view, view.projection, view.near_plane, min, max)
                                   : (state & seen::kHidden) != 0;
    if (hidden) state &= static_cast<std::uint8_t>(~seen::kLastFrame);
    else state |= seen::kLastFrame;
  });
  return not_drawn;
}

void write_depth_tiles(gfx::ShaderLibrary& shaders, GLuint depth, glm::ivec2 tiles, GLuint buffer) {
  gfx::ShaderProgram& program = shaders.get({"culling/depth_tiles.comp"});
  program.use();
  program.set("u_tiles", glm::uvec2(tiles));
  glBindTextureUnit(kDepthTextureUnit, depth);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTileStorageBinding, buffer);
  // 8 tiles side by side per work group.
  glDispatchCompute(static_cast<GLuint>(tiles.x + 7) / 8, static_cast<GLuint>(tiles.y), 1);
  glBindTextureUnit(kDepthTextureUnit, 0);
}

DepthPyramid DepthReader::read(GLuint depth, glm::ivec2 size) {
  const glm::ivec2 tiles = (size + DepthPyramid::kTileSize - 1) / DepthPyramid::kTileSize;
  const std::size_t count = static_cast<std::size_t>(tiles.x) * static_cast<std::size_t>(tiles.y);
  if (count == 0) return {};
  if (count > capacity_) {
    tiles_ = gfx::create_buffer();
    glNamedBufferStorage(tiles_.id(), static_cast<GLsizeiptr>(count * sizeof(float)), nullptr, GL_DYNAMIC_STORAGE_BIT);
    capacity_ = count;
  }
  GLint program = 0;
  glGetIntegerv(GL_CURRENT_PROGRAM, &program);
  write_depth_tiles(shaders_, depth, tiles, tiles_.id());
  std::vector<float> farthest(count);
  gfx::read_buffer(tiles_.id(), 0, static_cast<GLsizeiptr>(count * sizeof(float)), farthest.data());
  glUseProgram(static_cast<GLuint>(program));
  return DepthPyramid(std::move(farthest), tiles, size);
}

}  // namespace atrium::render
