// Reads typed values out of JSON for every JSON file Atrium opens (glTF models,
// scene files), so that all of them are checked alike and refused in one
// phrasing: the file, the JSON pointer of the value (RFC 6901, the form
// gltf-validator reports) and what was expected:
//   "scenes/x.json: /lights/3/radius: expected a positive number, got -1"
//   "box.gltf: /meshes/0/primitives: is missing"
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace atrium::assets {

using Json = nlohmann::json;

// What a JsonReader throws; each file type's loader turns it into its own error.
class JsonError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Where a value sits: JsonPointer() / "meshes" / 0 / "primitives" reads
// "/meshes/0/primitives"; the document itself reads "/".
class JsonPointer {
 public:
  JsonPointer() = default;
  [[nodiscard]] JsonPointer operator/(std::string_view key) const;  // escapes '~' and '/' as RFC 6901 asks
  [[nodiscard]] JsonPointer operator/(std::size_t index) const;
  [[nodiscard]] std::string str() const { return text_.empty() ? "/" : text_; }

 private:
  std::string text_;
};

class JsonReader {
 public:
  static constexpr double kLargest = std::numeric_limits<double>::max();

  explicit JsonReader(std::string file) : file_(std::move(file)) {}
  [[nodiscard]] const std::string& file() const { return file_; }

  // The document, or "<file>: not valid JSON (<where and why>)".
  [[nodiscard]] Json parse(std::string_view text) const;

  // Throws JsonError("<file>: <pointer>: <problem>").
  [[noreturn]] void fail(const JsonPointer& at, const std::string& problem) const;
  // A value as a message quotes it, cut short past 40 characters.
  [[nodiscard]] static std::string describe(const Json& value);

  // Values: each fails with "expected ..., got <value>".
  const Json& object(const Json& value, const JsonPointer& at) const;
  const Json& array(const Json& value, const JsonPointer& at) const;
  [[nodiscard]] std::string string(const Json& value, const JsonPointer& at) const;
  [[nodiscard]] bool boolean(const Json& value, const JsonPointer& at) const;
  // A finite number in [min, max]; `expected` says so in words.
  [[nodiscard]] double number(const Json& value, const JsonPointer& at, double min = -kLargest, double max = kLargest,
                              std::string_view expected = "a number") const;
  [[nodiscard]] std::uint64_t whole(const Json& value, const JsonPointer& at, std::uint64_t min, std::uint64_t max) const;
  // An index into the array at `target` holding `size` elements.
  [[nodiscard]] std::size_t index(const Json& value, const JsonPointer& at, std::size_t size, const JsonPointer& target) const;
  template <std::size_t N>
  [[nodiscard]] std::array<double, N> numbers(const Json& value, const JsonPointer& at, double min = -kLargest,
                                              double max = kLargest) const {
    if (!value.is_array() || value.size() != N) fail(at, "expected an array of " + std::to_string(N) + " numbers, got " + describe(value));
    std::array<double, N> out{};
    for (std::size_t i = 0; i < N; ++i) out[i] = number(value[i], at / i, min, max, range_words(min, max));
    return out;
  }
  // Fails on a key outside `keys`, naming the ones it knows.
  void only_keys(const Json& object, const JsonPointer& at, std::initializer_list<std::string_view> keys) const;

  // Members of an object at `at`: absent ones give nullptr or the fallback;
  // `required` fails "<at>/<key>: is missing".
  [[nodiscard]] static const Json* find(const Json& object, std::string_view key);
  const Json& required(const Json& object, const JsonPointer& at, std::string_view key) const;
  const Json& array_or_empty(const Json& object, const JsonPointer& at, std::string_view key) const;
  const Json& object_or_empty(const Json& object, const JsonPointer& at, std::string_view key) const;
  [[nodiscard]] std::string string_or(const Json& object, const JsonPointer& at, std::string_view key, std::string fallback) const;
  [[nodiscard]] bool boolean_or(const Json& object, const JsonPointer& at, std::string_view key, bool fallback) const;
  [[nodiscard]] double number_or(const Json& object, const JsonPointer& at, std::string_view key, double fallback,
                                 double min = -kLargest, double max = kLargest, std::string_view expected = "a number") const;
  [[nodiscard]] std::uint64_t whole_or(const Json& object, const JsonPointer& at, std::string_view key, std::uint64_t min,
                                       std::uint64_t max, std::uint64_t fallback) const;
  template <std::size_t N>
  [[nodiscard]] std::array<double, N> numbers_or(const Json& object, const JsonPointer& at, std::string_view key,
                                                 std::array<double, N> fallback) const {
    const Json* value = find(object, key);
    return value ? numbers<N>(*value, at / key) : fallback;
  }

  // "a number from 0 to 90" for a bounded range, "a number" for an open one.
  [[nodiscard]] static std::string range_words(double min, double max);

 private:
  std::string file_;
};

}  // namespace atrium::assets
