// The soft body's finite elements against exact solutions: rigid motion stores no energy, a
// uniform strain is reproduced exactly, a held load settles to the static solution, damping
// takes the energy out, and a step allocates nothing.
#include "god_finger/soft/elastic_body.h"
#include "allocation_counter.h"
#include "god_finger/soft/block_mesh.h"
#include "god_finger/soft/surface_load.h"
#include "god_finger/support/input_error.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace god_finger
{
namespace
{
SoftMaterial rubber()
{
  SoftMaterial material;
  material.young_modulus = 50e3;
  material.poisson_ratio = 0.45;
  material.density = 1000.0;
  material.stiffness_damping = 0.01;
  return material;
}

TetMesh cube(int cells, double grading = 1.0)
{
  BlockMeshSpec spec;
  spec.cells = {cells, cells, cells};
  spec.grading = grading;
  return blockTetMesh(spec);
}

// The nodal forces of 1 N pressed down by a 2 cm pad at the centre of the cube's top face.
Eigen::VectorXd topPress(const ElasticBody& body)
{
  Eigen::VectorXd forces = Eigen::VectorXd::Zero(3 * body.nodeCount());
  PadDisk pad;
  pad.centre = Eigen::Vector3d(0.0, 0.0, 0.1);
  pad.radius = 0.02;
  addPadPressure(body.restMesh().nodes, body.surface(), pad, Eigen::Vector3d(0, 0, -1.0), &forces);
  return forces;
}

TEST(ElasticBody, StiffnessOfARigidMotionIsZero)
{
  const TetMesh mesh = cube(3, 1.5);
  ElasticBody body(mesh, rubber(), {}, 1e-3, Eigen::Vector3d::Zero(), {0});
  const Eigen::SparseMatrix<double>& k = body.stiffness();
  Eigen::VectorXd translation(3 * body.nodeCount());
  Eigen::VectorXd rotation(3 * body.nodeCount());
  Eigen::VectorXd stretch(3 * body.nodeCount());
  for (int node = 0; node < body.nodeCount(); ++node)
  {
    translation.segment<3>(3 * node) = Eigen::Vector3d(0.3, -0.2, 0.1);
    rotation.segment<3>(3 * node) = Eigen::Vector3d(0.0, 0.0, 1.0).cross(mesh.nodes[node]);
    stretch.segment<3>(3 * node) = Eigen::Vector3d(mesh.nodes[node].x(), 0.0, 0.0);
  }
  const double scale = k.norm();
  EXPECT_LT((k * translation).norm(), 1e-12 * scale);
  EXPECT_LT((k * rotation).norm(), 1e-12 * scale);
  // A stretch is not rigid: it stores E' / 2 strain^2 V, E' = lambda + 2 mu (no lateral strain).
  const double energy = 0.5 * stretch.dot(k * stretch);
  const SoftMaterial material = rubber();
  EXPECT_NEAR(energy, 0.5 * (material.lameLambda() + 2.0 * material.shearModulus()) * body.volume(), 1e-9 * energy);
  EXPECT_NEAR(body.volume(), 1e-3, 1e-15);
  EXPECT_NEAR(body.mass(), 1.0, 1e-12);
}

TEST(ElasticBody, TheStepsStiffnessWithoutTheMatrixIsTheMatrix)
{
  // K u per element (deviatoric stress, the nodes' averaged pressure) against the assembled K,
  // on a graded mesh and a random displacement.
  const TetMesh mesh = cube(4, 2.0);
  ElasticBody body(mesh, rubber(), {0, 1, 2}, 1e-3, Eigen::Vector3d(0.0, 0.0, -9.81));
  std::srand(7);
  const Eigen::VectorXd u = 1e-3 * Eigen::VectorXd::Random(3 * body.nodeCount());
  Eigen::VectorXd ku(3 * body.nodeCount());
  body.applyStiffness(u, &ku);
  const Eigen::VectorXd expected = body.stiffness() * u;
  EXPECT_LT((ku - expected).norm(), 1e-12 * expected.norm());
  EXPECT_GT(expected.norm(), 0.0);
}

TEST(ElasticBody, UniaxialStressShortensTheBlockByFLOverEA)
{
  // Rollers under the bottom, a uniform pressure on top: linear tetrahedra represent the uniform
  // strain exactly, on a graded mesh too; the block widens by nu times its strain.
  const TetMesh mesh = cube(4, 1.7);
  const std::vector<int> bottom = nodesAtHeight(mesh, 0.0, 1e-12);
  std::vector<int> rollers;
  for (int node : bottom)
  {
    rollers.push_back(3 * node + 2);
  }
  rollers.insert(rollers.end(), {0, 1, 3 * 4 + 1});
  ElasticBody body(mesh, rubber(), {}, 1e-3, Eigen::Vector3d::Zero(), rollers);
  Eigen::VectorXd forces = Eigen::VectorXd::Zero(3 * body.nodeCount());
  PadDisk plate;
  plate.centre = Eigen::Vector3d(0.0, 0.0, 0.1);
  plate.radius = 0.2;
  EXPECT_NEAR(addPadPressure(mesh.nodes, body.surface(), plate, Eigen::Vector3d(0, 0, -2.0), &forces), 0.01, 1e-15);
  const Eigen::VectorXd u = body.staticDisplacement(forces);
  const double strain = 2.0 / (0.01 * 50e3);  // F / (A E)
  for (int node = 0; node < body.nodeCount(); ++node)
  {
    const Eigen::Vector3d& x = mesh.nodes[node];
    const Eigen::Vector3d expected((x.x() + 0.05) * 0.45 * strain, (x.y() + 0.05) * 0.45 * strain, -x.z() * strain);
    ASSERT_LT((u.segment<3>(3 * node) - expected).norm(), 1e-12) << "node " << node;
  }
}

TEST(ElasticBody, AHeldLoadSettlesToTheStaticSolutionAndDampingTakesTheEnergyOut)
{
  const TetMesh mesh = cube(4, 1.5);
  ElasticBody body(mesh, rubber(), nodesAtHeight(mesh, 0.0, 1e-12), 1e-3, Eigen::Vector3d::Zero());
  const Eigen::VectorXd forces = topPress(body);
  const Eigen::VectorXd settled = body.staticDisplacement(forces);
  // It settles until it sleeps (ElasticBodySleep below): within 1e-3 of the static solution.
  for (int step = 0; step < 3000 && !body.sleeping(); ++step)
  {
    body.step(forces);
  }
  EXPECT_TRUE(body.sleeping());
  EXPECT_LT((body.displacement() - settled).norm(), 1e-3 * settled.norm());
  EXPECT_EQ(body.kineticEnergy(), 0.0);
  // Let go: the energy it stored (the work of the load, 1/2 f.u) only ever decreases.
  const Eigen::VectorXd none = Eigen::VectorXd::Zero(3 * body.nodeCount());
  EXPECT_NEAR(body.elasticEnergy(), 0.5 * forces.dot(settled), 1e-3 * 0.5 * forces.dot(settled));
  double energy = body.elasticEnergy() + body.kineticEnergy();
  for (int step = 0; step < 2000; ++step)
  {
    body.step(none);
    const double now = body.elasticEnergy() + body.kineticEnergy();
    ASSERT_LE(now, energy * (1.0 + 1e-12)) << "step " << step;
    energy = now;
  }
  EXPECT_LT(energy, 1e-6 * 0.5 * forces.dot(settled));
}

TEST(ElasticBody, GravitySagsAGluedBlockAndFixedNodesNeverMove)
{
  const TetMesh mesh = cube(3);
  const std::vector<int> bottom = nodesAtHeight(mesh, 0.0, 1e-12);
  ElasticBody body(mesh, rubber(), bottom, 1e-3, Eigen::Vector3d(0, 0, -9.81));
  const Eigen::VectorXd none = Eigen::VectorXd::Zero(3 * body.nodeCount());
  for (int step = 0; step < 200; ++step)
  {
    body.step(none);
  }
  for (int node : bottom)
  {
    EXPECT_TRUE(body.isFixed(node));
    EXPECT_EQ(body.displacement().segment<3>(3 * node).norm(), 0.0);
  }
  // Its own weight on a glued column: the top sinks about rho g L^2 / (2 E') with E' between E
  // and the constrained modulus; here between 0.98 and 3.3 of rho g L^2 / (2 E) = 0.98 mm.
  const double top = body.position(body.nodeCount() - 1).z() - 0.1;
  EXPECT_LT(top, -0.98e-3 * 0.2);
  EXPECT_GT(top, -0.98e-3 * 1.2);
}

TEST(ElasticBody, AStepAllocatesNothing)
{
  const TetMesh mesh = cube(5, 1.5);
  ElasticBody body(mesh, rubber(), nodesAtHeight(mesh, 0.0, 1e-12), 1e-3, Eigen::Vector3d(0, 0, -9.81));
  Eigen::VectorXd forces = Eigen::VectorXd::Zero(3 * body.nodeCount());
  std::vector<Eigen::Vector3d> positions;
  body.positions(&positions);
  body.step(forces);
  const long before = test::allocationCount();
  for (int step = 0; step < 10; ++step)
  {
    forces.setZero();
    body.positions(&positions);
    PadDisk pad;
    pad.centre = Eigen::Vector3d(0.0, 0.0, 0.1);
    pad.radius = 0.01;
    addPadPressure(positions, body.surface(), pad, Eigen::Vector3d(0, 0, -1.0), &forces);
    addPointForce(positions, body.surface(), Eigen::Vector3d(0.01, 0.0, 0.1), Eigen::Vector3d(0, 0, -0.5), &forces);
    body.step(forces);
  }
  EXPECT_EQ(test::allocationCount() - before, 0);
}

TEST(ElasticBody, RefusesWhatCannotMove)
{
  const TetMesh mesh = cube(1);
  std::vector<int> every(mesh.nodes.size());
  for (std::size_t n = 0; n < every.size(); ++n)
  {
    every[n] = static_cast<int>(n);
  }
  try
  {
    ElasticBody body(mesh, rubber(), every, 1e-3, Eigen::Vector3d::Zero());
    FAIL() << "no error";
  }
  catch (const InputError& error)
  {
    EXPECT_STREQ(error.what(), "soft body: every node is fixed: nothing can move");
  }
  // Held by one node (or two), it can still turn: no equilibrium, said so, not a number.
  for (const std::vector<int>& held : {std::vector<int>{0}, std::vector<int>{0, 7}})
  {
    ElasticBody loose(cube(3), rubber(), held, 1e-3, Eigen::Vector3d(0, 0, -9.81));
    try
    {
      loose.staticDisplacement(Eigen::VectorXd::Zero(3 * loose.nodeCount()));
      FAIL() << "no error";
    }
    catch (const InputError& error)
    {
      const std::string message = error.what();
      EXPECT_EQ(message.substr(0, 92),
                "soft body: its fixed nodes do not hold it (it can still turn or slide: reciprocal "
                "condition ")
          << message;
      EXPECT_NE(message.find("); fix at least three nodes not on one line"), std::string::npos) << message;
    }
  }
  try
  {
    ElasticBody body(mesh, rubber(), {8}, 1e-3, Eigen::Vector3d::Zero());
    FAIL() << "no error";
  }
  catch (const InputError& error)
  {
    EXPECT_STREQ(error.what(), "soft body: fixed node 8 is not one of its 8 nodes");
  }
}
}  // namespace
}  // namespace god_finger

