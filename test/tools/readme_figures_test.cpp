// The docs' measured figures agree with their one source: scripts/readme_figures --check
// regenerates every generated block (from bench/REPORT.md and god_finger_experiment) and fails
// when one differs; an edited figure in any block, or a block lost, is caught (on a copy of the
// docs' pages that hold the blocks).
#include "tool_run.h"

#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace god_finger
{
namespace
{
const std::string kSourceDir = GOD_FINGER_SOURCE_DIR;
// The docs' generated blocks, as scripts/readme_figures names them, and the page each lives in
// (relative to the repository).
const std::map<std::string, std::string> kBlocks = {{"experiments", "docs/experiments.md"},
                                                    {"push_height", "docs/experiments.md"},
                                                    {"haptic_loop", "docs/servo_loop.md"},
                                                    {"pad_fidelity", "docs/performance.md"},
                                                    {"delay", "README.md"}};

// The generated blocks, made by this run's first check and read by the others (readme_figures
// --blocks): the experiments run once, not once per copy of the docs.
const std::string kBlocksFile = ::testing::TempDir() + "readme_figures_blocks.json";

test::ToolRun checkDocs(const std::string& root)
{
  return test::runTool("/usr/bin/python3 " + kSourceDir + "/scripts/readme_figures",
                       "--check --root " + root + " --tool " + GOD_FINGER_EXPERIMENT_TOOL + " --blocks " + kBlocksFile);
}

// Every run of this binary generates the blocks afresh (from this build's experiments).
class BlocksMadeOnce : public ::testing::Environment
{
 public:
  void SetUp() override
  {
    std::filesystem::remove(kBlocksFile);
  }
};
const ::testing::Environment* const kBlocksMadeOnce = ::testing::AddGlobalTestEnvironment(new BlocksMadeOnce);

// A copy of the pages that hold the blocks under a fresh root named `name`, each page's text
// passed through `edit` (page, text) first.
template <typename Edit>
std::string copyDocs(const std::string& name, Edit edit)
{
  const std::string root = ::testing::TempDir() + name;
  std::filesystem::create_directories(root + "/docs");
  for (const auto& [block, page] : kBlocks)
  {
    std::ofstream(root + "/" + page) << edit(page, test::readFile(kSourceDir + "/" + page));
  }
  return root;
}

// The page's text with the first digit of the block's first table row changed.
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

TEST(ReadmeFigures, TheDocsAgreeWithTheReportAndTheExperiments)
{
  const test::ToolRun run = checkDocs(kSourceDir);
  EXPECT_EQ(run.exit_code, 0) << run.out << run.err
                              << "scripts/readme_figures rewrites the blocks (scripts/bench --report runs it)";
  EXPECT_NE(run.out.find("all 5 blocks agree"), std::string::npos) << run.out;
}

TEST(ReadmeFigures, AFigureEditedInAnyBlockFailsTheCheck)
{
  const std::string root = copyDocs("readme_figures_edited",
                                    [](const std::string& page, std::string text)
                                    {
                                      for (const auto& [block, its_page] : kBlocks)
                                      {
                                        if (its_page == page)
                                        {
                                          text = withOneFigureChanged(text, block);
                                        }
                                      }
                                      return text;
                                    });
  const test::ToolRun run = checkDocs(root);
  EXPECT_EQ(run.exit_code, 1) << run.out << run.err;
  for (const auto& [block, page] : kBlocks)
  {
    EXPECT_NE(run.err.find(block), std::string::npos) << block << " not named stale: " << run.err;
  }
}

TEST(ReadmeFigures, ALostBlockIsAnErrorNamingIt)
{
  const std::string end_marker = "<!-- end generated: haptic_loop -->";
  const std::string root = copyDocs("readme_figures_lost",
                                    [&end_marker](const std::string&, std::string text)
                                    {
                                      const std::size_t end = text.find(end_marker);
                                      if (end != std::string::npos)
                                      {
                                        text.erase(end, end_marker.size());
                                      }
                                      return text;
                                    });
  const test::ToolRun run = checkDocs(root);
  EXPECT_EQ(run.exit_code, 2) << run.out << run.err;
  EXPECT_NE(run.err.find("docs/servo_loop.md lacks the block(s) haptic_loop"), std::string::npos) << run.err;
}
}  // namespace
}  // namespace god_finger
