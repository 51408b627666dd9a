#include "cli_values.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <unistd.h>

#include "common/input_error.hpp"
#include "common/text_util.hpp"

namespace arbor::cli {

namespace {

namespace fs = std::filesystem;

std::string between(double lo, double hi) { return "a finite number from " + formatNumber(lo) + " to " + formatNumber(hi); }

}  // namespace

bool parseFinite(const std::string& text, double& out) {
  if (text.empty() || std::isspace(static_cast<unsigned char>(text.front()))) return false;
  char* end = nullptr;
  errno = 0;
  out = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && errno != ERANGE && std::isfinite(out);
}

CLI::Validator Number(double lo, double hi) {
  return CLI::Validator(
      [lo, hi](std::string& text) -> std::string {
        double x = 0.0;
        if (!parseFinite(text, x) || x < lo || x > hi) return "'" + text + "': allowed " + between(lo, hi);
        return "";
      },
      "NUMBER in [" + formatNumber(lo) + ", " + formatNumber(hi) + "]");
}

CLI::Validator OffOrNumber(double lo, double hi) {
  return CLI::Validator(
      [lo, hi](std::string& text) -> std::string {
        double x = 0.0;
        if (!parseFinite(text, x) || (x != 0.0 && (x < lo || x > hi))) return "'" + text + "': allowed 0 (off) or " + between(lo, hi);
        return "";
      },
      "0 or NUMBER in [" + formatNumber(lo) + ", " + formatNumber(hi) + "]");
}

CLI::Validator Whole(long long lo, long long hi) {
  return CLI::Validator(
      [lo, hi](std::string& text) -> std::string {
        const std::string allowed = "'" + text + "': allowed a whole number from " + std::to_string(lo) + " to " + std::to_string(hi);
        std::size_t i = text.size() > 1 && (text[0] == '-' || text[0] == '+') ? 1 : 0;
        if (i == text.size() || text.size() > 19) return allowed;
        for (std::size_t k = i; k < text.size(); ++k) {
          if (!std::isdigit(static_cast<unsigned char>(text[k]))) return allowed;
        }
        const long long x = std::strtoll(text.c_str(), nullptr, 10);
        if (x < lo || x > hi) return allowed;
        return "";
      },
      "INT in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
}

CLI::Validator Seed() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const std::string allowed = "'" + text + "': a seed is a whole number from 0 to 18446744073709551615";
        if (text.empty() || text.size() > 20) return allowed;
        for (char c : text) {
          if (!std::isdigit(static_cast<unsigned char>(c))) return allowed;
        }
        errno = 0;
        std::strtoull(text.c_str(), nullptr, 10);
        return errno == ERANGE ? allowed : "";
      },
      "SEED");
}

std::vector<std::string> splitList(const std::string& text, const std::string& field) {
  std::vector<std::string> items;
  if (text.empty()) return items;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    items.push_back(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (items.back().empty()) throw InputError(text, field, "an empty item in the list; give comma-separated values, e.g. 1,2,4");
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return items;
}

std::vector<float> parseNumbers(const std::string& text, const std::string& field, float lo, float hi) {
  std::vector<float> values;
  for (const std::string& item : splitList(text, field)) {
    double v = 0.0;
    if (!parseFinite(item, v) || v < lo || v > hi) {
      throw InputError(item, field, "allowed: comma-separated numbers from " + formatNumber(lo) + " to " + formatNumber(hi));
    }
    values.push_back(static_cast<float>(v));
  }
  return values;
}

void requireOutputFile(const std::string& path, const std::string& field) {
  const fs::path p(path);
  if (p.filename().empty() || p.stem().empty() || p.stem().string().front() == '.') {
    throw InputError(path, field, "needs a file name before its extension, e.g. tree" + p.extension().string());
  }
  std::error_code ec;
  if (fs::is_directory(p, ec)) throw InputError(path, field, "is a directory; give a file name");
  const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  if (!fs::is_directory(dir, ec)) throw InputError(path, field, "its folder " + dir.string() + " does not exist");
  if (::access(dir.c_str(), W_OK | X_OK) != 0) throw InputError(path, field, "its folder " + dir.string() + " is not writable");
}

void requireOutputFolder(const std::string& path, const std::string& field) {
  if (path.empty()) throw InputError(path, field, "give a folder");
  std::error_code ec;
  fs::path p = fs::absolute(path, ec);
  if (fs::exists(p, ec) && !fs::is_directory(p, ec)) throw InputError(path, field, "exists and is not a folder");
  while (!p.empty() && !fs::exists(p, ec)) p = p.parent_path();
  if (p.empty() || !fs::is_directory(p, ec) || ::access(p.c_str(), W_OK | X_OK) != 0) {
    throw InputError(path, field, "cannot be created or written (" + p.string() + " is not a writable folder)");
  }
}

void parseSize(const std::string& text, std::uint32_t& width, std::uint32_t& height) {
  // Digits only: sscanf's %u would wrap 4294967360 to 64.
  const auto x = text.find('x');
  const auto side = [&](const std::string& digits) -> long {
    if (digits.empty() || digits.size() > 5 || digits.find_first_not_of("0123456789") != std::string::npos) return -1;
    return std::stol(digits);
  };
  const long w = x == std::string::npos ? -1 : side(text.substr(0, x)), h = x == std::string::npos ? -1 : side(text.substr(x + 1));
  if (w < 16 || h < 16 || w > 8192 || h > 8192) {
    throw InputError(text, "--size", "expected WIDTHxHEIGHT with each in [16, 8192], e.g. 640x800");
  }
  width = static_cast<std::uint32_t>(w);
  height = static_cast<std::uint32_t>(h);
}

glm::vec2 parseSunAngles(const std::string& text) {
  float az = 0.0f, el = 0.0f;
  char comma = 0, rest = 0;
  if (std::sscanf(text.c_str(), "%f%c%f%c", &az, &comma, &el, &rest) != 3 || comma != ',' || !(el >= -90.0f && el <= 90.0f) ||
      !std::isfinite(az)) {
    throw InputError(text, "--light", "expected AZIMUTH,ELEVATION in degrees, elevation from -90 to 90, e.g. 30,45");
  }
  return {az, el};
}

}  // namespace arbor::cli
