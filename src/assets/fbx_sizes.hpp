// A binary FBX declares each array's length and packs its values with zlib;
// libassimp allocates the declared length before inflating, so a hostile file
// can ask for gigabytes in a few bytes, and it leaks its zlib stream when the
// bytes do not inflate. This walks the file's node records and names the
// first array whose declared size is beyond the load budget or beyond what its
// compressed bytes can hold, or whose bytes zlib cannot inflate.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

namespace atrium::assets {

// Empty when every array's size is believable and every packed array
// inflates, or when `bytes` is not a binary FBX; otherwise the problem in a
// few words.
[[nodiscard]] std::string fbx_array_size_problem(std::span<const std::uint8_t> bytes, std::size_t limit);

}  // namespace atrium::assets
