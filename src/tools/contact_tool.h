// god_finger_contact: the contact area on a user's mesh, sampled, checked and timed.
// See docs/experiments.md, "The contact tool". Exit codes: 0 success, 2 bad options or input.
#pragma once

#include "god_finger/contact/contact_params.h"

#include <cstdint>
#include <ostream>
#include <string>

namespace god_finger
{
struct ContactToolOptions
{
  std::string mesh;
  int samples = 1000;
  std::uint64_t seed = 1;
  ContactParams params;
  std::string dump;  // CSV path, empty for none
  bool help = false;
};

// Empty string on success, else one line saying what is wrong.
std::string parseContactToolOptions(int argc, const char* const* argv, ContactToolOptions* options);
std::string contactToolUsage();
// Runs the tool: health report on `report`, one JSON object on `out`. Returns the exit code;
// on error writes one line "god_finger_contact: ..." on `report`.
int runContactTool(const ContactToolOptions& options, std::ostream& out, std::ostream& report);
}  // namespace god_finger
