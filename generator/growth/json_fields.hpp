#pragma once
// Reading fields of JSON documents (skeletons, branch graphs) with every refusal an InputError that names
// the file, the field and what is allowed.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/input_error.hpp"
#include "common/input_file.hpp"
#include "common/text_util.hpp"
#include "growth/tree_limits.hpp"
#include "math.hpp"

namespace arbor::json_fields {

using nlohmann::json;

inline std::string typeName(const json& v) {
  if (v.is_null()) return "null";
  if (v.is_boolean()) return "a boolean";
  if (v.is_number()) return "a number";
  if (v.is_string()) return "a string";
  if (v.is_array()) return "an array";
  return "an object";
}

// Parses a whole document; brackets nested deeper than `maxDepth` are refused before the parser sees them.
inline json parseDocument(const std::string& text, const std::string& file, int maxDepth) {
  requireText(text, file);
  if (const std::size_t at = jsonNestingPast(text, maxDepth); at != std::string::npos) {
    throw InputError(file, "(document)", "nested deeper than " + std::to_string(maxDepth) + " levels at " + lineAndColumn(text, at));
  }
  try {
    return json::parse(text);
  } catch (const json::parse_error& e) {
    const std::size_t at = std::min<std::size_t>(e.byte == 0 ? 0 : e.byte - 1, text.size());
    const std::string field = lastJsonKeyBefore(text, at);
    std::string message = "invalid JSON at " + lineAndColumn(text, at);
    const std::string tail = text.substr(std::min(at, text.size()), 8);
    for (const char* word : {"NaN", "nan", "Inf", "inf", "-Inf", "-inf"}) {
      if (tail.rfind(word, 0) == 0) {
        message += ": NaN and Infinity are not numbers in JSON; give a finite number";
        break;
      }
    }
    throw InputError(file, field.empty() ? "(document)" : field, message);
  } catch (const json::exception& e) {
    throw InputError(file, "(document)", std::string("invalid JSON: ") + e.what());
  }
}

inline const json& member(const json& object, const char* key, const std::string& file, const std::string& prefix,
                          const std::string& allowed) {
  const auto it = object.find(key);
  if (it == object.end()) throw InputError(file, prefix + key, "missing required field (" + allowed + ")");
  return *it;
}

inline void onlyKeys(const json& object, std::initializer_list<const char*> keys, const std::string& file,
                     const std::string& prefix) {
  std::vector<std::string> known(keys.begin(), keys.end());
  for (auto it = object.begin(); it != object.end(); ++it) {
    if (std::find(known.begin(), known.end(), it.key()) != known.end()) continue;
    std::string message = "unknown field";
    const std::string guess = closestName(it.key(), known);
    if (!guess.empty()) message += " (did you mean '" + guess + "'?)";
    throw InputError(file, prefix + it.key(), message);
  }
}

inline const json& object(const json& v, const std::string& file, const std::string& field) {
  if (!v.is_object()) throw InputError(file, field, "expected an object, got " + typeName(v));
  return v;
}

inline const json& array(const json& v, const std::string& file, const std::string& field) {
  if (!v.is_array()) throw InputError(file, field, "expected an array, got " + typeName(v));
  return v;
}

inline double number(const json& v, const std::string& file, const std::string& field, double min, double max,
                     const std::string& allowed) {
  if (!v.is_number()) throw InputError(file, field, "expected " + allowed + ", got " + typeName(v));
  const double x = v.get<double>();
  if (!std::isfinite(x)) throw InputError(file, field, "not a finite number; allowed " + allowed);
  if (x < min || x > max) throw InputError(file, field, formatNumber(x) + " is out of range; allowed " + allowed);
  return x;
}

inline std::int64_t integer(const json& v, const std::string& file, const std::string& field, std::int64_t min,
                            std::int64_t max, const std::string& allowed) {
  if (!v.is_number_integer()) {
    if (v.is_number_float()) throw InputError(file, field, "not a whole number; allowed " + allowed);
    throw InputError(file, field, "expected " + allowed + ", got " + typeName(v));
  }
  if (v.is_number_unsigned() && v.get<std::uint64_t>() > static_cast<std::uint64_t>(max)) {
    throw InputError(file, field, "out of range; allowed " + allowed);
  }
  const std::int64_t x = v.get<std::int64_t>();
  if (x < min || x > max) throw InputError(file, field, std::to_string(x) + " is out of range; allowed " + allowed);
  return x;
}

inline std::string string(const json& v, const std::string& file, const std::string& field) {
  if (!v.is_string()) throw InputError(file, field, "expected a string, got " + typeName(v));
  return v.get<std::string>();
}

inline Vec3 vec3(const json& v, const std::string& file, const std::string& field) {
  if (!v.is_array() || v.size() != 3) throw InputError(file, field, "expected [x, y, z] (three finite numbers), got " + typeName(v));
  Vec3 out;
  for (int k = 0; k < 3; ++k) {
    out[k] = number(v[static_cast<std::size_t>(k)], file, field + "[" + std::to_string(k) + "]", -1e300, 1e300, "a finite number");
  }
  return out;
}

// A node's position: three finite numbers, each within kMaxCoordinate of the origin.
inline Vec3 position(const json& v, const std::string& file, const std::string& field) {
  const Vec3 p = vec3(v, file, field);
  for (int k = 0; k < 3; ++k) {
    if (const std::string why = outOfReach(p[k]); !why.empty()) throw InputError(file, field + "[" + std::to_string(k) + "]", why);
  }
  return p;
}

}  // namespace arbor::json_fields
