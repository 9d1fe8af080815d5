// Our own PLY reader (ascii, binary_little_endian and binary_big_endian 1.0), used instead of
// assimp's, which runs out of memory or loops forever on some malformed files
// (inputs kept in test/fuzz/regressions/mesh_loading_fuzz/).
//
// Reads the "vertex" element's x, y, z (any numeric type) and the "face" element's
// vertex_indices (or vertex_index) list; every other element and property is read past.
// Header lines that are neither keywords nor comments (older Blender exporters write free
// text) are skipped, as other readers do. Every element count and list length is checked
// against the bytes left in the file before anything is allocated for it, so that a corrupt
// file costs at most a few times its own size in memory and gives an InputError: one line,
// without the file's name (the caller adds it). `check_size` sees the "vertex" and "face"
// elements' counts right after the header, before any of them is read. Not real-time.
#pragma once

#include "god_finger/mesh_io/polygon_soup.h"

#include <string>

namespace god_finger
{
PolygonSoup readPly(const std::string& bytes, const DeclaredSizeCheck& check_size = nullptr);
}  // namespace god_finger
