// The test programs poison every buffer allocated without data
// (support/gl_test_main.cpp): such a buffer holds the marker word when made,
// through both allocation calls; one allocated with data holds its data.
#include <cstdint>
#include <vector>

#include "gfx/allocation_poison.hpp"
#include "gfx/gl_object.hpp"
#include "gfx/gpu_waits.hpp"
#include "support/gl_test.hpp"

namespace atrium::gfx {
namespace {

using AllocationPoison = testing::GlTest;

std::vector<std::uint32_t> words_of(const Buffer& buffer, std::size_t count) {
  std::vector<std::uint32_t> words(count);
  read_buffer(buffer.id(), 0, static_cast<GLsizeiptr>(count * sizeof(std::uint32_t)), words.data());
  return words;
}

TEST_F(AllocationPoison, ABufferMadeWithoutDataHoldsTheMarker) {
  const Buffer immutable = create_buffer();
  glNamedBufferStorage(immutable.id(), 64, nullptr, 0);
  EXPECT_EQ(words_of(immutable, 16), std::vector<std::uint32_t>(16, kPoisonWord));
  const Buffer second = create_buffer();
  glNamedBufferStorage(second.id(), 8, nullptr, GL_DYNAMIC_STORAGE_BIT);
  EXPECT_EQ(words_of(second, 2), std::vector<std::uint32_t>(2, kPoisonWord));
  const Buffer mutable_buffer = create_buffer();
  glNamedBufferData(mutable_buffer.id(), 32, nullptr, GL_DYNAMIC_DRAW);
  EXPECT_EQ(words_of(mutable_buffer, 8), std::vector<std::uint32_t>(8, kPoisonWord));
}

TEST_F(AllocationPoison, ABufferMadeWithDataHoldsItsData) {
  const std::vector<std::uint32_t> data{1, 2, 3, 4};
  const Buffer immutable = create_buffer();
  glNamedBufferStorage(immutable.id(), 16, data.data(), 0);
  EXPECT_EQ(words_of(immutable, 4), data);
  const Buffer mutable_buffer = create_buffer();
  glNamedBufferData(mutable_buffer.id(), 16, data.data(), GL_STATIC_DRAW);
  EXPECT_EQ(words_of(mutable_buffer, 4), data);
}

}  // namespace
}  // namespace atrium::gfx
