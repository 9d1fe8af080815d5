// One table per parameter set: each row is a parameter's name, unit, allowed range, one-line
// meaning and where it lives in its struct. The struct's member initialiser is the one default
// (a row reads it from a default-constructed struct). Everything that touches parameters is
// built from the tables: validation, reading from a ParameterSource (ROS or a map), the CLI
// flags, the JSON output (parameter_json.h), the README's tables and dynamic_reconfigure
// (test/physics/parameter_tables_test checks the README and the cfg against the tables).
// Adding a parameter is its struct member and one row.
//
// Not real-time: reading and printing allocate. Names are as ROS, JSON and the cfg spell them;
// the CLI flag is "--" + the name with '_' as '-'.
#pragma once

#include "god_finger/support/parameter_source.h"

#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace god_finger
{
// [low, high], either end open; an end may be infinite.
struct ParameterRange
{
  double low = -INFINITY;
  double high = INFINITY;
  bool low_open = false;
  bool high_open = false;

  bool contains(double value) const
  {
    return (low_open ? value > low : value >= low) && (high_open ? value < high : value <= high);
  }
  // "(0, 1000]", "[1, 100]", "[0, inf]".
  std::string text() const;
};

ParameterRange closed(double low, double high);
ParameterRange openClosed(double low, double high);

// One command-line value, named by its flag in messages ("parameter '--r-max' ...").
class FlagParameterSource : public ParameterSource
{
 public:
  FlagParameterSource(std::string name, ParameterValue value) : name_(std::move(name)), value_(std::move(value)) {}
  bool get(const std::string& name, ParameterValue* value) const override;
  std::string fullName(const std::string& name) const override;

 private:
  std::string name_;
  ParameterValue value_;
};

// Helpers of the templates below.
std::string formatNumber(double value);  // shortest text that reads back exactly; "inf"
double readNumber(const ParameterSource& source, const std::string& name, double fallback, const ParameterRange& range,
                  const std::string& unit, bool whole = false);
[[noreturn]] void throwNotAChoice(const ParameterSource& source, const std::string& name, const std::string& text,
                                  const std::string& choices);
std::string flagOf(const std::string& name);
ParameterValue parseValueText(const std::string& text);
std::string usageLine(const std::string& flag, const std::string& unit, const std::string& meaning,
                      const std::string& default_text);

template <typename Params>
struct ParameterRow
{
  enum class Kind
  {
    kReal,
    kInteger,
    kChoice
  };
  Kind kind = Kind::kReal;
  const char* name = "";
  const char* unit = "";  // "m", "N/m", "dimensionless", "count", "" for a choice
  ParameterRange range;   // for kReal and kInteger
  // The range a running node accepts (dynamic_reconfigure): `range` unless the row narrows it
  // (withLiveRange). A live value in `range` but outside it is clamped, and the clamp reported.
  ParameterRange live;
  bool has_live = false;
  const char* meaning = "";
  std::function<double&(Params&)> real;
  std::function<int&(Params&)> integer;
  // kChoice: the value's name, and setting it from a name (false for an unknown one).
  std::function<std::string(const Params&)> choice_name;
  std::function<bool(Params*, const std::string&)> choose;
  std::string choices;  // "project, unfold"

  // The value in `params` as text: "0.01", "8", "unfold", "inf".
  std::string valueText(const Params& params) const;
  // The default: the struct's own member initialiser.
  std::string defaultText() const
  {
    return valueText(Params{});
  }
  const ParameterRange& liveRange() const
  {
    return has_live ? live : range;
  }
  double number(const Params& params) const
  {
    Params copy = params;
    return kind == Kind::kReal ? real(copy) : static_cast<double>(integer(copy));
  }
};

template <typename Params>
ParameterRow<Params> realRow(const char* name, const char* unit, ParameterRange range, const char* meaning,
                             std::function<double&(Params&)> member)
{
  ParameterRow<Params> row;
  row.kind = ParameterRow<Params>::Kind::kReal;
  row.name = name;
  row.unit = unit;
  row.range = range;
  row.meaning = meaning;
  row.real = member;
  return row;
}

template <typename Params>
ParameterRow<Params> integerRow(const char* name, ParameterRange range, const char* meaning,
                                std::function<int&(Params&)> member)
{
  ParameterRow<Params> row;
  row.kind = ParameterRow<Params>::Kind::kInteger;
  row.name = name;
  row.unit = "count";
  row.range = range;
  row.meaning = meaning;
  row.integer = member;
  return row;
}

template <typename Params>
ParameterRow<Params> choiceRow(const char* name, const std::string& choices, const char* meaning,
                               std::function<std::string(const Params&)> choice_name,
                               std::function<bool(Params*, const std::string&)> choose)
{
  ParameterRow<Params> row;
  row.kind = ParameterRow<Params>::Kind::kChoice;
  row.name = name;
  row.choices = choices;
  row.meaning = meaning;
  row.choice_name = choice_name;
  row.choose = choose;
  return row;
}

// `row` with a live range narrower than its range (closed, inside the range).
template <typename Params>
ParameterRow<Params> withLiveRange(ParameterRow<Params> row, ParameterRange live)
{
  row.live = live;
  row.has_live = true;
  return row;
}

template <typename Params>
using ParameterTable = std::vector<ParameterRow<Params>>;

// A live value of `row`: in its range but outside its live range, it is clamped to the nearer
// end of the live range and `note` says so ("parameter 'r_max' = 1 is outside the live range
// [0.0005, 0.05]: clamped to 0.05"); any other value is returned as it is (the range check
// refuses what lies outside the range).
template <typename Params>
double clampToLive(const ParameterRow<Params>& row, double value, std::string* note)
{
  const ParameterRange& live = row.liveRange();
  if (!row.has_live || !row.range.contains(value) || live.contains(value))
  {
    return value;
  }
  const double clamped = value < live.low ? live.low : live.high;
  *note = "parameter '" + std::string(row.name) + "' = " + formatNumber(value) + " is outside the live range " +
          live.text() + ": clamped to " + formatNumber(clamped);
  return clamped;
}

// `table`'s rows as rows of `Outer`, which holds a `Params` reached through `part` (a device
// profile's coupling, the world's contact parameters): the inner table stays the one definition.
template <typename Outer, typename Params>
ParameterTable<Outer> liftRows(const ParameterTable<Params>& table, Params& (*part)(Outer&))
{
  ParameterTable<Outer> lifted;
  for (const ParameterRow<Params>& row : table)
  {
    ParameterRow<Outer> outer;
    outer.kind = static_cast<typename ParameterRow<Outer>::Kind>(row.kind);
    outer.name = row.name;
    outer.unit = row.unit;
    outer.range = row.range;
    outer.live = row.live;
    outer.has_live = row.has_live;
    outer.meaning = row.meaning;
    outer.choices = row.choices;
    if (row.real)
    {
      outer.real = [row, part](Outer& o) -> double& { return row.real(part(o)); };
    }
    if (row.integer)
    {
      outer.integer = [row, part](Outer& o) -> int& { return row.integer(part(o)); };
    }
    if (row.choice_name)
    {
      outer.choice_name = [row, part](const Outer& o) { return row.choice_name(part(const_cast<Outer&>(o))); };
      outer.choose = [row, part](Outer* o, const std::string& text) { return row.choose(&part(*o), text); };
    }
    lifted.push_back(outer);
  }
  return lifted;
}

// The row's value as a parameter value (what a ParameterSource would hold for it).
template <typename Params>
ParameterValue valueOf(const ParameterRow<Params>& row, const Params& params)
{
  switch (row.kind)
  {
    case ParameterRow<Params>::Kind::kReal:
      return ParameterValue::of(row.number(params));
    case ParameterRow<Params>::Kind::kInteger:
      return ParameterValue::ofInteger(static_cast<int>(row.number(params)));
    case ParameterRow<Params>::Kind::kChoice:
      break;
  }
  return ParameterValue::of(row.choice_name(params));
}

template <typename Params>
std::string ParameterRow<Params>::valueText(const Params& params) const
{
  if (kind == Kind::kChoice)
  {
    return choice_name(params);
  }
  return formatNumber(number(params));
}

// "" when every row's value is in its range (NaN never is) and every choice row's value is one
// of its choices (its name reads back); else one line for the first that is not.
template <typename Params>
std::string validateRows(const ParameterTable<Params>& table, const Params& params)
{
  for (const ParameterRow<Params>& row : table)
  {
    if (row.kind == ParameterRow<Params>::Kind::kChoice)
    {
      Params chosen = params;
      const std::string name = row.choice_name(params);
      if (!row.choose(&chosen, name))
      {
        return "parameter '" + std::string(row.name) + "' = '" + name + "' is not one of " + row.choices;
      }
      continue;
    }
    if (!row.range.contains(row.number(params)))
    {
      return "parameter '" + std::string(row.name) + "' = " + formatNumber(row.number(params)) + " is out of range " +
             row.range.text() + " (" + row.unit + ")";
    }
  }
  return std::string();
}

// Reads every row that `source` sets into `params` (unset ones keep their value) and checks its
// type, range or choice: InputError naming the parameter's full name otherwise.
template <typename Params>
void readRows(const ParameterSource& source, const ParameterTable<Params>& table, Params* params)
{
  for (const ParameterRow<Params>& row : table)
  {
    switch (row.kind)
    {
      case ParameterRow<Params>::Kind::kReal:
        row.real(*params) = readNumber(source, row.name, row.real(*params), row.range, row.unit);
        break;
      case ParameterRow<Params>::Kind::kInteger:
        row.integer(*params) = static_cast<int>(readNumber(source, row.name, row.integer(*params), row.range, row.unit,
                                                           /*whole=*/true));
        break;
      case ParameterRow<Params>::Kind::kChoice:
      {
        const std::string text = readString(source, row.name, row.choice_name(*params));
        if (!row.choose(params, text))
        {
          throwNotAChoice(source, row.name, text, row.choices);
        }
        break;
      }
    }
  }
}

// Sets one row from command-line text ("--n-sgo", "12"); false when `flag` is no row's.
// InputError for text that is not a value of the row (the range is checked by validateRows).
template <typename Params>
bool parseFlag(const ParameterTable<Params>& table, const std::string& flag, const std::string& text, Params* params)
{
  for (const ParameterRow<Params>& row : table)
  {
    if (flag == flagOf(row.name))
    {
      const FlagParameterSource source(row.name, parseValueText(text));
      readRows(source, ParameterTable<Params>{row}, params);
      return true;
    }
  }
  return false;
}

// Usage lines: "  --r-max M   maximum contact radius (m) ..." one per row.
template <typename Params>
std::string usageLines(const ParameterTable<Params>& table)
{
  std::string text;
  for (const ParameterRow<Params>& row : table)
  {
    text += usageLine(flagOf(row.name), row.kind == ParameterRow<Params>::Kind::kChoice ? row.choices : row.unit,
                      row.meaning, row.defaultText());
  }
  return text;
}

// The README's table: | name | unit | default | range | meaning |.
template <typename Params>
std::string markdownTable(const ParameterTable<Params>& table)
{
  std::string text = "| parameter | unit | default | range | meaning |\n|---|---|---|---|---|\n";
  for (const ParameterRow<Params>& row : table)
  {
    const bool choice = row.kind == ParameterRow<Params>::Kind::kChoice;
    text += "| `" + std::string(row.name) + "` | " + (choice ? "" : row.unit) + " | " + row.defaultText() + " | " +
            (choice ? row.choices : row.range.text()) + " | " + row.meaning + " |\n";
  }
  return text;
}

}  // namespace god_finger
