#include "assets/json_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "base/format.hpp"

namespace atrium::assets {
namespace {

// 10000000, 0.5, -1: the shortest form that reads back the same.
std::string compact(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", v);
  return text;
}

// A bound as a user reads it: 1,000,000,000 rather than 1e+09.
std::string readable(double v) {
  if (v >= 1000.0 && v < 1e15 && v == std::floor(v)) return with_commas(static_cast<std::uint64_t>(v));
  return compact(v);
}

}  // namespace

JsonPointer JsonPointer::operator/(std::string_view key) const {
  JsonPointer out = *this;
  out.text_ += '/';
  for (const char c : key) {
    if (c == '~') out.text_ += "~0";
    else if (c == '/') out.text_ += "~1";
    else out.text_ += c;
  }
  return out;
}

JsonPointer JsonPointer::operator/(std::size_t index) const {
  JsonPointer out = *this;
  out.text_ += '/' + std::to_string(index);
  return out;
}

Json JsonReader::parse(std::string_view text) const {
  try {
    return Json::parse(text.begin(), text.end());
  } catch (const Json::exception& e) {
    // parse_error, and out_of_range for numbers beyond a double (1e400); the
    // library's "[json.exception.parse_error.101] " tag is no user's business.
    const std::string what = e.what();
    const std::size_t tag = what.find("] ");
    throw JsonError(file_ + ": not valid JSON (" + (tag == std::string::npos ? what : what.substr(tag + 2)) + ")");
  }
}

void JsonReader::fail(const JsonPointer& at, const std::string& problem) const {
  throw JsonError(file_ + ": " + at.str() + ": " + problem);
}

std::string JsonReader::describe(const Json& value) {
  const std::string text = value.dump();
  return text.size() > 40 ? text.substr(0, 37) + "..." : text;
}

std::string JsonReader::range_words(double min, double max) {
  if (min == -kLargest && max == kLargest) return "a number";
  if (max == kLargest) return "a number from " + compact(min);
  return "a number from " + compact(min) + " to " + compact(max);
}

const Json& JsonReader::object(const Json& value, const JsonPointer& at) const {
  if (!value.is_object()) fail(at, "expected an object, got " + describe(value));
  return value;
}

const Json& JsonReader::array(const Json& value, const JsonPointer& at) const {
  if (!value.is_array()) fail(at, "expected an array, got " + describe(value));
  return value;
}

std::string JsonReader::string(const Json& value, const JsonPointer& at) const {
  if (!value.is_string()) fail(at, "expected a string, got " + describe(value));
  return value.get<std::string>();
}

bool JsonReader::boolean(const Json& value, const JsonPointer& at) const {
  if (!value.is_boolean()) fail(at, "expected true or false, got " + describe(value));
  return value.get<bool>();
}

double JsonReader::number(const Json& value, const JsonPointer& at, double min, double max, std::string_view expected) const {
  const double v = value.is_number() ? value.get<double>() : 0.0;
  if (!value.is_number() || !std::isfinite(v) || v < min || v > max) {
    // A phrase that names no range ("a positive number") gets the bound the
    // number passed: "expected a positive number, got 1e+30" would puzzle.
    std::string bound;
    if (value.is_number() && std::isfinite(v) && expected.find(" from ") == std::string_view::npos) {
      if (v > max) bound = " no greater than " + readable(max);
      else if (v > 0.0 && v < min) bound = " no less than " + readable(min);
    }
    fail(at, "expected " + std::string(expected) + bound + ", got " + describe(value));
  }
  return v;
}

std::uint64_t JsonReader::whole(const Json& value, const JsonPointer& at, std::uint64_t min, std::uint64_t max) const {
  const double v = value.is_number() ? value.get<double>() : -1.0;
  if (!value.is_number() || !(v >= static_cast<double>(min)) || !(v <= static_cast<double>(max)) || v != std::floor(v)) {
    fail(at, "expected a whole number from " + with_commas(min) + " to " + with_commas(max) + ", got " + describe(value));
  }
  return static_cast<std::uint64_t>(v);
}

std::size_t JsonReader::index(const Json& value, const JsonPointer& at, std::size_t size, const JsonPointer& target) const {
  if (!value.is_number()) fail(at, "expected an index into " + target.str() + ", got " + describe(value));
  const double v = value.get<double>();
  if (!(v >= 0.0) || v != std::floor(v) || v >= static_cast<double>(size)) {
    fail(at, "refers to " + target.str() + "/" + describe(value) + ", which does not exist (the file has " + std::to_string(size) + ")");
  }
  return static_cast<std::size_t>(v);
}

void JsonReader::only_keys(const Json& object, const JsonPointer& at, std::initializer_list<std::string_view> keys) const {
  this->object(object, at);
  for (const auto& item : object.items()) {
    if (std::find(keys.begin(), keys.end(), item.key()) != keys.end()) continue;
    std::string known;
    for (const std::string_view k : keys) known += (known.empty() ? "" : ", ") + std::string(k);
    fail(at / item.key(), "unknown key (expected one of: " + known + ")");
  }
}

const Json* JsonReader::find(const Json& object, std::string_view key) {
  if (!object.is_object()) return nullptr;
  const auto it = object.find(key);
  return it == object.end() ? nullptr : &*it;
}

const Json& JsonReader::required(const Json& object, const JsonPointer& at, std::string_view key) const {
  const Json* value = find(this->object(object, at), key);
  if (!value) fail(at / key, "is missing");
  return *value;
}

const Json& JsonReader::array_or_empty(const Json& object, const JsonPointer& at, std::string_view key) const {
  static const Json kEmpty = Json::array();
  const Json* value = find(object, key);
  return value ? array(*value, at / key) : kEmpty;
}

const Json& JsonReader::object_or_empty(const Json& object, const JsonPointer& at, std::string_view key) const {
  static const Json kEmpty = Json::object();
  const Json* value = find(object, key);
  return value ? this->object(*value, at / key) : kEmpty;
}

std::string JsonReader::string_or(const Json& object, const JsonPointer& at, std::string_view key, std::string fallback) const {
  const Json* value = find(object, key);
  return value ? string(*value, at / key) : fallback;
}

bool JsonReader::boolean_or(const Json& object, const JsonPointer& at, std::string_view key, bool fallback) const {
  const Json* value = find(object, key);
  return value ? boolean(*value, at / key) : fallback;
}

double JsonReader::number_or(const Json& object, const JsonPointer& at, std::string_view key, double fallback, double min, double max,
                             std::string_view expected) const {
  const Json* value = find(object, key);
  return value ? number(*value, at / key, min, max, expected) : fallback;
}

std::uint64_t JsonReader::whole_or(const Json& object, const JsonPointer& at, std::string_view key, std::uint64_t min, std::uint64_t max,
                                   std::uint64_t fallback) const {
  const Json* value = find(object, key);
  return value ? whole(*value, at / key, min, max) : fallback;
}

}  // namespace atrium::assets
