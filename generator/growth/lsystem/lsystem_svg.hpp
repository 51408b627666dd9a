#pragma once
// A 2D drawing of an L-system whose turns are all about U (ABOP ch. 1's figures): the turtle's segments as
// SVG paths and its polygons filled, scaled to fit, y up.
#include <string>

#include "derivation.hpp"
#include "turtle.hpp"

namespace arbor::lsys {

// Derives and draws with H = +y, L = -x in the picture's plane. Throws InputError when the derived string
// turns out of the plane ('&', '^', '\', '/', '$') or tropism bends it out.
std::string writeLsystemSvg(const Lsystem& system, const DeriveOptions& options = {}, int pixels = 800);

// An interpretation recorded with its drawing, as SVG (x right, y up, fit into pixels x pixels).
std::string writeTurtleSvg(const Interpretation& drawing, int pixels = 800);

}  // namespace arbor::lsys
