#include "render/frame/draw_list.hpp"

#include <algorithm>
#include <cstring>
#include <map>
#include <optional>
#include <tuple>
#include <unordered_map>

#include "components/bounds.hpp"
#include "components/mesh_instance.hpp"
#include "components/transform.hpp"
#include "components/visibility.hpp"
#include "gfx/depth.hpp"
#include "assets/meshlets.hpp"
#include "base/frustum.hpp"
#include "render/frame/frame_draws.hpp"

namespace atrium::render {

DrawBatch batch_state(const assets::Material& material, const GpuAssets& gpu, GLuint vertex_array, bool mirrored) {
  DrawBatch state;
  state.vertex_array = vertex_array;
  const auto slots = material.texture_slots();
  for (std::size_t s = 0; s < kMaterialTextureSlots; ++s) {
    state.textures[s] = gpu.texture(slots[s]->texture);
    state.samplers[s] = gpu.sampler(slots[s]->sampler);
  }
  state.double_sided = material.double_sided;
  state.mirrored = mirrored;
  state.alpha_masked = material.alpha_mode == assets::AlphaMode::Mask;
  return state;
}

namespace {

// The GL state a batch sets: batches are merged and ordered by it.
auto state_key(const DrawBatch& b) {
  return std::tie(b.alpha_masked, b.vertex_array, b.textures, b.samplers, b.double_sided, b.mirrored);
}

// Opaque geometry before it is placed: one command, all instances of a
// primitive drawn with one material. Its instances are gathered in one array
// for the whole list (Placed::command), not per command.
struct PendingCommand {
  std::uint32_t state;  // into the list's distinct batch states
  DrawCommand command;
  float nearest = 0.0f;  // view depth of its nearest instance
  std::uint32_t first_placed = 0, placed_count = 0;  // its run of the placed instances, once sorted
};

// DrawSelection::EachInView: one primitive instance's units in view (its
// meshlets, or the primitive whole), each a command of its own. The list has
// tens of thousands of units, and the units of one primitive instance share
// its record, state and depth, so the gathering keeps the group and where its
// units lie, and each unit is written once, straight into the list, in draw order.
struct UnitGroup {
  std::uint32_t state;   // into the list's distinct batch states
  float depth;           // view depth of the primitive instance
  std::uint32_t record;  // into DrawList::instances
  std::uint32_t unit;    // its DrawList::visibility_units entry
  std::uint32_t first_index;  // the primitive's range in the index pool
  std::int32_t base_vertex;
  // By meshlet: the primitive's meshlets, their world spheres and seen:: bits,
  // and the cull unit of the first. Else one unit: the whole primitive with
  // its box (cull unit CullRecord::kNeverCulled: no box, always drawn).
  std::span<const assets::Meshlet> meshlets{};
  const MeshletBounds* spheres = nullptr;
  const std::uint8_t* meshlet_states = nullptr;
  std::uint32_t cull_unit = CullRecord::kNeverCulled;
  std::uint32_t index_count = 0;
  glm::vec3 box_min{0.0f}, box_max{0.0f};
};

struct Placed {
  float depth;  // view depth
  std::uint32_t record;  // its primitive instance's, into DrawList::instances
  std::uint32_t first_triangle;  // of its command's range within the primitive (InstanceSlot)
  std::uint32_t unit;  // its DrawList::visibility_units entry
  std::uint32_t command;  // its PendingCommand
};

// A float's bits as an unsigned integer that orders as the float does
// (memcpy: the page's libc++ has no std::bit_cast).
std::uint32_t ordered_bits(float value) {
  std::uint32_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  return (bits & 0x80000000u) ? ~bits : bits | 0x80000000u;
}

// Each distinct (material, winding) is looked up once a list: the draw state
// its primitives share (textures and samplers resolved), and its rank among
// the list's states by state_key, equal for states that may share a batch.
class BatchStates {
 public:
  BatchStates(const GpuAssets& gpu, GLuint vertex_array) : gpu_(gpu), vertex_array_(vertex_array) {}
  std::uint32_t of(const assets::Material& material, bool mirrored) {
    const auto [it, added] = index_.try_emplace({&material, mirrored}, static_cast<std::uint32_t>(states_.size()));
    if (added) states_.push_back(batch_state(material, gpu_, vertex_array_, mirrored));
    return it->second;
  }
  [[nodiscard]] const DrawBatch& operator[](std::uint32_t state) const { return states_[state]; }
  // Ranks by state_key, after the last of(): masked last, then by GL state.
  [[nodiscard]] std::vector<std::uint32_t> ranks() const {
    std::vector<std::uint32_t> order(states_.size());
    for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return state_key(states_[a]) < state_key(states_[b]); });
    std::vector<std::uint32_t> rank(states_.size());
    std::uint32_t r = 0;
    for (std::size_t i = 0; i < order.size(); ++i) {
      if (i > 0 && state_key(states_[order[i - 1]]) != state_key(states_[order[i]])) ++r;
      rank[order[i]] = r;
    }
    return rank;
  }

