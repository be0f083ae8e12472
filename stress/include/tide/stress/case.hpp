#pragma once

// A stress case: scenes built to push WCSPH to the edges where SPH is known to fail (long runs,
// tension, violent impacts, extreme parameters, too large a time step) and the measured outcome
// of each, against a stated bound. The registry (cases()) is what `tide stress` runs and what
// the stress tests run in their short form.

#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tide::stress {

/// How long a case runs: its full form (the table in docs/stability.md) or a short one (ctest).
enum class Length { full, short_run };

/// What a metric must satisfy: value < limit (below) or value > limit (above).
struct Bound {
  enum class Kind { below, above };
  Kind kind = Kind::below;
  double limit = 0;

  bool holds(double value) const { return kind == Kind::below ? value < limit : value > limit; }
  std::string text() const;  // "< 0.01", "> 0.5"
};

inline Bound below(double limit) { return {Bound::Kind::below, limit}; }
inline Bound above(double limit) { return {Bound::Kind::above, limit}; }

/// One row of the stress table: one run of one case, its metric and the bound it is held to.
struct Row {
  Row(std::string case_name_, std::string settings_, std::string metric_, Bound bound_, bool expect_pass_ = true)
      : case_name(std::move(case_name_)),
        settings(std::move(settings_)),
        metric(std::move(metric_)),
        bound(bound_),
        expect_pass(expect_pass_) {}

  std::string case_name;    // e.g. "tension"
  std::string settings;     // what is varied in this run, e.g. "artificial stress ε = 0.2"
  std::string metric;       // e.g. "close_pair_fraction"
  double value = 0;         // the metric measured (NaN when the run failed before it)
  Bound bound;              // what the metric must satisfy
  bool expect_pass = true;  // false for a run that shows a failure mode (it must fail its bound)
  std::string failure;      // empty unless the run stopped with an error, e.g. an instability
  std::string note;         // what else the run showed: binding time-step limits, the report it gave
  double simulated_seconds = 0;
  double wall_seconds = 0;

  bool passed() const { return failure.empty() && bound.holds(value); }
  /// The row behaves as the case says it should: passes its bound, or fails it on purpose.
  bool as_expected() const { return passed() == expect_pass; }
  /// "pass", "fail (expected)", "FAIL", "FAIL: <error>", ...
  std::string outcome() const;
};

struct Case {
  std::string name;         // command-line name, e.g. "long_rest"
  std::string title;        // one line: the scene and what it stresses
  std::string metric_note;  // how its metrics are defined and why the bound is what it is
  std::function<std::vector<Row>(Length)> run;
};

/// Every stress case, in the order the suite runs and documents them.
const std::vector<Case>& cases();

/// The case called `name`, or nullptr.
const Case* find_case(std::string_view name);

}  // namespace tide::stress
