// god_finger.World: a GodFingerWorld (physics/god_finger_world.h) made from a scene file and
// parameters by name, its fingers, bodies and joints read as Python objects with numpy arrays.
//
// Thread safety: every call takes the world's mutex; step() releases the GIL while it steps (a
// second Python thread runs meanwhile, and waits on the mutex if it calls this world).
#include "bindings.h"

#include "god_finger/physics/contact_model.h"
#include "god_finger/physics/god_finger_world.h"
#include "god_finger/physics/world_params.h"
#include "god_finger/scene/scene_file.h"
#include "god_finger/support/input_error.h"

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <algorithm>
#include <cstring>
#include <memory>
#include <mutex>

namespace god_finger::python
{
namespace
{
using Rows3 = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

struct ContactView
{
  std::string body;
  int body_index = -1;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double depth = 0.0;
  double radius = 0.0;
  std::string feature;
  Rows3 sub_god_objects;
  double overlap_area = 0.0;
};

struct FingerView
{
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();  // meaningful when oriented
  Eigen::Vector3d velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
  Eigen::Quaterniond target_orientation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  Eigen::Vector3d torque = Eigen::Vector3d::Zero();
  bool saturated = false;
  bool oriented = false;
  // The contact areas as the world gave them, and the names of the bodies they touch: made into
  // Contact objects when read (a loop that reads only the force pays nothing for them).
  std::vector<WorldContactArea> areas;
  std::vector<std::string> bodies;
  double overlap_area = 0.0;
  Eigen::Vector3d overlap_push = Eigen::Vector3d::Zero();
};

struct BodyView
{
  std::string name;
  int index = -1;
  bool is_static = false;
  double mass = 0.0;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  py::object orientation;
  Eigen::Matrix4d pose = Eigen::Matrix4d::Identity();
  Eigen::Vector3d center_of_mass = Eigen::Vector3d::Zero();
  Eigen::Vector3d linear_velocity = Eigen::Vector3d::Zero();
  Eigen::Vector3d angular_velocity = Eigen::Vector3d::Zero();
  bool awake = true;
  int left_world = 0;
};

struct JointView
{
  std::string name;
  std::string kind;
  double position = 0.0;
  double velocity = 0.0;
};

// What the keyword arguments of World may name: the world's table, the coupling's (the default
// profile of every finger) and time_step.
std::set<std::string> worldParameterNames()
{
  std::set<std::string> names = rowNames(worldParameterTable());
  const std::set<std::string> coupling = rowNames(couplingParameterTable());
  names.insert(coupling.begin(), coupling.end());
  names.insert("time_step");
  return names;
}

WorldParams worldParams(const std::string& model, const py::kwargs& kwargs)
{
  py::dict all;
  for (const auto& item : kwargs)
  {
    all[item.first] = item.second;
  }
  all["model"] = model;
  const MapParameterSource source = parameterSource(all, worldParameterNames(), "the world's parameters");
  WorldParams params;
  readRows(source, worldParameterTable(), &params);
  CouplingProfile& coupling = params.coupling;
  readRows(source, couplingParameterTable(), &coupling);
  params.time_step = readNumber(source, "time_step", params.time_step, timeStepRange(), "s");
  validateOrThrow(params);
  return params;
}

// The parameters checked first (cheap), then the scene loaded.
std::unique_ptr<GodFingerWorld> makeWorld(const std::string& scene, const std::string& model, const py::kwargs& kwargs)
{
  const WorldParams params = worldParams(model, kwargs);
  return std::make_unique<GodFingerWorld>(loadScene(scene), params);
}

class World
{
 public:
  World(const std::string& scene, const std::string& model, const py::kwargs& kwargs)
      : path_(scene), world_(makeWorld(scene, model, kwargs))
  {
  }

