"""god_finger: the god-finger method (a finger pad, not a point) on a Bullet world, from Python.

    import god_finger
    world = god_finger.World("urdf/scenes/table_ball.urdf", model="god_finger", r_max=0.01)
    finger = world.add_finger([-0.06, 0.0, 0.05])
    world.set_target(finger, [-0.03, 0.0, 0.05])
    world.step(500)
    print(world.finger(finger).contact, world.body("ball").position)

The compiled core (god_finger._core, pybind11 over the C++ libraries) holds World, Mesh,
load_mesh, contact_area and run_experiment; units are SI, frames as the C++ headers say, and
quaternions (x, y, z, w). A bad file, parameter or argument raises god_finger.Error, a ValueError,
with the C++ message. In a ROS workspace the same package also holds the messages and services
(god_finger.msg, god_finger.srv). README, "Python"; examples/ has runnable scripts.
"""

import os as _os

from god_finger._core import (  # noqa: F401
    Body,
    Contact,
    ContactArea,
    Error,
    Finger,
    Joint,
    Mesh,
    ProxyInsideBodyError,
    ResourceLimitError,
    World,
    contact_area,
    load_mesh,
    models,
    scenarios,
)
from god_finger import _core


def share_dir():
    """The folder of the package's own files (urdf/scenes, urdf/meshes, config): the source
    checkout for a catkin or plain CMake build, the installed copy for `pip install .`."""
    installed = _os.path.join(_os.path.dirname(_core.__file__), "share")
    if _os.path.isdir(installed):
        return installed
    return _os.path.dirname(_os.path.dirname(_core.default_scenes_dir))


def data_path(*parts):
    """A path to one of the package's own files: data_path("urdf", "scenes", "table_ball.urdf")."""
    return _os.path.join(share_dir(), *parts)


def run_experiment(scenario, model="god_finger", hand="ideal", **options):
    options.setdefault("scenes", data_path("urdf", "scenes"))
    return _core.run_experiment(scenario, model, hand, **options)


run_experiment.__doc__ = _core.run_experiment.__doc__
