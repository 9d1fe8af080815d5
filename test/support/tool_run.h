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
// The number after "key": in a flat JSON text (first occurrence); -1 (and a test failure) if
// absent.
double jsonValue(const std::string& json, const std::string& key);
}  // namespace test
}  // namespace god_finger
