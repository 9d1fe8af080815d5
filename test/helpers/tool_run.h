// Running a command-line tool from a test as a user would: stdout, stderr and exit code.
#pragma once

#include <string>

namespace god_finger
{
namespace test
{
struct ToolRun
{
  int exit_code = -1;
  std::string out;
  std::string err;
};

std::string readFile(const std::string& path);
// Runs `tool arguments` through the shell.
ToolRun runTool(const std::string& tool, const std::string& arguments);
// The number named `key` in a JSON text (parsed with nlohmann-json; the first such key, depth
// first; NaN for null); -1 (and a test failure) if the text is no JSON or has no such number.
double jsonValue(const std::string& json, const std::string& key);
}  // namespace test
}  // namespace god_finger
