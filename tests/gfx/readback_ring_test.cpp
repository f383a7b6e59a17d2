#include <cstdint>
#include <cstring>
#include <vector>

#include "gfx/gl_features.hpp"
#include "gfx/readback_ring.hpp"
#include "support/gl_test.hpp"

namespace atrium::gfx {
namespace {

using ReadbackRingTest = testing::GlTest;

struct Arrival {
  std::vector<std::uint32_t> words;
  std::uint64_t tag = 0;
};

std::vector<Arrival> poll_all(ReadbackRing& ring) {
  std::vector<Arrival> arrivals;
  ring.poll([&](const void* data, std::size_t bytes, std::uint64_t tag) {
    Arrival arrival{std::vector<std::uint32_t>((bytes + 3) / 4), tag};
    std::memcpy(arrival.words.data(), data, bytes);
    arrivals.push_back(std::move(arrival));
  });
  return arrivals;
}

Buffer buffer_of(const std::vector<std::uint32_t>& words) {
  Buffer buffer = create_buffer();
  glNamedBufferStorage(buffer.id(), static_cast<GLsizeiptr>(words.size() * sizeof(std::uint32_t)), words.data(), 0);
  return buffer;
}

// Copies arrive oldest first, each with its tag and the words from its offset,
// whether the shader writes the slot (whole words) or a buffer copy does (the rest).
TEST_F(ReadbackRingTest, CopiesArriveOldestFirstWithTheirTags) {
  ReadbackRing ring(16, 3);
  const Buffer first = buffer_of({1, 2, 3, 4});
  const Buffer second = buffer_of({5, 6, 7, 8});
  ASSERT_TRUE(ring.copy(first.id(), 4, 12, 10));
  ASSERT_TRUE(ring.copy(second.id(), 0, 6, 20));
  glFinish();
  const std::vector<Arrival> arrivals = poll_all(ring);
  ASSERT_EQ(arrivals.size(), 2u);
  EXPECT_EQ(arrivals[0].tag, 10u);
  EXPECT_EQ(arrivals[0].words, (std::vector<std::uint32_t>{2, 3, 4}));
  EXPECT_EQ(arrivals[1].tag, 20u);
  EXPECT_EQ(arrivals[1].words[0], 5u);
  EXPECT_EQ(arrivals[1].words[1] & 0xffffu, 6u);
  EXPECT_TRUE(poll_all(ring).empty()) << "each copy arrives once";
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// A copy while every slot is in flight is dropped, and a slot is free again once read.
TEST_F(ReadbackRingTest, ACopyIsDroppedWhileEverySlotIsInFlight) {
  ReadbackRing ring(4, 2);
  const Buffer source = buffer_of({42});
  EXPECT_TRUE(ring.copy(source.id(), 0, 4, 1));
  EXPECT_TRUE(ring.copy(source.id(), 0, 4, 2));
  EXPECT_FALSE(ring.copy(source.id(), 0, 4, 3));
  glFinish();
  EXPECT_EQ(poll_all(ring).size(), 2u);
  EXPECT_TRUE(ring.copy(source.id(), 0, 4, 4));
}

// The copy leaves the caller's program current: passes go on drawing with it.
TEST_F(ReadbackRingTest, TheCurrentProgramStaysCurrent) {
  const ShaderProgram program = ShaderProgram::load({"common/light_list_scan.comp"});
  program.use();
  ReadbackRing ring(8);
  const Buffer source = buffer_of({7, 9});
  ASSERT_TRUE(ring.copy(source.id(), 0, 8, 0));
  GLint current = 0;
  glGetIntegerv(GL_CURRENT_PROGRAM, &current);
  EXPECT_EQ(static_cast<GLuint>(current), program.id());
  glFinish();
  const std::vector<Arrival> arrivals = poll_all(ring);
  ASSERT_EQ(arrivals.size(), 1u);
  EXPECT_EQ(arrivals[0].words, (std::vector<std::uint32_t>{7, 9}));
}

}  // namespace
}  // namespace atrium::gfx
