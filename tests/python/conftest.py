"""Shared fixtures of the `import sylva` tests. ctest runs them with Debian's python3 and
PYTHONPATH pointing at the build's module; SYLVA_CLI names sylva-cli for the comparisons."""
import os
import pathlib
import subprocess

import pytest

SOURCE = pathlib.Path(__file__).resolve().parents[2]
DATA = SOURCE / "tests" / "data"
PRESETS = SOURCE / "presets"


@pytest.fixture(scope="session")
def cli():
    path = os.environ.get("SYLVA_CLI")
    if not path or not os.path.exists(path):
        pytest.fail("SYLVA_CLI must name the built sylva-cli")

    def run(*args, cwd=None, check=True):
        r = subprocess.run([path, *map(str, args)], cwd=cwd, capture_output=True, text=True)
        if check and r.returncode != 0:
            raise AssertionError(f"sylva-cli {' '.join(map(str, args))}: {r.returncode}\n{r.stderr}")
        return r

    return run


@pytest.fixture(scope="session")
def data():
    return DATA


@pytest.fixture(scope="session")
def presets():
    return PRESETS


def read_obj_mesh(path):
    """Vertices and triangles of a simple OBJ (v and f lines), for obstacles given as arrays."""
    import numpy as np

    verts, faces = [], []
    for line in pathlib.Path(path).read_text().splitlines():
        parts = line.split()
        if not parts:
            continue
        if parts[0] == "v":
            verts.append([float(x) for x in parts[1:4]])
        elif parts[0] == "f":
            idx = [int(p.split("/")[0]) - 1 for p in parts[1:]]
            for k in range(1, len(idx) - 1):
                faces.append([idx[0], idx[k], idx[k + 1]])
    return np.array(verts, dtype=np.float64), np.array(faces, dtype=np.int64)
