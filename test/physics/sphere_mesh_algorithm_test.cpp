// The sphere-against-mesh algorithm (sphere_mesh_algorithm.h) reports the contacts Bullet's own
// convex-against-concave algorithm reports: for spheres placed all over a mug (its floor, wall,
// rim, handle and their creases, where a sphere touches several triangles at once), each
// candidate contact the algorithm hands the manifold (every addContactPoint, seen through
// Bullet's contact-added callback) is Bullet's, triangle for triangle, in the same order, within
// rounding (0.1 nm: the formulas round differently near a triangle's edges). Both orders of the pair, the mesh alone
// and inside a compound (as bodies place it), and Bullet's closest-point query (the world's start checks) agree. The
// manifolds they leave are then the same wherever the manifold keeps every candidate (4 or fewer); where it must drop
// some, its choice (by area, Bullet's code) can turn on a rounding-level tie between two mirror-image candidates. And a
// hull's box is its points' plus its margin and a set reach (collision_shape.h).
#include "sphere_mesh_algorithm.h"
#include "collision_shape.h"

#include "god_finger/geometry/mesh_primitives.h"

#include <btBulletCollisionCommon.h>
#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <vector>

namespace god_finger::internal
{
namespace
{
struct Contact
{
  btVector3 on_a;
  btVector3 on_b;
  btVector3 normal_on_b;
  btScalar distance;
  int index0;
  int index1;
};

// Where Bullet's contact-added callback records each candidate (sphere first), while set.
std::vector<Contact>* recorded = nullptr;
const btCollisionObject* recorded_sphere = nullptr;

bool recordCandidate(btManifoldPoint& point, const btCollisionObjectWrapper* first, int, int index0,
                     const btCollisionObjectWrapper*, int, int index1)
{
  if (recorded != nullptr)
  {
    const bool sphere_is_0 = first->getCollisionObject() == recorded_sphere;
    recorded->push_back(sphere_is_0 ? Contact{point.getPositionWorldOnA(), point.getPositionWorldOnB(),
                                              point.m_normalWorldOnB, point.getDistance(), index0, index1}
                                    : Contact{point.getPositionWorldOnB(), point.getPositionWorldOnA(),
                                              -point.m_normalWorldOnB, point.getDistance(), index1, index0});
  }
  return false;
}

struct Pass
{
  std::vector<Contact> candidates;  // every contact handed to the manifold, in order
  std::vector<Contact> kept;        // the manifold's points after the pass
};

// One collision world with a mesh body and a sphere, either dispatcher.
class SphereAndMesh
{
 public:
  SphereAndMesh(btCollisionShape* mesh_shape, const btTransform& mesh_pose, double radius, bool ours, bool sphere_first)
      : dispatcher_(&configuration_), sphere_shape_(radius)
  {
    if (ours)
    {
      registerSphereMeshAlgorithm(&dispatcher_);
    }
    world_ = std::make_unique<btCollisionWorld>(&dispatcher_, &broadphase_, &configuration_);
    mesh_.setCollisionShape(mesh_shape);
    mesh_.setWorldTransform(mesh_pose);
    sphere_.setCollisionShape(&sphere_shape_);
    sphere_.setCollisionFlags(btCollisionObject::CF_CUSTOM_MATERIAL_CALLBACK);
    if (sphere_first)
    {
      world_->addCollisionObject(&sphere_);
      world_->addCollisionObject(&mesh_);
    }
    else
    {
      world_->addCollisionObject(&mesh_);
      world_->addCollisionObject(&sphere_);
    }
  }

  ~SphereAndMesh()
  {
    world_->removeCollisionObject(&sphere_);
    world_->removeCollisionObject(&mesh_);
  }

