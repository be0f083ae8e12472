#pragma once

// The case tables of marching squares (2D) and marching cubes (3D), generated rather than typed:
// one rule for a square, applied to a 2D cell and to each face of a cube, decides every case, so
// two cells that share a face always cut it the same way and the surface has no cracks.
//
// The rule on a square whose corners are listed counter-clockwise: an edge whose corners are on
// different sides of the iso-level is crossed; a segment leaves the inside region where walking
// the border counter-clockwise goes from an inside corner to an outside one ("exit") and joins the
// nearest entry going backwards round the square. With two crossings that is the only pairing;
// with four (the ambiguous saddle, inside corners on a diagonal) each inside corner is cut off on
// its own, so inside corners never connect across a face (Lorensen & Cline 1987's cases with the
// face ambiguity always resolved towards separated inside corners, as Nielson & Hamann 1991
// discuss). Segments run with the inside on their left.
//
// A cube's cases are the loops its six faces' segments form (each face listed counter-clockwise
// seen from inside the cube, so the segments run clockwise round the inside seen from outside),
// each loop split into a fan of triangles whose normals point out of the inside region.

#include <array>
#include <cstdint>

namespace tide::surface {

/// Corners of a square cell, counter-clockwise: (0,0), (1,0), (1,1), (0,1). Edge i joins corners
/// i and i + 1 (mod 4). Bit i of a corner mask is set where corner i is inside.
struct SquareCase {
  int segment_count = 0;
  /// Directed (from edge, to edge): the inside is on the segment's left.
  std::array<std::array<std::uint8_t, 2>, 2> segments{};
};

/// Corners of a cube cell: corner c is at (c & 1, c >> 1 & 1, c >> 2 & 1). Edge e runs along axis
/// e / 4 from cube_edge_start(e). Bit c of a corner mask is set where corner c is inside.
struct CubeCase {
  int triangle_count = 0;
  /// Edges whose crossings are the triangle's corners, counter-clockwise seen from outside.
  std::array<std::array<std::uint8_t, 3>, 12> triangles{};
};

/// The segments of a square cell whose inside corners are `corner_mask` (0..15).
const SquareCase& square_case(unsigned corner_mask);

/// The triangles of a cube cell whose inside corners are `corner_mask` (0..255).
const CubeCase& cube_case(unsigned corner_mask);

/// Offset of square corner `corner` (0..3) in the cell.
std::array<int, 2> square_corner(int corner);

/// Square edge `edge` (0..3) runs along axis square_edge_axis(edge) (edges 0 and 2 along x, 1 and
/// 3 along y) from its end nearer the origin, square_edge_origin(edge).
int square_edge_axis(int edge);
std::array<int, 2> square_edge_origin(int edge);

/// Cube edge `edge` (0..11) runs along axis edge / 4 from its end nearer the origin,
/// cube_edge_origin(edge).
std::array<int, 3> cube_edge_origin(int edge);

}  // namespace tide::surface
