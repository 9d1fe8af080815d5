#include "god_finger/core/surface_location.h"

#include <algorithm>

namespace god_finger
{
const char* featureKindName(FeatureKind kind)
{
  switch (kind)
  {
    case FeatureKind::kFace:
      return "face";
    case FeatureKind::kEdge:
      return "edge";
    case FeatureKind::kVertex:
      return "vertex";
  }
  return "unknown";
}

SurfaceLocation locationFromBarycentric(const TriangleMesh& mesh, int face, const Eigen::Vector3d& barycentric,
                                        double feature_tolerance)
{
  SurfaceLocation location;
  location.face = face;
  Eigen::Vector3d lambda = barycentric.cwiseMax(0.0);
  double sum = lambda.sum();
  lambda = sum > 0.0 ? Eigen::Vector3d(lambda / sum) : Eigen::Vector3d(1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0);

  int zeros = 0;
  int zero_index = -1;
  int kept_index = -1;
  for (int j = 0; j < 3; ++j)
  {
    if (lambda[j] <= feature_tolerance)
    {
      ++zeros;
      zero_index = j;
    }
    else
    {
      kept_index = j;
    }
  }
  if (zeros >= 2)
  {
    location.feature = FeatureKind::kVertex;
    location.feature_index = kept_index;
    lambda = Eigen::Vector3d::Zero();
    lambda[kept_index] = 1.0;
  }
  else if (zeros == 1)
  {
    location.feature = FeatureKind::kEdge;
    // The edge opposite vertex j runs from corner j+1 to corner j+2: edge index (j+1)%3.
    location.feature_index = (zero_index + 1) % 3;
    lambda[zero_index] = 0.0;
    lambda /= lambda.sum();
  }
  location.barycentric = lambda;
  location.point =
      lambda[0] * mesh.corner(face, 0) + lambda[1] * mesh.corner(face, 1) + lambda[2] * mesh.corner(face, 2);
  if (location.feature == FeatureKind::kVertex)
  {
    location.point = mesh.corner(face, location.feature_index);
  }
  return location;
}

SurfaceLocation locateOnFace(const TriangleMesh& mesh, int face, const Eigen::Vector3d& query, double feature_tolerance)
{
  // Region test of Ericson, "Real-Time Collision Detection", 5.1.5, returning barycentrics.
  const Eigen::Vector3d& a = mesh.corner(face, 0);
  const Eigen::Vector3d& b = mesh.corner(face, 1);
  const Eigen::Vector3d& c = mesh.corner(face, 2);
  const Eigen::Vector3d ab = b - a;
  const Eigen::Vector3d ac = c - a;
  const Eigen::Vector3d ap = query - a;
  Eigen::Vector3d lambda;
  const double d1 = ab.dot(ap);
  const double d2 = ac.dot(ap);
  const Eigen::Vector3d bp = query - b;
  const double d3 = ab.dot(bp);
  const double d4 = ac.dot(bp);
  const Eigen::Vector3d cp = query - c;
  const double d5 = ab.dot(cp);
  const double d6 = ac.dot(cp);
  const double vc = d1 * d4 - d3 * d2;
  const double vb = d5 * d2 - d1 * d6;
  const double va = d3 * d6 - d5 * d4;
  if (d1 <= 0.0 && d2 <= 0.0)
  {
    lambda = Eigen::Vector3d(1.0, 0.0, 0.0);
  }
  else if (d3 >= 0.0 && d4 <= d3)
  {
    lambda = Eigen::Vector3d(0.0, 1.0, 0.0);
  }
  else if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
  {
    const double v = d1 / (d1 - d3);
    lambda = Eigen::Vector3d(1.0 - v, v, 0.0);
  }
  else if (d6 >= 0.0 && d5 <= d6)
  {
    lambda = Eigen::Vector3d(0.0, 0.0, 1.0);
  }
  else if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
  {
    const double w = d2 / (d2 - d6);
    lambda = Eigen::Vector3d(1.0 - w, 0.0, w);
  }
  else if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
  {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    lambda = Eigen::Vector3d(0.0, 1.0 - w, w);
  }
  else
  {
    const double denominator = 1.0 / (va + vb + vc);
    const double v = vb * denominator;
    const double w = vc * denominator;
    lambda = Eigen::Vector3d(1.0 - v - w, v, w);
  }
  SurfaceLocation location = locationFromBarycentric(mesh, face, lambda, feature_tolerance);
  location.distance = (query - location.point).norm();
  return location;
}
}  // namespace god_finger