  int addFinger(const py::object& position, const py::object& orientation, const py::object& coupling,
                bool allow_inside)
  {
    const Eigen::Vector3d start = vector3(position, "position");
    std::optional<Eigen::Quaterniond> rotation;
    if (!orientation.is_none())
    {
      rotation = quaternion(orientation, "orientation");
    }
    CouplingProfile profile = world_->params().coupling;
    if (!coupling.is_none())
    {
      if (!py::isinstance<py::dict>(coupling))
      {
        throw InputError("coupling must be a dict of " + names(rowNames(couplingParameterTable())));
      }
      readRows(
          parameterSource(coupling.cast<py::dict>(), rowNames(couplingParameterTable()), "the coupling's parameters"),
          couplingParameterTable(), &profile);
    }
    const std::lock_guard<std::mutex> lock(mutex_);
    const int finger = world_->addInterface(start, profile, allow_inside);
    if (rotation)
    {
      world_->setInterfaceTarget(finger, start, *rotation);
    }
    return finger;
  }

  void setTarget(int finger, const py::object& position, const py::object& orientation, const py::object& velocity)
  {
    const Eigen::Vector3d target = vector3(position, "position");
    if (!orientation.is_none() && !velocity.is_none())
    {
      throw InputError(
          "set_target: give orientation or velocity, not both (an oriented finger's velocity is the "
          "difference of its targets over a step)");
    }
    const std::lock_guard<std::mutex> lock(mutex_);
    checkFinger(finger);
    if (!orientation.is_none())
    {
      world_->setInterfaceTarget(finger, target, quaternion(orientation, "orientation"));
    }
    else if (!velocity.is_none())
    {
      world_->setInterfaceTarget(finger, target, vector3(velocity, "velocity"));
    }
    else
    {
      world_->setInterfaceTarget(finger, target);
    }
  }

  std::unique_ptr<FingerView> finger(int finger) const
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    checkFinger(finger);
    return fingerView(world_->interfaceState(finger));
  }

  void step(long count)
  {
    if (count < 0)
    {
      throw InputError("step: n must be >= 0, not " + std::to_string(count));
    }
    if (count == 1)
    {
      // One step (a few microseconds): the GIL is kept, as a Python loop calling it takes it
      // back at once (releasing it would cost a tenth of the call).
      const std::lock_guard<std::mutex> lock(mutex_);
      world_->step();
      return;
    }
    // In chunks, the GIL released for each: between them Ctrl-C (KeyboardInterrupt) stops a long
    // run, the world left at the last whole step.
    constexpr long kChunk = 1000;
    for (long done = 0; done < count;)
    {
      const long chunk = std::min(kChunk, count - done);
      {
        py::gil_scoped_release release;
        const std::lock_guard<std::mutex> lock(mutex_);
        for (long i = 0; i < chunk; ++i)
        {
          world_->step();
        }
      }
      done += chunk;
      if (done < count && PyErr_CheckSignals() != 0)
      {
        throw py::error_already_set();
      }
    }
  }

