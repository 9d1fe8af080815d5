// god_finger_make_meshes OUTDIR: writes the meshes shipped in urdf/meshes (regenerate them
// with this tool, so that they stay exactly what the generators make).
#include "god_finger/support/input_error.h"
#include "god_finger/geometry/mesh_primitives.h"
#include "god_finger/mesh_io/mesh_writer.h"

#include <iostream>

int main(int argc, char** argv)
{
  if (argc != 2)
  {
    std::cerr << "usage: god_finger_make_meshes OUTDIR\n";
    return 2;
  }
  const std::string folder = argv[1];
  try
  {
    using god_finger::writeTriangleSoup;
    writeTriangleSoup(god_finger::makeBox(Eigen::Vector3d::Constant(0.05)), folder + "/box.stl");
    writeTriangleSoup(god_finger::makeIcosphere(0.05, 3), folder + "/sphere.obj");
    writeTriangleSoup(god_finger::makeCylinder(0.03, 0.12, 48), folder + "/cylinder.ply");
    writeTriangleSoup(god_finger::makeTorus(0.06, 0.02, 48, 24), folder + "/torus.dae");
    writeTriangleSoup(god_finger::makeLBlock(0.05, 0.05), folder + "/l_block.off");
    writeTriangleSoup(god_finger::makeMug(0.04, 0.09, 0.005, 0.006, 48), folder + "/mug.obj");
  }
  catch (const god_finger::InputError& error)
  {
    std::cerr << "god_finger_make_meshes: " << error.what() << "\n";
    return 2;
  }
  return 0;
}
