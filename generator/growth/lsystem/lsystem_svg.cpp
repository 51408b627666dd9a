#include "lsystem_svg.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>

#include "common/input_error.hpp"

namespace arbor::lsys {

namespace {

constexpr const char* kColours[] = {"#5a3a1e", "#3f7f2a", "#6fae3c", "#a8c94a", "#c0392b", "#e1b12c", "#2c6fbb", "#8e44ad"};

}  // namespace

std::string writeTurtleSvg(const Interpretation& drawing, int pixels) {
  double x0 = std::numeric_limits<double>::max(), y0 = x0, x1 = -x0, y1 = -x0;
  const auto grow = [&](const Vec3& v) {
    x0 = std::min(x0, v.x), x1 = std::max(x1, v.x), y0 = std::min(y0, v.y), y1 = std::max(y1, v.y);
  };
  for (const TurtleSegment& s : drawing.drawing) grow(s.from), grow(s.to);
  for (const TurtlePolygon& p : drawing.polygons)
    for (const Vec3& v : p.vertices) grow(v);
  if (x0 > x1) x0 = y0 = 0, x1 = y1 = 1;
  const double margin = 10, extent = std::max({x1 - x0, y1 - y0, 1e-12});
  const double scale = (pixels - 2 * margin) / extent;
  const double width = (x1 - x0) * scale + 2 * margin, height = (y1 - y0) * scale + 2 * margin;
  char buffer[96];
  const auto point = [&](const Vec3& v) {  // y up: the picture's rows grow downward
    std::snprintf(buffer, sizeof buffer, "%.2f,%.2f", margin + (v.x - x0) * scale, height - margin - (v.y - y0) * scale);
    return std::string(buffer);
  };
  std::string out;
  std::snprintf(buffer, sizeof buffer, "%.0f\" height=\"%.0f\" viewBox=\"0 0 %.2f %.2f", width, height, width, height);
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::string(buffer) + "\">\n";
  // Segments that continue one another share one path (one per colour run).
  std::string path;
  Vec3 end(std::numeric_limits<double>::quiet_NaN());
  int colour = -1;
  const auto flush = [&] {
    if (path.empty()) return;
    out += "<path fill=\"none\" stroke=\"" + std::string(kColours[colour % 8]) + "\" stroke-width=\"1\" d=\"" + path + "\"/>\n";
    path.clear();
  };
  for (const TurtleSegment& s : drawing.drawing) {
    const int c = std::max(0, s.colour);
    if (c != colour || !(s.from == end)) {
      flush();
      colour = c;
      path = "M" + point(s.from);
    }
    path += " L" + point(s.to);
    end = s.to;
  }
  flush();
  for (const TurtlePolygon& p : drawing.polygons) {
    out += "<polygon fill=\"" + std::string(kColours[std::max(0, p.colour) % 8]) + "\" points=\"";
    for (std::size_t i = 0; i < p.vertices.size(); ++i) out += (i ? " " : "") + point(p.vertices[i]);
    out += "\"/>\n";
  }
  out += "</svg>\n";
  return out;
}

std::string writeLsystemSvg(const Lsystem& system, const DeriveOptions& options, int pixels) {
  if (system.susceptibility != 0 && system.tropism.y != 0)
    throw InputError(system.file, "tropism", "bends the turtle out of the drawing plane (T has a y component; the picture is the x-z plane): not a 2D grammar");
  const ModuleString str = derive(system, options);
  for (const Module& m : str.modules) {
    if (std::string_view("&^\\/$").find(m.symbol) != std::string_view::npos)
      throw InputError(system.file, "(drawing)",
                       std::string("the derived string turns out of the plane ('") + m.symbol + "'): only + - | turn a 2D drawing");
  }
  return writeTurtleSvg(interpret(str, planarTurtleSettings(system), true), pixels);
}

}  // namespace arbor::lsys
