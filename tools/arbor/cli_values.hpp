#pragma once
// Command-line values checked as text, before CLI11 converts them: CLI11's Range lets NaN through (it fails
// both comparisons) and its unsigned conversion wraps "-1" and 2^64, so every number option uses these.
#include <CLI/CLI.hpp>
#include <glm/vec2.hpp>
#include <cstdint>
#include <string>
#include <vector>

namespace arbor::cli {

// The whole text as one finite number (no leading blank, no trailing text, no overflow).
bool parseFinite(const std::string& text, double& out);
// A finite decimal number within [lo, hi] ("nan", "inf", "1e999", "" are refused).
CLI::Validator Number(double lo, double hi);
// 0 (off) or a finite number within [lo, hi]: options where tiny values would ask for unbounded work.
CLI::Validator OffOrNumber(double lo, double hi);
// A whole decimal number (optional sign, digits only) within [lo, hi].
CLI::Validator Whole(long long lo, long long hi);
// A seed: decimal digits only, 0 to 18446744073709551615.
CLI::Validator Seed();

// "a,b,c" -> {"a", "b", "c"}; "" -> {}. An empty item ("1,,2", ",") is bad input naming `field`.
std::vector<std::string> splitList(const std::string& text, const std::string& field);
// Comma-separated finite numbers, each within [lo, hi]; anything else is an InputError naming `field`.
std::vector<float> parseNumbers(const std::string& text, const std::string& field, float lo, float hi);

// "WIDTHxHEIGHT", each in [16, 8192].
void parseSize(const std::string& text, std::uint32_t& width, std::uint32_t& height);
// "AZIMUTH,ELEVATION" in degrees (--light), elevation within [-90, 90].
glm::vec2 parseSunAngles(const std::string& text);

// An output file name must have a name before its extension ("--out .obj" is refused), and its folder must
// exist and be writable: checked before any work, so a run never fails at its end for a path given at its start.
void requireOutputFile(const std::string& path, const std::string& field = "--out");
// An output folder is created if missing; its nearest existing ancestor must be a writable directory.
void requireOutputFolder(const std::string& path, const std::string& field = "--out");

}  // namespace arbor::cli
