#include "god_finger/mesh_io/ply_reader.h"

#include "god_finger/support/input_error.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>
#include <string_view>

namespace god_finger
{
namespace
{
enum class Format
{
  kAscii,
  kBinaryLittleEndian,
  kBinaryBigEndian
};

enum class ScalarType
{
  kInt8,
  kUint8,
  kInt16,
  kUint16,
  kInt32,
  kUint32,
  kFloat32,
  kFloat64
};

struct ScalarTypeName
{
  const char* name;
  ScalarType type;
  int bytes;
};

// Both spellings the PLY format allows.
constexpr ScalarTypeName kScalarTypes[] = {
    {"char", ScalarType::kInt8, 1},      {"int8", ScalarType::kInt8, 1},       {"uchar", ScalarType::kUint8, 1},
    {"uint8", ScalarType::kUint8, 1},    {"short", ScalarType::kInt16, 2},     {"int16", ScalarType::kInt16, 2},
    {"ushort", ScalarType::kUint16, 2},  {"uint16", ScalarType::kUint16, 2},   {"int", ScalarType::kInt32, 4},
    {"int32", ScalarType::kInt32, 4},    {"uint", ScalarType::kUint32, 4},     {"uint32", ScalarType::kUint32, 4},
    {"float", ScalarType::kFloat32, 4},  {"float32", ScalarType::kFloat32, 4}, {"double", ScalarType::kFloat64, 8},
    {"float64", ScalarType::kFloat64, 8}};

const ScalarTypeName& scalarType(const std::string& name, int line)
{
  for (const ScalarTypeName& type : kScalarTypes)
  {
    if (name == type.name)
    {
      return type;
    }
  }
  throw InputError("PLY header line " + std::to_string(line) + ": unknown property type '" + name + "'");
}

struct Property
{
  std::string name;
  ScalarTypeName value;
  bool is_list = false;
  ScalarTypeName count{"", ScalarType::kUint8, 0};  // the list's length type, when is_list
};

struct Element
{
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;

  // The fewest bytes one instance can take in the body: in binary, its scalars and list
  // lengths; in ascii, one character and one separator per value (the last may end the file).
  std::uint64_t minimumBytes(Format format) const
  {
    std::uint64_t bytes = 0;
    for (const Property& property : properties)
    {
      bytes += format == Format::kAscii ? 2 : (property.is_list ? property.count.bytes : property.value.bytes);
    }
    return bytes;
  }
};

// Reads the body's values one at a time, in either encoding, never past its end.
class BodyReader
{
 public:
  BodyReader(const std::string& bytes, std::size_t start, Format format)
      : bytes_(bytes), position_(start), format_(format)
  {
  }

  std::uint64_t bytesLeft() const
  {
    return bytes_.size() - position_;
  }

  double scalar(const ScalarTypeName& type)
  {
    return format_ == Format::kAscii ? asciiNumber() : binaryScalar(type);
  }

  // A list length or an index: must be a whole number.
  long long integer(const ScalarTypeName& type)
  {
    if (format_ == Format::kAscii)
    {
      const std::string_view token = nextToken();
      long long value = 0;
      const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
      if (error != std::errc() || end != token.data() + token.size())
      {
        throw InputError(where() + "'" + std::string(token.substr(0, 32)) + "' is not a whole number");
      }
      return value;
    }
    const double value = binaryScalar(type);
    if (type.type == ScalarType::kFloat32 || type.type == ScalarType::kFloat64)
    {
      if (!(std::abs(value) < 9e15) || value != static_cast<double>(static_cast<long long>(value)))
      {
        throw InputError(where() + "a list length or index is not a whole number");
      }
    }
    return static_cast<long long>(value);
  }

  std::string where() const
  {
    return "PLY body at byte " + std::to_string(position_) + ": ";
  }

 private:
  std::string_view nextToken()
  {
    while (position_ < bytes_.size() && std::isspace(static_cast<unsigned char>(bytes_[position_])))
    {
      ++position_;
    }
    const std::size_t start = position_;
    while (position_ < bytes_.size() && !std::isspace(static_cast<unsigned char>(bytes_[position_])))
    {
      ++position_;
    }
    if (start == position_)
    {
      throw InputError("PLY body ends early (a value is missing at its end)");
    }
    return std::string_view(bytes_).substr(start, position_ - start);
  }

