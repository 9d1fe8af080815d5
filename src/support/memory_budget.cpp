#include "god_finger/support/memory_budget.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace god_finger
{
namespace
{
// Fitted to the measured peaks (header comment), rounded up. Per triangle, TriangleMesh keeps
// 112 B (corners, normal, neighbours, barycentric gradients, vertex-face table, source index)
// and SurfaceLocator 32 B; while loading, the polygon and triangle soups, build()'s edge and
// duplicate tables and the collision shape's copy and tree add about twice that.
constexpr std::uint64_t kBytesPerTriangle = 400;
// Per vertex: the position in the soups, the mesh and the collision shape's copy, the weld grid.
constexpr std::uint64_t kBytesPerVertex = 100;
constexpr double kAvailableFraction = 0.8;

// MemAvailable in bytes, 0 when unknown.
std::uint64_t memAvailable()
{
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  std::uint64_t kib = 0;
  std::string unit;
  while (meminfo >> key >> kib >> unit)
  {
    if (key == "MemAvailable:")
    {
      return kib * 1024;
    }
  }
  const long pages = sysconf(_SC_AVPHYS_PAGES);
  const long page = sysconf(_SC_PAGESIZE);
  return pages > 0 && page > 0 ? static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page) : 0;
}
}  // namespace

std::uint64_t estimatedMeshBytes(std::uint64_t vertices, std::uint64_t triangles)
{
  // Saturating: a header may claim anything up to 2^64.
  const std::uint64_t max = UINT64_MAX;
  const std::uint64_t for_triangles =
      triangles > max / (2 * kBytesPerTriangle) ? max / 2 : triangles * kBytesPerTriangle;
  const std::uint64_t for_vertices = vertices > max / (2 * kBytesPerVertex) ? max / 2 : vertices * kBytesPerVertex;
  return for_triangles + for_vertices;
}

MemoryLimit memoryLimit()
{
  MemoryLimit limit;
  const std::uint64_t available = memAvailable();
  if (available > 0)
  {
    limit.bytes = static_cast<std::uint64_t>(kAvailableFraction * static_cast<double>(available));
    limit.source = "80 % of MemAvailable " + formatBytes(static_cast<double>(available));
  }
  else
  {
    limit.bytes = UINT64_MAX;
    limit.source = "available memory unknown";
  }
  const char* configured = std::getenv("GOD_FINGER_MEMORY_LIMIT");
  if (configured != nullptr && *configured != '\0')
  {
    char* end = nullptr;
    const double bytes = std::strtod(configured, &end);
    if (end != configured && *end == '\0' && bytes > 0.0 && bytes < 1.8e19 &&
        static_cast<std::uint64_t>(bytes) < limit.bytes)
    {
      limit.bytes = static_cast<std::uint64_t>(bytes);
      limit.source = std::string("GOD_FINGER_MEMORY_LIMIT=") + configured;
    }
  }
  return limit;
}

void checkMeshFits(std::uint64_t vertices, std::uint64_t faces, std::uint64_t extra_bytes, const std::string& claim)
{
  const std::uint64_t estimate = estimatedMeshBytes(vertices, faces);
  const std::uint64_t needed = estimate > UINT64_MAX - extra_bytes ? UINT64_MAX : estimate + extra_bytes;
  const MemoryLimit limit = memoryLimit();
  if (needed > limit.bytes)
  {
    throw ResourceLimitError(
        (claim.empty() ? "declares " + std::to_string(faces) + " faces and " + std::to_string(vertices) + " vertices"
                       : claim) +
        ": loading them needs about " + formatBytes(static_cast<double>(needed)) + ", more than the limit of " +
        formatBytes(static_cast<double>(limit.bytes)) + " (" + limit.source + ")");
  }
}

std::string formatBytes(double bytes)
{
  static const char* const kUnits[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  int unit = 0;
  while (bytes >= 1024.0 && unit < 6)
  {
    bytes /= 1024.0;
    ++unit;
  }
  char text[32];
  std::snprintf(text, sizeof(text), unit == 0 ? "%.0f %s" : "%.3g %s", bytes, kUnits[unit]);
  return text;
}
}  // namespace god_finger
