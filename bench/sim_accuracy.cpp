// Speed against error of the simulation: runs a paper scenario (god-finger model) at the time
// steps and solver iterations given, and prints one JSON line per run with the compute time per
// simulated second and the watched object's trajectory (centre of mass and orientation every
// 20 ms). scripts/bench_report compares each run with the finest one (the reference) and marks
// the Pareto front. Built twice: against Bullet in float64 (sim_accuracy) and in float32
// (sim_accuracy_f32), the same sources.
//
// usage: sim_accuracy --scenario slide|pinch_cylinder --duration S --dt S[,S...] --iterations N[,N...]
//        [--reference 1]   (marks the lines as the reference run)
#include "god_finger/support/parameter_json.h"
#include "god_finger/support/text_numbers.h"
#include "god_finger/scenarios/experiment.h"

#include <LinearMath/btScalar.h>

#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
std::vector<std::string> splitList(const std::string& text)
{
  std::vector<std::string> items;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ','))
  {
    items.push_back(item);
  }
  return items;
}

int fail(const std::string& message)
{
  std::cerr << "sim_accuracy: " << message << "\n"
            << "usage: sim_accuracy --scenario NAME --duration S --dt S[,S...] --iterations N[,N...]\n";
  return 2;
}
}  // namespace

int main(int argc, char** argv)
{
  using namespace god_finger;
  ExperimentOptions options;
  options.scenes_dir = GOD_FINGER_SCENES_DIR;
  options.sample_period = 0.02;
  std::vector<double> time_steps;
  std::vector<int> iterations;
  bool reference = false;
  for (int i = 1; i + 1 < argc; i += 2)
  {
    const std::string option = argv[i];
    const std::string value = argv[i + 1];
    if (option == "--scenario")
    {
      if (!parseScenario(value, &options.scenario))
      {
        return fail("unknown scenario '" + value + "'");
      }
    }
    else if (option == "--duration")
    {
      if (!parseDouble(value, &options.duration) || !(options.duration > 0.0))
      {
        return fail("bad --duration '" + value + "'");
      }
    }
    else if (option == "--reference")
    {
      reference = value == "1";
    }
    else if (option == "--dt" || option == "--iterations")
    {
      for (const std::string& item : splitList(value))
      {
        double number = 0.0;
        if (!parseDouble(item, &number) || !(number > 0.0))
        {
          return fail("bad " + option + " '" + item + "'");
        }
        if (option == "--dt")
        {
          time_steps.push_back(number);
        }
        else
        {
          iterations.push_back(static_cast<int>(number));
        }
      }
    }
    else
    {
      return fail("unknown option '" + option + "'");
    }
  }
  if (time_steps.empty() || iterations.empty())
  {
    return fail("--dt and --iterations are required");
  }
  const char* precision = sizeof(btScalar) == 8 ? "float64" : "float32";
  for (double dt : time_steps)
  {
    for (int iteration_count : iterations)
    {
      options.time_step = dt;
      options.solver_iterations = iteration_count;
      try
      {
        const ExperimentResult result = runExperiment(options);
        Json line;
        line["scenario"] = result.scenario;
        line["precision"] = precision;
        line["dt"] = jsonMeasure(dt);
        line["iterations"] = iteration_count;
        line["compute_s_per_sim_s"] = jsonMeasure(1e-6 * result.step_us_total / result.duration_s);
        line["nan"] = result.nan;
        line["reference"] = reference;
        line["trajectory"] = Json::array();
        for (const PoseSample& sample : result.trajectory)
        {
          line["trajectory"].push_back({jsonMeasure(sample.time), jsonMeasure(sample.position.x()),
                                        jsonMeasure(sample.position.y()), jsonMeasure(sample.position.z()),
                                        jsonMeasure(sample.orientation.w()), jsonMeasure(sample.orientation.x()),
                                        jsonMeasure(sample.orientation.y()), jsonMeasure(sample.orientation.z())});
        }
        std::cout << line.dump() << std::endl;
      }
      catch (const std::exception& error)
      {
        std::cerr << "sim_accuracy: " << error.what() << "\n";
        return 1;
      }
    }
  }
  return 0;
}