  // One collision pass with the sphere at `centre`, from a fresh pair.
  Pass passAt(const btVector3& centre)
  {
    world_->removeCollisionObject(&sphere_);
    sphere_.setWorldTransform(btTransform(btQuaternion::getIdentity(), centre));
    world_->addCollisionObject(&sphere_);
    Pass pass;
    recorded = &pass.candidates;
    recorded_sphere = &sphere_;
    gContactAddedCallback = &recordCandidate;
    world_->performDiscreteCollisionDetection();
    gContactAddedCallback = nullptr;
    recorded = nullptr;
    std::vector<Contact>& contacts = pass.kept;
    for (int m = 0; m < dispatcher_.getNumManifolds(); ++m)
    {
      const btPersistentManifold* manifold = dispatcher_.getManifoldByIndexInternal(m);
      const bool sphere_is_0 = manifold->getBody0() == &sphere_;
      for (int p = 0; p < manifold->getNumContacts(); ++p)
      {
        const btManifoldPoint& point = manifold->getContactPoint(p);
        // In the sphere-first order whichever order the manifold keeps.
        contacts.push_back(sphere_is_0
                               ? Contact{point.getPositionWorldOnA(), point.getPositionWorldOnB(),
                                         point.m_normalWorldOnB, point.getDistance(), point.m_index0, point.m_index1}
                               : Contact{point.getPositionWorldOnB(), point.getPositionWorldOnA(),
                                         -point.m_normalWorldOnB, point.getDistance(), point.m_index1, point.m_index0});
      }
    }
    return pass;
  }

  // Bullet's closest-point query (contactPairTest), as the world's start checks use it: each
  // point as reported, sphere first.
  std::vector<Contact> pairTestAt(const btVector3& centre)
  {
    struct Collect : btCollisionWorld::ContactResultCallback
    {
      const btCollisionObject* sphere;
      std::vector<Contact>* out;
      btScalar addSingleResult(btManifoldPoint& point, const btCollisionObjectWrapper* first, int, int index0,
                               const btCollisionObjectWrapper*, int, int index1) override
      {
        const bool sphere_is_0 = first->getCollisionObject() == sphere;
        out->push_back(sphere_is_0 ? Contact{point.getPositionWorldOnA(), point.getPositionWorldOnB(),
                                             point.m_normalWorldOnB, point.getDistance(), index0, index1}
                                   : Contact{point.getPositionWorldOnB(), point.getPositionWorldOnA(),
                                             -point.m_normalWorldOnB, point.getDistance(), index1, index0});
        return 0;
      }
    };
    sphere_.setWorldTransform(btTransform(btQuaternion::getIdentity(), centre));
    std::vector<Contact> contacts;
    Collect collect;
    collect.sphere = &sphere_;
    collect.out = &contacts;
    world_->contactPairTest(&sphere_, &mesh_, collect);
    return contacts;
  }

 private:
  btDefaultCollisionConfiguration configuration_;
  btCollisionDispatcher dispatcher_;
  btDbvtBroadphase broadphase_;
  btSphereShape sphere_shape_;
  btCollisionObject mesh_;
  btCollisionObject sphere_;
  std::unique_ptr<btCollisionWorld> world_;
};

double distance(const btVector3& a, const btVector3& b)
{
  return (a - b).length();
}

void expectSame(const std::vector<Contact>& bullet, const std::vector<Contact>& ours, const btVector3& centre,
                double* largest_difference)
{
  ASSERT_EQ(bullet.size(), ours.size()) << "sphere at " << centre.x() << " " << centre.y() << " " << centre.z();
  for (size_t i = 0; i < bullet.size(); ++i)
  {
    const double difference = std::max({distance(bullet[i].on_a, ours[i].on_a), distance(bullet[i].on_b, ours[i].on_b),
                                        distance(bullet[i].normal_on_b, ours[i].normal_on_b),
                                        std::abs(static_cast<double>(bullet[i].distance - ours[i].distance))});
    *largest_difference = std::max(*largest_difference, difference);
    EXPECT_LT(difference, 1e-10) << "contact " << i << ", sphere at " << centre.x() << " " << centre.y() << " "
                                 << centre.z();
    EXPECT_EQ(bullet[i].index1, ours[i].index1) << "the triangle of contact " << i;
  }
}

class SphereMeshAlgorithmTest : public ::testing::Test
{
 protected:
  SphereMeshAlgorithmTest()
      : mesh_(TriangleMesh::build(makeMug(0.04, 0.09, 0.005, 0.012, 64))), shape_(makeTriangleMeshShape(mesh_))
  {
    pose_.setOrigin(btVector3(0.1, -0.05, 0.02));
    pose_.setRotation(btQuaternion(btVector3(1, 2, 3).normalized(), 0.4));
  }

