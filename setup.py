"""The pip build of the Python module obbsat, run by setuptools.build_meta.

The extension obbsat._core is the CMake target obbsat_python, configured for
the interpreter that runs this file (Release, library linked in statically,
no tests, benchmarks or program) in a scratch folder that is removed at the
end. The pure Python files come from python/obbsat/, the ones that
python/CMakeLists.txt installs. Nothing is written into the source tree.

Environment: MAX_JOBS or CMAKE_BUILD_PARALLEL_LEVEL sets the build's parallel
jobs (default 2); CMAKE names the cmake program (default: cmake on PATH).
"""
import atexit
import os
import re
import shutil
import subprocess
import sys
import sysconfig
import tempfile
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE_DIR = Path(__file__).resolve().parent


def read_project_version():
    """The VERSION of project(obbsat ...) in the top CMakeLists.txt."""
    text = (SOURCE_DIR / "CMakeLists.txt").read_text(encoding="utf-8")
    match = re.search(r"project\(\s*obbsat\s+VERSION\s+([0-9]+(?:\.[0-9]+)*)", text)
    if not match:
        raise RuntimeError("no 'project(obbsat VERSION x.y.z ...)' in CMakeLists.txt")
    return match.group(1)


def read_package_files():
    """The files of python/obbsat/ that `cmake --install` installs (obbsat_python_files)."""
    text = (SOURCE_DIR / "python" / "CMakeLists.txt").read_text(encoding="utf-8")
    match = re.search(r"set\(obbsat_python_files\s+([^)]*)\)", text)
    if not match:
        raise RuntimeError("no 'set(obbsat_python_files ...)' in python/CMakeLists.txt")
    return match.group(1).split()


def make_scratch_dir():
    """A folder for setuptools' and CMake's build trees, removed when this process ends."""
    path = tempfile.mkdtemp(prefix="obbsat-pip-build.")
    atexit.register(shutil.rmtree, path, ignore_errors=True)
    return path


def build_jobs():
    for variable in ("MAX_JOBS", "CMAKE_BUILD_PARALLEL_LEVEL"):
        value = os.environ.get(variable, "").strip()
        if value:
            if not value.isdigit() or int(value) < 1:
                raise RuntimeError(f"{variable}={value!r} is not a positive number of jobs")
            return value
    return "2"


class CMakeBuildExt(build_ext):
    """Builds obbsat._core with the project's CMake build instead of compiling sources itself."""

    def build_extension(self, ext):
        cmake = os.environ.get("CMAKE") or shutil.which("cmake")
        if not cmake:
            raise RuntimeError("building obbsat needs CMake 3.16 or later (Debian package cmake)")
        build_dir = Path(self.build_temp).resolve() / "cmake"
        configure = [
            cmake, "-S", str(SOURCE_DIR), "-B", str(build_dir),
            "-DCMAKE_BUILD_TYPE=Release",
            f"-DPython_EXECUTABLE={sys.executable}",
            "-DOBBSAT_BUILD_PYTHON=ON",
            "-DOBBSAT_PYTHON_REQUIRED=ON",
            "-DOBBSAT_BUILD_TESTS=OFF",
            "-DOBBSAT_BUILD_BENCH=OFF",
            "-DOBBSAT_BUILD_TOOLS=OFF",
            "-DOBBSAT_INSTALL=OFF",
            # The library goes into the extension: nothing to install beside it.
            "-DBUILD_SHARED_LIBS=OFF",
        ]
        try:
            import pybind11  # the pip-installed pybind11 carries its CMake files
            configure.append(f"-Dpybind11_DIR={pybind11.get_cmake_dir()}")
        except (ImportError, AttributeError):
            pass  # CMake looks for pybind11-dev's files itself
        self.announce("configuring obbsat with: " + " ".join(configure), level=2)
        subprocess.run(configure, check=True)
        subprocess.run([cmake, "--build", str(build_dir), "--target", "obbsat_python",
                        "--parallel", build_jobs()], check=True)

        built_dir = build_dir / "python" / "obbsat"
        built = built_dir / ("_core" + sysconfig.get_config_var("EXT_SUFFIX"))
        if not built.is_file():
            found = sorted(p.name for p in built_dir.glob("_core*"))
            raise RuntimeError(f"the CMake build made {found} in {built_dir}, not {built.name}")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


package_files = read_package_files()
scratch = make_scratch_dir()

setup(
    version=read_project_version(),
    package_dir={"": "python"},
    packages=["obbsat"],
    package_data={"obbsat": [f for f in package_files if not f.endswith(".py")]},
    ext_modules=[Extension("obbsat._core", sources=[])],
    cmdclass={"build_ext": CMakeBuildExt},
    zip_safe=False,
    # setuptools' build/ and obbsat.egg-info/ would otherwise land in the
    # source tree (and build/ is where the README's CMake build lives).
    options={
        "build": {"build_base": os.path.join(scratch, "build")},
        "egg_info": {"egg_base": scratch},
    },
)
