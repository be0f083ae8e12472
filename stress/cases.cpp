#include <algorithm>

#include "cases/case_support.hpp"
#include "tide/stress/case.hpp"

namespace tide::stress {

std::string Bound::text() const { return (kind == Kind::below ? "< " : "> ") + format_number(limit); }

std::string Row::outcome() const {
  if (!failure.empty()) return "FAIL: " + failure;
  if (passed()) return expect_pass ? "pass" : "PASS (expected to fail)";
  return expect_pass ? "FAIL" : "fail (as expected)";
}

const std::vector<Case>& cases() {
  static const std::vector<Case> all{long_rest_case(), tension_case(),   violent_impact_case(),
                                     extremes_case(),  time_step_case(), conservation_case()};
  return all;
}

const Case* find_case(std::string_view name) {
  const auto& all = cases();
  const auto found = std::find_if(all.begin(), all.end(), [&](const Case& c) { return c.name == name; });
  return found == all.end() ? nullptr : &*found;
}

}  // namespace tide::stress
