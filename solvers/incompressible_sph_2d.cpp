#include "incompressible_sph_members.hpp"

namespace tide {

template class IncompressibleSph<2>;

}  // namespace tide
