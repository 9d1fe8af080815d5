// The package's documentation as one text, for the tests that hold it to the code (the parameter
// tables it shows as generated): README.md, then every page of docs/ in name order. Each table
// lives in one page (docs/parameters.md, docs/devices.md, docs/nodes.md); scripts/
// update_parameter_tables rewrites it where it is. Header-only; reads GOD_FINGER_SOURCE_DIR.
#pragma once

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace god_finger
{
namespace test
{
inline std::string docsText()
{
  const std::filesystem::path root(GOD_FINGER_SOURCE_DIR);
  std::vector<std::filesystem::path> pages = {root / "README.md"};
  std::vector<std::filesystem::path> docs;
  for (const auto& entry : std::filesystem::directory_iterator(root / "docs"))
  {
    if (entry.path().extension() == ".md")
    {
      docs.push_back(entry.path());
    }
  }
  std::sort(docs.begin(), docs.end());
  pages.insert(pages.end(), docs.begin(), docs.end());
  std::stringstream text;
  for (const auto& page : pages)
  {
    std::ifstream in(page);
    text << in.rdbuf() << "\n";
  }
  return text.str();
}
}  // namespace test
}  // namespace god_finger
