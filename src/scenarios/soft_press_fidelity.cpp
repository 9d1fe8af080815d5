#include "god_finger/scenarios/soft_press_fidelity.h"

#include "god_finger/soft/block_mesh.h"
#include "god_finger/soft/elastic_body.h"
#include "god_finger/soft/surface_load.h"
#include "god_finger/support/text_numbers.h"

#include <cmath>

namespace god_finger
{
namespace
{
SoftMaterial material(const SoftPressSetup& setup)
{
  SoftMaterial result;
  result.young_modulus = setup.young_modulus;
  result.poisson_ratio = setup.poisson_ratio;
  result.density = 1000.0;
  return result;
}
}  // namespace

SoftPressResult pressSoftBlock(const SoftPressSetup& setup)
{
  BlockMeshSpec spec;
  spec.size = Eigen::Vector3d::Constant(setup.block_size);
  const int cells = cubeCellsForNodes(setup.nodes);
  spec.cells = {cells, cells, cells};
  spec.grading = setup.grading;
  TetMesh mesh = blockTetMesh(spec);
  const double tolerance = 1e-9 * setup.block_size;
  const std::vector<int> bottom = nodesAtHeight(mesh, 0.0, tolerance);
  const Eigen::Vector3d top_centre(0.0, 0.0, setup.block_size);
  SoftPressResult result;
  result.nodes = static_cast<int>(mesh.nodes.size());
  result.tets = static_cast<int>(mesh.tets.size());
  result.boussinesq = boussinesqCentreSink(setup.force, setup.pad_radius, setup.young_modulus, setup.poisson_ratio);

  ElasticBody body(mesh, material(setup), bottom, 1e-3, Eigen::Vector3d::Zero());
  result.factor_nonzeros = body.factorNonZeros();
  const Eigen::Vector3d down(0.0, 0.0, -setup.force);
  Eigen::VectorXd forces = Eigen::VectorXd::Zero(3 * body.nodeCount());
  PadDisk pad;
  pad.centre = top_centre;
  pad.radius = setup.pad_radius;
  result.covered_area = addPadPressure(body.restMesh().nodes, body.surface(), pad, down, &forces);
  result.pad_centre =
      -surfaceDisplacementAt(body.restMesh().nodes, body.surface(), body.staticDisplacement(forces), top_centre).z();
  forces.setZero();
  addPointForce(body.restMesh().nodes, body.surface(), top_centre, down, &forces);
  result.point_centre =
      -surfaceDisplacementAt(body.restMesh().nodes, body.surface(), body.staticDisplacement(forces), top_centre).z();

  // The plate: the bottom on rollers (every bottom node held in z; its first corner in x and y,
  // the next corner along x in y: no rigid motion, free lateral expansion), the top face loaded
  // as a uniform pressure loads it.
  {
    const std::vector<int> top = nodesAtHeight(mesh, setup.block_size, tolerance);
    std::vector<int> rollers;
    for (int node : bottom)
    {
      rollers.push_back(3 * node + 2);
    }
    rollers.push_back(3 * bottom.front());
    rollers.push_back(3 * bottom.front() + 1);
    rollers.push_back(3 * cells + 1);  // node (cells, 0, 0): the bottom's corner along x
    ElasticBody free_body(mesh, material(setup), {}, 1e-3, Eigen::Vector3d::Zero(), rollers);
    Eigen::VectorXd plate = Eigen::VectorXd::Zero(3 * free_body.nodeCount());
    PadDisk whole;
    whole.radius = 2.0 * setup.block_size;
    whole.centre = top_centre;
    addPadPressure(free_body.restMesh().nodes, free_body.surface(), whole, down, &plate);
    const Eigen::VectorXd u = free_body.staticDisplacement(plate);
    double top_sum = 0.0;
    double bottom_sum = 0.0;
    for (int node : top)
    {
      top_sum += u(3 * node + 2);
    }
    for (int node : bottom)
    {
      bottom_sum += u(3 * node + 2);
    }
    result.plate_shortening = bottom_sum / bottom.size() - top_sum / top.size();
    result.plate_expected =
        setup.force * setup.block_size / (setup.young_modulus * setup.block_size * setup.block_size);
  }
  return result;
}

std::string softPressJson(const SoftPressSetup& setup, const SoftPressResult& result)
{
  return "{\"nodes\": " + std::to_string(result.nodes) + ", \"tets\": " + std::to_string(result.tets) +
         ", \"grading\": " + jsonNumber(setup.grading) + ", \"young_modulus\": " + jsonNumber(setup.young_modulus) +
         ", \"poisson_ratio\": " + jsonNumber(setup.poisson_ratio) +
         ", \"block_size\": " + jsonNumber(setup.block_size) + ", \"pad_radius\": " + jsonNumber(setup.pad_radius) +
         ", \"force\": " + jsonNumber(setup.force) + ", \"boussinesq\": " + jsonNumber(result.boussinesq) +
         ", \"pad_centre\": " + jsonNumber(result.pad_centre) +
         ", \"point_centre\": " + jsonNumber(result.point_centre) +
         ", \"covered_area\": " + jsonNumber(result.covered_area) +
         ", \"plate_shortening\": " + jsonNumber(result.plate_shortening) +
         ", \"plate_expected\": " + jsonNumber(result.plate_expected) +
         ", \"factor_nonzeros\": " + std::to_string(result.factor_nonzeros) + "}";
}
}  // namespace god_finger
