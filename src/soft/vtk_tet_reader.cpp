#include "god_finger/soft/vtk_tet_reader.h"

#include "god_finger/support/input_error.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace god_finger
{
namespace
{
constexpr int kVtkTetra = 10;
// Cell types below this are points, lines, triangles, polygons and quads: boundary cells.
constexpr int kFirstVolumeCellType = 10;

// Reads the whitespace-separated tokens of a VTK file after its three header lines.
class Cursor
{
 public:
  Cursor(const std::string& text, std::size_t start, const std::string& source)
      : text_(text), at_(start), source_(source)
  {
  }

  [[noreturn]] void fail(const std::string& problem) const
  {
    const long line =
        1 + std::count(text_.begin(), text_.begin() + static_cast<long>(std::min(at_, text_.size())), '\n');
    throw InputError(source_ + ": line " + std::to_string(line) + ": " + problem);
  }

  std::string peekWord()
  {
    const std::size_t at = at_;
    std::string next = word();
    at_ = at;
    return next;
  }

  bool atEnd()
  {
    skipSpace();
    return at_ >= text_.size();
  }

  std::string word()
  {
    skipSpace();
    const std::size_t start = at_;
    while (at_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[at_])))
    {
      ++at_;
    }
    return text_.substr(start, at_ - start);
  }

  double number(const char* what)
  {
    skipSpace();
    if (at_ >= text_.size())
    {
      fail(std::string("the file ends where ") + what + " should be");
    }
    const char* begin = text_.c_str() + at_;
    char* end = nullptr;
    const double value = std::strtod(begin, &end);
    if (end == begin || (*end != '\0' && !std::isspace(static_cast<unsigned char>(*end))))
    {
      fail(std::string("'") + tokenAt(begin) + "' is not a number (" + what + ")");
    }
    at_ += static_cast<std::size_t>(end - begin);
    return value;
  }

  long long integer(const char* what)
  {
    skipSpace();
    if (at_ >= text_.size())
    {
      fail(std::string("the file ends where ") + what + " should be");
    }
    const char* begin = text_.c_str() + at_;
    char* end = nullptr;
    errno = 0;
    const long long value = std::strtoll(begin, &end, 10);
    if (end == begin || errno == ERANGE || (*end != '\0' && !std::isspace(static_cast<unsigned char>(*end))))
    {
      fail(std::string("'") + tokenAt(begin) + "' is not a whole number (" + what + ")");
    }
    at_ += static_cast<std::size_t>(end - begin);
    return value;
  }

  long long count(const char* what, long long limit)
  {
    const long long value = integer(what);
    if (value < 0 || value > limit)
    {
      fail(std::string(what) + " " + std::to_string(value) + " is out of range [0, " + std::to_string(limit) + "]");
    }
    return value;
  }

 private:
  void skipSpace()
  {
    while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_])))
    {
      ++at_;
    }
  }

  static std::string tokenAt(const char* begin)
  {
    std::string token;
    for (const char* c = begin; *c != '\0' && !std::isspace(static_cast<unsigned char>(*c)) && token.size() < 24; ++c)
    {
      token += *c;
    }
    return token;
  }

  const std::string& text_;
  std::size_t at_;
  const std::string& source_;
};

std::string upper(std::string word)
{
  for (char& c : word)
  {
    c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  return word;
}

// The start of line `index` (0-based) of `text`, or npos.
std::size_t lineStart(const std::string& text, int index)
{
  std::size_t at = 0;
  for (int line = 0; line < index; ++line)
  {
    at = text.find('\n', at);
    if (at == std::string::npos)
    {
      return at;
    }
    ++at;
  }
  return at;
}

std::string trimmed(const std::string& text, std::size_t begin, std::size_t end)
{
  while (begin < end && std::isspace(static_cast<unsigned char>(text[begin])))
  {
    ++begin;
  }
  while (end > begin && std::isspace(static_cast<unsigned char>(text[end - 1])))
  {
    --end;
  }
  return text.substr(begin, end - begin);
}

std::string cellTypeName(long long type)
{
  switch (type)
  {
    case 11:
      return "a voxel";
    case 12:
      return "a hexahedron";
    case 13:
      return "a wedge";
    case 14:
      return "a pyramid";
    case 24:
      return "a quadratic tetrahedron";
    default:
      return "not a linear tetrahedron";
  }
}
}  // namespace

