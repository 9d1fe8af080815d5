// The paper's scenarios through the servo loop on simulated time: each finger is a fake
// device (the simulated handle of config/devices/fake.yaml) whose hand follows the scenario's
// script (world = device frame; an oriented scenario's fingers, roll_finger, report the script's
// orientation, FakeDevice), so that the coupling, the handle's dynamics and the force on
// it are those of a ROS session on the servo loop, step for step. Beside runExperiment's ideal
// hand (god_finger_experiment --hand ideal|fake).
#pragma once

#include "god_finger/devices/fake_device.h"
#include "god_finger/scenarios/experiment.h"

namespace god_finger
{
// Throws InputError on a bad option or scene.
ExperimentResult runServoExperiment(const ExperimentOptions& options,
                                    const FakeDeviceParams& handle = FakeDeviceParams());
}  // namespace god_finger
