#include "wcsph_members.hpp"

namespace tide {

template class Wcsph<3>;

}  // namespace tide
