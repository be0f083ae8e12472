#pragma once

// One row of comma-separated numbers, for the CSV files TideSPH reads (motion tables, series).

#include <cstddef>
#include <string_view>
#include <vector>

namespace tide::io {

/// The numbers of `row` (blanks around each allowed); std::invalid_argument "line L: expected a
/// number, got "x"" (or "a finite number" when `finite`) at the first field that is not one.
std::vector<double> csv_numbers(std::string_view row, std::size_t line, bool finite);

}  // namespace tide::io
