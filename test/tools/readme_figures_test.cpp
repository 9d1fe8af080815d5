// The README's measured figures agree with their one source: scripts/readme_figures --check
// regenerates every generated block (from bench/REPORT.md and god_finger_experiment) and fails
// when one differs; an edited figure in any block, or a block lost, is caught.
#include "tool_run.h"

#include <gtest/gtest.h>

#include <cctype>
#include <fstream>
#include <string>
#include <vector>

namespace god_finger
{
namespace
{
const std::string kSourceDir = GOD_FINGER_SOURCE_DIR;
// The README's generated blocks, as scripts/readme_figures names them.
const std::vector<std::string> kBlocks = {"experiments", "push_height", "haptic_loop", "pad_fidelity"};

test::ToolRun checkReadme(const std::string& readme)
{
  return test::runTool("/usr/bin/python3 " + kSourceDir + "/scripts/readme_figures",
                       "--check --readme " + readme + " --tool " + GOD_FINGER_EXPERIMENT_TOOL);
}

std::string writeCopy(const std::string& text, const std::string& name)
{
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

// The README with the first digit of the block's first table row changed.
std::string withOneFigureChanged(std::string text, const std::string& block)
{
  const std::size_t start = text.find("<!-- generated: " + block + " ");
  const std::size_t separator = text.find("\n|---", start);
  const std::size_t row = text.find('\n', separator + 1) + 1;
  std::size_t digit = row;
  while (digit < text.size() && !std::isdigit(static_cast<unsigned char>(text[digit])))
  {
    ++digit;
  }
  EXPECT_NE(start, std::string::npos) << block;
  EXPECT_LT(digit, text.find("<!-- end generated: " + block, start)) << block << ": no figure in its first row";
  text[digit] = text[digit] == '9' ? '1' : static_cast<char>(text[digit] + 1);
  return text;
}

TEST(ReadmeFigures, TheReadmeAgreesWithTheReportAndTheExperiments)
{
  const test::ToolRun run = checkReadme(kSourceDir + "/README.md");
  EXPECT_EQ(run.exit_code, 0) << run.out << run.err
                              << "scripts/readme_figures rewrites the blocks (scripts/bench --report runs it)";
  EXPECT_NE(run.out.find("all 4 blocks agree"), std::string::npos) << run.out;
}

TEST(ReadmeFigures, AFigureEditedInAnyBlockFailsTheCheck)
{
  std::string text = test::readFile(kSourceDir + "/README.md");
  for (const std::string& block : kBlocks)
  {
    text = withOneFigureChanged(text, block);
  }
  const test::ToolRun run = checkReadme(writeCopy(text, "readme_figures_edited.md"));
  EXPECT_EQ(run.exit_code, 1) << run.out << run.err;
  for (const std::string& block : kBlocks)
  {
    EXPECT_NE(run.err.find(block), std::string::npos) << block << " not named stale: " << run.err;
  }
}

TEST(ReadmeFigures, ALostBlockIsAnErrorNamingIt)
{
  std::string text = test::readFile(kSourceDir + "/README.md");
  const std::string end_marker = "<!-- end generated: haptic_loop -->";
  const std::size_t end = text.find(end_marker);
  ASSERT_NE(end, std::string::npos);
  text.erase(end, end_marker.size());
  const test::ToolRun run = checkReadme(writeCopy(text, "readme_figures_lost.md"));
  EXPECT_EQ(run.exit_code, 2) << run.out << run.err;
  EXPECT_NE(run.err.find("lacks the block(s) haptic_loop"), std::string::npos) << run.err;
}
}  // namespace
}  // namespace god_finger