TetMesh parseVtkTetMesh(const std::string& text, const std::string& source, TetMeshRepairs* repairs)
{
  const std::size_t third = lineStart(text, 2);
  const std::size_t fourth = lineStart(text, 3);
  // "# vtk DataFile Version 2.0", as VTK writes it; PyBullet's own files also write "#vtk".
  const std::size_t second = lineStart(text, 1);
  const std::string first_line =
      upper(trimmed(text, text.empty() ? 0 : 1, second == std::string::npos ? text.size() : second));
  if (text.empty() || text[0] != '#' || first_line.rfind("VTK DATAFILE", 0) != 0 || third == std::string::npos)
  {
    throw InputError(source + ": not a legacy VTK file (its first line must be '# vtk DataFile Version ...')");
  }
  const std::string format = upper(trimmed(text, third, fourth == std::string::npos ? text.size() : fourth));
  if (format == "BINARY")
  {
    throw InputError(source + ": line 3: BINARY VTK files are not read: write it as ASCII");
  }
  if (format != "ASCII")
  {
    throw InputError(source + ": line 3: '" + format.substr(0, 24) + "' where ASCII should be");
  }
  Cursor cursor(text, fourth == std::string::npos ? text.size() : fourth, source);
  if (upper(cursor.word()) != "DATASET" || upper(cursor.word()) != "UNSTRUCTURED_GRID")
  {
    cursor.fail("a soft body's file must be 'DATASET UNSTRUCTURED_GRID'");
  }
  const long long text_size = static_cast<long long>(text.size());
  TetMesh mesh;
  std::vector<long long> offsets;  // cell c's nodes: connectivity[offsets[c] .. offsets[c + 1])
  std::vector<long long> connectivity;
  bool have_points = false;
  bool have_cells = false;
  bool have_types = false;
  std::vector<long long> types;  // empty: none given
  while (!have_types && !cursor.atEnd())
  {
    const std::string section = upper(cursor.word());
    if (section == "POINTS")
    {
      // Each count is bounded by the text too (a point takes at least 6 characters, a number 2),
      // so that a lying header cannot allocate what the file does not hold.
      const long long count = cursor.count("the point count", std::min(kMaxVtkPoints, text_size / 6));
      cursor.word();  // float, double...: every number is read as a double
      mesh.nodes.resize(static_cast<std::size_t>(count));
      for (Eigen::Vector3d& node : mesh.nodes)
      {
        node.x() = cursor.number("a point's x");
        node.y() = cursor.number("a point's y");
        node.z() = cursor.number("a point's z");
      }
      have_points = true;
    }
    else if (section == "CELLS")
    {
      const long long first = cursor.count("the cell count", std::min(kMaxVtkCells, text_size / 2));
      const long long second = cursor.count("the cells' size", std::min(9 * kMaxVtkCells, text_size / 2));
      offsets.assign(1, 0);
      connectivity.clear();
      if (upper(cursor.peekWord()) == "OFFSETS")
      {
        // Version 5: `first` offsets (one more than the cells), then `second` node indices.
        cursor.word();
        cursor.word();
        for (long long i = 0; i < first; ++i)
        {
          const long long offset = cursor.integer("a cell offset");
          if ((i == 0 && offset != 0) || offset < offsets.back() || offset > second)
          {
            cursor.fail("cell offset " + std::to_string(offset) + " is out of order or past the " +
                        std::to_string(second) + " node indices");
          }
          if (i > 0)
          {
            offsets.push_back(offset);
          }
        }
        if (upper(cursor.word()) != "CONNECTIVITY")
        {
          cursor.fail("CONNECTIVITY should follow the cell offsets");
        }
        cursor.word();
        connectivity.resize(static_cast<std::size_t>(second));
        for (long long& node : connectivity)
        {
          node = cursor.integer("a cell's node");
        }
      }
      else
      {
        // Version 2: each cell is its node count, then its nodes.
        for (long long i = 0; i < first; ++i)
        {
          const long long size = cursor.integer("a cell's node count");
          if (size < 1 || size > 64)
          {
            cursor.fail("a cell of " + std::to_string(size) + " nodes (at most 64)");
          }
          for (long long k = 0; k < size; ++k)
          {
            connectivity.push_back(cursor.integer("a cell's node"));
          }
          offsets.push_back(static_cast<long long>(connectivity.size()));
        }
      }
      have_cells = true;
    }
    else if (section == "CELL_TYPES")
    {
      const long long count = cursor.count("the cell-type count", std::min(kMaxVtkCells, text_size / 2));
      // Bullet's reduced-deformable files end with a bare "CELL_TYPES 10" (Bullet's reader never
      // reads the types): no types at all reads as none given (below); some, then the end, is
      // a truncated file.
      if (!cursor.atEnd())
      {
        types.resize(static_cast<std::size_t>(count));
        for (long long& type : types)
        {
          type = cursor.integer("a cell type");
        }
      }
      have_types = true;
    }
    else if (section == "POINT_DATA" || section == "CELL_DATA" || section == "FIELD" || section == "METADATA")
    {
      break;
    }
    else
    {
      cursor.fail("unknown section '" + section.substr(0, 24) + "' (POINTS, CELLS and CELL_TYPES make a volume)");
    }
  }
  if (!have_points || !have_cells)
  {
    throw InputError(source + ": no " + std::string(!have_points ? "POINTS" : "CELLS") +
                     " section (a volume needs POINTS and CELLS)");
  }
  const std::size_t cells = offsets.size() - 1;
  if (types.empty())
  {
    // No cell types given (no CELL_TYPES, or a bare one): cells of 4 nodes are tetrahedra, as
    // Bullet's own reader takes every cell to be.
    for (std::size_t c = 0; c < cells; ++c)
    {
      if (offsets[c + 1] - offsets[c] != 4)
      {
        throw InputError(source + ": cell " + std::to_string(c) + " has " +
                         std::to_string(offsets[c + 1] - offsets[c]) +
                         " nodes and the file gives no CELL_TYPES (without them, every cell must be a tetrahedron)");
      }
    }
    types.assign(cells, kVtkTetra);
  }
  if (types.size() != cells)
  {
    throw InputError(source + ": CELL_TYPES lists " + std::to_string(types.size()) + " types for " +
                     std::to_string(cells) + " cells");
  }
  const long long node_count = static_cast<long long>(mesh.nodes.size());
  for (std::size_t c = 0; c < cells; ++c)
  {
    const long long size = offsets[c + 1] - offsets[c];
    if (types[c] < kFirstVolumeCellType && types[c] >= 1)
    {
      continue;
    }
    if (types[c] != kVtkTetra)
    {
      throw InputError(source + ": cell " + std::to_string(c) + " has type " + std::to_string(types[c]) + " (" +
                       cellTypeName(types[c]) + "): a soft body's volume must be linear tetrahedra (type 10)");
    }
    if (size != 4)
    {
      throw InputError(source + ": cell " + std::to_string(c) + " is a tetrahedron (type 10) of " +
                       std::to_string(size) + " nodes");
    }
    std::array<int, 4> tet{};
    for (int k = 0; k < 4; ++k)
    {
      const long long node = connectivity[static_cast<std::size_t>(offsets[c] + k)];
      if (node < 0 || node >= node_count)
      {
        throw InputError(source + ": cell " + std::to_string(c) + " names point " + std::to_string(node) +
                         ", but the file has " + std::to_string(node_count) + " points");
      }
      tet[k] = static_cast<int>(node);
    }
    mesh.tets.push_back(tet);
  }
  return checkedTetMesh(std::move(mesh), source, repairs);
}

