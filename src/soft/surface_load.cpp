#include "god_finger/soft/surface_load.h"

#include "god_finger/geometry/surface_location.h"

#include <Eigen/Geometry>
#include <cmath>
#include <limits>

namespace god_finger
{
namespace
{
// Calls visit(corner weights, area) for each of the s^2 equal sub-triangles of triangle abc, at
// its centroid: the midpoint rule on a uniform subdivision (barycentric grid of step 1/s).
template <typename Visit>
void forEachSubTriangle(double area, Visit&& visit)
{
  constexpr int s = kPadQuadratureDivisions;
  const double sub_area = area / (s * s);
  for (int i = 0; i < s; ++i)
  {
    for (int j = 0; j < s - i; ++j)
    {
      // Upward sub-triangle (i, j), (i + 1, j), (i, j + 1): centroid at (i + 1/3, j + 1/3).
      visit(Eigen::Vector3d((i + 1.0 / 3.0) / s, (j + 1.0 / 3.0) / s, 0.0), sub_area);
      if (j < s - i - 1)
      {
        // Downward sub-triangle (i + 1, j), (i, j + 1), (i + 1, j + 1): centroid (i + 2/3, j + 2/3).
        visit(Eigen::Vector3d((i + 2.0 / 3.0) / s, (j + 2.0 / 3.0) / s, 0.0), sub_area);
      }
    }
  }
}

// Whether the pad covers the surface point `point`.
bool covered(const PadDisk& pad, const Eigen::Vector3d& point)
{
  const Eigen::Vector3d offset = point - pad.centre;
  const double height = offset.dot(pad.normal);
  return std::abs(height) <= pad.radius && (offset - height * pad.normal).squaredNorm() <= pad.radius * pad.radius;
}

// Visits every covered quadrature point of the faces facing the pad: visit(face, weights, area).
template <typename Visit>
void forEachCoveredPoint(const std::vector<Eigen::Vector3d>& positions, const std::vector<std::array<int, 3>>& surface,
                         const PadDisk& pad, Visit&& visit)
{
  const double reach = 2.0 * pad.radius;  // a face can touch the disk only if a corner is this near
  for (std::size_t f = 0; f < surface.size(); ++f)
  {
    const Eigen::Vector3d& a = positions[surface[f][0]];
    const Eigen::Vector3d& b = positions[surface[f][1]];
    const Eigen::Vector3d& c = positions[surface[f][2]];
    const Eigen::Vector3d normal = (b - a).cross(c - a);
    if (normal.dot(pad.normal) <= 0.0)
    {
      continue;
    }
    const Eigen::Vector3d lower = a.cwiseMin(b).cwiseMin(c);
    const Eigen::Vector3d upper = a.cwiseMax(b).cwiseMax(c);
    if (((pad.centre.array() + reach) < lower.array()).any() || ((pad.centre.array() - reach) > upper.array()).any())
    {
      continue;
    }
    const double area = 0.5 * normal.norm();
    forEachSubTriangle(area,
                       [&](Eigen::Vector3d weights, double sub_area)
                       {
                         weights.z() = 1.0 - weights.x() - weights.y();
                         // weights (x, y, z) belong to corners b, c, a.
                         const Eigen::Vector3d point = weights.z() * a + weights.x() * b + weights.y() * c;
                         if (covered(pad, point))
                         {
                           visit(f, Eigen::Vector3d(weights.z(), weights.x(), weights.y()), sub_area);
                         }
                       });
  }
}
}  // namespace

double addPadPressure(const std::vector<Eigen::Vector3d>& positions, const std::vector<std::array<int, 3>>& surface,
                      const PadDisk& pad, const Eigen::Vector3d& force, Eigen::VectorXd* forces)
{
  double covered_area = 0.0;
  forEachCoveredPoint(positions, surface, pad,
                      [&](std::size_t, const Eigen::Vector3d&, double sub_area) { covered_area += sub_area; });
  if (covered_area <= 0.0)
  {
    return 0.0;
  }
  const Eigen::Vector3d traction = force / covered_area;  // N/m^2: the pressure (and shear) the pad puts down
  forEachCoveredPoint(positions, surface, pad,
                      [&](std::size_t f, const Eigen::Vector3d& weights, double sub_area)
                      {
                        for (int k = 0; k < 3; ++k)
                        {
                          forces->segment<3>(3 * surface[f][k]) += (weights[k] * sub_area) * traction;
                        }
                      });
  return covered_area;
}

Eigen::Vector3d addPointForce(const std::vector<Eigen::Vector3d>& positions,
                              const std::vector<std::array<int, 3>>& surface, const Eigen::Vector3d& point,
                              const Eigen::Vector3d& force, Eigen::VectorXd* forces)
{
  double best = std::numeric_limits<double>::infinity();
  std::size_t best_face = 0;
  Eigen::Vector3d best_weights = Eigen::Vector3d::Zero();
  Eigen::Vector3d best_point = Eigen::Vector3d::Zero();
  for (std::size_t f = 0; f < surface.size(); ++f)
  {
    const Eigen::Vector3d& a = positions[surface[f][0]];
    const Eigen::Vector3d& b = positions[surface[f][1]];
    const Eigen::Vector3d& c = positions[surface[f][2]];
    const Eigen::Vector3d weights = closestBarycentric(a, b, c, point);
    const Eigen::Vector3d closest = weights[0] * a + weights[1] * b + weights[2] * c;
    const double distance = (closest - point).squaredNorm();
    if (distance < best)
    {
      best = distance;
      best_face = f;
      best_weights = weights;
      best_point = closest;
    }
  }
  for (int k = 0; k < 3; ++k)
  {
    forces->segment<3>(3 * surface[best_face][k]) += best_weights[k] * force;
  }
  return best_point;
}

Eigen::Vector3d surfaceDisplacementAt(const std::vector<Eigen::Vector3d>& rest_nodes,
                                      const std::vector<std::array<int, 3>>& surface,
                                      const Eigen::VectorXd& displacement, const Eigen::Vector3d& point)
{
  double best = std::numeric_limits<double>::infinity();
  Eigen::Vector3d result = Eigen::Vector3d::Zero();
  for (const std::array<int, 3>& face : surface)
  {
    const Eigen::Vector3d& a = rest_nodes[face[0]];
    const Eigen::Vector3d& b = rest_nodes[face[1]];
    const Eigen::Vector3d& c = rest_nodes[face[2]];
    const Eigen::Vector3d weights = closestBarycentric(a, b, c, point);
    const double distance = (weights[0] * a + weights[1] * b + weights[2] * c - point).squaredNorm();
    if (distance < best)
    {
      best = distance;
      result = weights[0] * displacement.segment<3>(3 * face[0]) + weights[1] * displacement.segment<3>(3 * face[1]) +
               weights[2] * displacement.segment<3>(3 * face[2]);
    }
  }
  return result;
}

double boussinesqCentreSink(double force, double radius, double young_modulus, double poisson_ratio)
{
  const double pressure = force / (M_PI * radius * radius);
  return 2.0 * (1.0 - poisson_ratio * poisson_ratio) * pressure * radius / young_modulus;
}
}  // namespace god_finger
