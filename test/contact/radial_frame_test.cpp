// Radial vectors: orthonormal to the normal, evenly spaced, and continuous in time when the
// first tangent is transported, including through the fixed basis's singular direction.
#include "god_finger/contact/radial_frame.h"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <cmath>
#include <random>

namespace god_finger
{
namespace
{
TEST(RadialFrame, DefaultTangentIsOrthonormalEverywhere)
{
  std::mt19937_64 random(5);
  std::normal_distribution<double> gaussian;
  for (int trial = 0; trial < 10000; ++trial)
  {
    Eigen::Vector3d n(gaussian(random), gaussian(random), gaussian(random));
    if (trial == 0)
    {
      n = Eigen::Vector3d(0, 0, -1);  // the one direction where the formula switches sign
    }
    n.normalize();
    const Eigen::Vector3d t = defaultTangent(n);
    EXPECT_NEAR(t.norm(), 1.0, 1e-14);
    EXPECT_NEAR(t.dot(n), 0.0, 1e-14);
  }
}

TEST(RadialFrame, RadialVectorsAreEvenlySpacedAndOrthogonal)
{
  const Eigen::Vector3d n = Eigen::Vector3d(0.3, -0.4, 0.8).normalized();
  const Eigen::Vector3d t = defaultTangent(n);
  for (int count : {3, 8, 64})
  {
    for (int i = 0; i < count; ++i)
    {
      const Eigen::Vector3d r = radialVector(n, t, i, count);
      const Eigen::Vector3d next = radialVector(n, t, (i + 1) % count, count);
      EXPECT_NEAR(r.norm(), 1.0, 1e-15);
      EXPECT_NEAR(r.dot(n), 0.0, 1e-15);
      EXPECT_NEAR(std::acos(std::min(1.0, r.dot(next))), 2.0 * M_PI / count, 1e-7);
      EXPECT_GT(r.cross(next).dot(n), 0.0);  // counter-clockwise about the normal
    }
  }
}

TEST(RadialFrame, TransportIsContinuousThroughTheSingularDirection)
{
  // The normal sweeps a full great circle through -z (where defaultTangent jumps) in 0.1
  // degree steps, as it could in 3.6 s of a 1 kHz loop. The transported tangent moves by no
  // more than the normal does; the fixed basis alone jumps.
  const double step = 0.1 * M_PI / 180.0;
  Eigen::Vector3d tangent = Eigen::Vector3d::Zero();
  Eigen::Vector3d previous_normal(0, 0, 1);
  double largest_transport_jump = 0.0;
  double largest_default_jump = 0.0;
  Eigen::Vector3d previous_default = defaultTangent(previous_normal);
  for (int i = 0; i <= 3600; ++i)
  {
    const double a = i * step + 1e-4;
    const Eigen::Vector3d normal(std::sin(a) * 0.6, std::sin(a) * 0.8, std::cos(a));
    const Eigen::Vector3d next = transportTangent(tangent, normal);
    if (i > 0)
    {
      largest_transport_jump = std::max(largest_transport_jump, (next - tangent).norm());
      largest_default_jump = std::max(largest_default_jump, (defaultTangent(normal) - previous_default).norm());
    }
    EXPECT_NEAR(next.dot(normal), 0.0, 1e-14);
    EXPECT_NEAR(next.norm(), 1.0, 1e-14);
    tangent = next;
    previous_default = defaultTangent(normal);
    previous_normal = normal;
  }
  EXPECT_LE(largest_transport_jump, 1.01 * step);
  EXPECT_GT(largest_default_jump, 0.5);  // why transport is needed
}

TEST(RadialFrame, TransportFallsBackOnUnusablePrevious)
{
  const Eigen::Vector3d n(0, 0, 1);
  EXPECT_EQ(transportTangent(Eigen::Vector3d::Zero(), n), defaultTangent(n));
  EXPECT_EQ(transportTangent(Eigen::Vector3d(0, 0, 1), n), defaultTangent(n));
  EXPECT_EQ(transportTangent(Eigen::Vector3d(NAN, 0, 0), n), defaultTangent(n));
  EXPECT_NEAR((transportTangent(Eigen::Vector3d(2, 0, 1), n) - Eigen::Vector3d(1, 0, 0)).norm(), 0.0, 1e-15);
}
}  // namespace
}  // namespace god_finger
