// god_finger.Mesh, load_mesh and contact_area: the paper's section 3 on a mesh, no world.
#include "bindings.h"

#include "god_finger/contact/contact_area.h"
#include "god_finger/contact/contact_params.h"
#include "god_finger/geometry/surface_locator.h"
#include "god_finger/haptics/virtual_coupling.h"
#include "god_finger/mesh_io/mesh_loader.h"
#include "god_finger/support/input_error.h"

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <memory>

namespace god_finger::python
{
namespace
{
using Rows3 = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
using IndexRows3 = Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>;

// A built triangle mesh and the tree that finds the closest point on it.
class Mesh
{
 public:
  explicit Mesh(TriangleMesh mesh, std::string source)
      : mesh_(std::make_shared<TriangleMesh>(std::move(mesh))), source_(std::move(source))
  {
    locator_ = std::make_unique<SurfaceLocator>(*mesh_);
  }
  const TriangleMesh& mesh() const
  {
    return *mesh_;
  }
  const SurfaceLocator& locator() const
  {
    return *locator_;
  }
  const std::string& source() const
  {
    return source_;
  }

 private:
  std::shared_ptr<TriangleMesh> mesh_;
  std::unique_ptr<SurfaceLocator> locator_;
  std::string source_;
};

Mesh meshFromArrays(const py::handle& vertices_object, const py::handle& triangles_object)
{
  using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;
  using Indices = py::array_t<long, py::array::c_style | py::array::forcecast>;
  const Array vertices = Array::ensure(vertices_object);
  const Indices triangles = Indices::ensure(triangles_object);
  if (!vertices || vertices.ndim() != 2 || vertices.shape(1) != 3)
  {
    PyErr_Clear();
    throw InputError("Mesh: vertices must be an array of shape (n, 3) (m)");
  }
  if (!triangles || triangles.ndim() != 2 || triangles.shape(1) != 3)
  {
    PyErr_Clear();
    throw InputError("Mesh: triangles must be an array of shape (m, 3) of vertex indices");
  }
  TriangleSoup soup;
  for (py::ssize_t i = 0; i < vertices.shape(0); ++i)
  {
    const Eigen::Vector3d vertex(vertices.at(i, 0), vertices.at(i, 1), vertices.at(i, 2));
    if (!vertex.allFinite())
    {
      throw InputError("Mesh: vertex " + std::to_string(i) + " is not finite");
    }
    soup.vertices.push_back(vertex);
  }
  for (py::ssize_t i = 0; i < triangles.shape(0); ++i)
  {
    std::array<int, 3> triangle{};
    for (int k = 0; k < 3; ++k)
    {
      const long index = triangles.at(i, k);
      if (index < 0 || index >= vertices.shape(0))
      {
        throw InputError("Mesh: triangle " + std::to_string(i) + " names vertex " + std::to_string(index) +
                         ", not one of the " + std::to_string(vertices.shape(0)) + " vertices");
      }
      triangle[k] = static_cast<int>(index);
    }
    soup.triangles.push_back(triangle);
  }
  return Mesh(TriangleMesh::build(soup), "arrays");
}

Rows3 rows(const std::vector<Eigen::Vector3d>& points)
{
  Rows3 out(points.size(), 3);
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    out.row(i) = points[i].transpose();
  }
  return out;
}

// The result of contact_area: the C++ ContactAreaResult, as arrays.
struct ContactAreaView
{
  bool valid = false;
  double radius = 0.0;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double depth = 0.0;
  Eigen::Vector3d first_tangent = Eigen::Vector3d::UnitX();
  std::string feature;
  int face = -1;
  Rows3 sub_god_objects;  // the active ones
  Rows3 positions;        // every entry, dropped ones included
  Rows3 radial;
  Eigen::VectorXd target_distance;
  std::vector<bool> dropped;
  std::vector<std::string> stops;
};

ContactAreaView contactArea(const Mesh& mesh, const py::object& point_object, const py::object& normal_object,
                            const py::object& coupling_object, const py::object& force_object,
                            const py::object& stiffness_object, double depth, const py::object& reference_object,
                            const py::kwargs& kwargs)
{
  ContactParams params;
  readRows(parameterSource(kwargs, rowNames(contactParameterTable()), "the contact area's parameters"),
           contactParameterTable(), &params);
  validateOrThrow(params);
  const Eigen::Vector3d point = vector3(point_object, "point");
  const Eigen::Vector3d normal = vector3(normal_object, "normal");
  if (normal.norm() < 1e-9)
  {
    throw InputError("normal must not be zero");
  }
  if (!std::isfinite(depth))
  {
    throw InputError("depth must be finite");
  }
  Eigen::Vector3d coupling;
  if (!coupling_object.is_none() && !force_object.is_none())
  {
    throw InputError("contact_area: give coupling (m) or force (N), not both");
  }
  if (!force_object.is_none())
  {
    // v = f / k: the coupling spring's stretch that pushes with `force` (N, on the object).
    const double stiffness = stiffness_object.is_none()
                                 ? CouplingProfile().stiffness
                                 : argument<double>(stiffness_object, "stiffness", "a number (N/m)");
    if (!(stiffness > 0.0) || !std::isfinite(stiffness))
    {
      throw InputError("stiffness must be a finite number > 0 (N/m)");
    }
    coupling = vector3(force_object, "force") / stiffness;
  }
  else if (!coupling_object.is_none())
  {
    coupling = vector3(coupling_object, "coupling");
  }
  else
  {
    throw InputError("contact_area: give coupling (m, v = p_I - p_GO) or force (N)");
  }
  ContactQuery query;
  query.location = mesh.locator().closest(point);
  query.normal = normal;
  query.depth = depth;
  query.coupling = coupling;
  if (!reference_object.is_none())
  {
    query.reference_tangent = vector3(reference_object, "reference_tangent");
  }
  ContactAreaResult area;
  computeContactArea(mesh.mesh(), query, params, &area);

  ContactAreaView view;
  view.valid = area.valid;
  view.radius = area.radius;
  view.point = area.point;
  view.normal = area.normal;
  view.depth = area.depth;
  view.first_tangent = area.first_tangent;
  view.feature = featureKindName(query.location.feature);
  view.face = query.location.face >= 0 ? mesh.mesh().sourceTriangle(query.location.face) : -1;
  std::vector<Eigen::Vector3d> active;
  std::vector<Eigen::Vector3d> positions;
  std::vector<Eigen::Vector3d> radial;
  view.target_distance.resize(area.count);
  for (int i = 0; i < area.count; ++i)
  {
    const SubGodObject& sgo = area.sub_god_objects[i];
    positions.push_back(sgo.position);
    radial.push_back(sgo.radial);
    view.target_distance[i] = sgo.target_distance;
    view.dropped.push_back(sgo.dropped());
    view.stops.push_back(walkStopName(sgo.walk.stop));
    if (!sgo.dropped())
    {
      active.push_back(sgo.position);
    }
  }
  view.sub_god_objects = rows(active);
  view.positions = rows(positions);
  view.radial = rows(radial);
  return view;
}
}  // namespace

