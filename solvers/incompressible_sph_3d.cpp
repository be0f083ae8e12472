#include "incompressible_sph_members.hpp"

namespace tide {

template class IncompressibleSph<3>;

}  // namespace tide