 private:
  const GpuAssets& gpu_;
  GLuint vertex_array_;
  std::map<std::pair<const assets::Material*, bool>, std::uint32_t> index_;
  std::vector<DrawBatch> states_;
};

struct PendingBlend {
  std::uint32_t state;
  DrawCommand command;
  std::uint32_t record;  // into DrawList::instances
  float depth = 0.0f;
};

}  // namespace

MaterialData material_data(const assets::Material& m, const GpuAssets& gpu) {
  MaterialData data;
  data.base_color_factor = m.base_color_factor;
  data.emissive = glm::vec4(m.emissive_factor * m.emissive_strength, m.normal_scale);
  data.metallic_factor = m.metallic_factor;
  data.roughness_factor = m.roughness_factor;
  data.occlusion_strength = m.occlusion_texture.valid() ? m.occlusion_strength : 0.0f;
  data.alpha_cutoff = m.alpha_mode == assets::AlphaMode::Mask ? m.alpha_cutoff : -1.0f;
  if (m.normal_texture.valid()) data.flags |= kMaterialHasNormalTexture;
  if (gpu.two_channel(m.normal_texture.texture)) data.flags |= kMaterialNormalXyOnly;
  if (m.normal_green_down) data.flags |= kMaterialNormalGreenDown;
  if (m.double_sided) data.flags |= kMaterialDoubleSided;
  if (m.unlit) data.flags |= kMaterialUnlit;
  if (m.alpha_mode == assets::AlphaMode::Mask) data.flags |= kMaterialAlphaMasked;
  const auto slots = m.texture_slots();
  for (std::size_t s = 0; s < kMaterialTextureSlots; ++s) {
    if (slots[s]->uv_set == 1) data.uv_sets |= 1u << s;
    const glm::mat3& t = slots[s]->uv_transform;  // column-major: t[column][row]
    data.uv_transform[2 * s] = glm::vec4(t[0][0], t[1][0], t[2][0], 0.0f);
    data.uv_transform[2 * s + 1] = glm::vec4(t[0][1], t[1][1], t[2][1], 0.0f);
  }
  return data;
}

bool selected(std::uint8_t state, DrawSelection selection) {
  if (!(state & seen::kInView)) return false;
  switch (selection) {
    case DrawSelection::InView:
    case DrawSelection::EachInView: return true;
    case DrawSelection::ShownLastFrame: return (state & seen::kLastFrame) != 0;
    case DrawSelection::Revealed: return (state & (seen::kLastFrame | seen::kRevealed)) == seen::kRevealed;
    case DrawSelection::Shown: return (state & (seen::kLastFrame | seen::kRevealed)) != 0;
  }
  return false;
}