void bindContact(py::module_& module)
{
  py::class_<Mesh, std::shared_ptr<Mesh>>(module, "Mesh",
                                          "A triangle mesh as the walk sees it: welded, cleaned and wound outward "
                                          "(geometry/triangle_mesh.h).\n"
                                          "Mesh(vertices, triangles): from an (n, 3) array of vertices (m) and an (m, "
                                          "3) array of vertex indices; load_mesh(path) reads a file.")
      .def(py::init([](const py::object& vertices, const py::object& triangles)
                    { return std::make_shared<Mesh>(meshFromArrays(vertices, triangles)); }),
           py::arg("vertices"), py::arg("triangles"))
      .def_property_readonly(
          "vertices", [](const Mesh& mesh) { return rows(mesh.mesh().vertices()); },
          "(n, 3) array of the vertices kept (m, the mesh's frame)")
      .def_property_readonly(
          "triangles",
          [](const Mesh& mesh)
          {
            IndexRows3 out(mesh.mesh().triangleCount(), 3);
            for (int t = 0; t < mesh.mesh().triangleCount(); ++t)
            {
              out.row(t) = mesh.mesh().triangles()[t].transpose();
            }
            return out;
          },
          "(m, 3) array of vertex indices, wound outward")
      .def_property_readonly(
          "normals", [](const Mesh& mesh) { return rows(mesh.mesh().normals()); }, "(m, 3) array of unit face normals")
      .def_property_readonly(
          "health",
          [](const Mesh& mesh)
          {
            const MeshHealth& h = mesh.mesh().health();
            py::dict health;
            health["input_vertices"] = h.input_vertices;
            health["input_triangles"] = h.input_triangles;
            health["welded_vertices"] = h.welded_vertices;
            health["degenerate_triangles"] = h.degenerate_triangles;
            health["duplicate_triangles"] = h.duplicate_triangles;
            health["flipped_triangles"] = h.flipped_triangles;
            health["boundary_edges"] = h.boundary_edges;
            health["non_manifold_edges"] = h.non_manifold_edges;
            health["inconsistent_winding_edges"] = h.inconsistent_winding_edges;
            health["components"] = h.components;
            return health;
          },
          "what building the mesh repaired (welded, degenerate, duplicate, flipped) and found (boundary, "
          "non-manifold, inconsistent winding edges; components)")
      .def(
          "closest",
          [](const Mesh& mesh, const py::object& point)
          {
            const SurfaceLocation location = mesh.locator().closest(vector3(point, "point"));
            py::dict out;
            out["point"] = Eigen::Vector3d(location.point);
            out["face"] = mesh.mesh().sourceTriangle(location.face);
            out["feature"] = featureKindName(location.feature);
            out["normal"] = Eigen::Vector3d(mesh.mesh().normals()[location.face]);
            out["distance"] = location.distance;
            return out;
          },
          py::arg("point"),
          "The closest point of the surface to `point` (m): {'point', 'face' (the file's triangle index), "
          "'feature' (face, edge, vertex), 'normal' (the face's, unit, outward), 'distance' (m)}.")
      .def("__repr__",
           [](const Mesh& mesh)
           {
             return "<god_finger.Mesh from " + mesh.source() + ": " + std::to_string(mesh.mesh().vertexCount()) +
                    " vertices, " + std::to_string(mesh.mesh().triangleCount()) + " triangles>";
           });

  module.def(
      "load_mesh",
      [](const std::string& path, const py::object& scale)
      {
        const Eigen::Vector3d factors = scale.is_none() ? Eigen::Vector3d::Ones() : vector3(scale, "scale");
        return std::make_shared<Mesh>(loadTriangleMesh(path, factors), path);
      },
      py::arg("path"), py::arg("scale") = py::none(),
      "load_mesh(path, scale=None) -> Mesh\n\n"
      "Reads a mesh file (PLY and OFF by our readers; STL, OBJ, DAE and the rest through assimp), all its meshes\n"
      "merged in the file's frame, coordinates taken as metres and multiplied by `scale` (3 numbers, URDF's <mesh\n"
      "scale>). god_finger.Error names the file and the problem (missing, unreadable, no triangles, too large).");

  py::class_<ContactAreaView>(module, "ContactArea",
                              "The god-finger contact area of one contact (contact/contact_area.h). Frame: the "
                              "mesh's; m.")
      .def_readonly("valid", &ContactAreaView::valid, "False on input the method refuses (count 0)")
      .def_readonly("radius", &ContactAreaView::radius, "r (m), Eq. 1")
      .def_readonly("point", &ContactAreaView::point, "c_p (m): the closest point of the mesh to the point given")
      .def_readonly("normal", &ContactAreaView::normal, "c_n, unit, out of the object")
      .def_readonly("depth", &ContactAreaView::depth, "c_d (m)")
      .def_readonly("first_tangent", &ContactAreaView::first_tangent,
                    "the first radial vector: pass it back as reference_tangent for a basis continuous in time")
      .def_readonly("feature", &ContactAreaView::feature, "where c_p lies: face, edge or vertex")
      .def_readonly("face", &ContactAreaView::face, "the triangle c_p lies on (the input's index)")
      .def_readonly("sub_god_objects", &ContactAreaView::sub_god_objects,
                    "(n, 3) array: the active sub-god-objects' positions (m), in radial order, dropped ones left out")
      .def_readonly("positions", &ContactAreaView::positions,
                    "(n_sgo, 3) array: every entry's position, dropped ones included (see dropped)")
      .def_readonly("radial", &ContactAreaView::radial, "(n_sgo, 3) array: each r_i, unit, orthogonal to c_n")
      .def_readonly("target_distance", &ContactAreaView::target_distance, "(n_sgo,) array: each d_i (m), Eq. 2")
      .def_readonly("dropped", &ContactAreaView::dropped, "per entry: its face was beyond tau_a or the friction cone")
      .def_readonly("stops", &ContactAreaView::stops, "per entry: why its walk stopped (surface_walk.h)")
      .def("__repr__",
           [](const ContactAreaView& area)
           {
             return "<god_finger.ContactArea r=" + std::to_string(area.radius) + " m, " +
                    std::to_string(area.sub_god_objects.rows()) + " sub-god-objects>";
           });

  module.def("contact_area", &contactArea, py::arg("mesh"), py::arg("point"), py::arg("normal"),
             py::arg("coupling") = py::none(), py::kw_only(), py::arg("force") = py::none(),
             py::arg("stiffness") = py::none(), py::arg("depth") = 0.0, py::arg("reference_tangent") = py::none(),
             "contact_area(mesh, point, normal, coupling=None, *, force=None, stiffness=None, depth=0.0,\n"
             "             reference_tangent=None, **params) -> ContactArea\n\n"
             "The god-finger method for one contact on `mesh`, no world (contact/contact_area.h, the C++ call\n"
             "computeContactArea): c_p is the closest point of the mesh to `point` (m, the mesh's frame); `normal` is\n"
             "c_n (out of the object; normalised); `coupling` is v = p_I - p_GO (m): pressing pushes the interface\n"
             "into the object, v . c_n < 0. Or `force` (N, on the object): v = force / stiffness, stiffness the\n"
             "coupling's (N/m, default the world's 400). `params` by the contact table's names: r_max (m), d0 (m),\n"
             "alpha, n_sgo, tau_a (rad), friction, walk (project|unfold), max_crossings; checked as everywhere.");
}
}  // namespace god_finger::python
