#include "tide/surface/marching_cases.hpp"

#include <stdexcept>
#include <vector>

namespace tide::surface {
namespace {

constexpr std::array<std::array<int, 2>, 4> square_corners = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};

/// Segments of a square whose corners, counter-clockwise, are inside where `inside` says (the rule
/// of the header): each exit edge joins the first entry edge found walking backwards.
SquareCase square_segments(const std::array<bool, 4>& inside) {
  SquareCase result;
  for (int exit = 0; exit < 4; ++exit) {
    if (!inside[exit] || inside[(exit + 1) % 4]) continue;
    for (int step = 1; step < 4; ++step) {
      const int entry = (exit + 4 - step) % 4;
      if (!inside[entry] && inside[(entry + 1) % 4]) {
        result.segments[result.segment_count++] = {static_cast<std::uint8_t>(exit), static_cast<std::uint8_t>(entry)};
        break;
      }
    }
  }
  return result;
}

int corner_index(const std::array<int, 3>& offset) { return offset[0] | offset[1] << 1 | offset[2] << 2; }

/// The cube edge joining corners a and b, which differ along one axis.
int cube_edge_between(int a, int b) {
  const int start = a & b;
  const int axis = (a ^ b) == 1 ? 0 : (a ^ b) == 2 ? 1 : 2;
  // Edges along an axis are numbered by the start corner's two other coordinates, lower axis first.
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const int first = u < v ? u : v, second = u < v ? v : u;
  return axis * 4 + ((start >> first) & 1) + 2 * ((start >> second) & 1);
}

/// Corners of the cube face normal to `axis` at `side` (0 or 1), counter-clockwise seen from inside
/// the cube: (u, v) = the next two axes in cyclic order run counter-clockwise about +axis, which
/// points inwards on side 0; side 1 takes them in the other order.
std::array<int, 4> face_corners(int axis, int side) {
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  std::array<int, 4> corners{};
  for (int k = 0; k < 4; ++k) {
    const auto [a, b] = square_corners[side == 0 ? k : (4 - k) % 4];
    std::array<int, 3> offset{};
    offset[axis] = side;
    offset[u] = a;
    offset[v] = b;
    corners[k] = corner_index(offset);
  }
  return corners;
}

/// Whether cube edges a and b lie on a common face of the cube.
bool share_a_face(int a, int b) {
  const std::array<int, 3> origin_a = cube_edge_origin(a), origin_b = cube_edge_origin(b);
  for (int axis = 0; axis < 3; ++axis)
    if (axis != a / 4 && axis != b / 4 && origin_a[axis] == origin_b[axis]) return true;
  return false;
}

/// The loop vertex to fan from: one whose diagonals join no two crossings of a common face. A
/// loop crosses a face twice where the face is ambiguous; a diagonal across it would be built by
/// the cell on the face's other side too, and four triangles would share that edge.
std::size_t fan_apex(const std::vector<int>& loop) {
  const std::size_t n = loop.size();
  for (std::size_t apex = 0; apex < n; ++apex) {
    bool clear = true;
    for (std::size_t k = 2; k + 1 < n; ++k) clear = clear && !share_a_face(loop[apex], loop[(apex + k) % n]);
    if (clear) return apex;
  }
  throw std::logic_error("marching cubes: a loop has no fan without a diagonal along a face");
}

CubeCase cube_triangles(unsigned mask) {
  // next[e]: the edge at which the segment leaving edge e's crossing ends, -1 where none starts.
  std::array<int, 12> next;
  next.fill(-1);
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      const std::array<int, 4> corners = face_corners(axis, side);
      std::array<bool, 4> inside{};
      for (int k = 0; k < 4; ++k) inside[k] = (mask >> corners[k] & 1) != 0;
      const SquareCase face = square_segments(inside);
      for (int s = 0; s < face.segment_count; ++s) {
        const auto [from, to] = face.segments[s];
        const int from_edge = cube_edge_between(corners[from], corners[(from + 1) % 4]);
        const int to_edge = cube_edge_between(corners[to], corners[(to + 1) % 4]);
        if (next[from_edge] != -1) throw std::logic_error("marching cubes: two segments leave one edge");
        next[from_edge] = to_edge;
      }
    }
  }
  CubeCase result;
  std::array<bool, 12> visited{};
  for (int first = 0; first < 12; ++first) {
    if (next[first] == -1 || visited[first]) continue;
    std::vector<int> loop;
    for (int edge = first; !visited[edge]; edge = next[edge]) {
      if (next[edge] == -1) throw std::logic_error("marching cubes: a loop on the cube's faces is open");
      visited[edge] = true;
      loop.push_back(edge);
    }
    if (loop.front() != next[loop.back()]) throw std::logic_error("marching cubes: a loop on the cube does not close");
    const std::size_t n = loop.size(), apex = fan_apex(loop);
    for (std::size_t k = 1; k + 1 < n; ++k)
      result.triangles[result.triangle_count++] = {static_cast<std::uint8_t>(loop[apex]),
                                                   static_cast<std::uint8_t>(loop[(apex + k) % n]),
                                                   static_cast<std::uint8_t>(loop[(apex + k + 1) % n])};
  }
  return result;
}

template <class Case, std::size_t Count, class Make>
std::array<Case, Count> all_cases(Make make) {
  std::array<Case, Count> cases;
  for (unsigned mask = 0; mask < Count; ++mask) cases[mask] = make(mask);
  return cases;
}

}  // namespace

const SquareCase& square_case(unsigned corner_mask) {
  static const std::array<SquareCase, 16> cases = all_cases<SquareCase, 16>([](unsigned mask) {
    return square_segments({(mask & 1) != 0, (mask & 2) != 0, (mask & 4) != 0, (mask & 8) != 0});
  });
  return cases.at(corner_mask);
}

const CubeCase& cube_case(unsigned corner_mask) {
  static const std::array<CubeCase, 256> cases = all_cases<CubeCase, 256>(cube_triangles);
  return cases.at(corner_mask);
}

std::array<int, 2> square_corner(int corner) { return square_corners.at(corner); }

int square_edge_axis(int edge) { return edge % 2; }

std::array<int, 2> square_edge_origin(int edge) {
  const auto a = square_corners.at(edge), b = square_corners.at((edge + 1) % 4);
  return {a[0] < b[0] ? a[0] : b[0], a[1] < b[1] ? a[1] : b[1]};
}

std::array<int, 3> cube_edge_origin(int edge) {
  const int axis = edge / 4, bits = edge % 4;
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const int first = u < v ? u : v, second = u < v ? v : u;
  std::array<int, 3> origin{};
  origin[first] = bits & 1;
  origin[second] = bits >> 1;
  return origin;
}

}  // namespace tide::surface
