// Embeds TideSPH through its installed CMake package: fills a cube of water with a particle
// lattice and checks its mass and centroid against the values the geometry implies, then runs a
// checkpoint round trip (checkpoint_round_trip.cpp).

#include <cstddef>
#include <cstdio>
#include <functional>

#include "checkpoint_round_trip.hpp"
#include "tide/core/config.hpp"
#include "tide/core/parallel.hpp"
#include "tide/core/particle_set.hpp"
#include "tide/core/types.hpp"

namespace {

using tide::Real;
using Vector3 = tide::Vector<3>;

// The spacing is a power of two, so every position, mass and partial sum below is exact in
// float and in double: the results must equal the expected values exactly, in either precision
// and for any thread count. 20^3 particles make two blocks of tide::reduce.
constexpr std::size_t per_side = 20;
constexpr Real spacing = Real(1) / 16;  // m
constexpr Real side = per_side * spacing;
constexpr Real rest_density = 1000;  // kg/m^3, water

}  // namespace

int main() {
  tide::ParticleSet<3> particles;
  particles.append(per_side * per_side * per_side);
  const tide::ScalarField mass_field = particles.add_scalar("mass");
  const tide::VectorView<3> position = particles[particles.position()];
  const auto mass = particles[mass_field];

  // Particle i sits at the centre of lattice cell (i mod n, i / n mod n, i / n^2).
  tide::for_each_particle(particles.size(), [&](std::size_t i) {
    const Vector3 cell(Real(i % per_side), Real(i / per_side % per_side), Real(i / (per_side * per_side)));
    position.set(i, (cell + Vector3::Constant(Real(0.5))) * spacing);
    mass[i] = rest_density * spacing * spacing * spacing;
  });

  const Real total_mass = tide::reduce(
      particles.size(), Real(0), [&](std::size_t i) { return mass[i]; }, std::plus<Real>());
  const Vector3 centroid = tide::reduce(
                               particles.size(), Vector3(Vector3::Zero()), [&](std::size_t i) { return position[i]; },
                               [](const Vector3& a, const Vector3& b) -> Vector3 { return a + b; }) /
                           Real(particles.size());

  const Real expected_mass = rest_density * side * side * side;
  const Vector3 expected_centroid = Vector3::Constant(side / 2);
  std::printf("TideSPH %s (Real = %s, %d threads): %zu particles in a %g m cube of water\n", TIDE_VERSION,
              TIDE_REAL_NAME, tide::thread_count(), particles.size(), double(side));
  std::printf("  mass      %.9g kg (expected %.9g)\n", double(total_mass), double(expected_mass));
  std::printf("  centroid  (%.9g, %.9g, %.9g) m (expected %.9g on each axis)\n", double(centroid.x()),
              double(centroid.y()), double(centroid.z()), double(expected_centroid.x()));

  const bool lattice_ok = total_mass == expected_mass && centroid == expected_centroid;
  if (!lattice_ok) std::printf("MISMATCH: the installed TideSPH computes a wrong mass or centroid\n");
  const bool resume_ok = checkpoint_round_trip();
  if (!resume_ok) std::printf("MISMATCH: a run resumed from its checkpoint differs from the straight run\n");
  if (lattice_ok && resume_ok) std::printf("OK\n");
  return lattice_ok && resume_ok ? 0 : 1;
}