namespace god_finger
{
namespace
{
TEST(ElasticBodySleep, AHeldPressSleepsNearItsEquilibriumAndAChangedForceWakesIt)
{
  const TetMesh mesh = cube(4, 1.5);
  ElasticBody body(mesh, rubber(), nodesAtHeight(mesh, 0.0, 1e-12), 1e-3, Eigen::Vector3d(0, 0, -9.81));
  const Eigen::VectorXd forces = topPress(body);
  const Eigen::VectorXd settled = body.staticDisplacement(forces);
  int steps = 0;
  while (!body.sleeping() && steps < 5000)
  {
    body.step(forces);
    ++steps;
  }
  ASSERT_TRUE(body.sleeping()) << "still awake after 5 s";
  std::printf("asleep after %d steps, %.2e of the settled displacement off it\n", steps,
              (body.displacement() - settled).norm() / settled.norm());
  EXPECT_LT((body.displacement() - settled).norm(), 1e-3 * settled.norm());
  EXPECT_EQ(body.velocity().norm(), 0.0);
  // Asleep: steps under the same forces cost nothing and change nothing, bit for bit.
  const long solved = body.solvedSteps();
  const Eigen::VectorXd frozen = body.displacement();
  for (int step = 0; step < 1000; ++step)
  {
    body.step(forces);
  }
  EXPECT_EQ(body.solvedSteps(), solved);
  EXPECT_EQ(body.displacement(), frozen);
  // A changed force wakes it on that step; let go, it springs back and sleeps again at rest
  // under its own weight.
  const Eigen::VectorXd weight_only = Eigen::VectorXd::Zero(3 * body.nodeCount());
  body.step(weight_only);
  EXPECT_FALSE(body.sleeping());
  EXPECT_EQ(body.solvedSteps(), solved + 1);
  EXPECT_NE(body.displacement(), frozen);
  const Eigen::VectorXd sag = body.staticDisplacement(weight_only);
  for (steps = 0; !body.sleeping() && steps < 5000; ++steps)
  {
    body.step(weight_only);
  }
  ASSERT_TRUE(body.sleeping());
  EXPECT_LT((body.displacement() - sag).norm(), 1e-3 * (settled - sag).norm());
}
}  // namespace
}  // namespace god_finger
