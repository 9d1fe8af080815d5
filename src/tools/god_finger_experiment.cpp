// god_finger_experiment: see experiment_tool.h and the README.
#include "experiment_tool.h"

#include <iostream>

#ifndef GOD_FINGER_SCENES_DIR
#error "GOD_FINGER_SCENES_DIR must name the folder of the scene URDFs"
#endif

int main(int argc, char** argv)
{
  god_finger::ExperimentToolOptions options;
  const std::string error = god_finger::parseExperimentToolOptions(argc, argv, GOD_FINGER_SCENES_DIR, &options);
  if (!error.empty())
  {
    std::cerr << "god_finger_experiment: " << error << "\n";
    return 2;
  }
  if (options.help)
  {
    std::cout << god_finger::experimentToolUsage();
    return 0;
  }
  if (options.list_scenarios)
  {
    std::cout << god_finger::scenarioNames("\n") << "\n";
    return 0;
  }
  if (options.list_models)
  {
    for (const god_finger::ContactModel model : god_finger::contactModels())
    {
      std::cout << god_finger::contactModelName(model) << "\n";
    }
    return 0;
  }
  return god_finger::runExperimentTool(options, std::cout, std::cerr);
}