TetMesh readVtkTetMesh(const std::string& path, TetMeshRepairs* repairs)
{
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
  {
    throw InputError("soft body file '" + path + "' does not exist or is not a regular file");
  }
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (error || size > kMaxVtkFileBytes)
  {
    throw InputError("soft body file '" + path + "' is larger than " + std::to_string(kMaxVtkFileBytes >> 20) + " MB");
  }
  std::ifstream stream(path, std::ios::binary);
  std::stringstream content;
  content << stream.rdbuf();
  if (!stream.good() && !stream.eof())
  {
    throw InputError("soft body file '" + path + "' cannot be read");
  }
  return parseVtkTetMesh(content.str(), path, repairs);
}

std::string vtkTetMeshText(const TetMesh& mesh, const std::string& title)
{
  std::string text = "# vtk DataFile Version 2.0\n" + title + "\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS " +
                     std::to_string(mesh.nodes.size()) + " double\n";
  char line[96];
  for (const Eigen::Vector3d& node : mesh.nodes)
  {
    std::snprintf(line, sizeof(line), "%.17g %.17g %.17g\n", node.x(), node.y(), node.z());
    text += line;
  }
  text += "\nCELLS " + std::to_string(mesh.tets.size()) + " " + std::to_string(5 * mesh.tets.size()) + "\n";
  for (const std::array<int, 4>& tet : mesh.tets)
  {
    std::snprintf(line, sizeof(line), "4 %d %d %d %d\n", tet[0], tet[1], tet[2], tet[3]);
    text += line;
  }
  text += "\nCELL_TYPES " + std::to_string(mesh.tets.size()) + "\n";
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
  {
    text += "10\n";
  }
  return text;
}
}  // namespace god_finger
