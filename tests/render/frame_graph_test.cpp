// The frame graph (render/frame_graph.hpp) on the real driver: passes run in
// the order added; a pass whose writes nothing reads is culled unless it keeps
// itself or writes a long-lived resource; transient targets whose lifetimes do
// not overlap share one GL object, and the memory report says so; a use after
// a storage write gets the barrier its access needs, and only then; pooled
// objects are reused frame after frame; every timed pass is timed; resources
// declared with a view kind are listed for the debug views; what a pass
// publishes is found by later ones until the next frame; a framebuffer on an
// imported target is made once and made again after forget_imports(); a
// texture read with sample_at is bound at its unit when the pass runs; with
// poisoning on, what the pass that writes a texture first leaves unwritten
// holds the marker, and a texture a pass reads before writing keeps its texels.
#include <vector>

#include <gtest/gtest.h>

#include "render/frame_graph.hpp"
#include "support/gl_test.hpp"

namespace atrium::render {
namespace {

using FrameGraphTest = testing::GlTest;

constexpr TextureDesc kColour{GL_RGBA8, {64, 32}, 1};

TEST_F(FrameGraphTest, PassesWhoseWritesNothingReadsAreCulled) {
  const gfx::Texture output = gfx::create_render_target(GL_RGBA8, 64, 32);
  FrameGraph graph;
  std::vector<std::string> ran;
  const ResourceId out = graph.import_texture("output", output.id(), kColour);
  graph.add_pass("unread", [](PassBuilder& b) { b.create("scratch", kColour); }, [&](const PassResources&) { ran.push_back("unread"); });
  ResourceId feeds;
  graph.add_pass("feeds", [&](PassBuilder& b) { feeds = b.create("fed", kColour); }, [&](const PassResources&) { ran.push_back("feeds"); });
  graph.add_pass("writes output", [&](PassBuilder& b) {
    b.read(feeds, Access::Sampled);
    b.write(out, Access::Attachment);
  }, [&](const PassResources&) { ran.push_back("writes output"); });
  graph.add_pass("kept", [](PassBuilder& b) { b.keep(); }, [&](const PassResources&) { ran.push_back("kept"); });
  graph.compile();
  graph.execute(nullptr);
  EXPECT_EQ(ran, (std::vector<std::string>{"feeds", "writes output", "kept"}));
  ASSERT_EQ(graph.passes().size(), 4u);
  EXPECT_TRUE(graph.passes()[0].culled);
  EXPECT_FALSE(graph.passes()[1].culled);
}

TEST_F(FrameGraphTest, ResourcesAreFoundByNameAndOnlyWhatWasDeclaredIsUsed) {
  FrameGraph graph;
  ResourceId made;
  graph.add_pass("first", [&](PassBuilder& b) { made = b.create("made", kColour); }, {});
  graph.add_pass("second", [&](PassBuilder& b) { EXPECT_EQ(b.read(b.find("made"), Access::Sampled), made); }, {});
  EXPECT_FALSE(graph.find("nothing").valid());
  EXPECT_THROW(graph.add_pass("third", [&](PassBuilder& b) { b.read(b.find("nothing"), Access::Sampled); }, {}), std::logic_error);
  EXPECT_THROW(graph.add_pass("fourth", [&](PassBuilder& b) { b.create("made", kColour); }, {}), std::logic_error) << "one name, one resource";
}

TEST_F(FrameGraphTest, TargetsThatNeverLiveTogetherShareOneObject) {
  const gfx::Texture output = gfx::create_render_target(GL_RGBA8, 64, 32);
  FrameGraph graph;
  const ResourceId out = graph.import_texture("output", output.id(), kColour);
  ResourceId a, b, c;
  GLuint object_a = 0, object_b = 0, object_c = 0;
  graph.add_pass("make a", [&](PassBuilder& p) { a = p.create("a", kColour); }, [&](const PassResources& r) { object_a = r.texture(a); });
  graph.add_pass("a to b", [&](PassBuilder& p) {
    p.read(a, Access::Sampled);
    b = p.create("b", kColour);
  }, [&](const PassResources& r) { object_b = r.texture(b); });
  graph.add_pass("b to c", [&](PassBuilder& p) {
    p.read(b, Access::Sampled);
    c = p.create("c", kColour);
  }, [&](const PassResources& r) { object_c = r.texture(c); });
  graph.add_pass("c to output", [&](PassBuilder& p) {
    p.read(c, Access::Sampled);
    p.write(out, Access::Attachment);
  }, {});
  graph.compile();
  graph.execute(nullptr);
  EXPECT_NE(object_a, object_b) << "a and b are both used by 'a to b'";
  EXPECT_NE(object_b, object_c);
  EXPECT_EQ(object_a, object_c) << "a's last use comes before c's first";
  const std::size_t one = texture_bytes(kColour);
  EXPECT_EQ(one, 64u * 32u * 4u);
  EXPECT_EQ(graph.memory().transient_bytes, 3 * one);
  EXPECT_EQ(graph.memory().aliased_bytes, 2 * one);
  EXPECT_EQ(graph.memory().imported_bytes, one);
  // The listing names each of them (info --memory), in the order declared.
  const std::vector<ResourceUse> used = graph.used_resources();
  ASSERT_EQ(used.size(), 4u);
  EXPECT_EQ(used[0].name, "output");
  EXPECT_TRUE(used[0].imported);
  EXPECT_EQ(used[1].name, "a");
  EXPECT_FALSE(used[1].imported);
  EXPECT_EQ(used[1].bytes, one);
  EXPECT_EQ(used[1].description, "RGBA8 64x32");
}

TEST_F(FrameGraphTest, ObjectsArePooledFromFrameToFrame) {
  const gfx::Texture output = gfx::create_render_target(GL_RGBA8, 64, 32);
  FrameGraph graph;
  std::vector<GLuint> seen;
  for (int frame = 0; frame < 3; ++frame) {
    graph.reset();
    const ResourceId out = graph.import_texture("output", output.id(), kColour);
    ResourceId t;
    graph.add_pass("make", [&](PassBuilder& p) { t = p.create("t", kColour); }, [&](const PassResources& r) { seen.push_back(r.texture(t)); });
    graph.add_pass("use", [&](PassBuilder& p) {
      p.read(t, Access::Sampled);
      p.write(out, Access::Attachment);
    }, {});
    graph.compile();
    graph.execute(nullptr);
  }
  EXPECT_EQ(graph.pooled_objects(), 1u);
  EXPECT_EQ(seen, std::vector<GLuint>(3, seen.front()));
  // A frame that no longer makes it lets it go after a few frames.
  for (int frame = 0; frame < 5; ++frame) {
    graph.reset();
    graph.add_pass("idle", [](PassBuilder& p) { p.keep(); }, {});
    graph.compile();
    graph.execute(nullptr);
  }
  EXPECT_EQ(graph.pooled_objects(), 0u);
}

TEST_F(FrameGraphTest, ATextureSampledAtAUnitIsBoundThereWhenThePassRuns) {
  const gfx::Texture atlas = gfx::create_render_target(GL_RGBA8, 64, 32);
  const gfx::Texture output = gfx::create_render_target(GL_RGBA8, 64, 32);
  FrameGraph graph;
  const ResourceId shared = graph.import_texture("atlas", atlas.id(), kColour);
  const ResourceId out = graph.import_texture("output", output.id(), kColour);
  constexpr unsigned kUnit = 11;
  glBindTextureUnit(kUnit, 0);
  GLint bound = -1;
  graph.add_pass("shade", [&](PassBuilder& p) {
    p.sample_at(shared, kUnit);
    p.write(out, Access::Attachment);
  }, [&](const PassResources&) {
    glActiveTexture(GL_TEXTURE0 + kUnit);
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
    glActiveTexture(GL_TEXTURE0);
  });
  graph.compile();
  graph.execute(nullptr);
  EXPECT_EQ(static_cast<GLuint>(bound), atlas.id());
}

TEST_F(FrameGraphTest, StorageWritesGetTheBarrierTheirReadersNeed) {
  const gfx::Buffer lists = gfx::create_buffer();
  glNamedBufferStorage(lists.id(), 256, nullptr, GL_DYNAMIC_STORAGE_BIT);
  const gfx::Texture output = gfx::create_render_target(GL_RGBA8, 64, 32);
  FrameGraph graph;
  const ResourceId buffer = graph.import_buffer("lists", lists.id(), {256});
  const ResourceId out = graph.import_texture("output", output.id(), kColour);
  ResourceId drawn;
  graph.add_pass("assign", [&](PassBuilder& p) { p.write(buffer, Access::Storage); }, {});
  graph.add_pass("draw", [&](PassBuilder& p) {
    p.read(buffer, Access::Indirect);
    p.read(buffer, Access::Storage);
    drawn = p.create("drawn", kColour);
  }, {});
  graph.add_pass("compose", [&](PassBuilder& p) {
    p.read(drawn, Access::Sampled);
    p.write(out, Access::Attachment);
  }, {});
  graph.compile();
  ASSERT_EQ(graph.passes().size(), 3u);
  EXPECT_EQ(graph.passes()[0].barriers, 0u);
  EXPECT_EQ(graph.passes()[1].barriers, static_cast<GLbitfield>(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT));
  EXPECT_EQ(graph.passes()[2].barriers, 0u) << "sampling what was rendered needs no barrier in GL";
  graph.execute(nullptr);
}

TEST_F(FrameGraphTest, PassesDrawIntoTheirTargetsAndAreTimed) {
  const gfx::Texture output = gfx::create_render_target(GL_RGBA8, 64, 32);
  const gfx::Framebuffer output_framebuffer = gfx::create_framebuffer();
  glNamedFramebufferTexture(output_framebuffer.id(), GL_COLOR_ATTACHMENT0, output.id(), 0);
  FrameGraph graph;
  gfx::PassTimer timer;
  timer.begin_frame();
  const ResourceId out = graph.import_texture("output", output.id(), kColour);
  ResourceId t;
  graph.add_pass("clear", [&](PassBuilder& p) { t = p.create("t", kColour); }, [&](const PassResources& r) {
    const GLfloat colour[] = {0.0f, 1.0f, 0.0f, 1.0f};
    glClearNamedFramebufferfv(r.framebuffer({t}), GL_COLOR, 0, colour);
  });
  graph.add_pass("copy", [&](PassBuilder& p) {
    p.read(t, Access::Transfer);
    p.write(out, Access::Transfer);
  }, [&](const PassResources& r) {
    glBlitNamedFramebuffer(r.framebuffer({t}), output_framebuffer.id(), 0, 0, 64, 32, 0, 0, 64, 32, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  });
  graph.add_pass("untimed", [](PassBuilder& p) { p.keep(); }, {}, false);
  graph.compile();
  graph.execute(&timer);
  timer.end_frame();
  std::uint8_t pixel[4] = {};
  glGetTextureSubImage(output.id(), 0, 10, 10, 0, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, 4, pixel);
  EXPECT_EQ(pixel[1], 255);
  EXPECT_EQ(pixel[0], 0);
  if (timer.method() == gfx::TimingMethod::CpuFinish) {
    ASSERT_EQ(timer.latest().size(), 2u);
    EXPECT_EQ(timer.latest()[0].name, "clear");
    EXPECT_EQ(timer.latest()[1].name, "copy");
  }
}

TEST_F(FrameGraphTest, ViewableResourcesArePublishedValuesAndCachedFramebuffersFollowTheFrame) {
  gfx::Texture depth = gfx::create_render_target(GL_DEPTH32F_STENCIL8, 64, 32);
  FrameGraph graph;
  struct Note {
    int value;
  };
  ResourceId colour;  // set by the setup, read by the execute
  auto build = [&] {
    graph.reset();
    const ResourceId d = graph.import_texture("depth", depth.id(), {GL_DEPTH32F_STENCIL8, {64, 32}, 1}, ViewKind::Depth);
    graph.import_buffer("lights", 0, {16});
    graph.add_pass("draws", [&](PassBuilder& b) {
      colour = b.create("colour", kColour, ViewKind::Color);
      b.create("scratch", kColour);
      b.write(d, Access::Attachment);
    }, [&, d](const PassResources& res) {
      const GLuint framebuffer = res.framebuffer({colour}, d);
      EXPECT_EQ(res.framebuffer({colour}, d), framebuffer) << "made once";
      glClearNamedFramebufferfi(framebuffer, GL_DEPTH_STENCIL, 0, 0.25f, 0);
    });
    graph.publish(Note{7});
  };
  build();
  const std::vector<ViewableResource> viewable = graph.viewable();
  ASSERT_EQ(viewable.size(), 2u);
  EXPECT_EQ(viewable[0].name, "depth");
  EXPECT_EQ(viewable[0].kind, ViewKind::Depth);
  EXPECT_EQ(viewable[1].name, "colour");
  EXPECT_EQ(viewable[1].kind, ViewKind::Color);
  EXPECT_EQ(viewable[1].written_by, "draws");
  ASSERT_NE(graph.published<Note>(), nullptr);
  EXPECT_EQ(graph.published<Note>()->value, 7);
  EXPECT_EQ(graph.published<int>(), nullptr);
  graph.execute(nullptr);
  graph.reset();
  EXPECT_EQ(graph.published<Note>(), nullptr) << "a new frame starts with nothing published";
  // The owner remakes its depth target (a resize; GL may give the new one
  // the old one's name) and says so: the next frame's framebuffer draws into
  // the new one.
  depth = {};
  depth = gfx::create_render_target(GL_DEPTH32F_STENCIL8, 64, 32);
  graph.forget_imports();
  build();
  graph.execute(nullptr);
  std::vector<float> texels(64 * 32, 0.0f);
  glGetTextureImage(depth.id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, static_cast<GLsizei>(texels.size() * sizeof(float)), texels.data());
  EXPECT_EQ(texels[0], 0.25f) << "the pass cleared the owner's current depth target";
}

TEST_F(FrameGraphTest, PoisoningMarksWhatTheFirstWriterLeavesAndSparesWhatAPassKeeps) {
  const gfx::Texture kept = gfx::create_render_target(GL_RGBA8, 64, 32);
  const GLfloat blue[] = {0.0f, 0.0f, 1.0f, 1.0f};
  glClearTexImage(kept.id(), 0, GL_RGBA, GL_FLOAT, blue);
  FrameGraph graph;
  graph.set_poison(true);
  const ResourceId cached = graph.import_texture("cached", kept.id(), kColour);
  ResourceId colour, identifiers, depth;
  graph.add_pass("half", [&](PassBuilder& p) {
    colour = p.create("colour", kColour);
    identifiers = p.create("identifiers", TextureDesc{GL_R32UI, {64, 32}, 1});
    depth = p.create("depth", TextureDesc{GL_DEPTH32F_STENCIL8, {64, 32}, 1});
    p.read(cached, Access::Attachment);
    p.write(cached, Access::Attachment);
  }, [&](const PassResources& r) {
    // Only the left half of the colour target; the others not at all.
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, 32, 32);
    const GLfloat green[] = {0.0f, 1.0f, 0.0f, 1.0f};
    glClearNamedFramebufferfv(r.framebuffer({colour}), GL_COLOR, 0, green);
    glDisable(GL_SCISSOR_TEST);
  });
  std::uint8_t left[4] = {}, right[4] = {}, keeps[4] = {};
  std::uint32_t identifier = 0;
  float depth_texel = 0.0f;
  graph.add_pass("read back", [&](PassBuilder& p) {
    for (const ResourceId t : {colour, identifiers, depth, cached}) p.read(t, Access::Transfer);
    p.keep();
  }, [&](const PassResources& r) {
    glGetTextureSubImage(r.texture(colour), 0, 10, 10, 0, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, 4, left);
    glGetTextureSubImage(r.texture(colour), 0, 50, 10, 0, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, 4, right);
    glGetTextureSubImage(r.texture(identifiers), 0, 5, 5, 0, 1, 1, 1, GL_RED_INTEGER, GL_UNSIGNED_INT, 4, &identifier);
    glGetTextureSubImage(r.texture(depth), 0, 5, 5, 0, 1, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, 4, &depth_texel);
    glGetTextureSubImage(r.texture(cached), 0, 5, 5, 0, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, 4, keeps);
  });
  graph.compile();
  graph.execute(nullptr);
  EXPECT_EQ(left[0], 0);
  EXPECT_EQ(left[1], 255) << "what the pass wrote";
  EXPECT_EQ(right[0], 255);
  EXPECT_EQ(right[1], 0);
  EXPECT_EQ(right[2], 255) << "left unwritten: the marker, magenta";
  EXPECT_EQ(identifier, FrameGraph::kPoisonIdentifier);
  EXPECT_EQ(depth_texel, FrameGraph::kPoisonDepth);
  EXPECT_EQ(keeps[2], 255) << "a texture the pass reads before it writes keeps its texels";
  EXPECT_EQ(keeps[0], 0);
}

}  // namespace
}  // namespace atrium::render
