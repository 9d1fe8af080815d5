// god_finger_soft: soft bodies (issue 28) with no ROS master: loads a URDF's <deformable>s as
// the scene loader reads them and presses one, or writes a block's tetrahedral volume.
//
//   god_finger_soft FILE [--press NEWTONS] [--radius METRES] [--point]
//   god_finger_soft --block SIDE --nodes N [--grading G] --out FILE.vtk
//   god_finger_soft --ball RADIUS --nodes N --out FILE.vtk
//
// FILE: a URDF (or xacro) holding PyBullet-style <deformable> elements (scene/deformable_object.h).
// Prints each body: nodes, tetrahedra, surface triangles, volume, mass, E, nu, damping. With
// --press, the first body, glued to the table by its lowest nodes (those within 2 % of its height
// of its lowest point, at least 0.1 mm; too few to hold it is refused), is pressed at the top of its bounding box's
// centre, straight down: by a pad of radius
// --radius (default 0.01 m) as a uniform pressure, or with --point at one point; the static
// equilibrium is solved (K u = f) and the sink under the centre printed, with Boussinesq's w0 of
// the same pad on a half-space of the body's material for comparison (its finite size and the
// mesh make the difference: docs/soft_bodies.md). --block writes a cube of side SIDE (m) with
// about N nodes graded toward its top centre (soft/block_mesh.h) as a VTK file; --ball a ball of
// radius RADIUS (m) with about N nodes, its lowest point at z = 0 (soft/block_mesh.h ballTetMesh).
// Exit codes: 0 success, 2 bad options or input (one line on stderr naming it).
#include "god_finger/scene/deformable_object.h"
#include "god_finger/soft/block_mesh.h"
#include "god_finger/soft/elastic_body.h"
#include "god_finger/soft/soft_surface.h"
#include "god_finger/soft/surface_load.h"
#include "god_finger/soft/vtk_tet_reader.h"
#include "god_finger/support/input_error.h"
#include "god_finger/support/text_numbers.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <string>

namespace
{
const char* const kUsage =
    "usage: god_finger_soft FILE [--press NEWTONS] [--radius METRES] [--point]\n"
    "       god_finger_soft --block SIDE --nodes N [--grading G] --out FILE.vtk\n"
    "       god_finger_soft --ball RADIUS --nodes N --out FILE.vtk\n"
    "Loads the <deformable> bodies of a URDF and prints them; --press glues the first to the table\n"
    "and presses its top centre with a pad (or --point), printing the sink against Boussinesq's w0.\n"
    "--block writes a cube's tetrahedral volume (side in m, about N nodes, graded toward its top),\n"
    "--ball a ball's (radius in m, about N nodes, its lowest point at z = 0).\n";

struct Options
{
  std::string file;
  double press = 0.0;
  double radius = 0.01;
  bool point = false;
  double block = 0.0;
  double ball = 0.0;
  long long nodes = 0;
  double grading = 3.0;
  std::string out;
};

double numberOption(const std::string& name, const std::string& text, double low, double high)
{
  double value = 0.0;
  if (!god_finger::parseDouble(text, &value) || !(value >= low && value <= high))
  {
    throw god_finger::InputError("option " + name + " '" + text + "' is not a number in [" +
                                 god_finger::roundedNumber(low) + ", " + god_finger::roundedNumber(high) + "]");
  }
  return value;
}

Options parse(int argc, char** argv)
{
  Options options;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    const auto value = [&]() -> std::string
    {
      if (i + 1 >= argc)
      {
        throw god_finger::InputError("option " + arg + " needs a value");
      }
      return argv[++i];
    };
    if (arg == "--press")
    {
      options.press = numberOption(arg, value(), 1e-6, 1e4);
    }
    else if (arg == "--radius")
    {
      options.radius = numberOption(arg, value(), 1e-5, 1.0);
    }
    else if (arg == "--point")
    {
      options.point = true;
    }
    else if (arg == "--block")
    {
      options.block = numberOption(arg, value(), 1e-3, 10.0);
    }
    else if (arg == "--ball")
    {
      options.ball = numberOption(arg, value(), 1e-3, 10.0);
    }
    else if (arg == "--nodes")
    {
      options.nodes = static_cast<long long>(numberOption(arg, value(), 8, 200000));
    }
    else if (arg == "--grading")
    {
      options.grading = numberOption(arg, value(), 0.0, 10.0);
    }
    else if (arg == "--out")
    {
      options.out = value();
    }
    else if (arg == "--help" || arg == "-h")
    {
      std::cout << kUsage;
      std::exit(0);
    }
    else if (!arg.empty() && arg[0] == '-')
    {
      throw god_finger::InputError("unknown option '" + arg + "'");
    }
    else if (options.file.empty())
    {
      options.file = arg;
    }
    else
    {
      throw god_finger::InputError("one FILE only ('" + arg + "' is a second)");
    }
  }
  if (options.block > 0.0 && options.ball > 0.0)
  {
    throw god_finger::InputError("--block and --ball: one volume at a time");
  }
  const bool writing = options.block > 0.0 || options.ball > 0.0;
  if (writing ? (options.nodes == 0 || options.out.empty() || !options.file.empty()) : options.file.empty())
  {
    throw god_finger::InputError(writing ? std::string(options.block > 0.0 ? "--block" : "--ball") +
                                               " needs --nodes and --out, and no FILE"
                                         : "no FILE given");
  }
  return options;
}