  double time() const
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    return world_->time();
  }
  long steps() const
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    return world_->steps();
  }
  void reset()
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    world_->reset();
  }
  std::string contactModel() const
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    return contactModelName(world_->contactModel());
  }
  void setContactModel(const std::string& name)
  {
    ContactModel model = ContactModel::kGodFinger;
    if (!parseContactModel(name, &model))
    {
      throw InputError("contact model '" + name + "' is not one of " + contactModelNames());
    }
    const std::lock_guard<std::mutex> lock(mutex_);
    world_->setContactModel(model);
  }

  py::dict params() const
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    WorldParams params = world_->params();
    params.model = world_->contactModel();
    py::dict values = rowValues(worldParameterTable(), params);
    const py::dict coupling = rowValues(couplingParameterTable(), static_cast<const CouplingProfile&>(params.coupling));
    for (const auto& item : coupling)
    {
      values[item.first] = item.second;
    }
    values["time_step"] = params.time_step;
    return values;
  }

  std::vector<std::string> bodies() const
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    std::vector<std::string> names;
    for (const BodyDescription& body : world_->scene().bodies)
    {
      names.push_back(body.name);
    }
    return names;
  }

  BodyView body(const std::string& name) const
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    return bodyView(bodyIndex(name));
  }

  std::vector<std::string> joints() const
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    std::vector<std::string> names;
    for (const JointDescription& joint : world_->scene().joints)
    {
      names.push_back(joint.name);
    }
    return names;
  }

  JointView joint(const std::string& name) const
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    const std::vector<JointDescription>& joints = world_->scene().joints;
    for (std::size_t j = 0; j < joints.size(); ++j)
    {
      if (joints[j].name == name)
      {
        return jointView(static_cast<int>(j));
      }
    }
    std::vector<std::string> known;
    for (const JointDescription& joint : joints)
    {
      known.push_back(joint.name);
    }
    throw InputError("no joint '" + name + "' in the scene (its joints: " + (known.empty() ? "none" : names(known)) +
                     ")");
  }

  void applyWrench(const std::string& name, const py::object& force, const py::object& torque)
  {
    const Eigen::Vector3d f = vector3(force, "force");
    const Eigen::Vector3d t = vector3(torque, "torque");
    const std::lock_guard<std::mutex> lock(mutex_);
    world_->applyBodyWrench(bodyIndex(name), f, t);
  }

  std::vector<std::string> spawn(const std::string& file, const std::string& name, const py::object& xyz,
                                 const py::object& rpy, const py::object& fixed)
  {
    ObjectPlacement placement;
    placement.name = name;
    placement.pose.translation() = vector3(xyz, "xyz");
    placement.pose.linear() = rpyRotation(vector3(rpy, "rpy"));
    if (!fixed.is_none())
    {
      placement.fixed = argument<bool>(fixed, "fixed", "true, false or None");
    }
    const SceneDescription object = loadPlacedObject(file, placement);
    const std::lock_guard<std::mutex> lock(mutex_);
    std::vector<std::string> warnings = object.warnings;
    const std::vector<std::string> overlaps = world_->addObject(object);
    warnings.insert(warnings.end(), overlaps.begin(), overlaps.end());
    return warnings;
  }

  int remove(const std::string& name)
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    return world_->removeObject(name);
  }

  py::dict snapshot() const
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    py::dict out;
    out["time"] = world_->time();
    out["steps"] = world_->steps();
    out["model"] = contactModelName(world_->contactModel());
    py::dict bodies;
    for (int b = 0; b < world_->bodyCount(); ++b)
    {
      bodies[py::str(world_->scene().bodies[b].name)] = bodyView(b);
    }
    out["bodies"] = bodies;
    py::list fingers;
    for (int f = 0; f < world_->interfaceCount(); ++f)
    {
      fingers.append(py::cast(fingerView(world_->interfaceState(f))));
    }
    out["fingers"] = fingers;
    py::dict joints;
    for (int j = 0; j < world_->jointCount(); ++j)
    {
      joints[py::str(world_->scene().joints[j].name)] = jointView(j);
    }
    out["joints"] = joints;
    return out;
  }

  int fingerCount() const
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    return world_->interfaceCount();
  }
  std::vector<std::string> warnings() const
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    std::vector<std::string> all = world_->scene().warnings;
    all.insert(all.end(), world_->startWarnings().begin(), world_->startWarnings().end());
    return all;
  }
  long rejectedTargets() const
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    return world_->counters().rejected_targets;
  }
  py::dict counters() const
  {
    WorldCounters counters;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      counters = world_->counters();
    }
    py::dict out;
    out["awake_bodies"] = counters.awake_bodies;
    out["solver_contact_rows"] = counters.solver_contact_rows;
    out["solver_iterations"] = counters.solver_iterations;
    out["solver_proxy_points"] = counters.solver_proxy_points;
    out["deepest_penetration"] = counters.deepest_penetration;
    out["rejected_targets"] = counters.rejected_targets;
    out["dropped_contacts"] = counters.dropped_contacts;
    out["dropped_contacts_total"] = counters.dropped_contacts_total;
    return out;
  }
  py::dict stepProfile() const
  {
    StepProfile profile;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      profile = world_->stepProfile();
    }
    py::dict out;
    out["step"] = profile.step;
    out["total_ns"] = profile.total_ns;
    for (int s = 0; s < kStepStageCount; ++s)
    {
      out[py::str(std::string(stepStageName(static_cast<StepStage>(s))) + "_ns")] = profile.stage_ns[s];
    }
    return out;
  }
  const std::string& path() const
  {
    return path_;
  }

 private:
  static std::string names(const std::vector<std::string>& list)
  {
    std::string text;
    for (const std::string& name : list)
    {
      text += (text.empty() ? "" : ", ") + name;
    }
    return text;
  }
  static std::string names(const std::set<std::string>& set)
  {
    return names(std::vector<std::string>(set.begin(), set.end()));
  }

  // Under the mutex.
  void checkFinger(int finger) const
  {
    const int count = world_->interfaceCount();
    if (finger < 0 || finger >= count)
    {
      throw InputError("no finger " + std::to_string(finger) + " (the world has " + std::to_string(count) +
                       (count == 1 ? " finger" : " fingers") + "; add_finger returns their ids)");
    }
  }

  // Under the mutex.
  int bodyIndex(const std::string& name) const
  {
    const int index = world_->scene().find(name);
    if (index < 0)
    {
      std::vector<std::string> known;
      for (const BodyDescription& body : world_->scene().bodies)
      {
        known.push_back(body.name);
      }
      throw InputError("no body '" + name + "' in the scene (its bodies: " + names(known) + ")");
    }
    return index;
  }

  BodyView bodyView(int index) const
  {
    const BodyDescription& description = world_->scene().bodies[index];
    const BodyState state = world_->bodyState(index);
    BodyView view;
    view.name = description.name;
    view.index = index;
    view.is_static = description.is_static;
    view.mass = description.mass;
    view.position = state.pose.translation();
    view.orientation = quaternionArray(Eigen::Quaterniond(state.pose.linear()));
    view.pose = state.pose.matrix();
    view.center_of_mass = state.center_of_mass;
    view.linear_velocity = state.linear_velocity;
    view.angular_velocity = state.angular_velocity;
    view.awake = !state.asleep;
    view.left_world = state.left_world;
    return view;
  }

  JointView jointView(int index) const
  {
    const JointDescription& description = world_->scene().joints[index];
    const JointState state = world_->jointState(index);
    return JointView{description.name, jointKindName(description.kind), state.position, state.velocity};
  }

  // Made in place on the heap: Python takes it as it is (no move into a holder).
  std::unique_ptr<FingerView> fingerView(const InterfaceState& state) const
  {
    auto made = std::make_unique<FingerView>();
    FingerView& view = *made;
    view.position = state.proxy_position;
    view.velocity = state.proxy_velocity;
    view.target = state.interface_position;
    view.force = state.user_force;
    view.torque = state.user_torque;
    view.saturated = state.saturated;
    view.oriented = state.oriented;
    view.orientation = state.proxy_orientation;
    view.target_orientation = state.interface_orientation;
    view.overlap_area = state.overlap_area;
    view.overlap_push = state.overlap_push;
    view.areas.assign(state.contacts.begin(), state.contacts.begin() + state.contact_count);
    for (const WorldContactArea& area : view.areas)
    {
      view.bodies.push_back(area.body >= 0 && area.body < world_->bodyCount() ? world_->scene().bodies[area.body].name
                                                                              : std::string());
    }
    return made;
  }

  std::string path_;
  std::unique_ptr<GodFingerWorld> world_;
  mutable std::mutex mutex_;
};

