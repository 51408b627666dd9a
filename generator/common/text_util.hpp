#pragma once
// Small text helpers for error messages.
#include <string>
#include <vector>

namespace arbor {

bool endsWith(const std::string& s, const std::string& suffix);

// Shortest text that reads back as the same number ("0.1", "3", "1e-05").
std::string formatNumber(double x);

// The known name closest to `name` by edit distance, or "" when nothing is close.
std::string closestName(const std::string& name, const std::vector<std::string>& known);

// The last "key": seen before byte `at` of a JSON text, for naming the field a parse error sits in.
std::string lastJsonKeyBefore(const std::string& text, std::size_t at);

// Where JSON text first nests objects or arrays deeper than maxDepth (outside strings), or npos: checked
// before a recursive parser meets it.
std::size_t jsonNestingPast(const std::string& text, int maxDepth);

// The string value of `key` in the outermost JSON object of `text` (escapes left as written), found by one
// scan without parsing; "" when it has none. Enough to tell file kinds apart before choosing a reader.
std::string topLevelJsonString(const std::string& text, const std::string& key);

}  // namespace arbor
