"""`pip install --no-build-isolation .` into a fresh virtual environment, then
`import skelconv` from another directory (docs/python.md, "Install").

Usage: pip_install_test.py SOURCE_DIR [PYTHON]

The environment is made by PYTHON (default Debian's /usr/bin/python3) with
--system-site-packages (numpy, setuptools, wheel and pybind11 come from
Debian) in a temporary directory; pip installs from SOURCE_DIR without the
network (--no-index). The CMake build directory is made afresh at
SOURCE_DIR/build/pip-install-test, the depth of build/release, so that
ccache (base_dir /work) sees the same compile commands and returns the
objects the release build compiled. Prints the time pip took.
"""
import os
import shutil
import subprocess
import sys
import tempfile
import time

SOURCE = os.path.abspath(sys.argv[1])
PYTHON = sys.argv[2] if len(sys.argv) > 2 else "/usr/bin/python3"
BUILD_DIR = os.path.join(SOURCE, "build", "pip-install-test")

# Run in the installed environment from a directory holding no skelconv: the
# module must come from the environment, and its grid mesher (the OpenVDB
# module it opens from beside itself) too.
CHECK = """
import skelconv
skeleton = skelconv.Skeleton([skelconv.Segment([0, 0, 0], [1, 0, 0], {"family": "cauchy", "degree": 4, "s": 2})],
                             iso=0.5)
f, grad = skeleton.field([[0.5, 0.5, 0.0]])
assert f.shape == (1,) and grad.shape == (1, 3) and f[0] > 0, (f, grad)
vertices, triangles, normals = skeleton.mesh(method="grid", size=0.1)
topology = skelconv.mesh_topology(vertices, triangles)
assert topology["closed"] and topology["euler_characteristic"] == 2, topology
print(skelconv.__file__)
"""


def main():
    shutil.rmtree(BUILD_DIR, ignore_errors=True)
    with tempfile.TemporaryDirectory() as tmp:
        venv = os.path.join(tmp, "venv")
        subprocess.run([PYTHON, "-m", "venv", "--system-site-packages", venv], check=True)
        env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "SKELCONV_GRID_MESHER")}
        env["SKELCONV_CMAKE_BUILD_DIR"] = BUILD_DIR
        start = time.monotonic()
        subprocess.run([os.path.join(venv, "bin", "pip"), "install", "--no-build-isolation", "--no-index",
                        "--quiet", SOURCE], check=True, env=env)
        print(f"pip install --no-build-isolation: {time.monotonic() - start:.1f} s")

        elsewhere = os.path.join(tmp, "elsewhere")
        os.mkdir(elsewhere)
        done = subprocess.run([os.path.join(venv, "bin", "python"), "-c", CHECK], cwd=elsewhere, env=env,
                              capture_output=True, text=True, check=False)
        if done.returncode != 0:
            sys.exit(f"import skelconv from the environment failed:\n{done.stdout}{done.stderr}")
        where = done.stdout.strip()
        if not where.startswith(venv + os.sep):
            sys.exit(f"skelconv was imported from {where}, not from the environment {venv}")
        print(f"import skelconv from {elsewhere}: {where}")
    shutil.rmtree(BUILD_DIR, ignore_errors=True)


if __name__ == "__main__":
    main()
