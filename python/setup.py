"""Builds the Python module `reebkit` with CMake for `pip install ./python`
(docs/install.md): the CMake project one folder up, configured with only the
library and the module (no tests, benchmarks, experiments or MPI), built for
the Python that runs pip, and the module copied into the wheel.

REEBKIT_BUILD_DIR=<a configured reebkit build folder> packages that build's
module instead (cmake --build of the target reebkit_python there, nothing
configured): what the test install.pip does with the build it tests.
"""
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE = Path(__file__).resolve().parent.parent
VERSION = re.search(r"project\(reebkit VERSION ([0-9.]+)", (SOURCE / "CMakeLists.txt").read_text()).group(1)
BUILD_DIR = os.environ.get("REEBKIT_BUILD_DIR")


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        if BUILD_DIR:
            build = Path(BUILD_DIR)
        else:
            build = Path(self.build_temp).resolve() / "cmake"
            subprocess.run(["cmake", "-S", SOURCE, "-B", build, "-DCMAKE_BUILD_TYPE=Release",
                            "-DREEBKIT_BUILD_TESTS=OFF", "-DREEBKIT_BUILD_BENCH=OFF",
                            "-DREEBKIT_BUILD_EXPERIMENTS=OFF", "-DREEBKIT_MPI=OFF", "-DREEBKIT_BUILD_PYTHON=ON",
                            f"-DPYTHON_EXECUTABLE={sys.executable}"], check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        subprocess.run(["cmake", "--build", build, "--target", "reebkit_python", "-j", jobs], check=True)
        built = list((build / "python").glob("reebkit*.so"))
        if len(built) != 1:
            sys.exit(f"{build / 'python'}: expected one reebkit module, found {[p.name for p in built]}")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[0], target)


# setuptools' own folders go into the build folder, not into python/.
work = Path(BUILD_DIR or SOURCE / "python" / "build") / "pip"
work.mkdir(parents=True, exist_ok=True)
setup(
    version=VERSION,
    ext_modules=[Extension("reebkit", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={"build": {"build_base": str(work)}, "egg_info": {"egg_base": str(work)}},
    zip_safe=False,
)
