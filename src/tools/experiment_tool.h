// god_finger_experiment: the paper's experiments, scripted and measured (no ROS master).
// See docs/experiments.md. Exit codes: 0 success, 2 bad options or input.
#pragma once

#include "god_finger/scenarios/experiment.h"

#include <ostream>
#include <string>

namespace god_finger
{
struct ExperimentToolOptions
{
  ExperimentOptions experiment;
  bool fake_hand = false;  // --hand fake: the servo loop with the fake device's handle
  bool help = false;
  bool list_scenarios = false;  // --list-scenarios: print the scenario names, one a line, for scripts
  bool list_models = false;     // --list-models: print the contact model names, one a line, for scripts
};

// Empty string on success, else one line saying what is wrong. `default_scenes_dir` is used
// unless --scenes is given.
std::string parseExperimentToolOptions(int argc, const char* const* argv, const std::string& default_scenes_dir,
                                       ExperimentToolOptions* options);
const char* experimentToolUsage();
// Runs one experiment and prints its JSON object on `out`; returns the exit code, and on
// error writes one line "god_finger_experiment: ..." on `report`.
int runExperimentTool(const ExperimentToolOptions& options, std::ostream& out, std::ostream& report);
}  // namespace god_finger
