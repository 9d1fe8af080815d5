"""The Python package god_finger (README, "Python").

- catkin (catkin_python_setup in CMakeLists.txt) reads packages and package_dir from here; the
  compiled module god_finger._core is CMake's (src/python), built into devel space.
- `pip install --no-build-isolation .` builds the same module with plain CMake (no ROS:
  -DGOD_FINGER_ROS=OFF) in build/ (or $GOD_FINGER_BUILD_DIR), reusing a build already there, and
  installs it with the package's own files (urdf/, config/, package.xml) under god_finger/share.
"""
import os
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build = os.environ.get("GOD_FINGER_BUILD_DIR", os.path.join(ROOT, "build"))
        subprocess.check_call(["cmake", "-S", ROOT, "-B", build, "-DGOD_FINGER_ROS=OFF",
                               "-DPYTHON_EXECUTABLE=" + sys.executable, "-DCMAKE_BUILD_TYPE=RelWithDebInfo"])
        subprocess.check_call(["cmake", "--build", build, "--target", "god_finger_python", "--parallel",
                               str(os.cpu_count() or 2)])
        package = os.path.join(build, "python", "god_finger")
        built = [name for name in os.listdir(package) if name.startswith("_core") and name.endswith(".so")]
        if len(built) != 1:
            raise RuntimeError("god_finger: no single _core*.so in " + package)
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(os.path.join(package, built[0]), target)
        share = os.path.join(os.path.dirname(target), "share")
        shutil.rmtree(share, ignore_errors=True)
        for folder in ("urdf", "config"):
            shutil.copytree(os.path.join(ROOT, folder), os.path.join(share, folder))
        shutil.copyfile(os.path.join(ROOT, "package.xml"), os.path.join(share, "package.xml"))


# catkin's install step runs this file with CATKIN_BINARY_DIR set: CMake installs the module then.
UNDER_CATKIN = "CATKIN_BINARY_DIR" in os.environ

setup(
    name="god_finger",
    version="0.1.0",
    description="The god-finger method: touching virtual objects with a finger pad, on Bullet",
    packages=["god_finger"],
    package_dir={"": "python"},
    ext_modules=[] if UNDER_CATKIN else [CMakeExtension("god_finger._core")],
    cmdclass={} if UNDER_CATKIN else {"build_ext": CMakeBuild},
    python_requires=">=3.8",
    install_requires=["numpy"],
)
