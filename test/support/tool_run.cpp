#include "tool_run.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
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

double jsonValue(const std::string& json, const std::string& key)
{
  const std::size_t at = json.find("\"" + key + "\": ");
  EXPECT_NE(at, std::string::npos) << key;
  return at == std::string::npos ? -1.0 : std::atof(json.c_str() + at + key.size() + 4);
}
}  // namespace test
}  // namespace god_finger
