#include "hull_cache.h"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <mutex>
#include <set>
#include <system_error>

namespace god_finger
{
namespace
{
constexpr char kMagic[8] = {'G', 'F', 'H', 'U', 'L', 'L', 'S', '1'};
constexpr std::size_t kKeyBytes = 32;
// A decomposition has tens of hulls of at most HACD's 100 points; far larger counts are corruption.
constexpr std::uint32_t kMaxHulls = 100000;
constexpr std::uint32_t kMaxPointsPerHull = 100000;
constexpr std::uintmax_t kMaxFileBytes = 256u << 20;

std::uint64_t fnv1a(const char* data, std::size_t size)
{
  std::uint64_t hash = 1469598103934665603ull;
  for (std::size_t i = 0; i < size; ++i)
  {
    hash = (hash ^ static_cast<unsigned char>(data[i])) * 1099511628211ull;
  }
  return hash;
}

template <typename T>
void append(std::string* bytes, const T& value)
{
  bytes->append(reinterpret_cast<const char*>(&value), sizeof(T));
}

// Reads values from a byte string, never past its end.
class Reader
{
 public:
  explicit Reader(const std::string& bytes) : bytes_(bytes) {}
  template <typename T>
  bool read(T* value)
  {
    if (bytes_.size() - position_ < sizeof(T))
    {
      return false;
    }
    std::memcpy(value, bytes_.data() + position_, sizeof(T));
    position_ += sizeof(T);
    return true;
  }
  std::size_t left() const
  {
    return bytes_.size() - position_;
  }

