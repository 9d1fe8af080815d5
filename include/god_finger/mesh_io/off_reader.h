// Our own OFF reader (Object File Format, ASCII), used instead of assimp's, which reads out of
// bounds on some malformed files (inputs kept in test/fuzz/regressions/mesh_loading_fuzz/).
//
// Reads the optional header keyword (OFF, COFF, NOFF, CNOFF, STOFF...: whatever precedes
// "OFF"; the counts may follow it on the same line), the vertex and face counts, one vertex
// per line (x y z, anything after them such as normals or colours ignored) and one face per line
// (n, then n vertex indices, anything after them ignored). '#' starts a comment. 4-D, n-D and
// binary OFF are refused. Counts are checked against the bytes left before anything is
// allocated for them, after `check_size` has seen them. Errors are InputError, one line without
// the file's name. Not real-time.
#pragma once

#include "god_finger/mesh_io/polygon_soup.h"

#include <string>

namespace god_finger
{
PolygonSoup readOff(const std::string& bytes, const DeclaredSizeCheck& check_size = nullptr);
}  // namespace god_finger
