// How much memory a mesh or a scene will take, checked before anything is allocated for it,
// so that a file or scene too large for the machine is refused with a clear message instead
// of the process being killed by the kernel half-way through a load.
//
// Units: bytes. The estimates are of the peak while loading (the polygon and triangle soups,
// TriangleMesh::build's temporaries, then what stays: TriangleMesh and SurfaceLocator, and
// the body's collision shape, its convex hull and decomposition included), plus the file's own
// bytes, which the caller adds. Measured peak (VmHWM) of a GodFingerWorld holding a
// 1M-triangle, 500k-vertex torus read from a binary PLY: 254 MiB as a static body, 405 MiB as a
// dynamic one; the estimate says 429 MiB (+ the file's 41 MiB).
//
// The limit is 80 % of MemAvailable (/proc/meminfo; sysconf's available pages where there is no
// /proc), or GOD_FINGER_MEMORY_LIMIT (bytes, e.g. "8e9") when that is set and smaller: the
// way to keep a scene from taking a shared machine's memory. Read at every check (load time
// only, never in the 1 kHz loop).
#pragma once

#include "god_finger/support/input_error.h"

#include <cstdint>
#include <string>

namespace god_finger
{
// A load refused because it would not fit: a subclass, so that callers may tell it from a
// malformed input. The message names the input, the count, the estimate and the limit.
class ResourceLimitError : public InputError
{
 public:
  using InputError::InputError;
};

// Peak bytes of loading a mesh of `vertices` and `triangles` as a walk mesh with its
// collision shape (see the header comment).
std::uint64_t estimatedMeshBytes(std::uint64_t vertices, std::uint64_t triangles);

// The bytes a load may take now (see the header comment), and where that number came from
// ("80 % of MemAvailable", "GOD_FINGER_MEMORY_LIMIT").
struct MemoryLimit
{
  std::uint64_t bytes = 0;
  std::string source;
};
MemoryLimit memoryLimit();

// Throws ResourceLimitError "CLAIM: loading them needs about X, more than the limit of Y
// (SOURCE)" when estimatedMeshBytes(vertices, faces) + extra_bytes exceeds the limit. CLAIM
// defaults to "declares F faces and V vertices". Faces of more than 3 corners count as one
// triangle (a lower bound).
void checkMeshFits(std::uint64_t vertices, std::uint64_t faces, std::uint64_t extra_bytes = 0,
                   const std::string& claim = std::string());

// "1.5 GiB", "340 MiB", "12 KiB", "512 B".
std::string formatBytes(double bytes);
}  // namespace god_finger
