// The one parameter table per set (support/parameter_table.h) is what every other place follows:
// the README's tables, dynamic_reconfigure's cfg, the defaults and the error messages (the
// shipped device profiles: test/devices/device_profiles_test). A parameter added to a table and not to the README or
// the cfg (or the other way round) fails here, with the text to paste.
#include "god_finger/devices/fake_hand.h"
#include "god_finger/devices/pose_source.h"
#include "god_finger/haptics/device_profile.h"
#include "god_finger/physics/world_params.h"
#include "god_finger/support/input_error.h"

#include "docs_text.h"

#include "god_finger/runtime/delay_line.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace god_finger
{
namespace
{
std::string readSource(const std::string& relative)
{
  std::ifstream in(std::string(GOD_FINGER_SOURCE_DIR) + "/" + relative);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The world's own rows (its table lifts the contact table's rows in too).
ParameterTable<WorldParams> worldOwnRows()
{
  std::set<std::string> contact_names;
  for (const auto& row : contactParameterTable())
  {
    contact_names.insert(row.name);
  }
  ParameterTable<WorldParams> own;
  for (const auto& row : worldParameterTable())
  {
    if (contact_names.count(row.name) == 0)
    {
      own.push_back(row);
    }
  }
  return own;
}

TEST(ParameterTables, TheDocsShowEachTableAsGenerated)
{
  const std::string readme = test::docsText();
  const std::pair<const char*, std::string> tables[] = {
      {"method (contactParameterTable)", markdownTable(contactParameterTable())},
      {"world (worldParameterTable, its own rows)", markdownTable(worldOwnRows())},
      {"device profile (deviceProfileTable)", markdownTable(deviceProfileTable())},
      {"fake_hand (fakeHandParameterTable)", markdownTable(fakeHandParameterTable())},
      {"pose_source (poseSourceParameterTable)", markdownTable(poseSourceParameterTable())},
      {"god_finger_delay (delayLineParameterTable)", markdownTable(delayLineParameterTable())},
  };
  for (const auto& [what, table] : tables)
  {
    EXPECT_NE(readme.find(table), std::string::npos) << "the docs lack the " << what << " table as generated:\n"
                                                     << table;
  }
}

TEST(ParameterTables, TheCfgFollowsTheWorldTable)
{
  // gen.add("name", type, 0, "meaning", default, min, max) or, for a choice, edit_method=...
  const std::string cfg = readSource("cfg/GodFinger.cfg");
  const std::regex add(
      "gen\\.add\\(\"(\\w+)\", (\\w+), 0,\\s*\"([^\"]*)\",\\s*([^,\\)]+)(?:,\\s*([^,\\)]+)(?:,\\s*([^,\\)]+))?)?");
  int entries = 0;
  for (std::sregex_iterator it(cfg.begin(), cfg.end(), add), end; it != end; ++it, ++entries)
  {
    const std::string name = (*it)[1];
    const std::string type = (*it)[2];
    const ParameterRow<WorldParams>* row = nullptr;
    for (const auto& candidate : worldParameterTable())
    {
      row = name == candidate.name ? &candidate : row;
    }
    ASSERT_NE(row, nullptr) << "cfg entry '" << name << "' is no row of worldParameterTable()";
    EXPECT_EQ((*it)[3].str(), row->meaning) << name << ": the cfg's description must be the row's meaning";
    using Kind = ParameterRow<WorldParams>::Kind;
    const std::string expected_type =
        row->kind == Kind::kReal ? "double_t" : (row->kind == Kind::kInteger ? "int_t" : "str_t");
    EXPECT_EQ(type, expected_type) << name;
    if (row->kind == Kind::kChoice)
    {
      EXPECT_EQ((*it)[4].str(), "\"" + row->defaultText() + "\"") << name;
      continue;
    }
    const double default_value = std::stod((*it)[4]);
    EXPECT_EQ(default_value, row->number(WorldParams{})) << name << ": one default, the struct's";
    // One range per parameter: the slider's ends are the row's range's (an infinite end left
    // out, unbounded), so that the server never clamps a value silently; a narrower live range is
    // the row's, applied (and reported) by the node.
    ASSERT_TRUE((*it)[5].matched || std::isinf(row->range.low)) << name << " has no slider range";
    const double low = (*it)[5].matched ? std::stod((*it)[5]) : -INFINITY;
    const double high = (*it)[6].matched ? std::stod((*it)[6]) : INFINITY;
    EXPECT_EQ(low, row->range.low) << name << ": the slider's low end must be the range's, " << row->range.text();
    EXPECT_EQ(high, row->range.high) << name << ": the slider's high end must be the range's, " << row->range.text();
    const ParameterRange& live = row->liveRange();
    EXPECT_TRUE(!row->has_live || (!live.low_open && !live.high_open && row->range.contains(live.low) &&
                                   row->range.contains(live.high) && live.contains(default_value)))
        << name << ": the live range " << live.text() << " must be closed, in " << row->range.text()
        << " and hold the default";
  }
  EXPECT_GE(entries, 8);
}

// The names of a choice's entries, "a, b, c", as a set.
std::set<std::string> choiceSet(const std::string& names)
{
  std::set<std::string> set;
  std::stringstream in(names);
  for (std::string name; std::getline(in, name, ',');)
  {
    set.insert(name.substr(name.find_first_not_of(' ')));
  }
  return set;
}

TEST(ParameterTables, TheCfgEnumsAreTheChoicesOfTheirRows)
{
  // gen.add("name", str_t, 0, ..., edit_method=VAR) and VAR = gen.enum([gen.const("a", ...), ...], ...):
  // a contact model (or walk) added to its list and not to the cfg fails here.
  const std::string cfg = readSource("cfg/GodFinger.cfg");
  // Each gen.add( call runs to the next one (or the end).
  const std::regex add("gen\\.add\\(\"(\\w+)\"((?:(?!gen\\.add)[\\s\\S])*)");
  const std::regex edit("edit_method=(\\w+)\\)");
  int enums = 0;
  for (std::sregex_iterator it(cfg.begin(), cfg.end(), add), end; it != end; ++it)
  {
    const std::string call = (*it)[2];
    std::smatch method;
    if (!std::regex_search(call, method, edit))
    {
      continue;
    }
    ++enums;
    const std::string name = (*it)[1];
    const std::string variable = method[1];
    const ParameterRow<WorldParams>* row = nullptr;
    for (const auto& candidate : worldParameterTable())
    {
      row = name == candidate.name ? &candidate : row;
    }
    ASSERT_NE(row, nullptr) << "cfg entry '" << name << "' is no row of worldParameterTable()";
    ASSERT_EQ(row->kind, ParameterRow<WorldParams>::Kind::kChoice) << name;
    const std::size_t start = cfg.find(variable + " = gen.enum([");
    ASSERT_NE(start, std::string::npos) << name << ": no enum " << variable;
    const std::string list = cfg.substr(start, cfg.find("],", start) - start);
    std::set<std::string> constants;
    const std::regex constant("gen\\.const\\(\"(\\w+)\", str_t, \"(\\w+)\"");
    for (std::sregex_iterator c(list.begin(), list.end(), constant), none; c != none; ++c)
    {
      EXPECT_EQ((*c)[1].str(), (*c)[2].str()) << name << ": an entry's name is its value";
      constants.insert((*c)[2]);
    }
    EXPECT_EQ(constants, choiceSet(row->choices))
        << name << ": the cfg's enum " << variable << " must list the row's choices, " << row->choices;
  }
  EXPECT_GE(enums, 2);  // model and walk
}

TEST(ParameterTables, AChoiceThatIsNoneOfItsRowsChoicesIsRefusedByName)
{
  ContactParams contact;
  contact.walk = static_cast<WalkVariant>(7);
  EXPECT_EQ(validate(contact), "parameter 'walk' = 'unknown' is not one of project, unfold");
  WorldParams world;
  world.model = static_cast<ContactModel>(9);
  EXPECT_EQ(validate(world), "parameter 'model' = 'unknown' is not one of " + contactModelNames());
  world = WorldParams();
  world.contact.walk = static_cast<WalkVariant>(-1);
  EXPECT_EQ(validate(world), "parameter 'walk' = 'unknown' is not one of project, unfold");
}

TEST(ParameterTables, DefaultsAreValidAndEveryBoundIsEnforcedWithTheParameterNamed)
{
  EXPECT_EQ(validate(ContactParams{}), "");
  EXPECT_EQ(validate(WorldParams{}), "");
  EXPECT_EQ(validate(DeviceProfile{}.coupling), "");
  // Just outside each finite end of each numeric row: read from a source, the error names
  // the parameter's full name, the value and the range.
  int checked = 0;
  for (const auto& row : worldParameterTable())
  {
    if (row.kind == ParameterRow<WorldParams>::Kind::kChoice)
    {
      continue;
    }
    for (const double outside :
         {row.range.low - (row.range.low_open ? 0.0 : 1.0), row.range.high + (row.range.high_open ? 0.0 : 1.0)})
    {
      if (!std::isfinite(outside))
      {
        continue;
      }
      MapParameterSource source("/physics/");
      source.set(row.name, row.kind == ParameterRow<WorldParams>::Kind::kInteger
                               ? ParameterValue::ofInteger(static_cast<int>(outside))
                               : ParameterValue::of(outside));
      WorldParams params;
      try
      {
        readRows(source, worldParameterTable(), &params);
        ADD_FAILURE() << row.name << " = " << outside << " was accepted";
      }
      catch (const InputError& error)
      {
        EXPECT_EQ(std::string(error.what()), "parameter '/physics/" + std::string(row.name) +
                                                 "' = " + formatNumber(outside) + " is out of range " +
                                                 row.range.text() + " (" + row.unit + ")");
      }
      ++checked;
    }
  }
  EXPECT_GE(checked, 25);
  // The same through validate() on the struct itself.
  WorldParams params;
  params.contact.distance_constant = 0.0;
  EXPECT_EQ(validate(params), "parameter 'd0' = 0 is out of range (0, 1000] (m)");
  params = WorldParams();
  params.pad.stiffness = -1.0;
  EXPECT_EQ(validate(params), "parameter 'pad_stiffness' = -1 is out of range (0, 10000000] (N/m)");
  // A choice outside its list.
  MapParameterSource source("/physics/");
  source.set("walk", ParameterValue::of(std::string("sideways")));
  EXPECT_THROW(
      {
        try
        {
          readRows(source, worldParameterTable(), &params);
        }
        catch (const InputError& error)
        {
          EXPECT_STREQ(error.what(), "parameter '/physics/walk' = 'sideways' is not one of project, unfold");
          throw;
        }
      },
      InputError);
}
// One range per parameter: a live range narrower than the range is the table's, and a live value
// outside it is clamped with a note (the reconfigure handler logs it and sends the value back).
struct LiveParams
{
  double radius = 0.01;
  int count = 8;
};

TEST(ParameterTables, ALiveRangeClampsAndSaysSo)
{
  using P = LiveParams;
  const ParameterTable<P> table = {
      withLiveRange(
          realRow<P>("radius", "m", openClosed(0.0, 1e3), "a radius", [](P& p) -> double& { return p.radius; }),
          closed(0.0005, 0.05)),
      integerRow<P>("count", closed(3, 64), "a count", [](P& p) -> int& { return p.count; }),
  };
  std::string note;
  EXPECT_EQ(clampToLive(table[0], 0.02, &note), 0.02);
  EXPECT_EQ(note, "");
  EXPECT_EQ(clampToLive(table[0], 1.0, &note), 0.05);
  EXPECT_EQ(note, "parameter 'radius' = 1 is outside the live range [0.0005, 0.05]: clamped to 0.05");
  note.clear();
  EXPECT_EQ(clampToLive(table[0], 0.0001, &note), 0.0005);
  EXPECT_NE(note.find("clamped to 0.0005"), std::string::npos) << note;
  // Outside the range itself: no clamp, the range check refuses it with its own message.
  note.clear();
  EXPECT_EQ(clampToLive(table[0], 2000.0, &note), 2000.0);
  EXPECT_EQ(note, "");
  // A row without a live range takes its whole range live.
  EXPECT_EQ(clampToLive(table[1], 64.0, &note), 64.0);
  EXPECT_EQ(note, "");
  EXPECT_EQ(table[1].liveRange().text(), table[1].range.text());
  // Lifted rows keep their live range.
  struct Outer
  {
    P inner;
  };
  const ParameterTable<Outer> lifted = liftRows<Outer, P>(table, [](Outer& o) -> P& { return o.inner; });
  EXPECT_TRUE(lifted[0].has_live);
  EXPECT_EQ(lifted[0].liveRange().text(), "[0.0005, 0.05]");
}

TEST(ParameterTables, RMaxIsLiveOverItsWholeRange)
{
  // Issue 18: the slider once stopped at 5 cm and clamped silently; r_max accepts its whole range.
  for (const ParameterRow<WorldParams>& row : worldParameterTable())
  {
    if (std::string(row.name) == "r_max")
    {
      std::string note;
      EXPECT_EQ(clampToLive(row, 0.2, &note), 0.2);
      EXPECT_EQ(note, "");
      EXPECT_EQ(row.liveRange().text(), "(0, 1000]");
    }
  }
}
}  // namespace
}  // namespace god_finger
