#!/usr/bin/python3
"""The release files agree with the one version, CMakeLists.txt's project(covsim VERSION ...):
`covsim --version`, the CMake package's version file, Python's covsim.__version__ (when the
module is built), CITATION.cff (version and date), CHANGELOG.md's newest entry (version and
date); LICENSE is the GPL version 3 that CITATION.cff and the README name.

Usage: check_release.py SOURCE_DIR BUILD_DIR COVSIM [PYTHON]
"""
import os
import re
import subprocess
import sys
from pathlib import Path


def main(source, build, covsim, python):
    problems = []

    def expect(what, found, wanted):
        if found != wanted:
            problems.append(f"{what}: {found!r}, expected {wanted!r}")

    project = re.search(r"project\(covsim VERSION (\S+)", (source / "CMakeLists.txt").read_text())
    if not project:
        return f"{source}/CMakeLists.txt: no project(covsim VERSION ...)"
    version = project.group(1)

    line = subprocess.run([covsim, "--version"], capture_output=True, text=True).stdout
    expect("covsim --version", line.split(" (")[0].strip(), f"covsim {version}")

    package = (build / "covsimConfigVersion.cmake").read_text()
    expect("covsimConfigVersion.cmake", re.search(r'PACKAGE_VERSION "([^"]*)"', package).group(1),
           version)

    if python:
        env = dict(os.environ, PYTHONPATH=str(build / "python"))
        if os.environ.get("COVSIM_PRELOAD"):  # a sanitized build's module
            env.update(LD_PRELOAD=os.environ["COVSIM_PRELOAD"], ASAN_OPTIONS="detect_leaks=0")
        got = subprocess.run([python, "-c", "import covsim; print(covsim.__version__)"],
                             capture_output=True, text=True, env=env)
        expect("covsim.__version__", got.stdout.strip() or got.stderr.strip(), version)

    citation = (source / "CITATION.cff").read_text()
    field = lambda key: (re.search(rf"^{key}: \"?([^\"\n]*)\"?$", citation, re.M) or [None, None])[1]
    expect("CITATION.cff version", field("version"), version)
    expect("CITATION.cff license", field("license"), "GPL-3.0-or-later")
    if "Breitenmoser" not in citation:
        problems.append("CITATION.cff does not cite the paper (Breitenmoser et al.)")

    entry = re.search(r"^## (\S+) \((\d{4}-\d\d-\d\d)\)$", (source / "CHANGELOG.md").read_text(), re.M)
    if not entry:
        problems.append("CHANGELOG.md: no entry '## VERSION (YYYY-MM-DD)'")
    else:
        expect("CHANGELOG.md's newest entry", entry.group(1), version)
        expect("CITATION.cff date-released", field("date-released"), entry.group(2))

    licence = (source / "LICENSE").read_text()
    if "GNU GENERAL PUBLIC LICENSE" not in licence or "Version 3, 29 June 2007" not in licence:
        problems.append("LICENSE is not the GNU GPL version 3")

    for p in problems:
        print(p)
    print(f"version {version}: {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    if len(sys.argv) not in (4, 5):
        sys.exit(__doc__)
    sys.exit(main(Path(sys.argv[1]), Path(sys.argv[2]), sys.argv[3],
                  sys.argv[4] if len(sys.argv) == 5 else None))
