#include "god_finger/support/text_numbers.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace god_finger
{
bool parseDouble(const std::string& text, double* value)
{
  char* end = nullptr;
  const double parsed = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size())
  {
    return false;
  }
  *value = parsed;
  return true;
}

bool parseInteger(const std::string& text, long long* value)
{
  char* end = nullptr;
  const long long parsed = std::strtoll(text.c_str(), &end, 10);
  if (text.empty() || end != text.c_str() + text.size())
  {
    return false;
  }
  *value = parsed;
  return true;
}

std::string jsonNumber(double value)
{
  if (!std::isfinite(value))
  {
    return "null";
  }
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.9g", value);
  return buffer;
}

std::string roundedNumber(double value)
{
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.3g", value);
  return buffer;
}

double percentile(std::vector<double> values, double fraction)
{
  if (values.empty())
  {
    return 0.0;
  }
  const std::size_t index = std::min(values.size() - 1, static_cast<std::size_t>(fraction * (values.size() - 1) + 0.5));
  std::nth_element(values.begin(), values.begin() + index, values.end());
  return values[index];
}
}  // namespace god_finger