DrawList build_draw_list(ecs::Registry& registry, const assets::AssetManager& assets, const GpuAssets& gpu,
                         const glm::mat4& view, DrawSelection selection) {
  // An entity without culling state is in view and was shown.
  constexpr std::uint8_t kEverything = seen::kInView | seen::kLastFrame;
  DrawList list;
  std::unordered_map<const assets::Material*, std::uint32_t> material_index;
  auto index_of = [&](const assets::Material& material) {
    const auto [it, added] = material_index.try_emplace(&material, static_cast<std::uint32_t>(list.materials.size()));
    if (added) list.materials.push_back(material_data(material, gpu));
    return it->second;
  };
  // Identical index ranges with one material and winding share a command.
  using CommandKey = std::tuple<GLuint, std::uint32_t, std::uint32_t, std::int32_t, const assets::Material*, bool>;
  std::map<CommandKey, std::size_t> command_of;
  std::vector<PendingCommand> pending;
  std::vector<Placed> placed;
  std::vector<UnitGroup> groups;  // DrawSelection::EachInView
  std::size_t group_units = 0;
  std::vector<PendingBlend> blended;
  BatchStates states(gpu, gpu.vertex_array());
  const bool each_unit = selection == DrawSelection::EachInView;

  registry.view<Transform, MeshInstance>().each([&](ecs::Entity entity, const Transform& transform, const MeshInstance& instance) {
    const assets::MeshAsset& asset = assets.mesh_asset(instance.asset);
    if (instance.mesh >= asset.meshes.size()) return;
    const auto* bounds = registry.try_get<WorldBounds>(entity);
    if (bounds && (bounds->asset != instance.asset || bounds->mesh != instance.mesh)) bounds = nullptr;
    const auto* visibility = bounds ? registry.try_get<Visibility>(entity) : nullptr;
    // Units (GPU culling): the entity's primitives, then its meshlets, numbered
    // in the registry's order, in view or not, so that a unit keeps its number
    // from frame to frame.
    const std::uint32_t first_unit = list.cull_units;
    if (bounds) list.cull_units += static_cast<std::uint32_t>(bounds->primitives.size() + bounds->meshlets.size());
    const auto& primitives = asset.meshes[instance.mesh].primitives;
    const std::size_t first_visibility_unit = list.visibility_units.size();
    for (const assets::Primitive& primitive : primitives) {
      list.triangles += primitive.indices.size() / 3;
      list.visibility_units.push_back({static_cast<std::uint32_t>(list.visibility_ids), VisibilityUnit::kNotDrawn});
      list.visibility_ids += primitive.indices.size() / 3;
    }
    if (visibility && !visibility->any) return;

    const GpuMeshAsset& gpu_asset = gpu.mesh_asset(instance.asset);
    InstanceData data;
    data.model = bounds ? bounds->model : to_matrix(transform);
    data.normal_matrix = glm::mat4(glm::transpose(glm::inverse(glm::mat3(data.model))));
    const bool mirrored = glm::determinant(glm::mat3(data.model)) < 0.0f;
    for (std::uint32_t p = 0; p < primitives.size(); ++p) {
      const assets::Primitive& primitive = primitives[p];
      if (primitive.indices.empty()) continue;
      const std::uint8_t state = visibility && p < visibility->primitives.size() ? visibility->primitives[p] : kEverything;
      if (!(state & seen::kInView)) continue;
      const assets::Material& material = asset.materials.at(primitive.material);
      const GpuPrimitive& range = gpu_asset.meshes[instance.mesh][p];
      const auto unit = static_cast<std::uint32_t>(first_visibility_unit + p);
      data.material = {index_of(material), list.visibility_units[unit].first_id, range.first_index, static_cast<std::uint32_t>(range.base_vertex)};
      const glm::vec3 centre = bounds && p < bounds->primitives.size()
                                   ? 0.5f * (bounds->primitives[p].min + bounds->primitives[p].max)
                                   : glm::vec3(data.model * glm::vec4(0.5f * (primitive.bounds_min + primitive.bounds_max), 1.0f));
      const float depth = -(view * glm::vec4(centre, 1.0f)).z;
      const GLuint vertex_array = gpu.vertex_array();
      const std::uint32_t state_index = states.of(material, mirrored);
      if (material.alpha_mode == assets::AlphaMode::Blend) {
        // Never occlusion-culled: blended surfaces go with every list but the late one.
        if (selection == DrawSelection::Revealed) continue;
        list.triangles_drawn += primitive.indices.size() / 3;
        blended.push_back({state_index, {range.index_count, 1, range.first_index, range.base_vertex, 0},
                           static_cast<std::uint32_t>(list.instances.size()), depth});
        list.instances.push_back(data);
        continue;
      }
      // One record for the primitive instance, which its meshlets' commands
      // share, made when the first of them is selected.
      std::optional<std::uint32_t> made;
      auto record = [&] {
        if (!made) {
          made = static_cast<std::uint32_t>(list.instances.size());
          list.instances.push_back(data);
        }
        return *made;
      };
      // (offset within the primitive, index count): one command per selected meshlet run.
      auto add_run = [&](std::uint32_t offset, std::uint32_t count) {
        list.triangles_drawn += count / 3;
        const DrawCommand command{count, 1, range.first_index + offset, range.base_vertex, 0};
        const CommandKey key{vertex_array, command.first_index, count, range.base_vertex, &material, mirrored};
        const auto [it, added] = command_of.try_emplace(key, pending.size());
        if (added) pending.push_back({state_index, command});
        placed.push_back({depth, record(), offset / 3, unit, static_cast<std::uint32_t>(it->second)});
      };
      const bool by_meshlet = visibility && !primitive.meshlets.empty() && visibility->meshlets.size() == bounds->meshlets.size() &&
                              bounds->meshlet_offsets[p + 1] - bounds->meshlet_offsets[p] == primitive.meshlets.size();
      if (each_unit) {
        UnitGroup group{.state = state_index, .depth = depth, .record = 0, .unit = unit, .first_index = range.first_index,
                        .base_vertex = range.base_vertex};
        std::size_t units = 1;
        if (by_meshlet) {
          const std::uint32_t first = bounds->meshlet_offsets[p];
          group.meshlets = primitive.meshlets;
          group.spheres = bounds->meshlets.data() + first;
          group.meshlet_states = visibility->meshlets.data() + first;
          group.cull_unit = first_unit + static_cast<std::uint32_t>(bounds->primitives.size()) + first;
          units = static_cast<std::size_t>(std::count_if(group.meshlet_states, group.meshlet_states + primitive.meshlets.size(),
                                                         [&](std::uint8_t bits) { return selected(bits, selection); }));
          if (units == 0) continue;
        } else {
          group.index_count = range.index_count;
          if (bounds && p < bounds->primitives.size()) {
            group.cull_unit = first_unit + p;
            group.box_min = bounds->primitives[p].min;
            group.box_max = bounds->primitives[p].max;
          }
        }
        group.record = record();
        groups.push_back(group);
        group_units += units;
      } else if (by_meshlet) {
        const std::uint8_t* meshlet_states = visibility->meshlets.data() + bounds->meshlet_offsets[p];
        assets::for_each_meshlet_run(primitive.meshlets, [&](std::size_t m) { return selected(meshlet_states[m], selection); }, add_run);
      } else if (selected(state, selection)) {
        add_run(0, range.index_count);
      }
    }
  });

  // Opaque: masked last (its discard defeats early depth tests on GPUs), then
  // by state, so that a batch holds every command of one state, then front to
  // back (instances by depth, commands by their nearest instance).
  // The instances grouped by command (a counting sort keeps their order), each
  // group by depth.
  std::vector<Placed> sorted(placed.size());
  for (const Placed& p : placed) ++pending[p.command].placed_count;
  std::uint32_t next = 0;
  for (PendingCommand& command : pending) {
    command.first_placed = next;
    next += command.placed_count;
    command.placed_count = 0;
  }
  for (const Placed& p : placed) {
    PendingCommand& command = pending[p.command];
    sorted[command.first_placed + command.placed_count++] = p;
  }
  for (PendingCommand& command : pending) {
    const auto first = sorted.begin() + command.first_placed;
    if (command.placed_count > 1) {
      std::stable_sort(first, first + command.placed_count, [](const Placed& a, const Placed& b) { return a.depth < b.depth; });
    }
    command.nearest = first->depth;
  }
  // Commands in runs of one key (state rank, then nearest depth): the meshlet
  // runs of one primitive instance, all at its depth. The runs are sorted,
  // tied ones in gathering order, so that the sort sees about as many runs as
  // primitive instances.
  const std::vector<std::uint32_t> rank = states.ranks();
  // Opaque draw order, for the pending commands and the unit groups alike.
  auto draw_key = [&](std::uint32_t state, float depth) { return (std::uint64_t{rank[state]} << 32) | ordered_bits(depth); };
  struct Run {
    std::uint64_t key;
    std::uint32_t first, count;  // of the pending commands
    bool operator<(const Run& other) const { return std::tie(key, first) < std::tie(other.key, other.first); }
  };
  std::vector<Run> order;
  for (std::uint32_t i = 0; i < pending.size(); ++i) {
    const std::uint64_t key = draw_key(pending[i].state, pending[i].nearest);
    if (order.empty() || order.back().key != key) order.push_back({key, i, 0});
    ++order.back().count;
  }
  std::sort(order.begin(), order.end());
  auto append = [&](std::vector<DrawBatch>& batches, const DrawBatch& state, DrawCommand command, float depth) {
    if (batches.empty() || state_key(batches.back()) != state_key(state)) {
      batches.push_back(state);
      batches.back().first_command = static_cast<std::uint32_t>(list.commands.size());
      batches.back().command_count = 0;
    }
    list.commands.push_back(command);
    list.command_depths.push_back(depth);
    ++batches.back().command_count;
  };
  list.slots.reserve(placed.size() + group_units + blended.size());
  list.commands.reserve(pending.size() + group_units + blended.size());
  list.command_depths.reserve(pending.size() + group_units + blended.size());
  list.cull_records.reserve(group_units);
  auto emit = [&](const PendingCommand& pending_command) {
    DrawCommand command = pending_command.command;
    command.base_instance = static_cast<std::uint32_t>(list.slots.size());
    command.instance_count = pending_command.placed_count;
    for (std::uint32_t p = pending_command.first_placed; p < pending_command.first_placed + pending_command.placed_count; ++p) {
      list.visibility_units[sorted[p].unit].record = sorted[p].record;
      list.slots.push_back({sorted[p].record, sorted[p].first_triangle});
    }
    append(list.opaque, states[pending_command.state], command, pending_command.nearest);
  };
  for (const Run& run : order) {
    for (std::uint32_t c = run.first; c < run.first + run.count; ++c) emit(pending[c]);
  }
  // The units by group in the same order (state rank, then depth; ties as
  // gathered), each with the box the GPU tests.
  std::stable_sort(groups.begin(), groups.end(),
                   [&](const UnitGroup& a, const UnitGroup& b) { return draw_key(a.state, a.depth) < draw_key(b.state, b.depth); });
  for (const UnitGroup& group : groups) {
    list.visibility_units[group.unit].record = group.record;
    auto emit_unit = [&](std::uint32_t offset, std::uint32_t count, glm::vec3 min, glm::vec3 max, std::uint32_t cull_unit) {
      list.triangles_drawn += count / 3;
      append(list.opaque, states[group.state],
             {count, 1, group.first_index + offset, group.base_vertex, static_cast<std::uint32_t>(list.slots.size())}, group.depth);
      list.slots.push_back({group.record, offset / 3});
      list.cull_records.push_back({glm::vec4(min, 0.0f), glm::vec4(max, 0.0f), cull_unit, count / 3, {0, 0}});
    };
    if (group.meshlets.empty()) {
      emit_unit(0, group.index_count, group.box_min, group.box_max, group.cull_unit);
      continue;
    }
    for (std::uint32_t m = 0; m < group.meshlets.size(); ++m) {
      if (!selected(group.meshlet_states[m], selection)) continue;
      const MeshletBounds& sphere = group.spheres[m];
      emit_unit(group.meshlets[m].first_index, group.meshlets[m].index_count, sphere.center - sphere.radius,
                sphere.center + sphere.radius, group.cull_unit + m);
    }
  }
  for (std::size_t b = 0; b < list.opaque.size(); ++b) list.opaque[b].count_slot = static_cast<std::uint32_t>(b);
  // Blended: farthest first, one instance per command.
  std::stable_sort(blended.begin(), blended.end(), [](const PendingBlend& a, const PendingBlend& b) { return a.depth > b.depth; });
  for (const PendingBlend& item : blended) {
    DrawCommand command = item.command;
    command.base_instance = static_cast<std::uint32_t>(list.slots.size());
    list.slots.push_back({item.record, 0});
    append(list.blended, states[item.state], command, item.depth);
  }
  for (std::size_t b = 0; b < list.blended.size(); ++b) list.blended[b].count_slot = static_cast<std::uint32_t>(list.opaque.size() + b);
  return list;
}

