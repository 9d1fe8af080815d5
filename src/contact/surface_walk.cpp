#include "god_finger/contact/surface_walk.h"

#include "god_finger/support/contract.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace god_finger
{
namespace
{
// A direction within this angle (rad) of an edge runs along the edge: it neither exits nor
// enters across it. Keeps walks along edges of flat fans from bouncing between two faces.
constexpr double kParallelTolerance = 1e-12;
// Barycentric coordinate below which a walk point that reached an edge is on a vertex too.
constexpr double kVertexTolerance = 1e-10;
// Crossings in a row without progress (zero-length steps) before a walk gives up.
constexpr int kMaxStalledCrossings = 64;

// Barycentric gradients of a face (1/m), in the face plane: d(lambda_j) = gradient[j] . dp.
// Read from the mesh's precomputed ones: no division or root per face entered.
struct FaceGradients
{
  Eigen::Vector3d gradient[3];

  // |gradient[j]|^2 = 1 / (height of the triangle above the edge opposite j)^2.
  double squaredNorm(int j) const
  {
    return gradient[j].squaredNorm();
  }
};

FaceGradients faceGradients(const TriangleMesh& mesh, int face)
{
  FaceGradients result;
  result.gradient[0] = mesh.barycentricGradient(face, 0);
  result.gradient[1] = mesh.barycentricGradient(face, 1);
  result.gradient[2] = -result.gradient[0] - result.gradient[1];
  return result;
}

// True when `rate` = gradient[j] . direction makes coordinate j fall faster than the parallel
// tolerance: the sine of the angle between the direction and the edge is below
// -kParallelTolerance (compared squared: no root; the norm only when the coordinate falls).
bool fallsAcross(const FaceGradients& gradients, int j, double rate)
{
  return rate < 0.0 && rate * rate > kParallelTolerance * kParallelTolerance * gradients.squaredNorm(j);
}

// Carries a unit direction lying in the plane with normal `from` onto the plane with normal
// `to`: projection (kProject) or minimal rotation from `from` to `to` (kUnfold; across an edge
// shared by both faces this is the rotation about that edge). Returns false when the result
// is degenerate.
bool carryDirection(const Eigen::Vector3d& direction, const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                    WalkVariant variant, Eigen::Vector3d* carried)
{
  if (from == to)
  {
    *carried = direction;  // coplanar faces (a flat region): nothing to carry
    return true;
  }
  Eigen::Vector3d result;
  if (variant == WalkVariant::kProject)
  {
    result = direction;
  }
  else
  {
    const double c = from.dot(to);
    if (!(c > -1.0 + 1e-12))
    {
      return false;  // faces folded flat onto each other: the rotation axis is undefined
    }
    const Eigen::Vector3d w = from.cross(to);
    result = direction * c + w.cross(direction) + w * (w.dot(direction) / (1.0 + c));
    if (std::abs(direction.dot(from)) < 1e-12)
    {
      // A unit direction in the old plane rotates onto a unit direction in the new one: no
      // projection or renormalisation needed (the rounding stays at 1e-16 per crossing).
      *carried = result;
      return true;
    }
  }
  result -= result.dot(to) * to;
  const double length = result.norm();
  if (!(length > 1e-9))
  {
    return false;
  }
  *carried = result / length;
  return true;
}

// How far inside face `face` a direction points from a point whose barycentric coordinates
// listed in `zero_mask` are zero: the smallest sine of the angle between the direction and
// the edges it must not cross. >= 0 means the direction enters the face.
double entryScore(const FaceGradients& gradients, const Eigen::Vector3d& direction, const bool zero_mask[3])
{
  double score = std::numeric_limits<double>::infinity();
  for (int j = 0; j < 3; ++j)
  {
    if (zero_mask[j])
    {
      score = std::min(score, gradients.gradient[j].dot(direction) / std::sqrt(gradients.squaredNorm(j)));
    }
  }
  return score;
}

struct FaceChoice
{
  int face = -1;
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();
  Eigen::Vector3d barycentric = Eigen::Vector3d::Zero();
  double score = -std::numeric_limits<double>::infinity();
  double alignment = -std::numeric_limits<double>::infinity();
};

// Among the faces incident to the vertices in `feature_vertices` (one vertex, or the two
// ends of an edge with their barycentric weights), the one the direction enters most
// centrally. `exclude` is skipped (the face a walk comes from).
FaceChoice chooseFaceAround(const TriangleMesh& mesh, const int* feature_vertices, const double* feature_weights,
                            int vertex_count, const Eigen::Vector3d& direction, const Eigen::Vector3d& direction_normal,
                            int exclude, const WalkLimits& limits)
{
  FaceChoice best;
  const int pivot = feature_vertices[0];
  for (const int* it = mesh.vertexFacesBegin(pivot); it != mesh.vertexFacesEnd(pivot); ++it)
  {
    const int face = *it;
    if (face == exclude)
    {
      continue;
    }
    Eigen::Vector3d barycentric = Eigen::Vector3d::Zero();
    bool on_face = true;
    for (int i = 0; i < vertex_count; ++i)
    {
      const int local = mesh.localVertex(face, feature_vertices[i]);
      if (local < 0)
      {
        on_face = false;
        break;
      }
      barycentric[local] = feature_weights[i];
    }
    if (!on_face)
    {
      continue;
    }
    Eigen::Vector3d carried;
    if (!carryDirection(direction, direction_normal, mesh.normals()[face], limits.variant, &carried))
    {
      continue;
    }
    const bool zero_mask[3] = {barycentric[0] == 0.0, barycentric[1] == 0.0, barycentric[2] == 0.0};
    const double score = entryScore(faceGradients(mesh, face), carried, zero_mask);
    const double alignment = limits.normal_sign * mesh.normals()[face].dot(limits.contact_normal);
    // Scores within the parallel tolerance are ties (a direction along a shared edge enters
    // both faces); prefer then the face closest to the contact normal.
    const bool better = score > best.score + kParallelTolerance ||
                        (score > best.score - kParallelTolerance && alignment > best.alignment);
    if (better)
    {
      best.face = face;
      best.direction = carried;
      best.barycentric = barycentric;
      best.score = score;
      best.alignment = alignment;
    }
  }
  return best;
}

WalkResult finish(const TriangleMesh& mesh, int face, const Eigen::Vector3d& barycentric, double walked, int crossings,
                  WalkStop stop)
{
  // The feature label uses the usual tolerance, but the position is not snapped onto it:
  // a sub-god-object 1e-9 m from an edge stays 1e-9 m from it.
  WalkResult result;
  result.location = locationFromBarycentric(mesh, face, barycentric);
  const Eigen::Vector3d lambda = barycentric.cwiseMax(0.0) / barycentric.cwiseMax(0.0).sum();
  result.location.barycentric = lambda;
  result.location.point =
      lambda[0] * mesh.corner(face, 0) + lambda[1] * mesh.corner(face, 1) + lambda[2] * mesh.corner(face, 2);
  result.position = result.location.point;
  result.walked = walked;
  result.crossings = crossings;
  result.stop = stop;
  return result;
}

// Where the walk leaves its face: the edge opposite the first barycentric coordinate to reach
// zero along r (index -1: none falls, the direction runs along the face's edges), after t
// metres, and every coordinate's rate of change (1/m).
struct ExitEdge
{
  int index = -1;
  double t = std::numeric_limits<double>::infinity();
  double rate[3] = {0.0, 0.0, 0.0};
};

// Algorithm 1's loop state: where the walk is (a face and barycentric coordinates on it), its
// direction in the face's plane, and how far it went.
struct Walk
{
  int face = -1;
  // Barycentric coordinates as plain doubles: stores at a runtime index followed by vector
  // loads of the same bytes (an Eigen vector) stall store forwarding on every crossing.
  double lambda[3] = {0.0, 0.0, 0.0};
  Eigen::Vector3d r = Eigen::Vector3d::Zero();  // unit, in the face's plane
  // The current face's gradients; an edge crossing computes the next face's anyway and hands
  // them on, so each face entered costs one faceGradients().
  FaceGradients gradients;
  double walked = 0.0;
  double remaining = 0.0;
  int crossings = 0;
  int stalled = 0;  // crossings in a row without progress

  Eigen::Vector3d coordinates() const
  {
    return Eigen::Vector3d(lambda[0], lambda[1], lambda[2]);
  }

  // The walk stops where it is.
  WalkResult stopHere(const TriangleMesh& mesh, WalkStop stop) const
  {
    return finish(mesh, face, coordinates(), walked, crossings, stop);
  }

  // The exit lies beyond the distance left: the walk ends inside the face.
  WalkResult endInsideFace(const TriangleMesh& mesh, const ExitEdge& exit);

  // Onto the exit edge: the exiting coordinate zero, the others moved and renormalised.
  void moveOntoExitEdge(const ExitEdge& exit);

  // Whether the point on exit edge `exit_index` is on one of its ends too: that end's local
  // vertex, or -1.
  int vertexReached(int exit_index) const
  {
    const int a_local = (exit_index + 1) % 3;
    const int b_local = (exit_index + 2) % 3;
    if (lambda[a_local] <= kVertexTolerance)
    {
      return b_local;
    }
    if (lambda[b_local] <= kVertexTolerance)
    {
      return a_local;
    }
    return -1;
  }

  // Onto face `next` (its gradients), with the direction carried there; the caller has set the
  // coordinates on it.
  void enter(int next, const Eigen::Vector3d& carried, const FaceGradients& next_gradients)
  {
    face = next;
    r = carried;
    gradients = next_gradients;
    ++crossings;
  }
};

// The smallest lambda_j / -rate_j over the coordinates that fall faster than the parallel
// tolerance, compared as cross products so that only the winner is divided.
inline ExitEdge findExitEdge(const Walk& walk)
{
  ExitEdge exit;
  double numerator_of_exit = 1.0;
  double denominator_of_exit = 0.0;
  for (int j = 0; j < 3; ++j)
  {
    exit.rate[j] = walk.gradients.gradient[j].dot(walk.r);
    if (fallsAcross(walk.gradients, j, exit.rate[j]))
    {
      const double numerator = std::max(walk.lambda[j], 0.0);
      if (exit.index < 0 || numerator * denominator_of_exit < numerator_of_exit * -exit.rate[j])
      {
        numerator_of_exit = numerator;
        denominator_of_exit = -exit.rate[j];
        exit.index = j;
      }
    }
  }
  if (exit.index >= 0)
  {
    exit.t = numerator_of_exit / denominator_of_exit;
  }
  return exit;
}

WalkResult Walk::endInsideFace(const TriangleMesh& mesh, const ExitEdge& exit)
{
  for (int j = 0; j < 3; ++j)
  {
    lambda[j] += remaining * exit.rate[j];
  }
  const Eigen::Vector3d reached = coordinates().cwiseMax(0.0);
  return finish(mesh, face, reached / reached.sum(), walked + remaining, crossings, WalkStop::kDistanceReached);
}

void Walk::moveOntoExitEdge(const ExitEdge& exit)
{
  const double l0 = exit.index == 0 ? 0.0 : std::max(lambda[0] + exit.t * exit.rate[0], 0.0);
  const double l1 = exit.index == 1 ? 0.0 : std::max(lambda[1] + exit.t * exit.rate[1], 0.0);
  const double l2 = exit.index == 2 ? 0.0 : std::max(lambda[2] + exit.t * exit.rate[2], 0.0);
  const double inverse_sum = 1.0 / (l0 + l1 + l2);
  lambda[0] = l0 * inverse_sum;
  lambda[1] = l1 * inverse_sum;
  lambda[2] = l2 * inverse_sum;
  walked += exit.t;
  remaining -= exit.t;
  // No progress: a step below 1e-12 of the face's largest height (t * min |gradient|, squared),
  // looked at only for steps below a nanometre (faces up to a kilometre).
  const bool no_progress =
      exit.t < 1e-9 &&
      exit.t * exit.t * std::min({gradients.squaredNorm(0), gradients.squaredNorm(1), gradients.squaredNorm(2)}) <
          1e-24;
  stalled = no_progress ? stalled + 1 : 0;
}

// Through vertex `vertex_local` of the walk's face: into the incident face whose corner wedge
// holds the direction, if it may be entered; else why the walk stops there.
inline std::optional<WalkStop> crossVertex(const TriangleMesh& mesh, const WalkLimits& limits, int vertex_local,
                                           Walk* walk)
{
  walk->lambda[0] = walk->lambda[1] = walk->lambda[2] = 0.0;
  walk->lambda[vertex_local] = 1.0;
  const int vertex = mesh.triangles()[walk->face][vertex_local];
  const double weight = 1.0;
  const FaceChoice choice =
      chooseFaceAround(mesh, &vertex, &weight, 1, walk->r, mesh.normals()[walk->face], walk->face, limits);
  if (choice.face < 0 || choice.score < -kParallelTolerance)
  {
    return WalkStop::kVertexBlocked;
  }
  if (const std::optional<WalkStop> limit = surfaceLimit(mesh.normals()[choice.face], limits))
  {
    return limit;
  }
  for (int j = 0; j < 3; ++j)
  {
    walk->lambda[j] = choice.barycentric[j];
  }
  walk->enter(choice.face, choice.direction, faceGradients(mesh, choice.face));
  return std::nullopt;
}

// Across exit edge `exit_index` (from local corner exit_index + 1 to exit_index + 2), through the
// neighbour table, if the next face may be entered and the carried direction enters it; else why
// the walk stops on the edge.
inline std::optional<WalkStop> crossEdge(const TriangleMesh& mesh, const WalkLimits& limits, int exit_index, Walk* walk)
{
  const int a_local = (exit_index + 1) % 3;
  const int b_local = (exit_index + 2) % 3;
  const int face = walk->face;
  const int next = mesh.neighbours()[face][a_local];  // edge k runs from corner k to corner k+1
  if (next == TriangleMesh::kBoundaryEdge)
  {
    return WalkStop::kBoundaryEdge;
  }
  if (next < 0)
  {
    return WalkStop::kNonManifoldEdge;
  }
  GOD_FINGER_EXPECTS(next < mesh.triangleCount(), "a mesh's neighbour indices name its own faces (TriangleMesh)");
  if (const std::optional<WalkStop> limit = surfaceLimit(mesh.normals()[next], limits))
  {
    return limit;
  }
  const Eigen::Vector3i& corners = mesh.triangles()[face];
  const int a_next = mesh.localVertex(next, corners[a_local]);
  const int b_next = mesh.localVertex(next, corners[b_local]);
  if (a_next < 0 || b_next < 0)
  {
    return WalkStop::kNonManifoldEdge;
  }
  Eigen::Vector3d carried;
  if (!carryDirection(walk->r, mesh.normals()[face], mesh.normals()[next], limits.variant, &carried))
  {
    return WalkStop::kDirectionLost;
  }
  // The carried direction must enter the new face: its coordinate opposite the shared edge has
  // to grow. The walk left the old face across this edge, so the unfolded direction always does;
  // the projection fails at folds of 90 degrees or more.
  const int opposite_next = 3 - a_next - b_next;
  const FaceGradients next_gradients = faceGradients(mesh, next);
  const double entering = next_gradients.gradient[opposite_next].dot(carried);
  if (entering <= 0.0 ||
      entering * entering <= kParallelTolerance * kParallelTolerance * next_gradients.squaredNorm(opposite_next))
  {
    return WalkStop::kDirectionLost;
  }
  // The point keeps its place on the shared edge (scalar stores: see Walk::lambda).
  const double on_a = walk->lambda[a_local];
  const double on_b = walk->lambda[b_local];
  for (int j = 0; j < 3; ++j)
  {
    walk->lambda[j] = j == a_next ? on_a : (j == b_next ? on_b : 0.0);
  }
  GOD_FINGER_EXPECTS(carried.allFinite() && std::abs(walk->lambda[0] + walk->lambda[1] + walk->lambda[2] - 1.0) <= 1e-6,
                     "the walk carries a finite direction and a point of the face onto the next face");
  walk->enter(next, carried, next_gradients);
  return std::nullopt;
}
}  // namespace

const char* walkStopName(WalkStop stop)
{
  switch (stop)
  {
    case WalkStop::kDistanceReached:
      return "distance_reached";
    case WalkStop::kAngleLimit:
      return "angle_limit";
    case WalkStop::kFrictionLimit:
      return "friction_limit";
    case WalkStop::kBoundaryEdge:
      return "boundary_edge";
    case WalkStop::kNonManifoldEdge:
      return "non_manifold_edge";
    case WalkStop::kVertexBlocked:
      return "vertex_blocked";
    case WalkStop::kDirectionLost:
      return "direction_lost";
    case WalkStop::kCrossingCap:
      return "crossing_cap";
    case WalkStop::kDropped:
      return "dropped";
    case WalkStop::kInvalidInput:
      return "invalid_input";
  }
  return "unknown";
}

WalkLimits makeWalkLimits(const ContactParams& params, const Eigen::Vector3d& contact_normal, double normal_sign)
{
  WalkLimits limits;
  limits.contact_normal = contact_normal;
  limits.normal_sign = normal_sign < 0.0 ? -1.0 : 1.0;
  limits.cos_max_angle = std::cos(params.max_angle);
  // cos(atan(theta)) = 1 / sqrt(1 + theta^2); an infinite coefficient removes the cone.
  limits.cos_friction = std::isinf(params.friction) ? -2.0 : 1.0 / std::sqrt(1.0 + params.friction * params.friction);
  limits.variant = params.walk;
  limits.max_crossings = params.max_crossings;
  return limits;
}

bool chooseStartFace(const TriangleMesh& mesh, const SurfaceLocation& start, const Eigen::Vector3d& direction,
                     const Eigen::Vector3d& direction_normal, const WalkLimits& limits, SurfaceLocation* start_on_face,
                     Eigen::Vector3d* direction_on_face, WalkStop* stop)
{
  FaceChoice choice;
  if (start.feature == FeatureKind::kFace)
  {
    choice.face = start.face;
    choice.barycentric = start.barycentric;
    if (!carryDirection(direction, direction_normal, mesh.normals()[start.face], limits.variant, &choice.direction))
    {
      *stop = WalkStop::kDropped;
      return false;
    }
    choice.score = 1.0;
  }
  else
  {
    const Eigen::Vector3i& corners = mesh.triangles()[start.face];
    int vertices[2];
    double weights[2];
    int count = 0;
    if (start.feature == FeatureKind::kVertex)
    {
      vertices[0] = corners[start.feature_index];
      weights[0] = 1.0;
      count = 1;
    }
    else
    {
      const int k = start.feature_index;
      vertices[0] = corners[k];
      vertices[1] = corners[(k + 1) % 3];
      weights[0] = start.barycentric[k];
      weights[1] = start.barycentric[(k + 1) % 3];
      count = 2;
    }
    choice = chooseFaceAround(mesh, vertices, weights, count, direction, direction_normal, -1, limits);
    if (choice.face < 0)
    {
      *stop = WalkStop::kDropped;
      return false;
    }
    if (choice.score < -kParallelTolerance)
    {
      // The direction points off the surface between the incident faces (a convex corner or
      // edge leaves a gap in the tangent plane): clamp it onto the best face's border so the
      // area wraps along that edge instead of losing the radial vector.
      const FaceGradients gradients = faceGradients(mesh, choice.face);
      for (int j = 0; j < 3; ++j)
      {
        const double along = gradients.gradient[j].dot(choice.direction);
        if (choice.barycentric[j] == 0.0 && along < 0.0)
        {
          choice.direction -= along / gradients.gradient[j].squaredNorm() * gradients.gradient[j];
        }
      }
      const bool zero_mask[3] = {choice.barycentric[0] == 0.0, choice.barycentric[1] == 0.0,
                                 choice.barycentric[2] == 0.0};
      const double length = choice.direction.norm();
      if (!(length > 1e-6) || entryScore(gradients, choice.direction / length, zero_mask) < -kParallelTolerance)
      {
        *stop = WalkStop::kDropped;
        return false;
      }
      choice.direction /= length;
    }
  }
  if (surfaceLimit(mesh.normals()[choice.face], limits))
  {
    *stop = WalkStop::kDropped;
    return false;
  }
  *start_on_face = locationFromBarycentric(mesh, choice.face, choice.barycentric, 0.0);
  start_on_face->barycentric = choice.barycentric;
  *direction_on_face = choice.direction;
  return true;
}

WalkResult walkSurface(const TriangleMesh& mesh, const SurfaceLocation& start, const Eigen::Vector3d& direction,
                       double distance, const WalkLimits& limits)
{
  if (start.face < 0 || start.face >= mesh.triangleCount() || !start.barycentric.allFinite() ||
      !direction.allFinite() || !std::isfinite(distance) || distance < 0.0 ||
      !(std::abs(start.barycentric.sum() - 1.0) <= kBarycentricTolerance) ||
      !(start.barycentric.minCoeff() >= -kBarycentricTolerance))
  {
    WalkResult invalid;
    invalid.stop = WalkStop::kInvalidInput;
    return invalid;
  }
  Walk walk;
  walk.face = start.face;
  walk.lambda[0] = start.barycentric[0];
  walk.lambda[1] = start.barycentric[1];
  walk.lambda[2] = start.barycentric[2];
  walk.r = direction - direction.dot(mesh.normals()[walk.face]) * mesh.normals()[walk.face];
  if (!(walk.r.norm() > 1e-9))
  {
    return walk.stopHere(mesh, WalkStop::kDirectionLost);
  }
  walk.r.normalize();
  walk.remaining = distance;
  walk.gradients = faceGradients(mesh, walk.face);

  // Algorithm 1: until the distance is walked, leave the face across the edge the direction
  // meets first, test the next face against tau_a and the friction cone, cross onto it and
  // carry the direction over.
  while (true)
  {
    const ExitEdge exit = findExitEdge(walk);
    if (exit.index < 0)
    {
      return walk.stopHere(mesh, WalkStop::kDirectionLost);
    }
    if (exit.t >= walk.remaining)
    {
      return walk.endInsideFace(mesh, exit);
    }
    walk.moveOntoExitEdge(exit);
    if (walk.crossings >= limits.max_crossings || walk.stalled > kMaxStalledCrossings)
    {
      return walk.stopHere(mesh, WalkStop::kCrossingCap);
    }
    const int vertex_local = walk.vertexReached(exit.index);
    const std::optional<WalkStop> stop =
        vertex_local >= 0 ? crossVertex(mesh, limits, vertex_local, &walk) : crossEdge(mesh, limits, exit.index, &walk);
    if (stop)
    {
      return walk.stopHere(mesh, *stop);
    }
  }
}
}  // namespace god_finger
