// The binary FBX check that runs before libassimp (assets/fbx_sizes.hpp): it
// must read every record libassimp 5.2.5's tokenizer reads, or an array that
// does not inflate reaches libassimp, which then leaks its zlib stream. A
// hostile file made from Blender's by make_hostile.py, and records written
// here for the tokenizer's corners no exporter writes.
#include "assets/fbx_sizes.hpp"

#include <cstring>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <zlib.h>

#include "assets/model_import.hpp"

namespace atrium::assets {
namespace {

constexpr std::size_t kLimit = std::size_t{1} << 30;

// A version 7400 file (32-bit words) written record by record.
class FbxWriter {
 public:
  FbxWriter() {
    const char header[] = "Kaydara FBX Binary  ";
    bytes_.assign(header, header + 20);
    bytes_.insert(bytes_.end(), {0x00, 0x1a, 0x00});
    word(7400);
  }

  // Opens a node record; its properties follow, then its children, then close().
  void open(const std::string& name, std::uint32_t properties) {
    open_.push_back(bytes_.size());
    word(0);  // end offset, written by close()
    word(properties);
    word(0);  // property bytes, written by end_properties()
    bytes_.push_back(static_cast<std::uint8_t>(name.size()));
    bytes_.insert(bytes_.end(), name.begin(), name.end());
    properties_start_ = bytes_.size();
  }
  void end_properties() { put_word(open_.back() + 8, static_cast<std::uint32_t>(bytes_.size() - properties_start_)); }
  // Closes the node; one with children ends in the null record.
  void close(bool children) {
    if (children) bytes_.insert(bytes_.end(), 13, 0);
    put_word(open_.back(), static_cast<std::uint32_t>(bytes_.size()));
    open_.pop_back();
  }

  void scalar(char type, std::size_t size) {
    bytes_.push_back(static_cast<std::uint8_t>(type));
    bytes_.insert(bytes_.end(), size, 0);
  }
  // An array of `count` values whose packed bytes are `packed` (encoding 1).
  void packed_array(char type, std::uint32_t count, const std::vector<std::uint8_t>& packed) {
    bytes_.push_back(static_cast<std::uint8_t>(type));
    word(count);
    word(1);
    word(static_cast<std::uint32_t>(packed.size()));
    bytes_.insert(bytes_.end(), packed.begin(), packed.end());
  }
  void raw_array(char type, const std::vector<std::uint8_t>& values) {
    bytes_.push_back(static_cast<std::uint8_t>(type));
    word(static_cast<std::uint32_t>(values.size()));
    word(0);
    word(static_cast<std::uint32_t>(values.size()));
    bytes_.insert(bytes_.end(), values.begin(), values.end());
  }
  void word(std::uint32_t value) {
    for (int i = 0; i < 4; ++i) bytes_.push_back(static_cast<std::uint8_t>(value >> (8 * i)));
  }

  std::vector<std::uint8_t> finish() {
    bytes_.insert(bytes_.end(), 13, 0);  // the top level's closing record
    return bytes_;
  }

 private:
  void put_word(std::size_t at, std::uint32_t value) {
    for (int i = 0; i < 4; ++i) bytes_[at + i] = static_cast<std::uint8_t>(value >> (8 * i));
  }