  double asciiNumber()
  {
    const std::string_view token = nextToken();
    double value = 0.0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (error != std::errc() || end != token.data() + token.size())
    {
      throw InputError(where() + "'" + std::string(token.substr(0, 32)) + "' is not a number");
    }
    return value;
  }

  double binaryScalar(const ScalarTypeName& type)
  {
    if (bytesLeft() < static_cast<std::uint64_t>(type.bytes))
    {
      throw InputError("PLY body ends early (a value is missing at its end)");
    }
    unsigned char raw[8];
    std::memcpy(raw, bytes_.data() + position_, type.bytes);
    position_ += type.bytes;
    const bool swap = (format_ == Format::kBinaryBigEndian) == hostIsLittleEndian();
    if (swap)
    {
      std::reverse(raw, raw + type.bytes);
    }
    switch (type.type)
    {
      case ScalarType::kInt8:
        return static_cast<double>(static_cast<std::int8_t>(raw[0]));
      case ScalarType::kUint8:
        return static_cast<double>(raw[0]);
      case ScalarType::kInt16:
        return static_cast<double>(load<std::int16_t>(raw));
      case ScalarType::kUint16:
        return static_cast<double>(load<std::uint16_t>(raw));
      case ScalarType::kInt32:
        return static_cast<double>(load<std::int32_t>(raw));
      case ScalarType::kUint32:
        return static_cast<double>(load<std::uint32_t>(raw));
      case ScalarType::kFloat32:
        return static_cast<double>(load<float>(raw));
      case ScalarType::kFloat64:
        return load<double>(raw);
    }
    return 0.0;
  }

  template <typename T>
  static T load(const unsigned char* raw)
  {
    T value;
    std::memcpy(&value, raw, sizeof(T));
    return value;
  }

  static bool hostIsLittleEndian()
  {
    const std::uint16_t one = 1;
    unsigned char first;
    std::memcpy(&first, &one, 1);
    return first == 1;
  }

  const std::string& bytes_;
  std::size_t position_;
  Format format_;
};

std::vector<std::string> words(const std::string& line)
{
  std::istringstream stream(line);
  std::vector<std::string> result;
  std::string word;
  while (stream >> word)
  {
    result.push_back(word);
  }
  return result;
}

std::uint64_t elementCount(const std::string& text, int line)
{
  std::uint64_t count = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), count);
  if (error != std::errc() || end != text.data() + text.size())
  {
    throw InputError("PLY header line " + std::to_string(line) + ": element count '" + text.substr(0, 32) +
                     "' is not a whole number");
  }
  return count;
}

int findProperty(const Element& element, const std::string& name, bool list)
{
  for (std::size_t p = 0; p < element.properties.size(); ++p)
  {
    if (element.properties[p].name == name && element.properties[p].is_list == list)
    {
      return static_cast<int>(p);
    }
  }
  return -1;
}
}  // namespace

