// The C++ side of test/python/test_contact.py's parity check: random contacts on a mesh file
// (contact/contact_sampling.h), each located on the mesh from its point and computed by
// computeContactArea as god_finger.contact_area does, printed at full precision.
//
//   god_finger_contact_trace MESH SAMPLES SEED
//
// One line per contact: point (3), normal (3), coupling (3), depth, then the result's radius,
// count and every entry's position (3 each); numbers as %.17g.
#include "god_finger/contact/contact_area.h"
#include "god_finger/contact/contact_sampling.h"
#include "god_finger/geometry/surface_locator.h"
#include "god_finger/mesh_io/mesh_loader.h"

#include <cstdio>
#include <exception>
#include <string>

int main(int argc, char** argv)
{
  using namespace god_finger;
  if (argc != 4)
  {
    std::fprintf(stderr, "usage: god_finger_contact_trace MESH SAMPLES SEED\n");
    return 2;
  }
  try
  {
    const TriangleMesh mesh = loadTriangleMesh(argv[1]);
    const SurfaceLocator locator(mesh);
    const ContactParams params;
    RandomContacts contacts(mesh, params, std::stoull(argv[3]));
    auto print = [](double value) { std::printf(" %.17g", value); };
    ContactAreaResult area;
    for (int sample = 0; sample < std::stoi(argv[2]); ++sample)
    {
      ContactQuery query = contacts.next();
      const Eigen::Vector3d point = query.location.point;  // what the user gives
      query.location = locator.closest(point);
      computeContactArea(mesh, query, params, &area);
      std::printf("%d", sample);
      for (int k = 0; k < 3; ++k)
      {
        print(point[k]);
      }
      for (int k = 0; k < 3; ++k)
      {
        print(query.normal[k]);
      }
      for (int k = 0; k < 3; ++k)
      {
        print(query.coupling[k]);
      }
      print(query.depth);
      print(area.radius);
      print(area.count);
      for (int i = 0; i < area.count; ++i)
      {
        for (int k = 0; k < 3; ++k)
        {
          print(area.sub_god_objects[i].position[k]);
        }
      }
      std::printf("\n");
    }
  }
  catch (const std::exception& error)
  {
    std::fprintf(stderr, "god_finger_contact_trace: %s\n", error.what());
    return 2;
  }
  return 0;
}
