#include "god_finger/scenarios/servo_experiment.h"

#include "god_finger/runtime/servo_loop.h"

#include <cmath>

namespace god_finger
{
ExperimentResult runServoExperiment(const ExperimentOptions& options, const FakeDeviceParams& handle)
{
  const ScenarioSetup setup = loadScenario(options);
  const WorldParams params = scenarioParams(options);
  std::vector<ServoInterface> interfaces;
  for (std::size_t f = 0; f < setup.fingers.size(); ++f)
  {
    ServoInterface interface;
    interface.name = "finger" + std::to_string(f);
    // An oriented scenario's fingers (roll_finger) report the script's orientation too.
    std::optional<OrientationPath> orientation;
    if (f < setup.orientations.size())
    {
      orientation = setup.orientations[f];
    }
    auto device = std::make_unique<FakeDevice>(handle, setup.fingers[f], orientation);
    device->setScriptStart(0.0);
    interface.device = std::move(device);
    interface.profile.coupling = params.coupling;  // the scenario's coupling, as the ideal hand's
    interfaces.push_back(std::move(interface));
  }
  ServoLoopParams loop_params;
  const double rate = 1.0 / options.time_step;
  loop_params.rate = rate;
  loop_params.simulated_time = true;
  loop_params.real_time_factor = 0.0;
  ServoLoop loop(std::make_unique<GodFingerWorld>(setup.scene, params), std::move(interfaces), loop_params);
  loop.prepare();
  ServoSample sample;
  WorldSnapshot snapshot;
  return measureScenario(options, loop.world(),
                         [&loop, &sample, &snapshot, &options](long i)
                         {
                           loop.tick(static_cast<double>(i) * options.time_step);
                           while (loop.samples().tryPop(&sample) || loop.snapshots().tryPop(&snapshot))
                           {
                           }
                         });
}
}  // namespace god_finger
