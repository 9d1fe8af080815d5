// libFuzzer target: the contact area and its walks on arbitrary meshes with arbitrary
// parameters. Bytes give the parameters (n_SGO, walk variant, tau_a, friction, alpha), then
// vertices (three int16 each, 1 mm units) and triangles (three uint8 indices each). Meshes
// that TriangleMesh::build refuses must be refused with InputError; on every mesh it accepts,
// 16 random contact areas must be sound (contactAreaDefect) and every walk must stop within
// the crossing cap. Run by scripts/fuzz.
#include "god_finger/contact/contact_sampling.h"
#include "god_finger/support/input_error.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  using namespace god_finger;
  if (size < 8)
  {
    return 0;
  }
  ContactParams params;
  params.sub_god_objects = 3 + data[0] % 62;
  params.walk = data[1] % 2 == 0 ? WalkVariant::kProject : WalkVariant::kUnfold;
  params.max_angle = 0.05 + 3.09 * (data[2] / 255.0);
  params.friction = data[3] == 255 ? INFINITY : data[3] / 32.0;
  params.alpha = 1.0 + data[4] / 16.0;
  const int vertex_count = 3 + data[5] % 64;
  size_t at = 6;
  TriangleSoup soup;
  for (int v = 0; v < vertex_count && at + 6 <= size; ++v, at += 6)
  {
    auto coordinate = [&](int k)
    { return 1e-3 * static_cast<int16_t>(data[at + 2 * k] | (data[at + 2 * k + 1] << 8)); };
    soup.vertices.emplace_back(coordinate(0), coordinate(1), coordinate(2));
  }
  const int vertices = static_cast<int>(soup.vertices.size());
  for (; at + 3 <= size && vertices > 0; at += 3)
  {
    soup.triangles.push_back({data[at] % vertices, data[at + 1] % vertices, data[at + 2] % vertices});
  }
  try
  {
    const TriangleMesh mesh = TriangleMesh::build(soup);
    const SurfaceLocator locator(mesh);
    params.max_radius = std::max(1e-3, 0.2 * mesh.boundingBoxDiagonal());
    params.distance_constant = 0.5 * params.max_radius;
    RandomContacts contacts(mesh, params, size);
    ContactAreaResult area;
    for (int i = 0; i < 16; ++i)
    {
      const ContactQuery query = contacts.next();
      computeContactArea(mesh, query, params, &area);
      const std::string defect = contactAreaDefect(locator, query, area, 1e-9 * mesh.boundingBoxDiagonal());
      if (!area.valid || !defect.empty())
      {
        std::fprintf(stderr, "contact area %s: %s\n", area.valid ? "defect" : "invalid", defect.c_str());
        std::abort();
      }
      for (int k = 0; k < area.count; ++k)
      {
        if (area.sub_god_objects[k].walk.crossings > params.max_crossings)
        {
          std::abort();
        }
      }
    }
  }
  catch (const InputError&)
  {
    // Refused with a clear error: fine.
  }
  return 0;
}