// The getter of a vector member: a fresh array each read (numpy's own, not a view of the state).
template <typename View>
auto vectorGetter(Eigen::Vector3d View::*member)
{
  return [member](const View& view) { return array3(view.*member); };
}

ContactView contactView(const FingerView& finger, std::size_t c)
{
  const WorldContactArea& area = finger.areas[c];
  ContactView contact;
  contact.body_index = area.body;
  contact.body = finger.bodies[c];
  contact.point = area.point;
  contact.normal = area.normal;
  contact.depth = area.depth;
  contact.radius = area.radius;
  contact.feature = featureKindName(area.feature);
  contact.sub_god_objects.resize(area.sub_god_object_count, 3);
  for (int i = 0; i < area.sub_god_object_count; ++i)
  {
    contact.sub_god_objects.row(i) = area.positions[i].transpose();
  }
  contact.overlap_area = area.overlap_area;
  return contact;
}

std::vector<ContactView> contactViews(const FingerView& finger)
{
  std::vector<ContactView> contacts;
  for (std::size_t c = 0; c < finger.areas.size(); ++c)
  {
    contacts.push_back(contactView(finger, c));
  }
  return contacts;
}

std::string vectorText(const Eigen::Vector3d& v)
{
  char buffer[96];
  std::snprintf(buffer, sizeof(buffer), "[%.6g, %.6g, %.6g]", v.x(), v.y(), v.z());
  return buffer;
}
}  // namespace