  std::vector<std::uint8_t> bytes_;
  std::vector<std::size_t> open_;
  std::size_t properties_start_ = 0;
};

std::vector<std::uint8_t> deflated(std::size_t size) {
  std::vector<std::uint8_t> values(size, 7), packed(compressBound(static_cast<uLong>(size)));
  uLongf packed_size = packed.size();
  EXPECT_EQ(compress(packed.data(), &packed_size, values.data(), static_cast<uLong>(values.size())), Z_OK);
  packed.resize(packed_size);
  return packed;
}

// Four doubles whose packed bytes start with a broken zlib header.
void broken_vertices(FbxWriter& fbx) {
  std::vector<std::uint8_t> packed = deflated(32);
  packed[0] = packed[1] = 0xff;
  fbx.open("Vertices", 1);
  fbx.packed_array('d', 4, packed);
  fbx.end_properties();
  fbx.close(false);
}

constexpr char kRefusal[] = "its array 'Vertices' at byte ";

TEST(FbxSizes, AnArrayThatInflatesToItsDeclaredSizePasses) {
  FbxWriter fbx;
  fbx.open("Vertices", 1);
  fbx.packed_array('d', 4, deflated(32));
  fbx.end_properties();
  fbx.close(false);
  EXPECT_EQ(fbx_array_size_problem(fbx.finish(), kLimit), "");
}

TEST(FbxSizes, AnArrayThatDoesNotInflateIsNamed) {
  FbxWriter fbx;
  broken_vertices(fbx);
  const std::string problem = fbx_array_size_problem(fbx.finish(), kLimit);
  EXPECT_EQ(problem.rfind(kRefusal, 0), 0u) << problem;
  EXPECT_NE(problem.find("whose compressed bytes do not inflate"), std::string::npos) << problem;
}

// The problem the walk finds in a file of `records`, then the broken Vertices.
std::string problem_after(const std::function<void(FbxWriter&)>& records) {
  FbxWriter fbx;
  records(fbx);
  broken_vertices(fbx);
  return fbx_array_size_problem(fbx.finish(), kLimit);
}

// libassimp tokenizes a byte array ('c') and never inflates one: the walk
// steps over it to the arrays after it.
TEST(FbxSizes, AByteArrayIsSteppedOver) {
  const std::string problem = problem_after([](FbxWriter& fbx) {
    fbx.open("Bytes", 1);
    fbx.raw_array('c', {1, 2, 3});
    fbx.end_properties();
    fbx.close(false);
  });
  EXPECT_EQ(problem.rfind(kRefusal, 0), 0u) << problem;
}

// libassimp's tokenizer gives a 'b' property the rest of its node's
// properties, however few bytes are left: the walk goes on to the next node.
TEST(FbxSizes, ABitPropertyTakesTheRestOfItsNode) {
  const std::string problem = problem_after([](FbxWriter& fbx) {
    fbx.open("Flags", 1);
    fbx.scalar('b', 2);
    fbx.end_properties();
    fbx.close(false);
  });
  EXPECT_EQ(problem.rfind(kRefusal, 0), 0u) << problem;
}

// Inside a node, libassimp skips a zero word and reads the record after it;
// only the top level stops at one.
TEST(FbxSizes, AZeroWordAmongChildrenIsSkippedAsLibassimpSkipsIt) {
  FbxWriter fbx;
  fbx.open("Geometry", 1);
  fbx.scalar('I', 4);
  fbx.end_properties();
  fbx.word(0);
  broken_vertices(fbx);
  fbx.close(true);
  EXPECT_EQ(fbx_array_size_problem(fbx.finish(), kLimit).rfind(kRefusal, 0), 0u);
}

// libassimp takes a file for binary FBX by its first 18 bytes.
TEST(FbxSizes, AFileLibassimpTakesForFbxByItsFirst18BytesIsWalked) {
  FbxWriter fbx;
  broken_vertices(fbx);
  std::vector<std::uint8_t> bytes = fbx.finish();
  std::memcpy(&bytes[18], "XX", 2);
  EXPECT_EQ(fbx_array_size_problem(bytes, kLimit).rfind(kRefusal, 0), 0u);
}

// The same, in a file Blender wrote (tests/fuzz/regressions/model/make_hostile.py):
// before the walk compared 18 bytes, libassimp got to inflate it and leaked.
TEST(FbxSizes, BlendersFileWithALooseMagicIsRefusedBeforeLibassimpInflatesIt) {
  const std::filesystem::path file =
      std::filesystem::path(ATRIUM_SOURCE_DIR) / "tests/fuzz/regressions/model/fbx-loose-magic-array-does-not-inflate.fbx";
  AssetManager assets;
  try {
    (void)import_model(file, assets);
    FAIL() << "imported";
  } catch (const ImportError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(file.string() + ": ", 0), 0u) << message;
    EXPECT_NE(message.find("its array 'Vertices'"), std::string::npos) << message;
    EXPECT_NE(message.find("do not inflate"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace atrium::assets
