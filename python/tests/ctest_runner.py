"""Runs the Python tests and examples for ctest, with the reason when they cannot run here.

    ctest_runner.py pytest TESTS_DIR_OR_FILE [PYTEST_ARGS...]
    ctest_runner.py example SCRIPT OUT_DIR FIGURE [ARGS...]
    ctest_runner.py pip SOURCE_DIR BUILD_DIR

Exit 77 (ctest's skip code) with the reason when a module the run needs is missing; an
example passes when it exits 0 and writes its figure as a PNG; `pip` installs the package
with `pip install --no-build-isolation` into a fresh venv (reusing BUILD_DIR's build) and
checks that the installed module runs the U-shaped scenario to the command-line program's
fingerprint.
"""
import importlib.util
import os
import subprocess
import sys

NEEDS = {
    "ensurepip": "python3-venv",
    "pip": "python3-pip",
    "setuptools": "python3-setuptools",
    "numpy": "python3-numpy",
    "pytest": "python3-pytest",
    "pandas": "python3-pandas",
    "matplotlib": "python3-matplotlib",
}


def skip_unless(modules):
    missing = [m for m in modules if importlib.util.find_spec(m) is None]
    if missing:
        print("skipped: " + ", ".join(f"{m} is not installed ({NEEDS[m]})" for m in missing))
        sys.exit(77)


def main(argv):
    if argv[0] == "pytest":
        skip_unless(["numpy", "pytest", "pandas"])
        import pytest

        return pytest.main(["-q", "-p", "no:cacheprovider", *argv[1:]])
    if argv[0] == "example":
        script, out, figure, rest = argv[1], argv[2], argv[3], argv[4:]
        skip_unless(["numpy", "matplotlib", "pandas"])
        # No folder beforehand: an example makes the one --out names.
        import shutil

        shutil.rmtree(out, ignore_errors=True)
        path = os.path.join(out, figure)
        code = subprocess.call([sys.executable, script, "--out", out, *rest])
        if code != 0:
            return code
        with open(path, "rb") as f:
            if f.read(8) != b"\x89PNG\r\n\x1a\n":
                print(f"{path} is not a PNG")
                return 1
        print(f"wrote {path}")
        return 0
    if argv[0] == "pip":
        return pip_install(argv[1], argv[2])
    print(f"unknown mode {argv[0]}")
    return 2


def pip_install(source, build):
    skip_unless(["ensurepip", "pip", "setuptools", "numpy"])
    import json
    import shutil
    import tempfile

    venv = os.path.join(build, "python", "pip-test-venv")
    shutil.rmtree(venv, ignore_errors=True)
    subprocess.check_call([sys.executable, "-m", "venv", "--system-site-packages", venv])
    python = os.path.join(venv, "bin", "python")
    env = dict(os.environ, COVSIM_BUILD_DIR=build)
    env.pop("PYTHONPATH", None)  # the installed package, not the build tree's
    subprocess.check_call([python, "-m", "pip", "install", "-q", "--no-build-isolation",
                           "--no-index", source], env=env)
    scenario = os.path.join(source, "scenarios", "u_shape.json")
    probe = ("import covsim, json, sys; "
             f"s = covsim.Simulation(covsim.Scenario.from_file({scenario!r})).run(); "
             "print(json.dumps([covsim.__file__, s['fingerprint']]))")
    where, fingerprint = json.loads(subprocess.check_output([python, "-c", probe], env=env,
                                                            cwd=tempfile.gettempdir()))
    if not os.path.realpath(where).startswith(os.path.realpath(venv)):
        print(f"imported {where}, not the installed package")
        return 1
    with tempfile.TemporaryDirectory() as out:
        subprocess.check_call([os.environ["COVSIM_PROGRAM"], "run", scenario, "--out", out],
                              stdout=subprocess.DEVNULL)
        with open(os.path.join(out, "final.json")) as f:
            expected = json.load(f)["fingerprint"]
    if fingerprint != expected:
        print(f"installed package: fingerprint {fingerprint}, covsim run: {expected}")
        return 1
    # pip installs the `covsim` command too, beside the venv's python.
    command = os.path.join(venv, "bin", "covsim")
    version = subprocess.run([command, "--version"], capture_output=True, text=True, env=env)
    if version.returncode != 0 or "covsim" not in version.stdout:
        print(f"{command} --version: exit {version.returncode}: {version.stdout}{version.stderr}")
        return 1
    print(f"pip-installed {where}: fingerprint {fingerprint}, as covsim run; "
          f"{command} runs ({version.stdout.splitlines()[0]})")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
