#include <vector>

#include "app/world.hpp"
#include "gfx/gl_object.hpp"
#include "support/gl_test.hpp"

namespace atrium::gfx {
namespace {

using GlObjects = testing::GlTest;

TEST_F(GlObjects, CreateDestroyCyclesLeaveNoObjectsBehind) {
  const std::int64_t before = live_gl_objects();
  for (int cycle = 0; cycle < 3; ++cycle) {
    std::vector<std::pair<GlKind, GLuint>> names;
    {
      std::vector<Buffer> buffers;
      std::vector<Texture> textures;
      std::vector<Framebuffer> framebuffers;
      std::vector<VertexArray> vertex_arrays;
      std::vector<Query> queries;
      std::vector<Sampler> samplers;
      for (int i = 0; i < 16; ++i) {
        buffers.push_back(create_buffer());
        textures.push_back(create_texture(GL_TEXTURE_2D));
        framebuffers.push_back(create_framebuffer());
        vertex_arrays.push_back(create_vertex_array());
        queries.push_back(create_query(GL_TIME_ELAPSED));
        samplers.push_back(create_sampler());
        names.insert(names.end(), {{GlKind::Buffer, buffers.back().id()}, {GlKind::Texture, textures.back().id()},
                                   {GlKind::Framebuffer, framebuffers.back().id()},
                                   {GlKind::VertexArray, vertex_arrays.back().id()},
                                   {GlKind::Query, queries.back().id()}, {GlKind::Sampler, samplers.back().id()}});
      }
      EXPECT_EQ(live_gl_objects(), before + 16 * 6);
      for (const auto& [kind, name] : names) EXPECT_TRUE(gl_object_exists(kind, name)) << gl_kind_name(kind);
    }
    EXPECT_EQ(live_gl_objects(), before);
    for (const auto& [kind, name] : names) EXPECT_FALSE(gl_object_exists(kind, name)) << gl_kind_name(kind) << " " << name;
  }
}

TEST_F(GlObjects, MovingTransfersOwnershipWithoutDoubleDelete) {
  const std::int64_t before = live_gl_objects();
  Buffer a = create_buffer();
  const GLuint name = a.id();
  Buffer b = std::move(a);
  EXPECT_EQ(a.id(), 0u);
  EXPECT_EQ(b.id(), name);
  Buffer c;
  c = std::move(b);
  EXPECT_EQ(live_gl_objects(), before + 1);
  c.reset();
  EXPECT_EQ(live_gl_objects(), before);
  EXPECT_FALSE(gl_object_exists(GlKind::Buffer, name));
}

TEST_F(GlObjects, AWholeWorldReleasesEverythingItCreated) {
  const std::int64_t before = live_gl_objects();
  for (int cycle = 0; cycle < 2; ++cycle) {
    World world({.scene = "atrium", .lights = 16u, .mode = std::nullopt, .size = {64, 36}});
    world.frame(0.0);
    EXPECT_GT(live_gl_objects(), before);
  }
  EXPECT_EQ(live_gl_objects(), before);
}

}  // namespace
}  // namespace atrium::gfx
