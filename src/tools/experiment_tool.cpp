#include "experiment_tool.h"

#include "god_finger/support/input_error.h"
#include "god_finger/support/text_numbers.h"
#include "god_finger/scenarios/servo_experiment.h"

#include <cmath>
#include <exception>

namespace god_finger
{
namespace
{
// "god_object|god_finger|soft_finger": the one list (physics/contact_model.h).
std::string modelChoices()
{
  std::string choices;
  for (const ContactModel model : contactModels())
  {
    choices += (choices.empty() ? "" : "|") + std::string(contactModelName(model));
  }
  return choices;
}
}  // namespace

const char* experimentToolUsage()
{
  static const std::string usage =
      "usage: god_finger_experiment --scenario " + scenarioNames("|") +
      "\n"
      "                             --model " +
      modelChoices() +
      "\n"
      "                             [--duration S] [--dt S] [--csv FILE] [--seed N] [--fast]\n"
      "                             [--push-height M] [--scenes DIR] [--hand ideal|fake]\n"
      "                             [--pad-solver points|constraint] [--overlap-stiffness N/M2]\n"
      "       god_finger_experiment --list-scenarios | --list-models\n"
      "Runs the scenario's scripted hand motion in the physics world and prints one JSON object:\n"
      "scenario, model, duration_s, steps, step_us_median, step_us_p99, max_penetration_m, nan,\n"
      "metrics. --duration 0 (default) runs the scenario's own length; --fast lifts ten times\n"
      "faster (lift scenarios); --push-height is the hand's height above the ball's centre (slide,\n"
      "default 0.0125 m); --csv writes the time series. --hand ideal (default) puts each interface\n"
      "where the script says; --hand fake runs the servo loop on simulated time with the fake\n"
      "device's handle held by the scripted hand, as a ROS session on the servo loop does.\n"
      "--overlap-stiffness sets the world's overlap_stiffness (0: no push apart of overlapping areas).\n"
      "--list-scenarios prints the scenario names, --list-models the contact models', one a line\n"
      "(the one lists scripts read).\n";
  return usage.c_str();
}

std::string parseExperimentToolOptions(int argc, const char* const* argv, const std::string& default_scenes_dir,
                                       ExperimentToolOptions* options)
{
  ExperimentOptions& experiment = options->experiment;
  experiment.scenes_dir = default_scenes_dir;
  bool have_scenario = false;
  bool have_model = false;
  for (int i = 1; i < argc; ++i)
  {
    const std::string option = argv[i];
    if (option == "--help" || option == "-h")
    {
      options->help = true;
      return "";
    }
    if (option == "--list-scenarios")
    {
      options->list_scenarios = true;
      return "";
    }
    if (option == "--list-models")
    {
      options->list_models = true;
      return "";
    }
    if (option == "--fast")
    {
      experiment.fast = true;
      continue;
    }
    if (option.rfind("--", 0) != 0)
    {
      return "unexpected argument '" + option + "' (see --help)";
    }
    if (i + 1 >= argc)
    {
      return "option '" + option + "' needs a value";
    }
    const std::string value = argv[++i];
    long long integer = 0;
    if (option == "--scenario")
    {
      if (!parseScenario(value, &experiment.scenario))
      {
        return "option '--scenario' = '" + value + "' is not one of " + scenarioNames();
      }
      have_scenario = true;
    }
    else if (option == "--model")
    {
      if (!parseContactModel(value, &experiment.model))
      {
        return "option '--model' = '" + value + "' is not one of " + contactModelNames();
      }
      have_model = true;
    }
    else if (option == "--pad-solver")
    {
      if (!parsePadSolver(value, &experiment.pad_solver))
      {
        return "option '--pad-solver' = '" + value + "' is not one of " + padSolverNames();
      }
    }
    else if (option == "--overlap-stiffness")
    {
      // Its range is the world table's (overlap_stiffness): the world names it.
      double stiffness = 0.0;
      if (!parseDouble(value, &stiffness))
      {
        return "option '--overlap-stiffness' = '" + value + "' is not a number (N/m^2)";
      }
      experiment.overlap_stiffness = stiffness;
    }
    else if (option == "--seed")
    {
      if (!parseInteger(value, &integer) || integer < 0)
      {
        return "option '--seed' = '" + value + "' is not a non-negative integer";
      }
      experiment.seed = static_cast<std::uint64_t>(integer);
    }
    else if (option == "--csv")
    {
      experiment.csv = value;
    }
    else if (option == "--hand")
    {
      if (value != "ideal" && value != "fake")
      {
        return "option '--hand' = '" + value + "' is not one of ideal, fake";
      }
      options->fake_hand = value == "fake";
    }
    else if (option == "--scenes")
    {
      experiment.scenes_dir = value;
    }
    else
    {
      try
      {
        // --dt, --duration, --push-height: the rows of experimentOptionTable(), ranges checked.
        if (!parseFlag(experimentOptionTable(), option, value, &experiment))
        {
          return "unknown option '" + option + "' (see --help)";
        }
      }
      catch (const InputError& error)
      {
        return error.what();
      }
    }
  }
  if (!have_scenario || !have_model)
  {
    return std::string("missing option '") + (have_scenario ? "--model" : "--scenario") + "' (see --help)";
  }
  return "";
}

int runExperimentTool(const ExperimentToolOptions& options, std::ostream& out, std::ostream& report)
{
  try
  {
    out << toJson(options.fake_hand ? runServoExperiment(options.experiment) : runExperiment(options.experiment))
        << std::endl;
    return 0;
  }
  catch (const std::exception& exception)
  {
    report << "god_finger_experiment: " << exception.what() << "\n";
    return 2;
  }
}
}  // namespace god_finger
