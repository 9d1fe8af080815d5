#include "contact_tool.h"

#include "god_finger/contact/contact_area.h"
#include "god_finger/contact/contact_sampling.h"
#include "god_finger/support/input_error.h"
#include "god_finger/support/parameter_json.h"
#include "god_finger/geometry/surface_locator.h"
#include "god_finger/support/text_numbers.h"
#include "god_finger/mesh_io/mesh_loader.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <vector>

namespace god_finger
{

std::string contactToolUsage()
{
  return "usage: god_finger_contact --mesh FILE [--samples N] [--seed S] [--dump FILE.csv] [PARAMETER VALUE...]\n"
         "Samples N random contacts on the mesh, computes each god-finger contact area and prints\n"
         "one JSON object on stdout (the mesh's health report goes to stderr). Parameters:\n" +
         usageLines(contactParameterTable());
}

std::string parseContactToolOptions(int argc, const char* const* argv, ContactToolOptions* options)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string flag = argv[i];
    if (flag == "--help" || flag == "-h")
    {
      options->help = true;
      return std::string();
    }
    if (i + 1 >= argc)
    {
      return flag.rfind("--", 0) == 0 ? "option " + flag + " needs a value" : "unexpected argument '" + flag + "'";
    }
    const std::string value = argv[++i];
    long long integer = 0;
    if (flag == "--mesh")
    {
      options->mesh = value;
    }
    else if (flag == "--dump")
    {
      options->dump = value;
    }
    else if (flag == "--samples" || flag == "--seed")
    {
      if (!parseInteger(value, &integer))
      {
        return flag + " needs an integer, got '" + value + "'";
      }
      if (flag == "--samples")
      {
        if (integer < 1 || integer > 10000000)
        {
          return "--samples = " + value + " is out of range [1, 10000000]";
        }
        options->samples = static_cast<int>(integer);
      }
      else
      {
        if (integer < 0)
        {
          return "--seed must not be negative, got " + value;
        }
        options->seed = static_cast<std::uint64_t>(integer);
      }
    }
    else
    {
      try
      {
        if (!parseFlag(contactParameterTable(), flag, value, &options->params))
        {
          return "unknown option '" + flag + "' (see --help)";
        }
      }
      catch (const InputError& error)
      {
        return error.what();
      }
    }
  }
  if (options->mesh.empty())
  {
    return "--mesh FILE is required (see --help)";
  }
  const std::string error = validate(options->params);
  if (!error.empty())
  {
    return error;
  }
  return std::string();
}