void bindWorld(py::module_& module)
{
  py::class_<ContactView>(module, "Contact",
                          "One contact area of a finger (physics/world_state.h WorldContactArea). m, world frame.")
      .def_readonly("body", &ContactView::body, "the body touched (its name)")
      .def_readonly("body_index", &ContactView::body_index, "its index in World.bodies")
      .def_property_readonly("point", vectorGetter(&ContactView::point), "c_p (m, world)")
      .def_property_readonly("normal", vectorGetter(&ContactView::normal), "c_n (world, unit, out of the body)")
      .def_readonly("depth", &ContactView::depth, "m, > 0 when penetrating")
      .def_readonly("radius", &ContactView::radius, "r (m), Eq. 1 (0 for the god_object and soft_finger models)")
      .def_readonly("feature", &ContactView::feature, "where c_p lies: face, edge or vertex")
      .def_readonly("sub_god_objects", &ContactView::sub_god_objects,
                    "(n, 3) array: the active sub-god-objects' positions (m, world)")
      .def_readonly("overlap_area", &ContactView::overlap_area,
                    "m^2: its overlap with other fingers' areas on this body (god_finger model)")
      .def("__repr__",
           [](const ContactView& c)
           {
             return "<god_finger.Contact on " + c.body + " at " + vectorText(c.point) + ", r " +
                    std::to_string(c.radius) + " m>";
           });

  py::class_<FingerView>(module, "Finger",
                         "A finger's state after the last step (physics/world_state.h InterfaceState). m, N, world "
                         "frame; quaternions (x, y, z, w).")
      .def_property_readonly("position", vectorGetter(&FingerView::position), "p_GO: the proxy (god-object) (m, world)")
      .def_property_readonly(
          "orientation", [](const FingerView& f) { return f.oriented ? quaternionArray(f.orientation) : py::none(); },
          "the proxy's orientation (x, y, z, w) of an oriented finger, else None")
      .def_property_readonly("velocity", vectorGetter(&FingerView::velocity), "the proxy's velocity (m/s, world)")
      .def_property_readonly("target", vectorGetter(&FingerView::target),
                             "p_I: the target set (the device in the world) (m)")
      .def_property_readonly(
          "target_orientation",
          [](const FingerView& f) { return f.oriented ? quaternionArray(f.target_orientation) : py::none(); },
          "the target's orientation (x, y, z, w) of an oriented finger, else None")
      .def_property_readonly("force", vectorGetter(&FingerView::force),
                             "the force on the hand (N, world): minus the coupling's on the proxy")
      .def_property_readonly("torque", vectorGetter(&FingerView::torque),
                             "the torque on the hand (N m, world; oriented fingers)")
      .def_readonly("saturated", &FingerView::saturated, "the coupling force hit max_force")
      .def_readonly("oriented", &FingerView::oriented, "the finger was given an orientation (6-DOF)")
      .def_property_readonly("contacts", &contactViews, "the contact areas (one per body touched, at most 4)")
      .def_property_readonly(
          "contact",
          [](const FingerView& f) -> py::object { return f.areas.empty() ? py::none() : py::cast(contactView(f, 0)); },
          "the first contact, or None when the finger touches nothing")
      .def_readonly("overlap_area", &FingerView::overlap_area, "m^2: overlap of its areas with other fingers'")
      .def_property_readonly("overlap_push", vectorGetter(&FingerView::overlap_push),
                             "N: the push apart it gets in the next step")
      .def("__repr__",
           [](const FingerView& f)
           {
             return "<god_finger.Finger at " + vectorText(f.position) + ", force " + vectorText(f.force) + " N, " +
                    std::to_string(f.areas.size()) + " contacts>";
           });

  py::class_<BodyView>(module, "Body", "A body's state (physics/world_state.h BodyState). m, world frame.")
      .def_readonly("name", &BodyView::name)
      .def_readonly("index", &BodyView::index)
      .def_readonly("static", &BodyView::is_static, "fixed to the world")
      .def_readonly("mass", &BodyView::mass, "kg (0 when static)")
      .def_property_readonly("position", vectorGetter(&BodyView::position), "the link frame's origin (m, world)")
      .def_readonly("orientation", &BodyView::orientation, "the link frame's orientation (x, y, z, w)")
      .def_readonly("pose", &BodyView::pose, "the link frame in the world, a 4x4 homogeneous matrix")
      .def_property_readonly("center_of_mass", vectorGetter(&BodyView::center_of_mass), "m, world")
      .def_property_readonly("linear_velocity", vectorGetter(&BodyView::linear_velocity),
                             "of the centre of mass (m/s, world)")
      .def_property_readonly("angular_velocity", vectorGetter(&BodyView::angular_velocity), "rad/s, world")
      .def_readonly("awake", &BodyView::awake, "simulated in the next step (False: asleep, WorldParams sleep)")
      .def_readonly("left_world", &BodyView::left_world,
                    "times it left the world's bounds and was put back at its initial pose")
      .def("__repr__",
           [](const BodyView& b) { return "<god_finger.Body " + b.name + " at " + vectorText(b.position) + ">"; });

  py::class_<JointView>(module, "Joint", "An articulated object's joint (physics/world_state.h JointState).")
      .def_readonly("name", &JointView::name)
      .def_readonly("kind", &JointView::kind, "revolute, continuous or prismatic")
      .def_readonly("position", &JointView::position, "rad or m from where the scene placed it")
      .def_readonly("velocity", &JointView::velocity, "rad/s or m/s")
      .def("__repr__", [](const JointView& j)
           { return "<god_finger.Joint " + j.name + " (" + j.kind + ") at " + std::to_string(j.position) + ">"; });

  py::class_<World>(
      module, "World",
      "A Bullet world of rigid (and soft) bodies touched by god-object proxies with god-finger contact\n"
      "areas (physics/god_finger_world.h). Fixed time step, deterministic: the same calls give the same\n"
      "trajectory bit for bit, the same as the C++ world's.\n\n"
      "World(scene, model='god_finger', **params)\n"
      "  scene: any file the loader takes (scene/scene_file.h): a URDF scene, an object URDF whose root\n"
      "    link is the body, a xacro file, a scene list (.yaml), soft bodies in them.\n"
      "  model: god_object, god_finger or soft_finger.\n"
      "  params: the world's parameters by their table names (docs/parameters.md: r_max, d0, alpha,\n"
      "    n_sgo, tau_a, friction, walk, pad_solver, solver_iterations, proxy_mass, ...), the coupling's\n"
      "    default (coupling_stiffness N/m, coupling_damping N s/m, max_force N) and time_step (s,\n"
      "    default 0.001). Checked as everywhere: god_finger.Error names the first bad one.\n"
      "Frames: z up, SI units; quaternions (x, y, z, w).")
      .def(py::init<const std::string&, const std::string&, const py::kwargs&>(), py::arg("scene"),
           py::arg("model") = "god_finger")
      .def("add_finger", &World::addFinger, py::arg("position"), py::arg("orientation") = py::none(),
           py::arg("coupling") = py::none(), py::arg("allow_inside") = false,
           "add_finger(position, orientation=None, coupling=None, allow_inside=False) -> int\n\n"
           "Adds a finger: a god-object proxy at `position` (m, world), its target there. `orientation` (x, y, z, "
           "w; the\nfinger frame: z out of the pulp, x towards the tip) makes it an oriented (6-DOF) finger. "
           "`coupling`: a dict\nof coupling_stiffness (N/m), coupling_damping (N s/m), max_force (N) over the "
           "world's. Returns its id.\nProxyInsideBodyError when it would start inside a body, unless allow_inside.")
      .def("set_target", &World::setTarget, py::arg("finger"), py::arg("position"), py::arg("orientation") = py::none(),
           py::arg("velocity") = py::none(),
           "set_target(finger, position, orientation=None, velocity=None)\n\n"
           "The device's pose in the world for the next step: position (m), orientation (x, y, z, w) for an "
           "oriented\nfinger, or the target's velocity (m/s) for the coupling's damping instead of the difference "
           "of targets\nover one step. A non-finite value raises god_finger.Error (the C++ world would ignore it).")
      .def("finger", &World::finger, py::arg("finger"),
           "finger(finger) -> Finger: the proxy's pose, the force on the hand, the contacts, after the last step.")
      .def_property_readonly("fingers", &World::fingerCount, "how many fingers were added")
      .def("step", &World::step, py::arg("n") = 1,
           "step(n=1): n fixed steps of time_step (s). For n > 1 the GIL is released while it steps, and Ctrl-C\n"
           "(KeyboardInterrupt) stops it within a thousand steps, the world at its last whole step.")
      .def_property_readonly("time", &World::time, "world time (s)")
      .def_property_readonly("steps", &World::steps, "steps taken since the world was made or reset")
      .def("reset", &World::reset,
           "Back to the scene's initial state, fingers where they were added, time 0 (a reset run repeats the first "
           "one bit for bit).")
      .def_property("contact_model", &World::contactModel, &World::setContactModel,
                    "god_object, god_finger or soft_finger; setting it takes effect from the next step")
      .def_property_readonly("params", &World::params,
                             "the world's parameters by name (what World(**params) took, defaults filled in)")
      .def_property_readonly("bodies", &World::bodies, "the bodies' names, in the scene's order")
      .def("body", &World::body, py::arg("name"), "body(name) -> Body: its pose, velocities, centre of mass, awake")
      .def_property_readonly("joints", &World::joints, "the joints' names (articulated objects)")
      .def("joint", &World::joint, py::arg("name"), "joint(name) -> Joint: its position and velocity")
      .def("apply_wrench", &World::applyWrench, py::arg("body"), py::arg("force"),
           py::arg("torque") = Eigen::Vector3d::Zero().eval(),
           "apply_wrench(body, force, torque=(0, 0, 0)): a force (N, world, at the centre of mass) and torque (N m, "
           "world)\non a dynamic body during the next step only; ignored for a static body.")
      .def("spawn", &World::spawn, py::arg("file"), py::arg("name") = "",
           py::arg("xyz") = Eigen::Vector3d::Zero().eval(), py::arg("rpy") = Eigen::Vector3d::Zero().eval(),
           py::arg("fixed") = py::none(),
           "spawn(file, name='', xyz=(0, 0, 0), rpy=(0, 0, 0), fixed=None) -> list of warnings\n\n"
           "Adds an object file (a URDF of either form, or xacro) with its frame at xyz (m) and rpy (rad, URDF's), "
           "named\n`name` (default: the file's; several links: NAME/LINK). fixed: None keeps the file's own (a body "
           "without\nmass is fixed). Every other body and finger keeps its state. Returns what the user should know "
           "(bodies\nit starts inside of). god_finger.Error, the world unchanged: a bad file, a name the scene has.")
      .def("remove", &World::remove, py::arg("name"),
           "remove(name) -> int: removes the bodies named `name` or `name/...`; returns how many. A finger pressing "
           "one\nlets go over let_go_time. god_finger.Error, nothing removed: no such body.")
      .def("snapshot", &World::snapshot,
           "snapshot() -> dict: time, steps, model, bodies {name: Body}, fingers [Finger], joints {name: Joint}")
      .def_property_readonly("warnings", &World::warnings,
                             "what the loader and the world found about the scene (one line each)")
      .def_property_readonly("rejected_targets", &World::rejectedTargets, "targets the C++ world ignored")
      .def_property_readonly("counters", &World::counters,
                             "dict: what the last step counted (awake_bodies, solver_contact_rows, solver_iterations,\n"
                             "solver_proxy_points, deepest_penetration m, dropped_contacts) and totals (rejected_targets,\n"
                             "dropped_contacts_total)")
      .def_property_readonly("step_profile", &World::stepProfile,
                             "dict: the last timed step (one in profile_every) stage by stage: step, total_ns and\n"
                             "<stage>_ns for coupling, wake, collide, contact_areas, solve, record, soft_bodies, "
                             "sleep,\nescapees, overlap")
      .def("__repr__",
           [](const World& w)
           {
             return "<god_finger.World " + w.path() + ", " + std::to_string(w.bodies().size()) + " bodies, model " +
                    w.contactModel() + ">";
           });
}
}  // namespace god_finger::python
