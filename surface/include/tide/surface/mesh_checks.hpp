#pragma once

// What makes a reconstructed surface usable: closed, consistently oriented, of the expected
// topology (Euler characteristic) and size (area; the volume is io::signed_volume).

#include <cstddef>

#include "tide/core/triangle_mesh.hpp"

namespace tide::surface {

struct MeshTopology {
  std::size_t vertices = 0;
  std::size_t edges = 0;
  std::size_t triangles = 0;
  /// Edges of one triangle only: holes.
  std::size_t open_edges = 0;
  /// Edges of more than two triangles: not a 2-manifold.
  std::size_t crowded_edges = 0;
  /// Edges of two triangles that walk them the same way: the orientation flips there.
  std::size_t misoriented_edges = 0;

  bool closed_and_oriented() const { return open_edges == 0 && crowded_edges == 0 && misoriented_edges == 0; }
  /// V − E + F: 2 per closed surface of genus 0 (a sphere), 2 − 2g for g handles.
  long long euler_characteristic() const {
    return static_cast<long long>(vertices) - static_cast<long long>(edges) + static_cast<long long>(triangles);
  }
};

MeshTopology mesh_topology(const scene::TriangleMesh& mesh);

/// Σ |(b − a) × (c − a)| / 2 over the triangles.
double surface_area(const scene::TriangleMesh& mesh);

}  // namespace tide::surface
