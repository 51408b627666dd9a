#pragma once
// Wavefront OBJ for artists' tools: the quad mesh as it is, object space in metres, y up as Blender, Maya and
// most engines import OBJ (z up on request, the project's own axes).
// A mesh vertex carries one position, one texture coordinate and one normal, so every face corner is "i/i/i";
// cards share texture coordinates and normals between corners.
#include <cstdint>
#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <string_view>

#include "mesh/quad_mesh.hpp"
#include "tree_asset.hpp"

namespace arbor {

// `v x y z`, `vt u v` (the flip coordinate w has no place in OBJ), `vn x y z`, then one `f` per quad,
// or two per quad split by arbor::triangulate when `triangles` is set. Numbers are written in the
// shortest form that reads back as the same float. Needs positions, uvw and normals for every vertex;
// throws std::invalid_argument otherwise.
// Up::Y turns the tree (z up inside Arbor) to y up: (x, y, z) -> (x, z, -y), a rotation, so windings and
// normals stay outward; the header says which.
enum class Up { Y, Z };
std::string writeObj(const QuadMesh& mesh, bool triangles, Up up = Up::Y);
// The same, streamed a megabyte at a time (a tree's OBJ is tens of megabytes).
void writeObj(const QuadMesh& mesh, bool triangles, std::ostream& out, Up up = Up::Y);

// The same with `mtllib mtlFile` and `usemtl bark` before the faces (no statements when mtlFile is empty).
void writeObj(const QuadMesh& mesh, bool triangles, std::ostream& out, Up up, const std::string& mtlFile);

// The objects cards are written as; readers of the tree's surface stop where the first of them begins.
inline bool isObjCardObject(std::string_view name) { return name == "branch_cards" || name == "leaves"; }

// How many v, vt and vn lines an OBJ file holds so far: the next part's indices count on from them.
struct ObjCounts {
  std::uint64_t v = 0, vt = 0, vn = 0;
};

// Cards after a mesh in the same file: `o object`, `usemtl material` (unless empty), their v lines, each distinct
// vt and vn once (a card's corners share its normal, leaves share their atlas cell's corners), and one quad per
// card, numbered after `before`, which then counts the cards' lines too. Each card has four corners of its own
// (quad i: 4i to 4i + 3) with one normal, as leafCards and branchCards make them; other cards are refused
// (std::invalid_argument).
void writeObjCards(const CardMesh& cards, const std::string& object, const std::string& material, ObjCounts& before,
                   std::ostream& out, Up up = Up::Y);

// A tree asset's finest level as one file: writeObj's bark (with mtlFile), then the cards of branchCards(branchSegments)
// and of leafCards(leaves) as writeObjCards writes them, objects `branch_cards` and `leaves` (materials of the same
// names when mtlFile is set; empty ones are left out): the same text as those calls in turn, printed in one pass on
// every core, each card made as it is printed instead of all held at once.
void writeObjAsset(const QuadMesh& bark, const std::vector<ImpostorSegment>& branchSegments, const std::vector<Leaf>& leaves,
                   bool triangles, std::ostream& out, Up up, const std::string& mtlFile);

// The leaves' numbering and the first of their lines that depend on nothing before them in the file (v, vt, vn),
// printed ahead a block at a time until enough() says so: the tree file writer prints them on another core while the bark is meshed.
// The leaves must outlive the writing (it prints the lines not printed ahead).
struct ObjLeafLines;
std::shared_ptr<const ObjLeafLines> printObjLeafLines(const std::vector<Leaf>& leaves, Up up, const std::function<bool()>& enough);
// writeObjAsset with those lines (the same text); lines printed for the other up axis are refused (std::invalid_argument).
void writeObjAsset(const QuadMesh& bark, const std::vector<ImpostorSegment>& branchSegments, const ObjLeafLines& leaves,
                   bool triangles, std::ostream& out, Up up, const std::string& mtlFile);
// The .mtl for an OBJ of a tree asset: materials bark, branch_cards and leaves (alpha from the atlas), naming the
// PNG files given (relative to the .mtl). Blender reads map_Bump as the normal map.
std::string writeMtl(const std::string& barkColor, const std::string& barkNormal, const std::string& leafAtlas);

// Reads what writeObj writes: v, vt, vn and f lines with 1-based "a/a/a" corners; comments, o, g, s,
// mtllib and usemtl are skipped, and `o branch_cards` or `o leaves` ends the mesh (the cards that
// follow the tree's surface are not part of it). Triangles must come in the consecutive pairs writeObj emits, and each
// pair is joined back into its quad (QuadMesh holds quads only). The result has positions, normals,
// uvw (w = 0) and quads; tangents, radius, level and openBoundary are not in OBJ and stay empty. A file
// whose Arbor header says "y up" is turned back to z up.
// Throws std::runtime_error naming `file` and the line on anything else.
QuadMesh readObj(const std::string& text, const std::string& file);

}  // namespace arbor
