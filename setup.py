"""Builds the molsurf Python module for `pip install .` through the project's CMake build.

build_ext configures the source tree (Release, no tests or benchmarks, for the interpreter
running pip) in setuptools' build directory, builds the `molsurf_python` target and puts the
module it makes into the wheel. With MOLSURF_BUILD_DIR naming an already configured build
(such as build/release), that build is brought up to date and its module taken instead: no
second build of the library. CMAKE_ARGS adds options to the configure step (a fresh build
only). The version and the description are project()'s in CMakeLists.txt, their one place.
"""
import os
import pathlib
import re
import shlex
import shutil
import subprocess
import sys
import sysconfig

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE_DIR = pathlib.Path(__file__).resolve().parent


def cmake_project():
    """(version, description) from CMakeLists.txt's project(molsurf VERSION ... DESCRIPTION ...)."""
    text = (SOURCE_DIR / "CMakeLists.txt").read_text(encoding="utf-8")
    match = re.search(r'project\(\s*molsurf\s+VERSION\s+([0-9][0-9.]*)\s+DESCRIPTION\s+"([^"]*)"', text)
    if not match:
        raise RuntimeError("CMakeLists.txt: no project(molsurf VERSION x.y.z DESCRIPTION \"...\")")
    return match.group(1), match.group(2)


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        reuse = os.environ.get("MOLSURF_BUILD_DIR")
        if reuse:
            build_dir = pathlib.Path(reuse).resolve()
            if not (build_dir / "CMakeCache.txt").is_file():
                raise RuntimeError(f"MOLSURF_BUILD_DIR={reuse}: not a configured CMake build (no CMakeCache.txt)")
        else:
            build_dir = pathlib.Path(self.build_temp).resolve() / "cmake"
            configure = ["cmake", "-S", str(SOURCE_DIR), "-B", str(build_dir), "-DCMAKE_BUILD_TYPE=Release",
                         "-DMOLSURF_TESTS=OFF", "-DMOLSURF_BENCH=OFF", "-DMOLSURF_PYTHON=ON",
                         f"-DPython_EXECUTABLE={sys.executable}"]
            if not (build_dir / "CMakeCache.txt").is_file() and shutil.which("ninja"):
                configure += ["-G", "Ninja"]
            configure += shlex.split(os.environ.get("CMAKE_ARGS", ""))
            subprocess.run(configure, check=True)
        build = ["cmake", "--build", str(build_dir), "--target", "molsurf_python"]
        if "CMAKE_BUILD_PARALLEL_LEVEL" not in os.environ:
            build += ["--parallel", str(os.cpu_count() or 1)]
        subprocess.run(build, check=True)

        # The module is named for the interpreter CMake built it for; it must be this one's.
        built = build_dir / "python" / (ext.name + sysconfig.get_config_var("EXT_SUFFIX"))
        if not built.is_file():
            found = sorted(p.name for p in (build_dir / "python").glob(ext.name + ".*"))
            raise RuntimeError(f"{built} was not built (found: {', '.join(found) or 'nothing'}); the build in "
                               f"{build_dir} must be for {sys.executable} ({sys.version.split()[0]}): see its "
                               "configure messages for what the module needs")
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


version, description = cmake_project()
# One extension module and no Python packages (no search of the source tree for any).
setup(version=version, description=description, packages=[], py_modules=[],
      ext_modules=[Extension("molsurf", sources=[])],
      cmdclass={"build_ext": CMakeBuild})