void draw_items(std::span<const DrawBatch> batches, const CommandSource& source) {
  const std::span<const DrawCommand> cpu_commands = source.cpu_commands;
  GLuint bound_vertex_array = 0;
  const DrawBatch* bound_textures = nullptr;
  glEnable(GL_CULL_FACE);
  for (const DrawBatch& batch : batches) {
    if (batch.vertex_array != bound_vertex_array) {
      glBindVertexArray(batch.vertex_array);
      bound_vertex_array = batch.vertex_array;
    }
    if (!bound_textures || bound_textures->textures != batch.textures || bound_textures->samplers != batch.samplers) {
      glBindTextures(0, kMaterialTextureSlots, batch.textures.data());
      glBindSamplers(0, kMaterialTextureSlots, batch.samplers.data());
      bound_textures = &batch;
    }
    if (batch.double_sided) glDisable(GL_CULL_FACE);
    else glEnable(GL_CULL_FACE);
    glFrontFace(batch.mirrored ? GL_CW : GL_CCW);
    const auto* first = reinterpret_cast<const void*>(static_cast<std::uintptr_t>(batch.first_command) * sizeof(DrawCommand));
    if (cpu_commands.empty() && source.count_base >= 0) {
      glMultiDrawElementsIndirectCountARB(GL_TRIANGLES, GL_UNSIGNED_INT, first,
                                          source.count_base + static_cast<GLintptr>(batch.count_slot) * static_cast<GLintptr>(sizeof(std::uint32_t)),
                                          static_cast<GLsizei>(batch.command_count), 0);
      continue;
    }
    if (cpu_commands.empty()) {
      glMultiDrawElementsIndirect(GL_TRIANGLES, GL_UNSIGNED_INT, first, static_cast<GLsizei>(batch.command_count), 0);
      continue;
    }
    glDisableVertexAttribArray(kInstanceSlotLocation);
    for (std::uint32_t c = batch.first_command; c < batch.first_command + batch.command_count && c < cpu_commands.size(); ++c) {
      const DrawCommand& command = cpu_commands[c];
      if (command.instance_count == 0) continue;
      glVertexAttribI4ui(kInstanceSlotLocation, command.base_instance, 0, 0, 0);
      const auto* indices = reinterpret_cast<const void*>(static_cast<std::uintptr_t>(command.first_index) * sizeof(std::uint32_t));
      // Base vertex 0 throughout where the context has none (GpuAssets offsets the indices).
      if (command.base_vertex == 0) {
        glDrawElementsInstanced(GL_TRIANGLES, static_cast<GLsizei>(command.count), GL_UNSIGNED_INT, indices,
                                static_cast<GLsizei>(command.instance_count));
      } else {
        glDrawElementsInstancedBaseVertex(GL_TRIANGLES, static_cast<GLsizei>(command.count), GL_UNSIGNED_INT, indices,
                                          static_cast<GLsizei>(command.instance_count), command.base_vertex);
      }
    }
    glEnableVertexAttribArray(kInstanceSlotLocation);
  }
  glEnable(GL_CULL_FACE);
  glFrontFace(GL_CCW);
  glBindVertexArray(0);
  glBindSamplers(0, kMaterialTextureSlots, nullptr);
}

