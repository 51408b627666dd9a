#include "text_util.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>

namespace arbor {

bool endsWith(const std::string& s, const std::string& suffix) {
  if (s.size() < suffix.size()) return false;
  return std::equal(suffix.rbegin(), suffix.rend(), s.rbegin(),
                    [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) == b; });
}

std::string formatNumber(double x) {
  char buf[32];
  for (int precision = 6; precision <= 17; ++precision) {
    std::snprintf(buf, sizeof buf, "%.*g", precision, x);
    if (std::strtod(buf, nullptr) == x) break;
  }
  return buf;
}

namespace {

std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      const bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                        std::tolower(static_cast<unsigned char>(b[j - 1]));
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string closestName(const std::string& name, const std::vector<std::string>& known) {
  std::string best;
  std::size_t bestDistance = std::max<std::size_t>(2, name.size() / 3) + 1;
  for (const std::string& k : known) {
    const std::size_t d = editDistance(name, k);
    if (d < bestDistance) { bestDistance = d; best = k; }
  }
  return best;
}

std::string lastJsonKeyBefore(const std::string& text, std::size_t at) {
  // Scan backwards for `"key" :`, skipping nothing clever: good enough to name the field.
  std::size_t pos = std::min(at, text.size());
  while (pos > 0) {
    const std::size_t colon = text.rfind(':', pos - 1);
    if (colon == std::string::npos) return "";
    std::size_t end = colon;
    while (end > 0 && std::isspace(static_cast<unsigned char>(text[end - 1]))) --end;
    if (end > 0 && text[end - 1] == '"') {
      const std::size_t start = text.rfind('"', end - 2);
      if (start != std::string::npos) return text.substr(start + 1, end - start - 2);
    }
    pos = colon;
  }
  return "";
}

std::size_t jsonNestingPast(const std::string& text, int maxDepth) {
  int depth = 0;
  bool inString = false, escaped = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (inString) {
      if (escaped) escaped = false;
      else if (c == '\\') escaped = true;
      else if (c == '"') inString = false;
      continue;
    }
    if (c == '"') inString = true;
    else if ((c == '{' || c == '[') && ++depth > maxDepth) return i;
    else if (c == '}' || c == ']') --depth;
  }
  return std::string::npos;
}

std::string topLevelJsonString(const std::string& text, const std::string& key) {
  int depth = 0;
  bool expectValue = false;  // the last token at depth 1 was `key` and its colon
  std::string last;          // the last string read at depth 1
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '"') {
      std::size_t j = i + 1;
      while (j < text.size() && text[j] != '"') j += text[j] == '\\' ? 2 : 1;
      if (j >= text.size()) return "";
      const std::string value = text.substr(i + 1, j - i - 1);
      if (depth == 1 && expectValue) return value;
      if (depth == 1) last = value;
      i = j;
      continue;
    }
    if (c == '{' || c == '[') ++depth;
    else if (c == '}' || c == ']') --depth;
    else if (c == ':' && depth == 1) expectValue = last == key;
    else if (c == ',' && depth == 1) expectValue = false, last.clear();
    if (depth != 1) expectValue = false;
  }
  return "";
}

}  // namespace arbor
