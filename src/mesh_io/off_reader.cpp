#include "god_finger/mesh_io/off_reader.h"

#include "god_finger/support/input_error.h"

#include <cctype>
#include <charconv>
#include <cstdint>
#include <limits>
#include <string_view>
#include <vector>

namespace god_finger
{
namespace
{
// The file's lines with comments stripped, empty ones skipped, handed out one at a time as
// whitespace-separated tokens.
class LineReader
{
 public:
  explicit LineReader(const std::string& bytes) : bytes_(bytes) {}

  // The next line holding a token, split into `tokens`; false at the end of the file.
  bool next(std::vector<std::string_view>* tokens)
  {
    tokens->clear();
    while (tokens->empty() && position_ < bytes_.size())
    {
      std::size_t end = bytes_.find('\n', position_);
      if (end == std::string::npos)
      {
        end = bytes_.size();
      }
      std::string_view line = std::string_view(bytes_).substr(position_, end - position_);
      position_ = end + 1;
      ++line_number_;
      line = line.substr(0, line.find('#'));
      std::size_t i = 0;
      while (i < line.size())
      {
        while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i])))
        {
          ++i;
        }
        const std::size_t start = i;
        while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i])))
        {
          ++i;
        }
        if (i > start)
        {
          tokens->push_back(line.substr(start, i - start));
        }
      }
    }
    return !tokens->empty();
  }

  std::uint64_t bytesLeft() const
  {
    return position_ >= bytes_.size() ? 0 : bytes_.size() - position_;
  }

  std::string where() const
  {
    return "OFF line " + std::to_string(line_number_) + ": ";
  }

 private:
  const std::string& bytes_;
  std::size_t position_ = 0;
  int line_number_ = 0;
};

template <typename T>
bool parse(std::string_view token, T* value)
{
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), *value);
  return error == std::errc() && end == token.data() + token.size();
}

bool endsWith(std::string_view text, std::string_view suffix)
{
  return text.size() >= suffix.size() && text.substr(text.size() - suffix.size()) == suffix;
}
}  // namespace

PolygonSoup readOff(const std::string& bytes, const DeclaredSizeCheck& check_size)
{
  LineReader reader(bytes);
  std::vector<std::string_view> tokens;
  if (!reader.next(&tokens))
  {
    throw InputError("OFF file is empty");
  }
  std::size_t first_count = 0;
  if (endsWith(tokens[0], "OFF"))
  {
    const std::string_view prefix = tokens[0].substr(0, tokens[0].size() - 3);
    if (prefix.find('4') != std::string_view::npos || prefix.find('n') != std::string_view::npos)
    {
      throw InputError(reader.where() + "only 3-D OFF files are read ('" + std::string(tokens[0]) + "')");
    }
    if (tokens.size() > 1 && tokens[1] == "BINARY")
    {
      throw InputError(reader.where() + "binary OFF files are not read");
    }
    first_count = 1;
    if (tokens.size() == 1)
    {
      if (!reader.next(&tokens))
      {
        throw InputError("OFF file ends before its vertex and face counts");
      }
      first_count = 0;
    }
  }
  std::int64_t vertex_count = 0;
  std::int64_t face_count = 0;
  if (tokens.size() < first_count + 2 || !parse(tokens[first_count], &vertex_count) ||
      !parse(tokens[first_count + 1], &face_count) || vertex_count < 0 || face_count < 0)
  {
    throw InputError(reader.where() + "expected the vertex and face counts (two whole numbers >= 0)");
  }
  if (check_size)
  {
    check_size(static_cast<std::uint64_t>(vertex_count), static_cast<std::uint64_t>(face_count));
  }
  // A vertex line holds at least "x y z" and a line end; a face line at least one number and one.
  const std::uint64_t left = reader.bytesLeft() + 1;
  if (static_cast<std::uint64_t>(vertex_count) > left / 6 ||
      static_cast<std::uint64_t>(face_count) > (left - 6 * static_cast<std::uint64_t>(vertex_count)) / 2)
  {
    throw InputError(reader.where() + "counts of " + std::to_string(vertex_count) + " vertices and " +
                     std::to_string(face_count) + " faces, more than the " + std::to_string(reader.bytesLeft()) +
                     " bytes left can hold");
  }
  PolygonSoup soup;
  soup.vertices.reserve(vertex_count);
  for (std::int64_t v = 0; v < vertex_count; ++v)
  {
    if (!reader.next(&tokens))
    {
      throw InputError("OFF file ends after " + std::to_string(v) + " of its " + std::to_string(vertex_count) +
                       " vertices");
    }
    Eigen::Vector3d position;
    if (tokens.size() < 3 || !parse(tokens[0], &position.x()) || !parse(tokens[1], &position.y()) ||
        !parse(tokens[2], &position.z()))
    {
      throw InputError(reader.where() + "vertex " + std::to_string(v) + " is not three numbers");
    }
    soup.vertices.push_back(position);
  }
  for (std::int64_t f = 0; f < face_count; ++f)
  {
    if (!reader.next(&tokens))
    {
      throw InputError("OFF file ends after " + std::to_string(f) + " of its " + std::to_string(face_count) + " faces");
    }
    std::int64_t corners = 0;
    if (!parse(tokens[0], &corners) || corners < 0 || static_cast<std::uint64_t>(corners) >= tokens.size())
    {
      throw InputError(reader.where() + "face " + std::to_string(f) +
                       " is not a corner count followed by that many vertex indices");
    }
    for (std::int64_t k = 1; k <= corners; ++k)
    {
      long long index = 0;
      if (!parse(tokens[k], &index))
      {
        throw InputError(reader.where() + "face " + std::to_string(f) + ": '" + std::string(tokens[k].substr(0, 32)) +
                         "' is not a vertex index");
      }
      soup.corners.push_back(index);
    }
    soup.endFace();
  }
  return soup;
}
}  // namespace god_finger
