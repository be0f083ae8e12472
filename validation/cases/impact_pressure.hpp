#pragma once

// The downstream-wall pressure of a dam break against Buchner's 2002 measurement in the
// Colagrossi–Landrini geometry (column H high and 2H long, tank 5.366H long, probe on the far
// wall at 0.2H), in the scaling that makes it independent of H: τ = t sqrt(g/H), p/(ρ g H).
// Shared by the 2D case and the 3D Lobovsky case, whose tank has the same proportions.

#include <string>
#include <vector>

#include "tide/solvers/front_offset_fit.hpp"
#include "tide/solvers/simulation.hpp"
#include "tide/validation/case.hpp"

namespace tide::validation {

/// τ range of the comparison (see buchner_metric_notes for why).
inline constexpr double impact_window_start = 2.0;
inline constexpr double impact_window_end = 5.3;

/// Width in τ of the centred moving average applied to a simulated probe history.
inline constexpr double impact_filter_width = 0.1;

/// A probe history (x = τ, y = p/(ρ g H), sampled every step) averaged over a centred window of
/// `width` in τ.
Curve moving_average(const Curve& history, double width);

/// first_peak_error, first_peak_time_error, impact_time_error and pressure_l2_error of a probe
/// history (sampled every step) filtered by moving_average over impact_filter_width, against
/// validation/data/buchner_2002_pressure_probe.csv, and plateau_spread of the raw history.
std::vector<Metric> buchner_metrics(const Curve& history);

/// Steps `simulation` (column height `height`) until τ = impact_window_end + 0.2, reading the
/// pressure probe at `probe` after every step, and returns the run's record with the
/// buchner_metrics of the filtered history.
template <int D>
RunRecord run_against_buchner(const std::string& case_name, const Variant& variant, int resolution,
                              Simulation<D>& simulation, const Vector<D>& probe, double height);

/// One line per metric of buchner_metrics, for Case::metric_notes.
std::vector<std::string> buchner_metric_notes();

}  // namespace tide::validation
