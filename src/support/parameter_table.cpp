#include "god_finger/support/parameter_table.h"

#include "god_finger/support/input_error.h"

#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>

namespace god_finger
{
ParameterRange closed(double low, double high)
{
  return ParameterRange{low, high, false, false};
}

ParameterRange openClosed(double low, double high)
{
  return ParameterRange{low, high, true, false};
}

std::string formatNumber(double value)
{
  if (std::isinf(value))
  {
    return value > 0 ? "inf" : "-inf";
  }
  // The shortest of %.{1..17}g that reads back as the same double, written out in full when
  // that takes at most 8 characters ("1000000", "0.001", but "1e-05", "3.141592653589793").
  std::string best;
  std::string plain;
  char text[32];
  for (int digits = 1; digits <= 17; ++digits)
  {
    std::snprintf(text, sizeof(text), "%.*g", digits, value);
    if (!(std::strtod(text, nullptr) == value || std::isnan(value)))
    {
      continue;
    }
    const std::size_t length = std::strlen(text);
    if (best.empty() || length < best.size())
    {
      best = text;
    }
    if (plain.empty() && std::strchr(text, 'e') == nullptr)
    {
      plain = text;
    }
  }
  return !plain.empty() && plain.size() <= 8 ? plain : best;
}

std::string ParameterRange::text() const
{
  const auto bound = [](double value) { return value == M_PI ? std::string("pi") : formatNumber(value); };
  return std::string(low_open ? "(" : "[") + bound(low) + ", " + bound(high) + (high_open ? ")" : "]");
}

double readNumber(const ParameterSource& source, const std::string& name, double fallback, const ParameterRange& range,
                  const std::string& unit, bool whole)
{
  ParameterValue value;
  double number = fallback;
  if (source.get(name, &value))
  {
    const bool numeric =
        value.kind == ParameterValue::Kind::kInteger || (!whole && value.kind == ParameterValue::Kind::kNumber);
    if (!numeric)
    {
      throw InputError("parameter '" + source.fullName(name) + "' must be " +
                       (whole ? std::string("an integer") : "a number (" + unit + ")"));
    }
    number = value.number;
  }
  if (!range.contains(number))
  {
    throw InputError("parameter '" + source.fullName(name) + "' = " + formatNumber(number) + " is out of range " +
                     range.text() + " (" + unit + ")");
  }
  return number;
}

void throwNotAChoice(const ParameterSource& source, const std::string& name, const std::string& text,
                     const std::string& choices)
{
  throw InputError("parameter '" + source.fullName(name) + "' = '" + text + "' is not one of " + choices);
}

bool FlagParameterSource::get(const std::string& name, ParameterValue* value) const
{
  if (name != name_)
  {
    return false;
  }
  *value = value_;
  return true;
}

std::string FlagParameterSource::fullName(const std::string& name) const
{
  return flagOf(name);
}

std::string flagOf(const std::string& name)
{
  std::string flag = "--" + name;
  for (char& c : flag)
  {
    c = c == '_' ? '-' : c;
  }
  return flag;
}

ParameterValue parseValueText(const std::string& text)
{
  long long integer = 0;
  const auto [integer_end, integer_error] = std::from_chars(text.data(), text.data() + text.size(), integer);
  if (integer_error == std::errc() && integer_end == text.data() + text.size() && integer >= INT32_MIN &&
      integer <= INT32_MAX)
  {
    return ParameterValue::ofInteger(static_cast<int>(integer));
  }
  if (text == "inf")
  {
    return ParameterValue::of(INFINITY);
  }
  double number = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), number);
  if (error == std::errc() && end == text.data() + text.size() && !text.empty())
  {
    return ParameterValue::of(number);
  }
  return ParameterValue::of(text);
}

std::string usageLine(const std::string& flag, const std::string& unit, const std::string& meaning,
                      const std::string& default_text)
{
  std::ostringstream line;
  line << "  " << flag << " " << (unit.empty() ? "VALUE" : unit);
  const std::string head = line.str();
  return head + std::string(head.size() < 28 ? 28 - head.size() : 1, ' ') + meaning + " (default " + default_text +
         ")\n";
}
}  // namespace god_finger
