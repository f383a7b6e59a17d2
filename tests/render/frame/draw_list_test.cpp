// The frame's draw list: the material table matches its GLSL twin byte for
// byte, opaque draws come one multi-draw per state, masked after opaque, front
// to back within a state (commands by their nearest instance, instances of one
// command nearest first), the GPU culling's list one command per unit in view,
// and blended draws farthest first.
#include "render/frame/draw_list.hpp"

#include <algorithm>
#include <set>
#include <string>
#include <tuple>

#include "app/world.hpp"
#include "components/frame_resources.hpp"
#include "components/visibility.hpp"
#include "assets/mesh_builder.hpp"
#include "components/transform.hpp"
#include "support/compute_probe.hpp"
#include "support/gl_test.hpp"

namespace atrium::render {
namespace {

using DrawListTest = testing::GlTest;

TEST_F(DrawListTest, MaterialTableLayoutAndFlagsMatchTheirGlslTwins) {
  std::vector<MaterialData> materials(3);
  for (std::size_t i = 0; i < materials.size(); ++i) {
    const float f = static_cast<float>(i + 1);
    materials[i].base_color_factor = glm::vec4(0.1f * f, 0.2f, 0.3f, 0.4f);
    materials[i].emissive = glm::vec4(1.0f, 2.0f, 3.0f, 0.5f * f);
    materials[i].metallic_factor = 0.25f * f;
    materials[i].roughness_factor = 0.125f;
    materials[i].occlusion_strength = 0.75f;
    materials[i].alpha_cutoff = 0.3f * f;
    materials[i].flags = 7u * static_cast<std::uint32_t>(i + 1);
    materials[i].uv_sets = 0x15u + static_cast<std::uint32_t>(i);
    materials[i].uv_transform[9] = glm::vec4(5.0f, 6.0f * f, 7.0f, 0.0f);
  }
  const auto read = testing::evaluate_glsl<glm::vec4, MaterialData>(
      "#include \"common/material_data.glsl\"\n", "Material", "vec4",
      "vec4(value.base_color_factor.x + value.emissive.a, value.metallic_factor + value.alpha_cutoff,"
      " float(value.flags) + float(value.uv_sets) * 100.0, value.uv_transform[9].y + value.occlusion_strength)",
      materials);
  for (std::size_t i = 0; i < materials.size(); ++i) {
    const MaterialData& m = materials[i];
    EXPECT_FLOAT_EQ(read[i].x, m.base_color_factor.x + m.emissive.a) << i;
    EXPECT_FLOAT_EQ(read[i].y, m.metallic_factor + m.alpha_cutoff) << i;
    EXPECT_FLOAT_EQ(read[i].z, static_cast<float>(m.flags) + static_cast<float>(m.uv_sets) * 100.0f) << i;
    EXPECT_FLOAT_EQ(read[i].w, m.uv_transform[9].y + m.occlusion_strength) << i;
  }
  const auto flags = testing::evaluate_glsl<glm::uvec4, std::uint32_t>(
      "#include \"common/material_data.glsl\"\n", "uint", "uvec4",
      "value == 0u ? uvec4(kMaterialHasNormalTexture, kMaterialNormalXyOnly, kMaterialNormalGreenDown, kMaterialDoubleSided)"
      " : uvec4(kMaterialUnlit, kMaterialAlphaMasked, 0u, 0u)",
      std::vector<std::uint32_t>{0u, 1u});
  EXPECT_EQ(flags[0], glm::uvec4(kMaterialHasNormalTexture, kMaterialNormalXyOnly, kMaterialNormalGreenDown, kMaterialDoubleSided));
  EXPECT_EQ(flags[1], glm::uvec4(kMaterialUnlit, kMaterialAlphaMasked, 0u, 0u));
}

// Each batch's GL state, for counting distinct ones.
auto state_of(const DrawBatch& b) { return std::tuple(b.vertex_array, b.textures, b.samplers, b.double_sided, b.mirrored); }

// The record instance `i` of `command` draws with, through its slot.
const InstanceData& record_of(const DrawList& list, const DrawCommand& command, std::uint32_t i = 0) {
  return list.instances.at(list.slots.at(command.base_instance + i).record);
}

// Every instance of every opaque command names a record of its primitive
// and where the command's triangles start in it: the index the vertex
// shader's identifiers count from (common/mesh.vert adds the two).
void expect_slots_match_commands(const DrawList& list, const std::string& where) {
  for (const DrawBatch& batch : list.opaque) {
    for (std::uint32_t c = batch.first_command; c < batch.first_command + batch.command_count; ++c) {
      const DrawCommand& command = list.commands[c];
      for (std::uint32_t i = 0; i < command.instance_count; ++i) {
        const InstanceSlot& slot = list.slots.at(command.base_instance + i);
        ASSERT_LT(slot.record, list.instances.size()) << where;
        EXPECT_EQ(command.first_index, list.instances[slot.record].material.z + 3u * slot.first_triangle) << where << ", command " << c;
      }
    }
  }
}

// Primitives without meshlets in view, and their meshlets in view, each one
// or (`runs`) each run of neighbours one.
std::size_t units_in_view(ecs::Registry& registry, bool runs) {
  std::size_t units = 0;
  registry.view<Visibility, WorldBounds>().each([&](const Visibility& visibility, const WorldBounds& bounds) {
    if (!visibility.any) return;
    for (std::uint32_t p = 0; p < visibility.primitives.size(); ++p) {
      if (!(visibility.primitives[p] & seen::kInView)) continue;
      const std::uint32_t first = bounds.meshlet_offsets[p], last = bounds.meshlet_offsets[p + 1];
      if (first == last) ++units;
      for (std::uint32_t m = first; m < last; ++m) {
        const bool in_view = visibility.meshlets[m] & seen::kInView;
        units += in_view && (!runs || m == first || !(visibility.meshlets[m - 1] & seen::kInView));
      }
    }
  });
  return units;
}

TEST_F(DrawListTest, OpaqueDrawsAreOneMultiDrawPerStateFrontToBackAndCoverWhatIsVisible) {
  for (int view = 1; view <= 5; ++view) {
    World world({.scene = "atrium", .lights = 8u, .mode = "deferred", .view = view, .size = {160, 90}});
    world.frame(0.0);
    auto& registry = world.registry();
    const DrawList list = build_draw_list(registry, registry.resource<assets::AssetManager>(),
                                          registry.resource<GpuAssets>(), registry.resource<ViewState>().view);
    std::set<decltype(state_of(DrawBatch{}))> states;
    std::size_t instances = 0, triangles = 0;
    bool masked_seen = false;
    for (const DrawBatch& batch : list.opaque) {
      EXPECT_TRUE(states.insert(state_of(batch)).second) << "a state in two batches, view " << view;
      // Masked materials come after every opaque one, never in one batch with
      // them (depth-only passes draw the two with different programs).
      const bool masked = batch.alpha_masked;
      for (std::uint32_t c = batch.first_command; c < batch.first_command + batch.command_count; ++c) {
        const DrawCommand& command = list.commands[c];
        const MaterialData& material = list.materials[record_of(list, command).material.x];
        EXPECT_EQ((material.flags & kMaterialAlphaMasked) != 0u, masked) << "a batch mixing masked and opaque, view " << view;
        if (c > batch.first_command) EXPECT_LE(list.command_depths[c - 1], list.command_depths[c]) << "front to back";
        instances += command.instance_count;
        triangles += static_cast<std::size_t>(command.count / 3) * command.instance_count;
      }
      EXPECT_TRUE(masked || !masked_seen) << "an opaque batch after a masked one, view " << view;
      masked_seen = masked_seen || masked;
    }
    EXPECT_EQ(triangles, list.triangles_drawn) << "the built-in scene has no blended surface";
    // One instance per primitive in view, or per run of meshlets in view.
    EXPECT_EQ(instances, units_in_view(registry, true)) << view;
    EXPECT_EQ(list.slots.size(), instances) << view;
    expect_slots_match_commands(list, "view " + std::to_string(view));
    EXPECT_EQ(list.draw_calls(), world.renderer().stats().draw_calls);
    EXPECT_LE(list.draw_calls(), 10u) << "no more draws than the scene's 10 materials";
  }
}

// GPU occlusion culling's list (DrawSelection::EachInView): one command and
// one instance per meshlet or primitive in view, each with the box and unit
// the culling shader tests, ordered as the other lists; one record per
// primitive instance in view, which its meshlets' slots share, and every
// primitive instance in view findable by the visibility buffer's resolve.
TEST_F(DrawListTest, EachInViewListHasOneCommandPerUnitInViewInDrawOrder) {
  for (int view = 1; view <= 5; ++view) {
    World world({.scene = "atrium", .lights = 8u, .mode = "deferred", .view = view, .size = {160, 90}});
    world.frame(0.0);
    auto& registry = world.registry();
    const auto& assets = registry.resource<assets::AssetManager>();
    const auto& gpu = registry.resource<GpuAssets>();
    const glm::mat4& eye = registry.resource<ViewState>().view;
    const DrawList each = build_draw_list(registry, assets, gpu, eye, DrawSelection::EachInView);
    const DrawList in_view = build_draw_list(registry, assets, gpu, eye, DrawSelection::InView);
    EXPECT_EQ(each.triangles_drawn, in_view.triangles_drawn) << "the same geometry, view " << view;
    const std::size_t units = units_in_view(registry, false);
    ASSERT_EQ(each.cull_records.size(), units) << view;
    std::size_t opaque_commands = 0;
    std::set<decltype(state_of(DrawBatch{}))> states;
    bool masked_seen = false;
    std::set<std::uint32_t> cull_units;
    for (const DrawBatch& batch : each.opaque) {
      EXPECT_TRUE(states.insert(state_of(batch)).second) << "a state in two batches, view " << view;
      EXPECT_TRUE(batch.alpha_masked || !masked_seen) << "an opaque batch after a masked one, view " << view;
      masked_seen = masked_seen || batch.alpha_masked;
      for (std::uint32_t c = batch.first_command; c < batch.first_command + batch.command_count; ++c) {
        const DrawCommand& command = each.commands[c];
        EXPECT_EQ(command.instance_count, 1u);
        EXPECT_EQ(command.base_instance, c) << "one instance per command, in command order";
        EXPECT_EQ(each.cull_records[c].triangles, command.count / 3);
        EXPECT_TRUE(cull_units.insert(each.cull_records[c].unit).second) << "a unit in two commands";
        if (c > batch.first_command) EXPECT_LE(each.command_depths[c - 1], each.command_depths[c]) << "front to back";
        ++opaque_commands;
      }
    }
    EXPECT_EQ(opaque_commands, units);
    expect_slots_match_commands(each, "view " + std::to_string(view));
    EXPECT_EQ(each.visibility_units.size(), in_view.visibility_units.size());
    std::size_t drawn_units = 0;
    for (std::size_t u = 0; u < each.visibility_units.size(); ++u) {
      const VisibilityUnit& unit = each.visibility_units[u];
      EXPECT_EQ(unit.first_id, in_view.visibility_units[u].first_id);
      EXPECT_EQ(unit.record == VisibilityUnit::kNotDrawn, in_view.visibility_units[u].record == VisibilityUnit::kNotDrawn) << u;
      if (unit.record == VisibilityUnit::kNotDrawn) continue;
      ASSERT_LT(unit.record, each.instances.size());
      ++drawn_units;
      EXPECT_EQ(each.instances[unit.record].material.y, unit.first_id) << u;
      EXPECT_EQ(each.instances[unit.record].material.z, in_view.instances[in_view.visibility_units[u].record].material.z) << u;
    }
    EXPECT_EQ(each.instances.size(), drawn_units) << "one record per primitive instance in view, view " << view;
    EXPECT_LT(each.instances.size(), each.slots.size()) << "meshlets share their primitive instance's record, view " << view;
  }
}

TEST_F(DrawListTest, InstancesOfOnePrimitiveShareACommandNearestFirst) {
  // Five copies of one opaque pane at shuffled distances, and one mirrored copy.
  assets::AssetManager manager;
  assets::MeshAsset panes;
  panes.materials.emplace_back();
  panes.meshes.push_back({"pane", {assets::add_geometry(
                                      panes, assets::shapes::grid(glm::vec3(-1, -1, 0), glm::vec3(2, 0, 0), glm::vec3(0, 2, 0), 1, 1, 1.0f), 0)}});
  assets::SceneDescription scene;
  const assets::MeshAssetHandle handle = manager.add_mesh_asset(std::move(panes));
  for (const float z : {-3.0f, -9.0f, -1.0f, -7.0f, -5.0f, -2.0f}) {
    Transform transform;
    transform.position = glm::vec3(2.0f * z, 0.0f, z);
    if (z == -2.0f) transform.scale = glm::vec3(-1.0f, 1.0f, 1.0f);
    scene.instances.push_back({handle, 0, transform});
  }
  scene.views.push_back({"eye", glm::vec3(0.0f, 0.0f, 4.0f), 0.0f, 0.0f});
  World world(std::move(manager), std::move(scene),
              WorldOptions{.scene = "", .lights = 0u, .mode = "forward", .size = {64, 36}, .frustum_culling = false});
  world.frame(0.0);
  auto& registry = world.registry();
  const DrawList list = build_draw_list(registry, registry.resource<assets::AssetManager>(),
                                        registry.resource<GpuAssets>(), registry.resource<ViewState>().view);
  ASSERT_EQ(list.opaque.size(), 2u) << "two windings: two draws";
  ASSERT_EQ(list.commands.size(), 2u);
  const DrawBatch& turned = list.opaque[0].mirrored ? list.opaque[0] : list.opaque[1];
  const DrawCommand& shared = list.commands[list.opaque[0].mirrored ? list.opaque[1].first_command : list.opaque[0].first_command];
  EXPECT_EQ(list.commands[turned.first_command].instance_count, 1u);
  ASSERT_EQ(shared.instance_count, 5u);
  for (std::uint32_t i = 0; i < 5; ++i) {
    EXPECT_FLOAT_EQ(record_of(list, shared, i).model[3].z, -1.0f - 2.0f * static_cast<float>(i)) << "nearest first";
  }
}

TEST_F(DrawListTest, BlendedDrawsComeFarthestFirstAndNeighboursOfOneStateShareADraw) {
  // Five glass panes of one material at shuffled distances along the view axis.
  assets::AssetManager manager;
  assets::MeshAsset panes;
  assets::Material glass;
  glass.alpha_mode = assets::AlphaMode::Blend;
  glass.base_color_factor = glm::vec4(0.2f, 0.5f, 1.0f, 0.4f);
  panes.materials.push_back(glass);
  panes.meshes.push_back({"pane", {assets::add_geometry(
                                      panes, assets::shapes::grid(glm::vec3(-1, -1, 0), glm::vec3(2, 0, 0), glm::vec3(0, 2, 0), 1, 1, 1.0f), 0)}});
  assets::SceneDescription scene;
  const assets::MeshAssetHandle handle = manager.add_mesh_asset(std::move(panes));
  for (const float z : {-3.0f, -9.0f, -1.0f, -7.0f, -5.0f}) {
    Transform transform;
    transform.position = glm::vec3(0.0f, 0.0f, z);
    scene.instances.push_back({handle, 0, transform});
  }
  scene.views.push_back({"eye", glm::vec3(0.0f, 0.0f, 4.0f), 0.0f, 0.0f});
  World world(std::move(manager), std::move(scene), WorldOptions{.scene = "", .lights = 0u, .mode = "forward", .size = {64, 36}});
  world.frame(0.0);
  auto& registry = world.registry();
  const DrawList list = build_draw_list(registry, registry.resource<assets::AssetManager>(),
                                        registry.resource<GpuAssets>(), registry.resource<ViewState>().view);
  EXPECT_TRUE(list.opaque.empty());
  ASSERT_EQ(list.blended.size(), 1u) << "one state: one draw, its commands in order";
  ASSERT_EQ(list.blended[0].command_count, 5u);
  for (std::uint32_t c = 0; c < 5; ++c) {
    EXPECT_EQ(list.commands[c].instance_count, 1u);
    const float z = record_of(list, list.commands[c]).model[3].z;
    EXPECT_FLOAT_EQ(z, -9.0f + 2.0f * static_cast<float>(c)) << "farthest first";
    EXPECT_FLOAT_EQ(list.command_depths[c], 4.0f - z);
  }
}

}  // namespace
}  // namespace atrium::render
