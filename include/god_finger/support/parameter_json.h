// The package's JSON output goes through nlohmann-json (strings escaped, numbers valid JSON):
// the type, today's number format and a parameter table as an object. Key order is as
// written (ordered_json), so that the output reads as before. Not real-time (allocates).
#pragma once

#include "god_finger/support/parameter_table.h"
#include "god_finger/support/text_numbers.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>

namespace god_finger
{
using Json = nlohmann::ordered_json;

// A measured number as jsonNumber writes it (9 significant digits); null when not finite.
inline Json jsonMeasure(double value)
{
  if (!std::isfinite(value))
  {
    return nullptr;
  }
  return std::strtod(jsonNumber(value).c_str(), nullptr);
}

// {"r_max": 0.01, "walk": "unfold", "n_sgo": 8, ...}: real rows as numbers at full precision,
// integer rows as integers, choices and infinite values as strings ("inf").
template <typename Params>
Json jsonObject(const ParameterTable<Params>& table, const Params& params)
{
  Json object = Json::object();
  for (const ParameterRow<Params>& row : table)
  {
    using Kind = typename ParameterRow<Params>::Kind;
    if (row.kind == Kind::kChoice || std::isinf(row.number(params)))
    {
      object[row.name] = row.valueText(params);
    }
    else if (row.kind == Kind::kInteger)
    {
      object[row.name] = static_cast<long long>(row.number(params));
    }
    else
    {
      object[row.name] = row.number(params);
    }
  }
  return object;
}
}  // namespace god_finger
