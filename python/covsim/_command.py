"""The `covsim` command installed by pip: runs the covsim program shipped in the package
(covsim/bin/covsim), with the same arguments and exit code."""
import os
import sys


def main():
    program = os.path.join(os.path.dirname(os.path.abspath(__file__)), "bin", "covsim")
    if not os.access(program, os.X_OK):
        sys.exit(f"covsim: the program is not in this package ({program}); "
                 "it is installed by `pip install` and by `cmake --install` (PREFIX/bin/covsim)")
    os.execv(program, [program] + sys.argv[1:])


if __name__ == "__main__":
    main()
