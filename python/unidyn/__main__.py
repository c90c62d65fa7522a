"""`python3 -m unidyn ARGS...`: the command line `unidyn ARGS...` (the command installed with the
package by `pip install .`, else `unidyn` on the PATH), run in this process's place."""

import os
import shutil
import sys


def main():
    packaged = os.path.join(os.path.dirname(os.path.abspath(__file__)), "bin", "unidyn")
    command = packaged if os.access(packaged, os.X_OK) else shutil.which("unidyn")
    if command is None:
        sys.exit("python3 -m unidyn: no unidyn command (pip install . puts one in the package)")
    os.execv(command, [command, *sys.argv[1:]])


if __name__ == "__main__":
    main()
