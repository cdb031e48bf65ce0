"""Builds the Python package `covsim` with CMake, for pip:

    python3 -m venv --system-site-packages venv && venv/bin/pip install --no-build-isolation .

Works offline with the system's setuptools (no build isolation: nothing is downloaded).
COVSIM_BUILD_DIR names a CMake build folder to build the module in (reusing what it has
built); otherwise a fresh one under setuptools' build folder. See docs/python.md.
"""
import os
import pathlib
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build import build
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent


def project_version():
    text = (ROOT / "CMakeLists.txt").read_text()
    return re.search(r"project\(covsim VERSION ([0-9.]+)", text).group(1)


class Build(build):
    def initialize_options(self):
        super().initialize_options()
        self.build_base = "build/pip"  # beside, not inside, the usual CMake build folder


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        folder = pathlib.Path(os.environ.get("COVSIM_BUILD_DIR") or
                              pathlib.Path(self.build_temp).resolve() / "cmake")
        if not (folder / "CMakeCache.txt").exists():
            generator = ["-G", "Ninja"] if shutil.which("ninja") else []
            subprocess.check_call(
                ["cmake", "-S", str(ROOT), "-B", str(folder), *generator,
                 "-DCMAKE_BUILD_TYPE=Release", "-DCOVSIM_PYTHON=ON", "-DCOVSIM_BUILD_TESTS=OFF",
                 "-DCOVSIM_BUILD_BENCH=OFF", f"-DPython_EXECUTABLE={sys.executable}"])
        subprocess.check_call(["cmake", "--build", str(folder), "--target", "_covsim", "covsim",
                               "-j", str(os.cpu_count() or 1)])
        built = sorted((folder / "python" / "covsim").glob("_covsim*.so"))
        if not built:
            raise RuntimeError(f"{folder}: the build made no covsim/_covsim module")
        target = pathlib.Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(built[0], target)
        # Which Python the module is for, and the covsim program behind the `covsim` command.
        shutil.copy2(folder / "python" / "covsim" / "_build.py", target.parent / "_build.py")
        (target.parent / "bin").mkdir(exist_ok=True)
        shutil.copy2(folder / "apps" / "covsim", target.parent / "bin" / "covsim")


setup(
    version=project_version(),
    packages=["covsim"],
    package_dir={"covsim": "python/covsim"},
    ext_modules=[Extension("covsim._covsim", sources=[])],
    cmdclass={"build": Build, "build_ext": CMakeBuild},
    entry_points={"console_scripts": ["covsim = covsim._command:main"]},
)
