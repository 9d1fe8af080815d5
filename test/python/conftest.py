"""The Python tests (scripts/test runs them on the catkin build, .ci/run again on the plain CMake
build). They import god_finger from wherever the environment puts it (a sourced devel space, or
PYTHONPATH=build/python) and find the C++ programs they compare with in $GOD_FINGER_BIN_DIR."""
import os
import shutil

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def _bin_dir():
    given = os.environ.get("GOD_FINGER_BIN_DIR")
    if given:
        return given
    for candidate in (os.path.join(ROOT, ".build", "ws", "devel", "lib", "god_finger"),
                      os.path.join(ROOT, "build", "bin")):
        if os.path.isdir(candidate):
            return candidate
    raise RuntimeError("set GOD_FINGER_BIN_DIR to the folder of god_finger_experiment")


@pytest.fixture(scope="session")
def root():
    return ROOT


@pytest.fixture(scope="session")
def program():
    """The path of one of the package's C++ programs (god_finger_experiment, the traces)."""
    folder = _bin_dir()

    def find(name):
        path = os.path.join(folder, name)
        assert os.access(path, os.X_OK), path + " is not built"
        return path

    return find


@pytest.fixture
def scene(root):
    def path(name):
        return os.path.join(root, "urdf", "scenes", name)

    return path


def pytest_report_header(config):
    # The docs' tests (test_docs.py's static checks, test_design_layers.py) need nothing built:
    # a missing module or build fails only the tests that use them.
    try:
        import god_finger
        return "god_finger from " + os.path.dirname(god_finger._core.__file__) + "; programs from " + _bin_dir()
    except (ImportError, RuntimeError) as error:
        return "god_finger: %s" % error


__all__ = ["shutil"]