void writeVolume(const Options& options)
{
  const int cells = god_finger::cubeCellsForNodes(static_cast<int>(options.nodes));
  god_finger::TetMesh mesh;
  std::string title;
  if (options.ball > 0.0)
  {
    mesh = god_finger::ballTetMesh(options.ball, std::max(2, cells));
    title = "god_finger ball of radius " + god_finger::roundedNumber(options.ball) + " m, " +
            std::to_string(mesh.nodes.size()) + " nodes";
  }
  else
  {
    god_finger::BlockMeshSpec spec;
    spec.size = Eigen::Vector3d::Constant(options.block);
    spec.cells = {cells, cells, cells};
    spec.grading = options.grading;
    mesh = god_finger::blockTetMesh(spec);
    title = "god_finger block " + god_finger::roundedNumber(options.block) + " m, " +
            std::to_string(mesh.nodes.size()) + " nodes, grading " + god_finger::roundedNumber(options.grading);
  }
  std::ofstream file(options.out);
  file << god_finger::vtkTetMeshText(mesh, title);
  if (!file.good())
  {
    throw god_finger::InputError("cannot write '" + options.out + "'");
  }
  std::printf("%s: %zu nodes, %zu tetrahedra\n", options.out.c_str(), mesh.nodes.size(), mesh.tets.size());
}

void press(const god_finger::DeformableDescription& body, const Options& options)
{
  Eigen::Vector3d lower = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d upper = -lower;
  for (const Eigen::Vector3d& node : body.mesh.nodes)
  {
    lower = lower.cwiseMin(node);
    upper = upper.cwiseMax(node);
  }
  // Glued where it rests, as the physics world glues it (soft/soft_surface.h).
  const std::vector<int> glued = god_finger::nodesGluedToSupport(body.mesh, Eigen::Isometry3d::Identity());
  god_finger::ElasticBody soft(body.mesh, body.material, glued, 1e-3, Eigen::Vector3d::Zero());
  const Eigen::Vector3d top(0.5 * (lower.x() + upper.x()), 0.5 * (lower.y() + upper.y()), upper.z());
  Eigen::VectorXd forces = Eigen::VectorXd::Zero(3 * soft.nodeCount());
  const Eigen::Vector3d down(0.0, 0.0, -options.press);
  Eigen::Vector3d at = top;
  double area = 0.0;
  if (options.point)
  {
    at = god_finger::addPointForce(body.mesh.nodes, soft.surface(), top, down, &forces);
  }
  else
  {
    god_finger::PadDisk pad;
    pad.centre = top;
    pad.radius = options.radius;
    area = god_finger::addPadPressure(body.mesh.nodes, soft.surface(), pad, down, &forces);
    if (area <= 0.0)
    {
      throw god_finger::InputError("the pad covers no face at the top of '" + body.name + "'");
    }
  }
  const Eigen::VectorXd u = soft.staticDisplacement(forces);
  // The sink under the centre: the displacement of the surface point there, by its face's weights.
  const double sink = -god_finger::surfaceDisplacementAt(body.mesh.nodes, soft.surface(), u, at).z();
  const double w0 = god_finger::boussinesqCentreSink(options.press, options.radius, body.material.young_modulus,
                                                     body.material.poisson_ratio);
  std::printf("press '%s': %zu nodes glued at z = %.4g m; %.4g N down at (%.4g, %.4g, %.4g) m\n", body.name.c_str(),
              glued.size(), lower.z(), options.press, at.x(), at.y(), at.z());
  if (options.point)
  {
    std::printf("  point load: sink %.4g mm (a point load's has no limit as the mesh is refined)\n", 1e3 * sink);
  }
  else
  {
    std::printf(
        "  pad of radius %.4g m, covered %.4g cm^2 (pi a^2 = %.4g cm^2): sink %.4g mm; Boussinesq's w0 on a "
        "half-space %.4g mm (ratio %.3f)\n",
        options.radius, 1e4 * area, 1e4 * M_PI * options.radius * options.radius, 1e3 * sink, 1e3 * w0, sink / w0);
  }
}
}  // namespace

int main(int argc, char** argv)
{
  try
  {
    const Options options = parse(argc, argv);
    if (options.block > 0.0 || options.ball > 0.0)
    {
      writeVolume(options);
      return 0;
    }
    const std::vector<god_finger::DeformableDescription> bodies = god_finger::loadDeformables(options.file);
    if (bodies.empty())
    {
      throw god_finger::InputError("URDF '" + options.file + "' holds no <deformable>");
    }
    for (const god_finger::DeformableDescription& body : bodies)
    {
      god_finger::ElasticBody soft(body.mesh, body.material, {}, 1e-3, Eigen::Vector3d::Zero());
      std::printf(
          "deformable '%s' (%s, %s): %zu nodes, %zu tetrahedra, %zu surface triangles, volume %.4g cm^3, "
          "mass %.4g kg, E %.4g Pa, nu %.3g, damping %.3g s, friction %.3g\n",
          body.name.c_str(), body.volume_file.c_str(), body.model.c_str(), body.mesh.nodes.size(),
          body.mesh.tets.size(), soft.surface().size(), 1e6 * soft.volume(), body.mass, body.material.young_modulus,
          body.material.poisson_ratio, body.material.stiffness_damping, body.friction);
    }
    if (options.press > 0.0)
    {
      press(bodies.front(), options);
    }
  }
  catch (const god_finger::InputError& error)
  {
    std::cerr << "god_finger_soft: " << error.what() << "\n";
    return 2;
  }
  return 0;
}