  // Sphere centres near the surface: on a random triangle, moved along its normal from 1.2 radii
  // inside to 0.2 mm outside (in contact, or just out of it), some on an edge or corner.
  std::vector<btVector3> centres(int count, double radius)
  {
    std::mt19937 random(7);
    std::uniform_int_distribution<int> triangle(0, mesh_.triangleCount() - 1);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::uniform_real_distribution<double> offset(-0.2 * radius, radius + 0.0002);
    std::vector<btVector3> result;
    for (int i = 0; i < count; ++i)
    {
      const int t = triangle(random);
      double u = unit(random);
      double v = unit(random);
      if (u + v > 1.0)
      {
        u = 1.0 - u;
        v = 1.0 - v;
      }
      if (i % 5 == 0)
      {
        v = 0.0;  // on an edge
      }
      const Eigen::Vector3d a = mesh_.corner(t, 0);
      const Eigen::Vector3d on = a + u * (mesh_.corner(t, 1) - a) + v * (mesh_.corner(t, 2) - a);
      const Eigen::Vector3d normal = (mesh_.corner(t, 1) - a).cross(mesh_.corner(t, 2) - a).normalized();
      const Eigen::Vector3d local = on + offset(random) * normal;
      result.push_back(pose_ * btVector3(local.x(), local.y(), local.z()));
    }
    return result;
  }