 private:
  const std::string& bytes_;
  std::size_t position_ = 0;
};

void warn(const std::string& message)
{
  std::cerr << "god_finger: warning: " << message << std::endl;
}

std::string fileName(const std::string& directory, const std::string& key)
{
  return directory + "/" + key + ".hulls";
}

// The hulls in `bytes`, or the reason they cannot be trusted.
std::optional<HullSet> parse(const std::string& bytes, const std::string& key, std::string* reason)
{
  if (bytes.size() <
      sizeof(kMagic) + sizeof(std::uint32_t) + kKeyBytes + 2 * sizeof(std::uint32_t) + sizeof(std::uint64_t))
  {
    *reason = "truncated (" + std::to_string(bytes.size()) + " bytes)";
    return std::nullopt;
  }
  const std::size_t body = bytes.size() - sizeof(std::uint64_t);
  std::uint64_t checksum = 0;
  std::memcpy(&checksum, bytes.data() + body, sizeof(checksum));
  if (std::memcmp(bytes.data(), kMagic, sizeof(kMagic)) != 0)
  {
    *reason = "not a hull cache file";
    return std::nullopt;
  }
  if (checksum != fnv1a(bytes.data(), body))
  {
    *reason = "checksum mismatch (truncated or corrupt)";
    return std::nullopt;
  }
  const std::string content = bytes.substr(0, body);
  Reader reader(content);
  char magic[sizeof(kMagic)];
  std::uint32_t version = 0;
  char stored_key[kKeyBytes];
  std::uint32_t hull_count = 0;
  reader.read(&magic);
  reader.read(&version);
  reader.read(&stored_key);
  reader.read(&hull_count);
  if (version != static_cast<std::uint32_t>(kDecompositionVersion) || key.size() != kKeyBytes ||
      std::memcmp(stored_key, key.data(), kKeyBytes) != 0)
  {
    *reason = "made for another mesh or version";
    return std::nullopt;
  }
  if (hull_count == 0 || hull_count > kMaxHulls)
  {
    *reason = "holds " + std::to_string(hull_count) + " hulls";
    return std::nullopt;
  }
  HullSet hulls(hull_count);
  for (std::vector<Eigen::Vector3d>& hull : hulls)
  {
    std::uint32_t points = 0;
    if (!reader.read(&points) || points < 4 || points > kMaxPointsPerHull || points > reader.left() / 24)
    {
      *reason = "a hull of " + std::to_string(points) + " points";
      return std::nullopt;
    }
    hull.resize(points);
    for (Eigen::Vector3d& p : hull)
    {
      double xyz[3];
      reader.read(&xyz);
      p = Eigen::Vector3d(xyz[0], xyz[1], xyz[2]);
      if (!p.allFinite())
      {
        *reason = "a non-finite point";
        return std::nullopt;
      }
    }
  }
  if (reader.left() != 0)
  {
    *reason = std::to_string(reader.left()) + " bytes after the last hull";
    return std::nullopt;
  }
  return hulls;
}
}  // namespace

std::string hullCacheDirectory()
{
  const auto set = [](const char* name) -> std::string
  {
    const char* value = std::getenv(name);
    return value != nullptr ? std::string(value) : std::string();
  };
  if (!set("GOD_FINGER_CACHE_DIR").empty())
  {
    return set("GOD_FINGER_CACHE_DIR");
  }
  if (!set("XDG_CACHE_HOME").empty())
  {
    return set("XDG_CACHE_HOME") + "/god_finger/hulls";
  }
  if (!set("HOME").empty())
  {
    return set("HOME") + "/.cache/god_finger/hulls";
  }
  return std::string();
}

std::optional<HullSet> readHullCache(const std::string& directory, const std::string& key)
{
  if (directory.empty())
  {
    return std::nullopt;
  }
  const std::string path = fileName(directory, key);
  std::error_code error;
  if (!std::filesystem::exists(path, error))
  {
    return std::nullopt;
  }
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  std::string reason;
  std::optional<HullSet> hulls;
  if (error)
  {
    reason = "unreadable (" + error.message() + ")";
  }
  else if (size > kMaxFileBytes)
  {
    reason = "too large (" + std::to_string(size) + " bytes)";
  }
  else
  {
    std::ifstream file(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    if (!file.good() && !file.eof())
    {
      reason = "unreadable";
    }
    else
    {
      hulls = parse(bytes, key, &reason);
    }
  }
  if (!hulls)
  {
    warn("hull cache file '" + path + "' is " + reason + "; decomposing again");
  }
  return hulls;
}

bool writeHullCache(const std::string& directory, const std::string& key, const HullSet& hulls)
{
  if (directory.empty())
  {
    return false;
  }
  std::string bytes(kMagic, sizeof(kMagic));
  append(&bytes, static_cast<std::uint32_t>(kDecompositionVersion));
  bytes.append(key.substr(0, kKeyBytes));
  bytes.resize(sizeof(kMagic) + sizeof(std::uint32_t) + kKeyBytes, '\0');
  append(&bytes, static_cast<std::uint32_t>(hulls.size()));
  for (const std::vector<Eigen::Vector3d>& hull : hulls)
  {
    append(&bytes, static_cast<std::uint32_t>(hull.size()));
    for (const Eigen::Vector3d& p : hull)
    {
      const double xyz[3] = {p.x(), p.y(), p.z()};
      append(&bytes, xyz);
    }
  }
  append(&bytes, fnv1a(bytes.data(), bytes.size()));

  static std::atomic<unsigned> counter{0};
  const std::string path = fileName(directory, key);
  const std::string temporary = path + ".tmp." + std::to_string(getpid()) + "." + std::to_string(counter.fetch_add(1));
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  bool written = !error;
  if (written)
  {
    std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
    file.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    file.close();
    written = file.good() && std::rename(temporary.c_str(), path.c_str()) == 0;
    if (!written)
    {
      std::remove(temporary.c_str());
    }
  }
  if (!written)
  {
    // One warning per folder and process: a read-only cache should not flood the log.
    static std::mutex mutex;
    static std::set<std::string> warned;
    std::lock_guard<std::mutex> lock(mutex);
    if (warned.insert(directory).second)
    {
      warn("cannot write the hull cache in '" + directory + "' (" +
           (error ? error.message() : std::string(std::strerror(errno))) +
           "); decompositions will be computed again on the next run");
    }
  }
  return written;
}
}  // namespace god_finger
