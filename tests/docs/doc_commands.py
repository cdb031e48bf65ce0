#!/usr/bin/python3
"""Every command that README.md and docs/ quote, as a reader would type it.

What is a command, and what is done with it:
- A line of a ```sh block (continuation lines joined), and an inline `build/apps/covsim ...`:
  a command to copy. It is run from a scratch folder that has the repository's folders and
  `build` (the build folder) in it, with `covsim` and `python3` (the Python the module was
  built for) first on PATH, and must exit 0. A block that uses shell variables is run whole,
  with SWEEP and OUT set to a small sweep (examples/sweeps/u_shape_loss.yaml).
- A command with a placeholder (SCENARIO, FILE, DIR, K/N, ..., [a|b]) and an inline
  `covsim ...` in prose name a subcommand and its options: the subcommand must exist and
  every --option must be in its --help.
- `build/bench/covsim_bench --benchmark_filter=F`: F must match a benchmark of bench/ (the
  suite does not build the benchmarks).
- `studies/NAME.py ...`: a study runs for minutes; the script must exist and take the options.
- The commands in EXEMPT are run by the test named beside them.
Sizes are cut where a command is a soak: --cases above 30 runs 30 cases.

Usage: doc_commands.py SOURCE_DIR BUILD_DIR WORK_DIR [PYTHON]
"""
import os
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

# Command (start) -> the test that runs it.
EXEMPT = {
    "scripts/demo": "the README's demo, timed on a fresh clone (README)",
    "scripts/test": "the README's test command: CI itself (.ci/run)",
    "cmake --install": "examples_out_of_tree (installs covsim, builds examples/ against it)",
    "python3 -m venv": "python_pip_install",
    "venv/bin/pip": "python_pip_install",
    "ctest": "the test suite itself",
    "mkdocs": "docs_site",
}
SLURM = "sbatch"  # a block that submits jobs: slurm_cluster runs it on a single-node Slurm
PLACEHOLDER = re.compile(r"\.\.\.|\b[A-Z][A-Z0-9_]*[A-Z]\b(?!=)|\[|\||<|\b[A-Z]\b(?!=)|/N\b")
SHELL_SCRIPT = "#!/bin/bash"
DOC_ENV = {"SWEEP": "examples/sweeps/u_shape_loss.yaml", "OUT": "out/cluster"}
MAX_CASES = 30
TIMEOUT = 600


def blocks_and_spans(text):
    """(sh blocks, inline code spans) of a Markdown text."""
    blocks = re.findall(r"^```(?:sh|bash|shell)\n(.*?)^```", text, re.S | re.M)
    prose = re.sub(r"^```.*?^```", "", text, flags=re.S | re.M)
    return blocks, re.findall(r"`([^`\n]+)`", prose)


def commands_of(block):
    """A block's commands: comments dropped, continuation lines joined."""
    joined = re.sub(r"\\\n\s*", " ", block)
    out = []
    for line in joined.splitlines():
        line = re.sub(r"(^|\s)#.*$", "", line).strip()
        if line:
            out.append(line)
    return out


