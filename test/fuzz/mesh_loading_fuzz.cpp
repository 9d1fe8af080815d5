// libFuzzer target: mesh files from arbitrary bytes. The first byte picks the extension (stl,
// obj, ply, off); the rest is the file. STL and OBJ go through assimp, PLY and OFF through our
// own readers (Debian's assimp 5.2 ran out of memory on PLY bodies, looped forever on PLY
// headers and read out of bounds on OFF files: those inputs are kept in
// test/fuzz/regressions/mesh_loading_fuzz/ and replayed by mesh_loader_test). A bad file must
// give InputError, never a crash, a hang, an allocation past the file's size or a sanitizer
// report; a file that loads must give a mesh on which contact areas are sound
// (contactAreaDefect). Run by scripts/fuzz (scripts/test: all four formats, fixed seed).
#include "god_finger/contact/contact_sampling.h"
#include "god_finger/support/input_error.h"
#include "god_finger/mesh_io/mesh_loader.h"

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace
{
const char* const kExtensions[] = {"stl", "obj", "ply", "off"};
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  if (size < 1)
  {
    return 0;
  }
  const std::string path = "/tmp/god_finger_fuzz_" + std::to_string(getpid()) + "." + kExtensions[data[0] % 4];
  FILE* file = std::fopen(path.c_str(), "wb");
  if (file == nullptr)
  {
    std::abort();
  }
  std::fwrite(data + 1, 1, size - 1, file);
  std::fclose(file);
  try
  {
    const god_finger::TriangleMesh mesh = god_finger::loadTriangleMesh(path);
    const god_finger::SurfaceLocator locator(mesh);
    god_finger::ContactParams params;
    params.max_radius = 0.1 * mesh.boundingBoxDiagonal();
    params.distance_constant = params.max_radius;
    god_finger::RandomContacts contacts(mesh, params, size);
    god_finger::ContactAreaResult area;
    for (int i = 0; i < 8; ++i)
    {
      const god_finger::ContactQuery query = contacts.next();
      god_finger::computeContactArea(mesh, query, params, &area);
      const std::string defect = god_finger::contactAreaDefect(locator, query, area, 1e-9 * mesh.boundingBoxDiagonal());
      if (area.valid && !defect.empty())
      {
        std::fprintf(stderr, "contact area defect: %s\n", defect.c_str());
        std::abort();
      }
    }
  }
  catch (const god_finger::InputError&)
  {
    // A clear error for a bad file: what we want.
  }
  std::remove(path.c_str());
  return 0;
}