  TriangleMesh mesh_;
  std::unique_ptr<CollisionShape> shape_;
  btTransform pose_ = btTransform::getIdentity();
};

// Compares two sides' passes over the same placements: every candidate the same (asserted); the
// manifolds the same wherever they kept every candidate. Returns how many placements' manifolds
// differ (each one where more than 4 candidates had to be reduced).
struct Tally
{
  int touching = 0;
  int several = 0;
  int reduced = 0;
  int kept_differ = 0;
  double largest_difference = 0.0;
};

bool sameContacts(const std::vector<Contact>& a, const std::vector<Contact>& b)
{
  if (a.size() != b.size())
  {
    return false;
  }
  for (size_t i = 0; i < a.size(); ++i)
  {
    if (a[i].index1 != b[i].index1 || distance(a[i].on_b, b[i].on_b) > 1e-10 ||
        distance(a[i].normal_on_b, b[i].normal_on_b) > 1e-10)
    {
      return false;
    }
  }
  return true;
}

void comparePasses(SphereAndMesh* bullet, SphereAndMesh* ours, const btVector3& centre, Tally* tally)
{
  const Pass expected = bullet->passAt(centre);
  const Pass got = ours->passAt(centre);
  expectSame(expected.candidates, got.candidates, centre, &tally->largest_difference);
  tally->touching += expected.candidates.empty() ? 0 : 1;
  tally->several += expected.candidates.size() > 1 ? 1 : 0;
  tally->reduced += expected.candidates.size() > 4 ? 1 : 0;
  if (!sameContacts(expected.kept, got.kept))
  {
    ++tally->kept_differ;
    EXPECT_GT(expected.candidates.size(), 4u) << "the manifolds differ with every candidate kept, sphere at "
                                              << centre.x() << " " << centre.y() << " " << centre.z();
  }
}

TEST_F(SphereMeshAlgorithmTest, SameContactsAsBulletsAlgorithmInEitherOrder)
{
  const double radius = 0.003;  // a finger's proxy
  for (const bool sphere_first : {true, false})
  {
    SphereAndMesh bullet(shape_->shape, pose_, radius, false, sphere_first);
    SphereAndMesh ours(shape_->shape, pose_, radius, true, sphere_first);
    Tally tally;
    for (const btVector3& centre : centres(1500, radius))
    {
      comparePasses(&bullet, &ours, centre, &tally);
    }
    // The placements cover touching, separate, and several triangles at once.
    EXPECT_GT(tally.touching, 1000);
    EXPECT_LT(tally.touching, 1500);
    EXPECT_GT(tally.several, 100);
    EXPECT_GT(tally.reduced, 100);
    // A rounding-level tie in the manifold's reduction is rare.
    EXPECT_LT(tally.kept_differ, 1500 / 50);
    std::printf(
        "sphere %s: %d of 1500 placements touching, %d on several triangles, %d on more than 4; "
        "candidates' largest difference %.3g m; manifolds differ at %d placements (ties in the "
        "reduction)\n",
        sphere_first ? "first" : "second", tally.touching, tally.several, tally.reduced, tally.largest_difference,
        tally.kept_differ);
  }
}

TEST_F(SphereMeshAlgorithmTest, SameContactsInsideACompound)
{
  const double radius = 0.003;
  btCompoundShape compound;
  btTransform child = btTransform::getIdentity();
  child.setOrigin(btVector3(0.0, 0.0, -0.01));
  compound.addChildShape(child, shape_->shape);
  SphereAndMesh bullet(&compound, pose_, radius, false, true);
  SphereAndMesh ours(&compound, pose_, radius, true, true);
  Tally tally;
  for (btVector3 centre : centres(500, radius))
  {
    centre += pose_.getBasis() * btVector3(0.0, 0.0, -0.01);  // the compound places the mesh 1 cm down
    comparePasses(&bullet, &ours, centre, &tally);
  }
  EXPECT_GT(tally.touching, 300);
  EXPECT_LT(tally.kept_differ, 500 / 50);
}

TEST_F(SphereMeshAlgorithmTest, SameClosestPointsAsBullet)
{
  const double radius = 0.003;
  SphereAndMesh bullet(shape_->shape, pose_, radius, false, true);
  SphereAndMesh ours(shape_->shape, pose_, radius, true, true);
  double largest_difference = 0.0;
  int touching = 0;
  for (const btVector3& centre : centres(500, radius))
  {
    const std::vector<Contact> expected = bullet.pairTestAt(centre);
    touching += expected.empty() ? 0 : 1;
    expectSame(expected, ours.pairTestAt(centre), centre, &largest_difference);
  }
  EXPECT_GT(touching, 300);
}

TEST(HullShapeBox, IsItsPointsItsMarginAndItsReach)
{
  // A 2 cm cube as a hull (a free mesh's, or a decomposed body's piece): its box is the cube's,
  // grown by its 0.5 mm margin twice (Bullet's cached box and getAabb each add it) and by
  // kHullPairReach. It was 4 cm too wide, Bullet's default margin, when the margin was set after
  // the box was cached.
  Geometry geometry;
  geometry.kind = GeometryKind::kMesh;
  const TriangleMesh cube = TriangleMesh::build(makeBox(Eigen::Vector3d(0.01, 0.01, 0.01)));
  const double margin = 0.0005;
  const std::unique_ptr<CollisionShape> shape = makeCollisionShape(geometry, cube, false, margin);
  ASSERT_EQ(shape->shape->getShapeType(), CONVEX_HULL_SHAPE_PROXYTYPE);
  btVector3 min;
  btVector3 max;
  shape->shape->getAabb(btTransform::getIdentity(), min, max);
  const double half = 0.01 + 2 * margin + kHullPairReach;
  EXPECT_NEAR(max.z(), half, 1e-12);
  EXPECT_NEAR(min.x(), -half, 1e-12);
}
}  // namespace
}  // namespace god_finger::internal
