// Small helpers for the command-line tools and their JSON output: strict number parsing,
// JSON numbers, percentiles. No allocation beyond the returned strings.
#pragma once

#include <string>
#include <vector>

namespace god_finger
{
// The whole of `text` as a number; false (value untouched) on anything else.
bool parseDouble(const std::string& text, double* value);
bool parseInteger(const std::string& text, long long* value);
// A number as JSON with 9 significant digits; non-finite values become null.
std::string jsonNumber(double value);
// A number for a message, with 3 significant digits ("0.000123", "1.5e+09", "nan").
std::string roundedNumber(double value);
// Nearest-rank percentile, fraction in [0, 1]; 0 for no values. Takes a copy (reorders it).
double percentile(std::vector<double> values, double fraction);
}  // namespace god_finger
