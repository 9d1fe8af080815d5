#include "tool_run.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/wait.h>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace god_finger
{
namespace test
{
std::string readFile(const std::string& path)
{
  std::ifstream stream(path);
  std::stringstream content;
  content << stream.rdbuf();
  return content.str();
}

ToolRun runTool(const std::string& tool, const std::string& arguments)
{
  const std::string err_path = ::testing::TempDir() + "god_finger_tool_stderr.txt";
  const std::string command = tool + " " + arguments + " 2>" + err_path;
  ToolRun run;
  FILE* pipe = popen(command.c_str(), "r");
  char buffer[4096];
  std::size_t n = 0;
  while ((n = fread(buffer, 1, sizeof(buffer), pipe)) > 0)
  {
    run.out.append(buffer, n);
  }
  const int status = pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.err = readFile(err_path);
  return run;
}

namespace
{
// The first value named `key`, depth first in document order; nullptr if none.
const nlohmann::ordered_json* findKey(const nlohmann::ordered_json& json, const std::string& key)
{
  if (!json.is_object() && !json.is_array())
  {
    return nullptr;
  }
  if (json.is_object() && json.contains(key))
  {
    return &json.at(key);
  }
  for (const auto& child : json)
  {
    if (const nlohmann::ordered_json* found = findKey(child, key))
    {
      return found;
    }
  }
  return nullptr;
}
}  // namespace

double jsonValue(const std::string& json, const std::string& key)
{
  const nlohmann::ordered_json parsed = nlohmann::ordered_json::parse(json, nullptr, /*allow_exceptions=*/false);
  EXPECT_FALSE(parsed.is_discarded()) << "not JSON: " << json;
  const nlohmann::ordered_json* value = findKey(parsed, key);
  EXPECT_NE(value, nullptr) << key;
  if (value == nullptr || !(value->is_number() || value->is_null()))
  {
    return -1.0;
  }
  return value->is_null() ? NAN : value->get<double>();
}
}  // namespace test
}  // namespace god_finger