void draw_depth(std::span<const DrawBatch> batches, const CommandSource& source, gfx::ShaderProgram& position_only,
                gfx::ShaderProgram& masked) {
  // build_draw_list puts the masked batches last.
  const auto first_masked = std::find_if(batches.begin(), batches.end(), [](const DrawBatch& b) { return b.alpha_masked; });
  const auto split = static_cast<std::size_t>(first_masked - batches.begin());
  position_only.use();
  draw_items(batches.first(split), source);
  if (split == batches.size()) return;
  masked.use();
  draw_items(batches.subspan(split), source);
}

void draw_transparent(const PassResources& res, gfx::ShaderProgram& forward_program, const FrameContext& frame,
                      const FrameTargets& targets) {
  if (frame.draws.list().blended.empty()) return;
  glBindFramebuffer(GL_FRAMEBUFFER, scene_framebuffer(res, frame));
  glViewport(0, 0, targets.size.x, targets.size.y);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(gfx::kDepthCloser);
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  forward_program.use();
  draw_items(frame.draws.list().blended, frame.draws.commands());
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
}

void begin_scene_pass(const PassResources& res, const FrameContext& frame, const FrameTargets& targets) {
  const GLuint framebuffer = scene_framebuffer(res, frame);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, targets.size.x, targets.size.y);
  const float clear_color[] = {frame.background.r, frame.background.g, frame.background.b, 1.0f};
  glClearNamedFramebufferfv(framebuffer, GL_COLOR, 0, clear_color);
  begin_depth(framebuffer);
}

void begin_depth(GLuint framebuffer) {
  glClearNamedFramebufferfi(framebuffer, GL_DEPTH_STENCIL, 0, gfx::kDepthFar, 0);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(gfx::kDepthCloser);
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
}

void FullscreenTriangle::draw() const {
  glBindVertexArray(vertex_array_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
}

}  // namespace atrium::render
