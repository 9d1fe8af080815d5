// Writes triangle soups to files: OBJ, OFF and ASCII STL by our own code (simple text
// formats), PLY and DAE (COLLADA) through assimp's exporter. The format follows the file
// extension. Throws InputError when the file cannot be written or the extension is unknown.
#pragma once

#include "god_finger/geometry/triangle_mesh.h"

#include <string>

namespace god_finger
{
void writeTriangleSoup(const TriangleSoup& soup, const std::string& path);
}  // namespace god_finger
