// god_finger.run_experiment: the paper's experiments and the operator scenarios, as the tool
// god_finger_experiment runs them (scenarios/experiment.h), their metrics a dict and their time
// series numpy arrays.
#include "bindings.h"

#include "god_finger/physics/contact_model.h"
#include "god_finger/scenarios/experiment.h"
#include "god_finger/scenarios/servo_experiment.h"
#include "god_finger/support/input_error.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

namespace god_finger::python
{
namespace
{
// What run_experiment's keyword arguments may name besides experimentOptionTable()'s rows.
const std::set<std::string>& extraOptions()
{
  static const std::set<std::string> names = {
      "seed", "fast", "pad_solver", "overlap_stiffness", "solver_iterations", "sample_period", "csv", "scenes"};
  return names;
}

ExperimentOptions experimentOptions(const std::string& scenario, const std::string& model, const py::kwargs& kwargs,
                                    const std::string& default_scenes)
{
  ExperimentOptions options;
  options.scenes_dir = default_scenes;
  if (!parseScenario(scenario, &options.scenario))
  {
    throw InputError("scenario '" + scenario + "' is not one of " + scenarioNames());
  }
  if (!parseContactModel(model, &options.model))
  {
    throw InputError("contact model '" + model + "' is not one of " + contactModelNames());
  }
  std::set<std::string> known = rowNames(experimentOptionTable());
  known.insert(extraOptions().begin(), extraOptions().end());
  checkNames(kwargs, known, "run_experiment's options");
  py::dict table_options;
  for (const auto& item : kwargs)
  {
    const std::string name = py::str(item.first);
    if (name == "seed")
    {
      const long long seed = argument<long long>(item.second, "option 'seed'", "an integer");
      if (seed < 0)
      {
        throw InputError("option 'seed' = " + std::to_string(seed) + " is not a non-negative integer");
      }
      options.seed = static_cast<std::uint64_t>(seed);
    }
    else if (name == "fast")
    {
      options.fast = argument<bool>(item.second, "option 'fast'", "true or false");
    }
    else if (name == "pad_solver")
    {
      const std::string text = argument<std::string>(item.second, "option 'pad_solver'", "text");
      if (!parsePadSolver(text, &options.pad_solver))
      {
        throw InputError("option 'pad_solver' = '" + text + "' is not one of " + padSolverNames());
      }
    }
    else if (name == "overlap_stiffness")
    {
      options.overlap_stiffness =
          argument<double>(item.second, "option 'overlap_stiffness'", "a number");  // the world's table checks it
    }
    else if (name == "solver_iterations")
    {
      options.solver_iterations =
          argument<int>(item.second, "option 'solver_iterations'", "an integer");  // the world's table checks it
    }
    else if (name == "sample_period")
    {
      options.sample_period = argument<double>(item.second, "option 'sample_period'", "a number");
    }
    else if (name == "csv")
    {
      options.csv = argument<std::string>(item.second, "option 'csv'", "a path");
    }
    else if (name == "scenes")
    {
      options.scenes_dir = argument<std::string>(item.second, "option 'scenes'", "a folder");
    }
    else
    {
      table_options[item.first] = item.second;
    }
  }
  readRows(parameterSource(table_options, rowNames(experimentOptionTable()), "run_experiment's options"),
           experimentOptionTable(), &options);
  options.series = true;
  return options;
}

py::dict resultDict(const ExperimentResult& result)
{
  py::dict out;
  out["scenario"] = result.scenario;
  out["model"] = result.model;
  out["duration_s"] = result.duration_s;
  out["steps"] = result.steps;
  out["step_us_median"] = result.step_us_median;
  out["step_us_p99"] = result.step_us_p99;
  out["max_penetration_m"] = result.max_penetration_m;
  out["nan"] = result.nan;
  py::dict metrics;
  for (const auto& entry : result.metrics)
  {
    metrics[py::str(entry.first)] = entry.second;
  }
  out["metrics"] = metrics;
  py::dict series;
  const std::size_t columns = result.series_names.size();
  const std::size_t rows = columns > 0 ? result.series.size() / columns : 0;
  for (std::size_t c = 0; c < columns; ++c)
  {
    py::array_t<double> column(static_cast<py::ssize_t>(rows));
    auto values = column.mutable_unchecked<1>();
    for (std::size_t r = 0; r < rows; ++r)
    {
      values(static_cast<py::ssize_t>(r)) = result.series[r * columns + c];
    }
    series[py::str(result.series_names[c])] = column;
  }
  out["series"] = series;
  return out;
}
}  // namespace

void bindExperiment(py::module_& module)
{
  module.def(
      "run_experiment",
      [](const std::string& scenario, const std::string& model, const std::string& hand, const py::kwargs& kwargs)
      {
        if (hand != "ideal" && hand != "fake")
        {
          throw InputError("hand '" + hand + "' is not one of ideal, fake");
        }
        const ExperimentOptions options = experimentOptions(scenario, model, kwargs, GOD_FINGER_SCENES_DIR);
        ExperimentResult result;
        {
          py::gil_scoped_release release;
          result = hand == "fake" ? runServoExperiment(options) : runExperiment(options);
        }
        return resultDict(result);
      },
      py::arg("scenario"), py::arg("model") = "god_finger", py::arg("hand") = "ideal",
      "run_experiment(scenario, model='god_finger', hand='ideal', **options) -> dict\n\n"
      "Runs a scenario (god_finger.scenarios()) with a contact model (god_finger.models()) as the tool\n"
      "god_finger_experiment does (scenarios/experiment.h; docs/experiments.md): the same numbers. hand: 'ideal'\n"
      "puts each finger where the script says; 'fake' runs the servo loop on simulated time with the fake device's\n"
      "handle held by the script. options: duration (s, 0: the scenario's own), dt (s), push_height (m, slide),\n"
      "seed, fast, pad_solver, overlap_stiffness (N/m^2), solver_iterations, sample_period (s), csv (a path),\n"
      "scenes (the scene folder).\n"
      "Returns scenario, model, duration_s, steps, step_us_median, step_us_p99, max_penetration_m, nan, metrics\n"
      "(a dict) and series: the time series, one numpy array per column (t, the object's x y z qx qy qz qw vx vy\n"
      "vz wx wy wz fx fy fz, then per finger i fi_ix.. target, fi_px.. proxy, fi_ux.. force on the hand,\n"
      "fi_contacts, fi_sgo), one entry per step.");
  module.def(
      "scenarios",
      []
      {
        std::vector<std::string> names;
        for (const Scenario scenario : kAllScenarios)
        {
          names.push_back(scenarioName(scenario));
        }
        return names;
      },
      "The scenarios run_experiment takes, in the tool's order.");
  module.def(
      "models",
      []
      {
        std::vector<std::string> names;
        for (const ContactModel model : contactModels())
        {
          names.push_back(contactModelName(model));
        }
        return names;
      },
      "The contact models: god_object, god_finger, soft_finger.");
  module.attr("default_scenes_dir") = GOD_FINGER_SCENES_DIR;
}
}  // namespace god_finger::python
