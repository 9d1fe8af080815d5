// The MuJoCo baseline's scene and stepping helpers, shared by bench/mujoco_baseline_bench.cpp
// and bench/operator_mujoco_bench.cpp (MuJoCo 2.2, Debian's libmujoco: a benchmark's dependency
// only, never the package's). Header-only: each benchmark binary compiles its own copy.
//
// The MuJoCo scene (mujocoXml):
//  - bodies: the same geoms (box, sphere, cylinder; the scenarios and the grip bar have no mesh),
//    poses, masses, inertias (full tensor at the inertial origin) and friction as the scene;
//    static bodies are world geoms, others have a free joint.
//  - proxies: a body per finger with three world-aligned slide joints (x, y, z), a sphere geom
//    of WorldParams().coupling.proxy_radius and proxy_mass (Bullet's proxy: rotation locked). No
//    gravity on them: qfrc_applied carries -m g (MuJoCo 2.2 has no gravcomp).
//  - coupling: haptics/virtual_coupling.h's couplingForce with WorldParams().coupling, applied on
//    the three slider dofs through qfrc_applied, explicit in time as GodFingerWorld::step():
//    the proxy's state at the start of the step, target velocity = (target - previous target)/dt,
//    target = the script at the end of the step (runExperiment's ideal hand).
//  - time step 1 ms, gravity (0, 0, -9.81), integrator Euler (MuJoCo's semi-implicit Euler,
//    like Bullet's).
//  - contacts: explicit <pair>s only (every geom's contype = conaffinity = 0), so that each pair
//    gets Bullet's combined friction (the product of both bodies' coefficients; MuJoCo would take
//    the max): proxy-body pairs mu = 1.0 (the proxy's) x body mu; body-body pairs mu_a x mu_b.
//    Proxies do not collide with each other (as in GodFingerWorld). Body-body pairs are condim 3
//    in every variant: the scenes give zero spinning and rolling friction (Bullet's product is
//    zero), which is condim 3. The benchmark's condim (3, 4, 6) is the finger contacts'.
//  - finger friction triple: sliding = mu; torsional = (2/3) mu a and rolling = a, with
//    a = ContactParams().max_radius = 1 cm, the pad's contact radius under a few newtons: what
//    god_finger's pad constraint bounds its rows by (pad_constraints.h: twist <= mu N (2/3) a for
//    a uniform disk, tilt <= N a). condim 4 uses the torsional value, condim 6 both.
//  - solver (the fairest we found; stated in the report): Newton (MuJoCo's default and its best
//    for small scenes), iterations 100 and tolerance 1e-8 (MuJoCo's defaults: it stops when
//    converged: 1-2 iterations per step here), elliptic friction cones (MuJoCo's
//    recommendation for grasping; condim 4 and 6 are exact cones, not pyramids), impratio 10
//    (frictional constraints 10 times harder than normal ones: MuJoCo's documented remedy for
//    the slip of soft contacts in grasps; god_finger's friction rows are hard), 3 noslip
//    iterations (MuJoCo's post-pass that removes the creep of its soft friction: without it the
//    pinched cylinder slides down the fingers and drops after 12.7 s of the 21.5 s hold with
//    condim 3, 4 and 6 alike, for about 1 us/step less; god_finger's pad anchors hold it, and
//    it has 2 support passes after its own solver), contact solref and solimp at MuJoCo's
//    defaults (0.02 s, damping ratio 1; 0.9 0.95 0.001), warm start on.
#pragma once

#include "god_finger/contact/contact_params.h"
#include "god_finger/haptics/virtual_coupling.h"
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/scene/scene_description.h"
#include "god_finger/physics/world_params.h"

#include <mujoco/mujoco.h>