class Checker:
    def __init__(self, source, build, work, python):
        self.source, self.build, self.work = source, build, work
        self.covsim = build / "apps" / "covsim"
        self.helps = {}
        self.verbose = bool(os.environ.get("VERBOSE"))
        self.problems, self.counts = [], {"run": 0, "synopsis": 0, "exempt": 0}
        self.run_dir = work / "run"
        shutil.rmtree(work, ignore_errors=True)
        self.run_dir.mkdir(parents=True)
        for name in ("scenarios", "examples", "studies", "scripts", "python", "docs", "bench"):
            (self.run_dir / name).symlink_to(source / name)
        (self.run_dir / "build").symlink_to(build)
        bin_dir = work / "bin"
        bin_dir.mkdir()
        preload = os.environ.get("COVSIM_PRELOAD")  # a sanitized build's module needs it first
        if preload:
            (bin_dir / "python3").write_text(
                f"#!/bin/sh\nLD_PRELOAD={preload} ASAN_OPTIONS=detect_leaks=0 exec {python} \"$@\"\n")
            (bin_dir / "python3").chmod(0o755)
        else:
            (bin_dir / "python3").symlink_to(python)
        (bin_dir / "covsim").symlink_to(self.covsim)
        self.env = dict(os.environ, PATH=f"{bin_dir}:{os.environ['PATH']}", **DOC_ENV)
        self.env.pop("PYTHONPATH", None)
        bench = "\n".join(p.read_text() for p in (source / "bench").glob("*.cpp"))
        self.benchmarks = sorted(set(re.findall(r"\b(BM_\w+)", bench)))

    def fail(self, where, command, what):
        self.problems.append(f"{where}: `{command}`: {what}")

    def help_of(self, program, sub):
        key = (program, sub)
        if key not in self.helps:
            args = [program] + ([sub] if sub else []) + ["--help"]
            r = subprocess.run(args, capture_output=True, text=True, env=self.env,
                               cwd=self.run_dir)
            self.helps[key] = r.stdout if r.returncode == 0 else None
        return self.helps[key]

    def synopsis(self, where, command):
        """The subcommand exists and takes every --option named."""
        self.counts["synopsis"] += 1
        if self.verbose:
            print(f"synopsis {where}: {command}")
        words = command.split()
        program = words[0]
        if program.endswith("covsim"):
            program = str(self.covsim)
        elif not (self.run_dir / program).exists():
            return self.fail(where, command, f"{program} does not exist")
        else:
            program = str(self.run_dir / program)
        sub = None
        if words[0].endswith("covsim") and len(words) > 1 and not words[1].startswith("-"):
            sub = words[1]
        text = self.help_of(program, sub)
        if text is None:
            return self.fail(where, command, f"`{words[0]} {sub or ''} --help` fails: no such "
                             "subcommand?")
        for option in re.findall(r"(?<!\S)(--[a-z][a-z0-9-]*)", command):
            if not re.search(rf"(^|[\s,]){re.escape(option)}\b", text, re.M):
                self.fail(where, command, f"{option} is not an option of it")

    def bench_filter(self, where, command):
        self.counts["synopsis"] += 1
        m = re.search(r"--benchmark_filter=('([^']*)'|(\S+))", command)
        pattern = m.group(2) or m.group(3) if m else ""
        if not any(re.search(pattern, b) for b in self.benchmarks):
            self.fail(where, command, f"the filter {pattern!r} matches no benchmark of bench/")

    def run(self, where, command):
        self.counts["run"] += 1
        if self.verbose:
            print(f"run {where}: {command}")
        command = re.sub(r"--cases (\d+)",
                         lambda m: f"--cases {min(int(m.group(1)), MAX_CASES)}", command)
        try:
            r = subprocess.run(["bash", "-euo", "pipefail", "-c", command], cwd=self.run_dir,
                               env=self.env, capture_output=True, text=True, timeout=TIMEOUT)
        except subprocess.TimeoutExpired:
            return self.fail(where, command, f"still running after {TIMEOUT} s")
        if r.returncode != 0:
            tail = (r.stderr or r.stdout).strip().splitlines()[-3:]
            self.fail(where, command, f"exit {r.returncode}: " + " / ".join(tail))

    def command(self, where, command, runnable):
        for start, test in EXEMPT.items():
            if command.startswith(start):
                self.counts["exempt"] += 1
                return
        if command.startswith("build/bench/covsim_bench"):
            return self.bench_filter(where, command)
        if command.startswith("studies/") or not runnable or PLACEHOLDER.search(command):
            return self.synopsis(where, command)
        self.run(where, command)

    def page(self, path):
        where = str(path.relative_to(self.source))
        blocks, spans = blocks_and_spans(path.read_text(encoding="utf-8"))
        for block in blocks:
            if block.startswith(SHELL_SCRIPT) or SLURM in block:
                self.counts["exempt"] += 1  # a job script or its submission: slurm_cluster
                continue
            commands = commands_of(block)
            uses_variables = "$" in block and not any(
                c.startswith(tuple(EXEMPT)) for c in commands)
            if uses_variables:
                self.run(where, "\n".join(commands))
            else:
                for c in commands:
                    self.command(where, c, runnable=True)
        for span in spans:
            if span.startswith("build/apps/covsim "):
                self.command(where, span, runnable=True)
            elif re.match(r"covsim( |$)", span) and span != "covsim":
                self.command(where, span, runnable=False)


def main(source, build, work, python):
    checker = Checker(source, build, work, python)
    for page in [source / "README.md"] + sorted((source / "docs").glob("*.md")):
        checker.page(page)
    for p in checker.problems:
        print(p)
    c = checker.counts
    print(f"{c['run']} commands run, {c['synopsis']} checked against --help or bench/, "
          f"{c['exempt']} run by other tests; {len(checker.problems)} problems")
    if c["run"] == 0 or c["synopsis"] == 0:
        print("no commands found: has the Markdown changed shape?")
        return 1
    return 1 if checker.problems else 0


if __name__ == "__main__":
    if len(sys.argv) not in (4, 5):
        sys.exit(__doc__)
    sys.exit(main(Path(sys.argv[1]).resolve(), Path(sys.argv[2]).resolve(),
                  Path(sys.argv[3]).resolve(), Path(sys.argv[4] if len(sys.argv) == 5 else
                                                    "/usr/bin/python3")))
