// StreamBuffer uploads land in command order: commands submitted between two
// uploads read the first one's data, however many uploads the CPU makes before
// the GPU runs them, and uploads into a stream the GPU has caught up with
// never wait. A gather upload lays its pieces back to back.
#include "gfx/stream_buffer.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "gfx/gpu_waits.hpp"
#include "support/gl_test.hpp"

namespace atrium::gfx {
namespace {

using StreamBufferTest = testing::GlTest;

std::vector<std::uint32_t> read_words(GLuint buffer, std::size_t words) {
  std::vector<std::uint32_t> out(words);
  read_buffer(buffer, 0, static_cast<GLsizeiptr>(words * sizeof(std::uint32_t)), out.data());
  return out;
}

// Each upload is copied on the GPU into its own part of `log` before the next
// upload: twice as many uploads as staging copies, with no wait in between.
TEST_F(StreamBufferTest, CommandsBetweenUploadsReadTheUploadBeforeThem) {
  constexpr std::size_t kWords = 1024, kUploads = 2 * StreamBuffer::kStagingCopies + 1;
  StreamBuffer stream;
  Buffer log = create_buffer();
  glNamedBufferStorage(log.id(), static_cast<GLsizeiptr>(kUploads * kWords * sizeof(std::uint32_t)), nullptr, 0);
  for (std::size_t u = 0; u < kUploads; ++u) {
    // The last upload grows the stream: a new buffer, and new staging copies.
    const std::size_t words = u + 1 == kUploads ? 4 * kWords : kWords;
    std::vector<std::uint32_t> data(words);
    for (std::size_t w = 0; w < words; ++w) data[w] = static_cast<std::uint32_t>(u * 100000 + w);
    stream.upload(data.data(), words * sizeof(std::uint32_t));
    glCopyNamedBufferSubData(stream.buffer.id(), log.id(), 0, static_cast<GLintptr>(u * kWords * sizeof(std::uint32_t)),
                             static_cast<GLsizeiptr>(kWords * sizeof(std::uint32_t)));
  }
  const std::vector<std::uint32_t> logged = read_words(log.id(), kUploads * kWords);
  for (std::size_t u = 0; u < kUploads; ++u) {
    for (std::size_t w = 0; w < kWords; w += 97) {
      ASSERT_EQ(logged[u * kWords + w], u * 100000 + w) << "upload " << u << ", word " << w;
    }
  }
  EXPECT_EQ(read_words(stream.buffer.id(), 4 * kWords)[4 * kWords - 1], (kUploads - 1) * 100000 + 4 * kWords - 1);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

TEST_F(StreamBufferTest, UploadsIntoAStreamTheGpuCaughtUpWithNeverWait) {
  StreamBuffer stream;
  const std::vector<std::uint32_t> data(4096, 7u);
  for (int frame = 0; frame < 4; ++frame) {
    finish();
    const std::uint64_t before = gpu_waits();
    for (std::size_t u = 0; u < StreamBuffer::kStagingCopies; ++u) stream.upload(data.data(), data.size() * sizeof(std::uint32_t));
    EXPECT_EQ(gpu_waits(), before) << "frame " << frame;
  }
  EXPECT_EQ(read_words(stream.buffer.id(), 1)[0], 7u);
}

// A head and an array in one upload, as the visibility buffer sends its units:
// the head at the start, the array right after it, an empty piece adding
// nothing; then a shorter gather leaves what lies past it as it was.
TEST_F(StreamBufferTest, AGatherUploadLaysItsPiecesBackToBack) {
  StreamBuffer stream;
  const std::uint32_t head = 0xABCD0123u;
  std::vector<std::uint32_t> array(777);
  for (std::size_t w = 0; w < array.size(); ++w) array[w] = static_cast<std::uint32_t>(w * 3 + 1);
  for (int frame = 0; frame < 3; ++frame) {
    stream.upload({std::as_bytes(std::span(&head, 1)), std::span<const std::byte>(), std::as_bytes(std::span(array))});
  }
  const std::vector<std::uint32_t> words = read_words(stream.buffer.id(), 1 + array.size());
  EXPECT_EQ(words[0], head);
  for (std::size_t w = 0; w < array.size(); ++w) ASSERT_EQ(words[1 + w], array[w]) << "word " << w;

  const std::uint32_t short_head = 5u;
  stream.upload({std::as_bytes(std::span(&short_head, 1)), std::as_bytes(std::span(array).first(2))});
  const std::vector<std::uint32_t> after = read_words(stream.buffer.id(), 4);
  EXPECT_EQ(after[0], short_head);
  EXPECT_EQ(after[1], array[0]);
  EXPECT_EQ(after[2], array[1]);
  EXPECT_EQ(after[3], array[2]) << "past the upload: the last one's word";
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

}  // namespace
}  // namespace atrium::gfx
