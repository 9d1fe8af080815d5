// A free soft body (issue 28's pinch_soft): on its support plane it settles under its weight and
// sleeps, the plane carrying exactly that weight and no node below it; its friction holds a push
// under friction x weight and lets a larger one slide; turned as a whole it keeps its shape
// (global corotation); the ball mesh is a ball.
#include "allocation_counter.h"
#include "god_finger/soft/block_mesh.h"
#include "god_finger/soft/elastic_body.h"
#include "god_finger/support/input_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>

namespace god_finger
{
namespace
{
SoftMaterial rubber(double mass, const TetMesh& mesh)
{
  SoftMaterial material;
  material.young_modulus = 100e3;
  material.poisson_ratio = 0.45;
  double volume = 0.0;
  for (const std::array<int, 4>& tet : mesh.tets)
  {
    volume += signedTetVolume(mesh.nodes, tet);
  }
  material.density = mass / volume;
  material.stiffness_damping = 0.01;
  return material;
}

TetMesh block5cm()
{
  BlockMeshSpec spec;
  spec.size = Eigen::Vector3d(0.05, 0.05, 0.05);
  spec.cells = {6, 6, 6};
  return blockTetMesh(spec);
}

double lowestHeight(const ElasticBody& body)
{
  double lowest = std::numeric_limits<double>::infinity();
  for (int node = 0; node < body.nodeCount(); ++node)
  {
    lowest = std::min(lowest, body.position(node).z());
  }
  return lowest;
}

// Steps until the body sleeps (at most `steps`); returns the steps taken.
int settle(ElasticBody* body, const Eigen::VectorXd& forces, int steps)
{
  int taken = 0;
  while (taken < steps && !(body->sleeping() && taken > 0))
  {
    body->step(forces);
    ++taken;
  }
  return taken;
}

TEST(FreeSoftBody, ABlockOnItsSupportCarriesItsWeightSleepsAndSagsAsAGluedOne)
{
  const TetMesh mesh = block5cm();
  const SoftMaterial material = rubber(0.1, mesh);
  const Eigen::Vector3d gravity(0, 0, -9.81);
  ElasticBody body(mesh, material, {}, 1e-3, gravity);
  SupportPlane plane;
  plane.friction = 0.8;
  body.setSupport(plane);
  const Eigen::VectorXd none = Eigen::VectorXd::Zero(3 * body.nodeCount());
  const int steps = settle(&body, none, 3000);
  EXPECT_TRUE(body.sleeping()) << "after " << steps << " steps";
  EXPECT_NEAR(body.supportForce(), 0.1 * 9.81, 1e-6);
  EXPECT_GE(lowestHeight(body), -1e-8);  // to the contact solver's tolerance: nanometres
  // Glued by its bottom face, the same block under the same weight: its top sinks as much (the
  // free one's bottom may spread a little along the plane within its friction).
  ElasticBody glued(mesh, material, nodesAtHeight(mesh, 0.0, 1e-12), 1e-3, gravity);
  const Eigen::VectorXd held = glued.staticDisplacement(none);
  const int top = body.nodeCount() - 1;
  EXPECT_LT(held(3 * top + 2), -1e-6);
  EXPECT_NEAR(body.displacement()(3 * top + 2), held(3 * top + 2), 0.1 * std::abs(held(3 * top + 2)));
  // Asleep, it stays asleep and costs nothing.
  const long solved = body.solvedSteps();
  body.step(none);
  EXPECT_EQ(body.solvedSteps(), solved);
}

TEST(FreeSoftBody, FrictionHoldsAPushUnderItsBoundAndLetsALargerOneSlide)
{
  const TetMesh mesh = block5cm();
  const double weight = 0.1 * 9.81;
  const auto pushed = [&](double push)
  {
    ElasticBody body(mesh, rubber(0.1, mesh), {}, 1e-3, Eigen::Vector3d(0, 0, -9.81));
    SupportPlane plane;
    plane.friction = 0.5;
    body.setSupport(plane);
    const Eigen::VectorXd none = Eigen::VectorXd::Zero(3 * body.nodeCount());
    settle(&body, none, 3000);
    // The push along x spread over the nodes of its lowest layer (where the friction acts: no
    // tipping moment).
    const std::vector<int> bottom = nodesAtHeight(mesh, 0.0, 1e-12);
    Eigen::VectorXd forces = none;
    for (int node : bottom)
    {
      forces(3 * node) = push / static_cast<double>(bottom.size());
    }
    for (int step = 0; step < 300; ++step)
    {
      body.step(forces);
    }
    double mean_x = 0.0;
    for (int node = 0; node < body.nodeCount(); ++node)
    {
      mean_x += body.displacement()(3 * node) / body.nodeCount();
    }
    return mean_x;
  };
  const double held = pushed(0.6 * 0.5 * weight);
  const double slid = pushed(1.5 * 0.5 * weight);
  EXPECT_LT(std::abs(held), 2e-4) << "under the bound: only the elastic shear";
  // Over it: (1.5 - 1) friction x weight accelerates 0.1 kg for 0.3 s: 0.11 m (less while it
  // starts).
  EXPECT_GT(slid, 0.05);
}

TEST(FreeSoftBody, TurnedAsAWholeItKeepsItsShape)
{
  const TetMesh mesh = ballTetMesh(0.03, 5);
  ElasticBody body(mesh, rubber(0.1, mesh), {}, 1e-3, Eigen::Vector3d::Zero());
  // A rigid turn of 60 degrees about x through the ball's centre.
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(M_PI / 3.0, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Eigen::Vector3d centre(0.0, 0.0, 0.03);
  Eigen::VectorXd turned(3 * body.nodeCount());
  for (int node = 0; node < body.nodeCount(); ++node)
  {
    turned.segment<3>(3 * node) = turn * (mesh.nodes[node] - centre) + centre - mesh.nodes[node];
  }
  body.restAt(turned);
  EXPECT_LT(body.elasticEnergy(), 1e-15);
  const Eigen::VectorXd none = Eigen::VectorXd::Zero(3 * body.nodeCount());
  for (int step = 0; step < 50; ++step)
  {
    body.step(none);
  }
  // Linear elements would take the turn for a strain of 1 - cos 60 = 50 % and swell it back.
  EXPECT_LT((body.displacement() - turned).lpNorm<Eigen::Infinity>(), 1e-9);
}

// Turned over (a ball rolled half a turn), the nodes that were on top rest on the support: every
// surface node can touch it (kSupportResponseBudget). Before, only the lowest quarter at rest
// could, and the turned ball sank through the plane.
TEST(FreeSoftBody, TurnedOverItStillRestsOnItsSupport)
{
  const TetMesh mesh = ballTetMesh(0.03, 5);
  ElasticBody body(mesh, rubber(0.1, mesh), {}, 1e-3, Eigen::Vector3d(0, 0, -9.81));
  SupportPlane plane;
  plane.friction = 0.8;
  body.setSupport(plane);
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.9 * M_PI, Eigen::Vector3d::UnitX()).toRotationMatrix();
  const Eigen::Vector3d centre(0.0, 0.0, 0.03);
  Eigen::VectorXd turned(3 * body.nodeCount());
  for (int node = 0; node < body.nodeCount(); ++node)
  {
    turned.segment<3>(3 * node) = turn * (mesh.nodes[node] - centre) + centre - mesh.nodes[node];
  }
  body.restAt(turned);
  const Eigen::VectorXd none = Eigen::VectorXd::Zero(3 * body.nodeCount());
  double lowest = std::numeric_limits<double>::infinity();
  for (int step = 0; step < 2000; ++step)
  {
    body.step(none);
    lowest = std::min(lowest, lowestHeight(body));
  }
  std::printf("turned 0.9 pi: lowest node over 2 s %.3g m, support at the end %.6f N\n", lowest, body.supportForce());
  EXPECT_GE(lowest, -1e-8);
  EXPECT_NEAR(body.supportForce(), 0.1 * 9.81, 1e-4);
}

TEST(FreeSoftBody, AStepOnItsSupportAllocatesNothing)
{
  const TetMesh mesh = block5cm();
  ElasticBody body(mesh, rubber(0.1, mesh), {}, 1e-3, Eigen::Vector3d(0, 0, -9.81));
  SupportPlane plane;
  plane.friction = 0.8;
  body.setSupport(plane);
  Eigen::VectorXd forces = Eigen::VectorXd::Zero(3 * body.nodeCount());
  body.step(forces);
  const long before = test::allocationCount();
  for (int step = 0; step < 20; ++step)
  {
    forces(3 * (body.nodeCount() - 1) + 2) = -0.1 * step;  // a changing press on a top corner
    body.step(forces);
  }
  EXPECT_EQ(test::allocationCount() - before, 0);
}

// A support ends where its extent does (a table's edge): a block over it rests exactly as on the
// whole plane; one beside it falls freely (implicit Euler's fall: g dt^2 n (n + 1) / 2).
TEST(FreeSoftBody, ItRestsOnlyOverItsSupportsExtent)
{
  const TetMesh mesh = block5cm();  // x, y in [-2.5, 2.5] cm
  const Eigen::VectorXd none = Eigen::VectorXd::Zero(3 * static_cast<int>(mesh.nodes.size()));
  const auto run = [&](const std::vector<SupportRectangle>& extent, int steps)
  {
    auto body =
        std::make_unique<ElasticBody>(mesh, rubber(0.1, mesh), std::vector<int>(), 1e-3, Eigen::Vector3d(0, 0, -9.81));
    SupportPlane plane;
    plane.friction = 0.8;
    body->setSupport(plane);
    body->setSupportExtent(extent);
    for (int step = 0; step < steps; ++step)
    {
      body->step(none);
    }
    return body;
  };
  SupportRectangle table;  // a table top 1 m square
  table.half_u = table.half_v = 0.5;
  const auto whole = run({}, 400);
  const auto over = run({table}, 400);
  EXPECT_EQ(over->displacement(), whole->displacement());
  EXPECT_NEAR(over->supportForce(), 0.1 * 9.81, 1e-6);
  SupportRectangle beside = table;  // its edge 1 mm short of the block's side
  beside.centre.x() = -0.5 - 0.026;
  const int fall_steps = 100;
  const auto fallen = run({beside}, fall_steps);
  EXPECT_EQ(fallen->supportForce(), 0.0);
  const double fall = 9.81 * 1e-6 * fall_steps * (fall_steps + 1) / 2.0;
  for (int node = 0; node < fallen->nodeCount(); ++node)
  {
    EXPECT_NEAR(fallen->displacement()(3 * node + 2), -fall, 1e-6 * fall) << "node " << node;
  }
  // Having fallen beside the table until its top is 6 cm below the table's, a node that comes over
  // the table is beside its side, not on its top: it is not lifted back onto the plane
  // (kSupportEdgeDepth; without it, 8.7 kN on the first step).
  {
    const int long_fall = 150;  // 0.111 m
    auto body = run({beside}, long_fall);
    const Eigen::VectorXd before = body->displacement();
    body->setSupportExtent({table});
    body->step(none);
    EXPECT_EQ(body->supportForce(), 0.0);
    for (int node = 0; node < body->nodeCount(); ++node)
    {
      EXPECT_LT(body->displacement()(3 * node + 2), before(3 * node + 2)) << "node " << node << " stopped falling";
    }
  }
  // Its centre 1 cm past the edge: the part beyond it drops below the plane, further and further
  // as it turns over the edge; the part over the table stays on the plane.
  SupportRectangle edge = table;
  edge.centre.x() = -0.5 - 0.01;
  const auto lowest = [&](const ElasticBody& body, bool beyond)
  {
    double z = std::numeric_limits<double>::infinity();
    for (int node = 0; node < body.nodeCount(); ++node)
    {
      if ((mesh.nodes[node].x() > -0.01) == beyond)
      {
        z = std::min(z, body.position(node).z());
      }
    }
    return z;
  };
  const auto early = run({edge}, 150);
  const auto later = run({edge}, 300);
  std::printf(
      "its centre 1 cm past the edge: after 0.15 s the part beyond it %.2f mm below the plane, "
      "after 0.3 s %.2f mm; the part over it %.4f mm above\n",
      -1e3 * lowest(*early, true), -1e3 * lowest(*later, true), 1e3 * lowest(*later, false));
  EXPECT_LT(lowest(*early, true), -5e-3);
  EXPECT_LT(lowest(*later, true), lowest(*early, true) - 1e-3);
  EXPECT_GE(lowest(*early, false), -1e-6);
  EXPECT_GE(lowest(*later, false), -1e-6);
}

TEST(FreeSoftBody, RefusesABadSupport)
{
  const TetMesh mesh = block5cm();
  ElasticBody body(mesh, rubber(0.1, mesh), {}, 1e-3, Eigen::Vector3d(0, 0, -9.81));
  SupportPlane plane;
  plane.normal = Eigen::Vector3d(0, 0, 2);
  EXPECT_THROW(body.setSupport(plane), InputError);
  plane.normal = Eigen::Vector3d::UnitZ();
  plane.friction = std::nan("");
  EXPECT_THROW(body.setSupport(plane), InputError);
  plane.friction = -0.1;
  EXPECT_THROW(body.setSupport(plane), InputError);
  plane.friction = 0.5;
  EXPECT_THROW(body.setSupportExtent({}), InputError) << "no support yet";
  body.setSupport(plane);
  SupportRectangle rectangle;
  rectangle.half_u = rectangle.half_v = 0.1;
  body.setSupportExtent({rectangle});
  for (const auto& bad :
       std::vector<std::function<void(SupportRectangle*)>>{
           [](SupportRectangle* r) { r->u = Eigen::Vector3d(0, 0, 1); },  // across the plane
           [](SupportRectangle* r) { r->v = Eigen::Vector3d(2, 0, 0); },  // not unit
           [](SupportRectangle* r) { r->v = Eigen::Vector3d::UnitX(); },  // not orthogonal
           [](SupportRectangle* r) { r->half_u = -0.1; },                 // negative
           [](SupportRectangle* r) { r->half_v = std::nan(""); },         // not a number
           [](SupportRectangle* r) { r->centre.x() = std::nan(""); }})
  {
    SupportRectangle broken = rectangle;
    bad(&broken);
    EXPECT_THROW(body.setSupportExtent({rectangle, broken}), InputError);
    plane.extent = {broken};
    EXPECT_THROW(body.setSupport(plane), InputError);
  }
}

TEST(BallMesh, IsABallOfItsRadiusStandingOnZeroAndRefusesTooFewCells)
{
  const double radius = 0.03;
  const TetMesh ball = ballTetMesh(radius, 8);
  EXPECT_EQ(ball.nodes.size(), 729u);
  double volume = 0.0;
  for (const std::array<int, 4>& tet : ball.tets)
  {
    const double v = signedTetVolume(ball.nodes, tet);
    EXPECT_GT(v, 0.0);
    volume += v;
  }
  // Flat faces inscribed in the sphere: a little less than 4/3 pi r^3.
  const double sphere = 4.0 / 3.0 * M_PI * radius * radius * radius;
  EXPECT_LT(volume, sphere);
  EXPECT_GT(volume, 0.97 * sphere);
  double lowest = 1.0;
  double farthest = 0.0;
  for (const Eigen::Vector3d& node : ball.nodes)
  {
    lowest = std::min(lowest, node.z());
    farthest = std::max(farthest, (node - Eigen::Vector3d(0, 0, radius)).norm());
  }
  EXPECT_NEAR(lowest, 0.0, 1e-15);
  EXPECT_NEAR(farthest, radius, 1e-12);
  EXPECT_THROW(ballTetMesh(radius, 1), InputError);
  EXPECT_THROW(ballTetMesh(-radius, 8), InputError);
  EXPECT_THROW(ballTetMesh(std::nan(""), 8), InputError);
}
}  // namespace
}  // namespace god_finger