#include <Eigen/Geometry>
#include <cstring>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace god_finger
{
inline std::string number(double value)
{
  std::ostringstream out;
  out.precision(17);
  out << value;
  return out.str();
}

inline std::string vec(const Eigen::Vector3d& v)
{
  return number(v.x()) + " " + number(v.y()) + " " + number(v.z());
}

// MuJoCo's quaternion order: w x y z.
inline std::string quat(const Eigen::Matrix3d& rotation)
{
  const Eigen::Quaterniond q(rotation);
  return number(q.w()) + " " + number(q.x()) + " " + number(q.y()) + " " + number(q.z());
}

inline std::string geomXml(const std::string& name, const BodyDescription& body, const Eigen::Isometry3d& pose)
{
  std::ostringstream out;
  out << "<geom name=\"" << name << "\" contype=\"0\" conaffinity=\"0\" pos=\"" << vec(pose.translation())
      << "\" quat=\"" << quat(pose.linear()) << "\" ";
  const Geometry& geometry = body.geometry;
  switch (geometry.kind)
  {
    case GeometryKind::kBox:
      out << "type=\"box\" size=\"" << vec(0.5 * geometry.size) << "\"";
      break;
    case GeometryKind::kSphere:
      out << "type=\"sphere\" size=\"" << number(geometry.radius) << "\"";
      break;
    case GeometryKind::kCylinder:
      // Both conventions put the axis along the geometry frame's z; MuJoCo's size is r, half length.
      out << "type=\"cylinder\" size=\"" << number(geometry.radius) << " " << number(0.5 * geometry.length) << "\"";
      break;
    case GeometryKind::kMesh:
      throw std::runtime_error("mujoco baseline: body '" + body.name + "' is a mesh (not needed by its scenarios)");
  }
  out << "/>\n";
  return out.str();
}

// Friction of the finger contacts, see the header.
struct FingerFriction
{
  double torsional_per_mu = 2.0 / 3.0 * ContactParams().max_radius;  // m, times mu
  double rolling = ContactParams().max_radius;                       // m
};

// `finger_solref` (s): the finger contacts' solref time constant; 0 keeps MuJoCo's default (0.02).
inline std::string mujocoXml(const SceneDescription& scene, const std::vector<Eigen::Vector3d>& finger_starts,
                             const WorldParams& params, int condim, double finger_solref = 0.0)
{
  std::ostringstream xml;
  xml << "<mujoco model=\"" << scene.name << "\">\n"
      << "<compiler angle=\"radian\" inertiafromgeom=\"false\" boundmass=\"0\" boundinertia=\"0\"/>\n"
      << "<option timestep=\"" << number(params.time_step) << "\" gravity=\"" << vec(params.gravity)
      << "\" integrator=\"Euler\" solver=\"Newton\" iterations=\"100\" tolerance=\"1e-8\" cone=\"elliptic\""
      << " impratio=\"10\" noslip_iterations=\"3\"/>\n"
      << "<worldbody>\n";
  for (std::size_t i = 0; i < scene.bodies.size(); ++i)
  {
    const BodyDescription& body = scene.bodies[i];
    const std::string geom = "g" + std::to_string(i);
    if (body.is_static)
    {
      xml << geomXml(geom, body, body.pose * body.collision_origin);
      continue;
    }
    // The tensor is given in the inertial frame; MuJoCo's fullinertia is in the body (link) frame.
    const Eigen::Matrix3d& R = body.inertial_origin.linear();
    const Eigen::Matrix3d I = R * body.inertia * R.transpose();
    xml << "<body name=\"b" << i << "\" pos=\"" << vec(body.pose.translation()) << "\" quat=\""
        << quat(body.pose.linear()) << "\">\n<freejoint/>\n<inertial pos=\"" << vec(body.inertial_origin.translation())
        << "\" mass=\"" << number(body.mass) << "\" fullinertia=\"" << number(I(0, 0)) << " " << number(I(1, 1)) << " "
        << number(I(2, 2)) << " " << number(I(0, 1)) << " " << number(I(0, 2)) << " " << number(I(1, 2)) << "\"/>\n"
        << geomXml(geom, body, body.collision_origin) << "</body>\n";
  }
  const double r = params.coupling.proxy_radius;
  const double m = params.coupling.proxy_mass;
  for (std::size_t f = 0; f < finger_starts.size(); ++f)
  {
    // A uniform sphere's inertia; the slide joints never turn it.
    xml << "<body name=\"p" << f << "\" pos=\"" << vec(finger_starts[f]) << "\">\n"
        << "<joint name=\"p" << f << "x\" type=\"slide\" axis=\"1 0 0\"/>\n"
        << "<joint name=\"p" << f << "y\" type=\"slide\" axis=\"0 1 0\"/>\n"
        << "<joint name=\"p" << f << "z\" type=\"slide\" axis=\"0 0 1\"/>\n"
        << "<inertial pos=\"0 0 0\" mass=\"" << number(m) << "\" diaginertia=\""
        << vec(Eigen::Vector3d::Constant(0.4 * m * r * r)) << "\"/>\n"
        << "<geom name=\"pg" << f << "\" type=\"sphere\" size=\"" << number(r)
        << "\" contype=\"0\" conaffinity=\"0\"/>\n</body>\n";
  }
  xml << "</worldbody>\n<contact>\n";
  const FingerFriction finger;
  for (std::size_t a = 0; a < scene.bodies.size(); ++a)
  {
    for (std::size_t b = a + 1; b < scene.bodies.size(); ++b)
    {
      if (scene.bodies[a].is_static && scene.bodies[b].is_static)
      {
        continue;
      }
      const double mu = scene.bodies[a].material.friction * scene.bodies[b].material.friction;
      xml << "<pair geom1=\"g" << a << "\" geom2=\"g" << b << "\" condim=\"3\" friction=\"" << number(mu) << " "
          << number(mu) << " 0 0 0\"/>\n";
    }
    for (std::size_t f = 0; f < finger_starts.size(); ++f)
    {
      const double mu = 1.0 * scene.bodies[a].material.friction;
      xml << "<pair geom1=\"pg" << f << "\" geom2=\"g" << a << "\" condim=\"" << condim << "\" friction=\""
          << number(mu) << " " << number(mu) << " " << number(finger.torsional_per_mu * mu) << " "
          << number(finger.rolling) << " " << number(finger.rolling) << "\"";
      if (finger_solref > 0.0)
      {
        xml << " solref=\"" << number(finger_solref) << " 1\"";
      }
      xml << "/>\n";
    }
  }
  xml << "</contact>\n</mujoco>\n";
  return xml.str();
}

struct ModelDeleter
{
  void operator()(mjModel* model) const
  {
    mj_deleteModel(model);
  }
};
struct DataDeleter
{
  void operator()(mjData* data) const
  {
    mj_deleteData(data);
  }
};
using ModelPtr = std::unique_ptr<mjModel, ModelDeleter>;
using DataPtr = std::unique_ptr<mjData, DataDeleter>;

inline ModelPtr loadMujoco(const std::string& xml)
{
  auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  const char* name = "scene.xml";
  if (mj_makeEmptyFileVFS(vfs.get(), name, static_cast<int>(xml.size())) != 0)
  {
    throw std::runtime_error("mujoco baseline: cannot make the VFS file");
  }
  std::memcpy(vfs->filedata[mj_findFileVFS(vfs.get(), name)], xml.data(), xml.size());
  char error[1000] = "";
  ModelPtr model(mj_loadXML(name, vfs.get(), error, sizeof(error)));
  mj_deleteVFS(vfs.get());
  if (!model)
  {
    throw std::runtime_error(std::string("mujoco baseline: ") + error + "\n" + xml);
  }
  return model;
}

// The object's sample from MuJoCo's state after mj_step (qpos, qvel are the new state; the
// derived quantities such as xpos are still the step's start, so they are not read). A free
// joint's qpos is the body frame (the link frame) in world, its qvel the frame origin's linear
// velocity (world) and the angular velocity (body frame).
inline BodyState mujocoSample(const mjModel* model, const mjData* data, int body, Eigen::Vector3d previous_velocity,
                              double mass, Eigen::Vector3d* com_velocity)
{
  const int qpos = model->jnt_qposadr[model->body_jntadr[body]];
  const int dof = model->jnt_dofadr[model->body_jntadr[body]];
  const mjtNum* q = data->qpos + qpos;
  const mjtNum* v = data->qvel + dof;
  BodyState sample;
  sample.pose.linear() = Eigen::Quaterniond(q[3], q[4], q[5], q[6]).normalized().toRotationMatrix();
  sample.pose.translation() = Eigen::Vector3d(q[0], q[1], q[2]);
  const Eigen::Vector3d com_offset = sample.pose.linear() * Eigen::Vector3d(model->body_ipos + 3 * body);
  sample.center_of_mass = Eigen::Vector3d(q[0], q[1], q[2]) + com_offset;
  sample.angular_velocity = sample.pose.linear() * Eigen::Vector3d(v[3], v[4], v[5]);
  const Eigen::Vector3d velocity = Eigen::Vector3d(v[0], v[1], v[2]) + sample.angular_velocity.cross(com_offset);
  sample.linear_velocity = velocity;
  sample.net_force = mass * (velocity - previous_velocity) / model->opt.timestep;
  *com_velocity = velocity;
  return sample;
}

// The coupling on a 3-DOF slider proxy (its x dof at `dof`, y and z following; its qpos relative
// to `start`), explicit as GodFingerWorld::step(): the proxy's state at the start of the step, the
// target velocity from the previous target; plus the proxy's gravity compensation. Returns the
// coupling's force on the proxy (N, world; the hand feels its opposite).
inline Eigen::Vector3d pullSlider(const WorldParams& params, const Eigen::Vector3d& target,
                                  const Eigen::Vector3d& start, int dof, int qpos,
                                  const Eigen::Vector3d& gravity_compensation, Eigen::Vector3d* previous_target,
                                  mjData* data)
{
  const double dt = params.time_step;
  const mjtNum* q = data->qpos + qpos;
  const Eigen::Vector3d position = start + Eigen::Vector3d(q[0], q[1], q[2]);
  const Eigen::Vector3d velocity(data->qvel[dof], data->qvel[dof + 1], data->qvel[dof + 2]);
  const Eigen::Vector3d coupling =
      couplingForce(params.coupling, target, (target - *previous_target) / dt, position, velocity).on_proxy;
  const Eigen::Vector3d force = coupling + gravity_compensation;
  for (int k = 0; k < 3; ++k)
  {
    data->qfrc_applied[dof + k] = force[k];
  }
  *previous_target = target;
  return coupling;
}
}  // namespace god_finger