int runContactTool(const ContactToolOptions& options, std::ostream& out, std::ostream& report)
{
  TriangleMesh mesh;
  try
  {
    mesh = loadTriangleMesh(options.mesh);
  }
  catch (const InputError& error)
  {
    report << "god_finger_contact: " << error.what() << "\n";
    return 2;
  }
  std::ofstream dump;
  if (!options.dump.empty())
  {
    dump.open(options.dump);
    if (!dump.good())
    {
      report << "god_finger_contact: cannot write '" << options.dump << "'\n";
      return 2;
    }
    dump << "sample,cx,cy,cz,nx,ny,nz,vx,vy,vz,sx,sy,sz,face\n";
    dump.precision(17);
  }
  const MeshHealth& health = mesh.health();
  report << "mesh " << options.mesh << ": " << health.input_vertices << " vertices and " << health.input_triangles
         << " triangles read; " << mesh.vertexCount() << " vertices and " << mesh.triangleCount() << " triangles kept\n"
         << "  repaired: " << health.welded_vertices << " duplicate vertices welded, " << health.degenerate_triangles
         << " degenerate and " << health.duplicate_triangles << " duplicate triangles removed, "
         << health.flipped_triangles << " triangles re-wound\n"
         << "  reported: " << health.boundary_edges << " boundary edges, " << health.non_manifold_edges
         << " non-manifold edges, " << health.inconsistent_winding_edges << " edges of inconsistent winding, "
         << health.components << " connected components\n";

  const SurfaceLocator locator(mesh);
  const ContactParams& params = options.params;
  std::unique_ptr<RandomContacts> contacts;
  try
  {
    contacts = std::make_unique<RandomContacts>(mesh, params, options.seed);
  }
  catch (const InputError& error)
  {
    report << "god_finger_contact: " << options.mesh << ": " << error.what() << "\n";
    return 2;
  }
  const double surface_tolerance = 1e-9 * std::max(mesh.boundingBoxDiagonal(), 1e-300);
  ContactAreaResult area;
  std::vector<double> times;
  times.reserve(options.samples);
  std::map<std::string, int> stops;
  int failures = 0;
  long nan_count = 0;
  long active_total = 0;
  double radius_total = 0.0;
  for (int sample = 0; sample < options.samples; ++sample)
  {
    const ContactQuery query = contacts->next();

    const auto start = std::chrono::steady_clock::now();
    computeContactArea(mesh, query, params, &area);
    const auto stop = std::chrono::steady_clock::now();
    times.push_back(std::chrono::duration<double, std::nano>(stop - start).count());

    bool failed = !area.valid || !contactAreaDefect(locator, query, area, surface_tolerance).empty();
    nan_count += std::isfinite(area.radius) ? 0 : 1;
    radius_total += std::isfinite(area.radius) ? area.radius : 0.0;
    active_total += area.active;
    if (area.valid && area.radius > 0.0 && area.active == 0 && params.friction > 0.0)
    {
      failed = true;  // a face contact always spreads onto its own face
    }
    for (int i = 0; i < area.count; ++i)
    {
      const SubGodObject& sgo = area.sub_god_objects[i];
      ++stops[walkStopName(sgo.walk.stop)];
      nan_count += 3 - sgo.position.array().isFinite().count();
      if (sgo.dropped() || !sgo.position.allFinite())
      {
        continue;
      }
      if (dump.is_open())
      {
        const Eigen::Vector3d& c = query.location.point;
        const Eigen::Vector3d& n = query.normal;
        const Eigen::Vector3d& v = query.coupling;
        const Eigen::Vector3d& s = sgo.position;
        dump << sample << ',' << c.x() << ',' << c.y() << ',' << c.z() << ',' << n.x() << ',' << n.y() << ',' << n.z()
             << ',' << v.x() << ',' << v.y() << ',' << v.z() << ',' << s.x() << ',' << s.y() << ',' << s.z() << ','
             << mesh.sourceTriangle(sgo.walk.location.face) << '\n';
      }
    }
    failures += failed ? 1 : 0;
  }
  if (dump.is_open())
  {
    dump.close();
    if (dump.fail())
    {
      report << "god_finger_contact: writing '" << options.dump << "' failed\n";
      return 2;
    }
  }

  Json json;
  json["mesh"] = {{"file", options.mesh},
                  {"vertices", mesh.vertexCount()},
                  {"triangles", mesh.triangleCount()},
                  {"degenerate", health.degenerate_triangles},
                  {"boundary_edges", health.boundary_edges},
                  {"non_manifold_edges", health.non_manifold_edges},
                  {"welded_vertices", health.welded_vertices},
                  {"duplicate_triangles", health.duplicate_triangles},
                  {"flipped_triangles", health.flipped_triangles},
                  {"inconsistent_winding_edges", health.inconsistent_winding_edges},
                  {"components", health.components}};
  json["params"] = jsonObject(contactParameterTable(), params);
  json["samples"] = options.samples;
  json["seed"] = options.seed;
  json["failures"] = failures;
  json["nan"] = nan_count;
  json["sgo_per_contact_mean"] = jsonMeasure(static_cast<double>(active_total) / options.samples);
  json["radius_mean_m"] = jsonMeasure(radius_total / options.samples);
  json["walk_ns_median"] = jsonMeasure(percentile(times, 0.5));
  json["walk_ns_p99"] = jsonMeasure(percentile(times, 0.99));
  json["stops"] = Json::object();
  for (const auto& entry : stops)
  {
    json["stops"][entry.first] = entry.second;
  }
  out << json.dump() << '\n';
  return 0;
}
}  // namespace god_finger
