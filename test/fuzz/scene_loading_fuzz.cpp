// libFuzzer target: scene files from arbitrary bytes, through the one loader the physics uses
// (scene/scene_file.h). The first byte picks the form (modulo 3: a URDF, a scene list in YAML,
// or a xacro file, scene/xacro.h); the rest is the file. A bad file must give InputError, never a crash, a hang or a
// sanitizer report; a file that loads must give bodies with finite poses and sizes in the scene's range. Run by
// scripts/fuzz (scripts/test: a fixed seed).
#include "god_finger/scene/scene_budget.h"
#include "god_finger/scene/scene_file.h"
#include "god_finger/support/input_error.h"

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  if (size < 1)
  {
    return 0;
  }
  const char* const forms[] = {".urdf", ".yaml", ".urdf.xacro"};
  const std::string path = "/tmp/god_finger_fuzz_" + std::to_string(getpid()) + forms[data[0] % 3];
  FILE* file = std::fopen(path.c_str(), "wb");
  if (file == nullptr)
  {
    std::abort();
  }
  std::fwrite(data + 1, 1, size - 1, file);
  std::fclose(file);
  try
  {
    const god_finger::SceneDescription scene = god_finger::loadScene(path);
    for (const god_finger::BodyDescription& body : scene.bodies)
    {
      const bool primitive = body.geometry.kind != god_finger::GeometryKind::kMesh;
      const double largest =
          body.geometry.kind == god_finger::GeometryKind::kBox ? body.geometry.size.maxCoeff() : body.geometry.radius;
      if (!body.pose.matrix().allFinite() || !body.collision_origin.matrix().allFinite() ||
          (primitive && largest > god_finger::kMaxBodySize) || (!body.is_static && !(body.mass > 0.0)))
      {
        std::abort();  // a scene the loader should have refused
      }
    }
  }
  catch (const god_finger::InputError&)
  {
  }
  std::remove(path.c_str());
  return 0;
}
