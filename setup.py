"""`pip install .`: the Python package python/unidyn with what CMake builds for it.

The compiled module (`_unidyn`) and the command (`unidyn`, for `python3 -m unidyn`) are built by
the project's CMake build — in $UNIDYN_BUILD_DIR if set, else ./build (configured here, Release,
without tests and benchmarks, if it is not yet; `bash scripts/build.sh` makes the same) — and put
in the package with the bundled models: unidyn/bin/unidyn and unidyn/share/unidyn/models, the
layout an installed command finds its models in. Only these two targets are built.
"""

import glob
import os
import shutil
import subprocess

from setuptools import setup
from setuptools.command.build_py import build_py

HERE = os.path.dirname(os.path.abspath(__file__))


def cmake_build():
    """The build directory with _unidyn and unidyn built in it."""
    build = os.path.abspath(os.environ.get("UNIDYN_BUILD_DIR") or os.path.join(HERE, "build"))
    if not os.path.exists(os.path.join(build, "CMakeCache.txt")):
        subprocess.run(["cmake", "-S", HERE, "-B", build, "-G", "Ninja",
                        "-DCMAKE_BUILD_TYPE=Release", "-DUNIDYN_BUILD_TESTS=OFF",
                        "-DUNIDYN_BUILD_BENCH=OFF"], check=True)
    subprocess.run(["cmake", "--build", build, "--target", "_unidyn", "unidyn"], check=True)
    return build


class BuildWithCMake(build_py):
    """The package's Python files, then the compiled module, the command and the models."""

    def run(self):
        super().run()
        build = cmake_build()
        package = os.path.join(self.build_lib, "unidyn")
        modules = glob.glob(os.path.join(build, "python", "unidyn", "_unidyn*.so"))
        if len(modules) != 1:
            raise RuntimeError(f"expected one compiled module _unidyn in {build}/python/unidyn")
        shutil.copy2(modules[0], package)
        os.makedirs(os.path.join(package, "bin"), exist_ok=True)
        shutil.copy2(os.path.join(build, "unidyn"), os.path.join(package, "bin"))
        models = os.path.join(package, "share", "unidyn", "models")
        shutil.rmtree(models, ignore_errors=True)
        shutil.copytree(os.path.join(HERE, "models"), models)


setup(cmdclass={"build_py": BuildWithCMake})