PolygonSoup readPly(const std::string& bytes, const DeclaredSizeCheck& check_size)
{
  // --- header ---
  std::vector<Element> elements;
  bool has_format = false;
  Format format = Format::kAscii;
  std::size_t start = 0;
  int line_number = 0;
  bool ended = false;
  while (!ended)
  {
    const std::size_t end = bytes.find('\n', start);
    if (end == std::string::npos)
    {
      throw InputError("PLY header has no end_header line");
    }
    std::string line = bytes.substr(start, end - start);
    start = end + 1;
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back();
    }
    ++line_number;
    const std::vector<std::string> word = words(line);
    if (line_number == 1)
    {
      if (word.size() != 1 || word[0] != "ply")
      {
        throw InputError("not a PLY file (its first line is not 'ply')");
      }
      continue;
    }
    const std::string where = "PLY header line " + std::to_string(line_number) + ": ";
    if (word.empty() || word[0] == "comment" || word[0] == "obj_info")
    {
      continue;
    }
    if (word[0] == "end_header")
    {
      ended = true;
    }
    else if (word[0] == "format")
    {
      if (word.size() < 2 ||
          (word[1] != "ascii" && word[1] != "binary_little_endian" && word[1] != "binary_big_endian"))
      {
        throw InputError(where + "unknown format (ascii, binary_little_endian or binary_big_endian)");
      }
      format = word[1] == "ascii"
                   ? Format::kAscii
                   : (word[1] == "binary_little_endian" ? Format::kBinaryLittleEndian : Format::kBinaryBigEndian);
      has_format = true;
    }
    else if (word[0] == "element")
    {
      if (word.size() != 3)
      {
        throw InputError(where + "an element needs a name and a count");
      }
      elements.push_back(Element{word[1], elementCount(word[2], line_number), {}});
    }
    else if (word[0] == "property")
    {
      if (elements.empty())
      {
        throw InputError(where + "a property before any element");
      }
      Property property;
      if (word.size() == 5 && word[1] == "list")
      {
        property.is_list = true;
        property.count = scalarType(word[2], line_number);
        property.value = scalarType(word[3], line_number);
        property.name = word[4];
      }
      else if (word.size() == 3)
      {
        property.value = scalarType(word[1], line_number);
        property.name = word[2];
      }
      else
      {
        throw InputError(where + "a property is 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME'");
      }
      elements.back().properties.push_back(property);
    }
    // Anything else is free text some exporters write (older Blender): skipped, as other readers do.
  }
  if (!has_format)
  {
    throw InputError("PLY header has no format line");
  }

  if (check_size)
  {
    std::uint64_t vertices = 0;
    std::uint64_t faces = 0;
    for (const Element& element : elements)
    {
      vertices += element.name == "vertex" ? element.count : 0;
      faces += element.name == "face" ? element.count : 0;
    }
    check_size(vertices, faces);
  }

  // --- body ---
  BodyReader body(bytes, start, format);
  PolygonSoup soup;
  bool has_vertices = false;
  for (const Element& element : elements)
  {
    if (element.name == "vertex" && element.count == 0)
    {
      throw InputError("PLY file declares no vertices (element vertex 0)");
    }
    if (element.count == 0)
    {
      continue;
    }
    const std::uint64_t minimum = element.minimumBytes(format);
    if (minimum == 0 || element.count > (body.bytesLeft() + 1) / minimum)
    {
      throw InputError("PLY element '" + element.name + "' claims " + std::to_string(element.count) +
                       " entries, more than the " + std::to_string(body.bytesLeft()) + " bytes left can hold");
    }
    int x = -1;
    int y = -1;
    int z = -1;
    int indices = -1;
    if (element.name == "vertex")
    {
      if (has_vertices)
      {
        throw InputError("PLY file has two vertex elements");
      }
      has_vertices = true;
      x = findProperty(element, "x", false);
      y = findProperty(element, "y", false);
      z = findProperty(element, "z", false);
      if (x < 0 || y < 0 || z < 0)
      {
        throw InputError("PLY vertex element lacks an x, y or z property");
      }
      if (element.count > static_cast<std::uint64_t>(std::numeric_limits<int>::max()))
      {
        throw InputError("PLY file has more vertices than can be indexed");
      }
      soup.vertices.reserve(element.count);
    }
    else if (element.name == "face")
    {
      indices = findProperty(element, "vertex_indices", true);
      if (indices < 0)
      {
        indices = findProperty(element, "vertex_index", true);
      }
      if (indices < 0)
      {
        throw InputError("PLY face element has no vertex_indices list");
      }
    }
    double values[3] = {0.0, 0.0, 0.0};
    for (std::uint64_t i = 0; i < element.count; ++i)
    {
      for (int p = 0; p < static_cast<int>(element.properties.size()); ++p)
      {
        const Property& property = element.properties[p];
        if (!property.is_list)
        {
          const double value = body.scalar(property.value);
          const int axis = p == x ? 0 : (p == y ? 1 : (p == z ? 2 : -1));
          if (axis >= 0)
          {
            values[axis] = value;
          }
          continue;
        }
        const long long length = body.integer(property.count);
        const std::uint64_t item_bytes = format == Format::kAscii ? 2 : property.value.bytes;
        if (length < 0 || static_cast<std::uint64_t>(length) > (body.bytesLeft() + 1) / item_bytes)
        {
          throw InputError(body.where() + "a list of " + std::to_string(length) +
                           " entries, more than the bytes left can hold");
        }
        for (long long k = 0; k < length; ++k)
        {
          const long long index = body.integer(property.value);
          if (p == indices)
          {
            soup.corners.push_back(index);
          }
        }
        if (p == indices)
        {
          soup.endFace();
        }
      }
      if (x >= 0)
      {
        soup.vertices.emplace_back(values[0], values[1], values[2]);
      }
    }
  }
  if (!has_vertices)
  {
    throw InputError("PLY file has no vertex element");
  }
  return soup;
}
}  // namespace god_finger
