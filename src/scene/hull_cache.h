// The disk cache of convex decompositions (convex_decomposition.h): one file per decomposition,
// <directory>/<key>.hulls, where key = decompositionKey(mesh) (content hash + version).
//
// Folder: $GOD_FINGER_CACHE_DIR when set, else $XDG_CACHE_HOME/god_finger/hulls, else
// $HOME/.cache/god_finger/hulls; created when first written.
// File: "GFHULLS1", the decomposition version (uint32), the key (32 bytes), the hull count
// (uint32), per hull its point count (uint32) and points (3 doubles each, metres), then an
// FNV-1a 64 checksum of everything before it; native byte order (a cache is per machine).
// Writes are atomic (a temporary file in the same folder, then rename), so that a reader never
// sees half a file, even with two processes loading the same scene.
//
// Failure is never fatal: a missing file is a miss; a corrupt, truncated or unreadable file, or
// a folder that cannot be written, gives one line on stderr and the caller decomposes again
// (and, for a corrupt file, replaces it). Not real-time.
#pragma once

#include "god_finger/scene/convex_decomposition.h"

#include <optional>
#include <string>

namespace god_finger
{
// "" when no folder can be named (no variable set).
std::string hullCacheDirectory();

// The hulls stored under `key`, or nullopt (see the header comment).
std::optional<HullSet> readHullCache(const std::string& directory, const std::string& key);

// Stores `hulls` under `key`; false (after one warning per folder and process) on failure.
bool writeHullCache(const std::string& directory, const std::string& key, const HullSet& hulls);
}  // namespace god_finger
