#include "json_writer.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <ostream>

namespace arbor {

void JsonWriter::newline() {
  out_ += '\n';
  out_.append(2 * first_.size(), ' ');
}

void JsonWriter::separate() {
  if (afterKey_) {
    afterKey_ = false;
    return;
  }
  if (first_.empty()) return;
  const bool comma = !first_.back();
  if (comma) out_ += ',';
  first_.back() = false;
  if (static_cast<int>(first_.size()) <= lineDepth_) newline();
  else if (comma) out_ += ' ';
}

JsonWriter& JsonWriter::beginObject() {
  separate();
  out_ += '{';
  first_.push_back(true);
  return *this;
}

JsonWriter& JsonWriter::endObject() {
  const bool empty = first_.back();
  first_.pop_back();
  if (!empty && static_cast<int>(first_.size()) < lineDepth_) newline();
  out_ += '}';
  if (first_.empty()) out_ += '\n';
  return *this;
}

JsonWriter& JsonWriter::beginArray() {
  separate();
  out_ += '[';
  first_.push_back(true);
  return *this;
}

JsonWriter& JsonWriter::endArray() {
  const bool empty = first_.back();
  first_.pop_back();
  if (!empty && static_cast<int>(first_.size()) < lineDepth_) newline();
  out_ += ']';
  return *this;
}

JsonWriter& JsonWriter::key(std::string_view name) {
  separate();
  writeString(name);
  out_ += ": ";
  afterKey_ = true;
  return *this;
}

JsonWriter& JsonWriter::value(double x) {
  separate();
  if (!std::isfinite(x)) {
    out_ += "null";  // never produced by the generator; keeps the file valid JSON regardless
    return *this;
  }
  if (x == 0.0) x = 0.0;  // no "-0"
  char buf[32];
  const auto result = std::to_chars(buf, buf + sizeof buf, x);
  out_.append(buf, result.ptr);
  return *this;
}

JsonWriter& JsonWriter::value(std::int64_t x) {
  separate();
  char buf[24];
  const auto result = std::to_chars(buf, buf + sizeof buf, x);
  out_.append(buf, result.ptr);
  return *this;
}

JsonWriter& JsonWriter::value(bool b) {
  separate();
  out_ += b ? "true" : "false";
  return *this;
}

JsonWriter& JsonWriter::value(std::string_view text) {
  separate();
  writeString(text);
  return *this;
}

void JsonWriter::writeString(std::string_view text) {
  out_ += '"';
  for (char c : text) {
    switch (c) {
      case '"': out_ += "\\\""; break;
      case '\\': out_ += "\\\\"; break;
      case '\n': out_ += "\\n"; break;
      case '\t': out_ += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char esc[8];
          std::snprintf(esc, sizeof esc, "\\u%04x", c);
          out_ += esc;
        } else {
          out_ += c;
        }
    }
  }
  out_ += '"';
}

JsonWriter& JsonWriter::vec3(double x, double y, double z) {
  separate();
  out_ += '[';
  first_.push_back(true);
  const int saved = lineDepth_;
  lineDepth_ = 0;
  value(x).value(y).value(z);
  lineDepth_ = saved;
  first_.pop_back();
  out_ += ']';
  return *this;
}

void JsonWriter::flushTo(std::ostream& out) {
  out.write(out_.data(), static_cast<std::streamsize>(out_.size()));
  out_.clear();
}

}  // namespace arbor
