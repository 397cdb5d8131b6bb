"""The build step of `pip install .` (pyproject.toml): the package's Python files from
python/hmfnet and its extension module hmfnet._hmfnet, which CMake builds from python/CMakeLists.txt
against an installed hmfnet found by find_package (set CMAKE_PREFIX_PATH to its prefix unless it
is in /usr or /usr/local).

setuptools writes its build and egg-info folders beside the sources by default, where build/ is
the CMake build; they go to HMFNET_PIP_BUILD_DIR instead, or to a folder of the system's temporary
directory named after this checkout, so a checkout stays as it was."""
import hashlib
import os
import re
import subprocess
import sys
import sysconfig
import tempfile
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent


def project_version():
    """The version of the CMake project(): one number for the library and the package."""
    text = (ROOT / "CMakeLists.txt").read_text()
    match = re.search(r"project\(hmfnet\s+VERSION\s+([0-9.]+)", text)
    if not match:
        raise RuntimeError("CMakeLists.txt: project(hmfnet VERSION ...) not found")
    return match.group(1)


def scratch_dir():
    given = os.environ.get("HMFNET_PIP_BUILD_DIR")
    if given:
        return Path(given).resolve()
    tag = hashlib.sha256(str(ROOT).encode()).hexdigest()[:12]
    return Path(tempfile.gettempdir()) / f"hmfnet-pip-{os.getuid()}-{tag}"


class CMakeBuild(build_ext):
    """Configures and builds python/CMakeLists.txt, which writes the module where setuptools
    takes it from."""

    def build_extension(self, ext):
        out = Path(self.get_ext_fullpath(ext.name)).resolve()
        build = Path(self.build_temp).resolve() / "cmake"
        configure = [
            "cmake", "-S", str(ROOT / "python"), "-B", str(build),
            "-DCMAKE_BUILD_TYPE=Release",
            f"-DHMFNET_VERSION={project_version()}",
            f"-DPython3_EXECUTABLE={sys.executable}",
            f"-DHMFNET_MODULE_OUTPUT_DIR={out.parent}",
            f"-DHMFNET_MODULE_SUFFIX={sysconfig.get_config_var('EXT_SUFFIX')}",
        ]
        # A build folder reused by another venv or against another prefix must not keep the
        # interpreter or the hmfnet that its cache found first; the objects stay, and are rebuilt
        # only where the flags changed.
        (build / "CMakeCache.txt").unlink(missing_ok=True)
        try:
            import pybind11

            configure.append(f"-Dpybind11_DIR={pybind11.get_cmake_dir()}")
        except ImportError:
            pass  # find_package(pybind11) searches the system (pybind11-dev)
        subprocess.run(configure, check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        subprocess.run(["cmake", "--build", str(build), "-j", jobs], check=True)


scratch = scratch_dir()
setup(
    version=project_version(),
    ext_modules=[Extension("hmfnet._hmfnet", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    options={
        "build": {"build_base": str(scratch / "build")},
        "egg_info": {"egg_base": str(scratch)},
    },
)
