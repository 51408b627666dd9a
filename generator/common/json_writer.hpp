#pragma once
// A small streaming JSON writer: shortest round-trip numbers, fixed key order, byte-identical output
// for identical input (a DOM is too slow for skeletons of a million values).
#include <cstdint>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

namespace arbor {

class JsonWriter {
 public:
  JsonWriter& beginObject();
  JsonWriter& endObject();
  JsonWriter& beginArray();
  JsonWriter& endArray();
  JsonWriter& key(std::string_view name);
  JsonWriter& value(double x);
  JsonWriter& value(std::int64_t x);
  JsonWriter& value(int x) { return value(static_cast<std::int64_t>(x)); }
  JsonWriter& value(std::string_view text);
  JsonWriter& value(const char* text) { return value(std::string_view(text)); }
  JsonWriter& value(bool b);
  JsonWriter& vec3(double x, double y, double z);  // [x, y, z] on one line

  template <class T>
  JsonWriter& field(std::string_view name, const T& v) {
    key(name);
    return value(v);
  }

  // Newlines only between the top-level fields and array elements of depth <= this.
  explicit JsonWriter(int lineDepth = 2) : lineDepth_(lineDepth) {}
  const std::string& str() const { return out_; }
  // Moves what is written so far to `out` (large documents are streamed, never held whole).
  void flushTo(std::ostream& out);
  std::size_t pending() const { return out_.size(); }

 private:
  void separate();
  void newline();
  void writeString(std::string_view text);
  std::string out_;
  std::vector<bool> first_;  // per open container: nothing written yet
  bool afterKey_ = false;
  int lineDepth_;
};

}  // namespace arbor
