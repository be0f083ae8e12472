#include "wcsph_members.hpp"

namespace tide {

template class Wcsph<2>;

}  // namespace tide
