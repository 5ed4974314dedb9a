"""Collision shapes that follow the visual meshes: an approximate convex decomposition (V-HACD) of each sub-type.

One convex hull per vehicle keeps bodies apart by the air between its wheels, wings and handlebars (a median
0.14 m at collision events, 0.40 m for aeroplanes: a viewer saw no contact). A compound of convex pieces that hugs
the mesh makes the rendered vehicles touch where the physics says they do.

V-HACD (Mamou's hierarchical approximate convex decomposition, built into pybullet) takes a few seconds per
sub-type, so the decompositions are made once (`python -m dynclevr.assets.collision`) and committed as OBJ files,
one object per convex piece, under `dynclevr/assets/collision/`; each file's first line records the sha256 of the
visual mesh it was made from, and `load` refuses a file that no longer matches its mesh.

Two-wheelers also get a thin stand under the wheels (real ones are held upright by riders and stands; two round
tyres would topple): a flat plate STAND_HEIGHT thick, as wide as STAND_WIDTH of the vehicle, along the wheelbase.
"""

from __future__ import annotations

import functools
import hashlib
import os
import sys
import tempfile
from pathlib import Path

import numpy as np
from scipy.spatial import ConvexHull

from dynclevr.assets.catalogue import SUBTYPES, get_asset
from dynclevr import DynclevrError

DIR = Path(__file__).with_name("collision")
# V-HACD settings: 400k voxels resolve a bicycle's 3.6 cm tubes; concavity 0.0025 (its default) keeps each piece
# within about 2 cm of the mesh; 32 vertices per piece keep contact generation cheap.
VHACD = dict(resolution=400000, concavity=0.0025, maxNumVerticesPerCH=32, minVolumePerCH=1e-5)
STAND_HEIGHT = 0.01      # metres
STAND_WIDTH = 0.5        # share of the vehicle's width
TWO_WHEELED = ("bicycle", "motorbike")


class CollisionShapeError(DynclevrError):
    pass


def mesh_digest(name: str) -> str:
    mesh = get_asset(name).mesh
    h = hashlib.sha256(np.ascontiguousarray(mesh.vertices, "<f8").tobytes())
    h.update(np.ascontiguousarray(mesh.faces, "<i8").tobytes())
    return h.hexdigest()


def path(name: str) -> Path:
    return DIR / f"{name}.obj"


def _stand(name: str) -> np.ndarray:
    """The plate under a two-wheeler's wheels: 8 corners."""
    length, width, height = get_asset(name).size
    x, y, z = length / 2 * 0.9, width / 2 * STAND_WIDTH, -height / 2
    return np.array([[sx * x, sy * y, z + dz] for sx in (-1, 1) for sy in (-1, 1) for dz in (0.0, STAND_HEIGHT)])


def decompose(name: str) -> list[np.ndarray]:
    """V-HACD of the sub-type's visual mesh (plus the stand): the vertices of each convex piece."""
    import pybullet as p

    with tempfile.TemporaryDirectory() as tmp:
        src, out = Path(tmp) / "mesh.obj", Path(tmp) / "vhacd.obj"
        get_asset(name).mesh.export(src)
        fd = os.dup(1)
        try:   # V-HACD prints its progress on stdout
            os.dup2(os.open(os.devnull, os.O_WRONLY), 1)
            p.vhacd(str(src), str(out), str(Path(tmp) / "log.txt"), **VHACD)
        finally:
            sys.stdout.flush()
            os.dup2(fd, 1)
            os.close(fd)
        pieces = _read_pieces(out.read_text().splitlines())
    # V-HACD's voxels stick out of the mesh by up to one voxel; clipped to the mesh's bounding box, the vehicle
    # stands on its wheels' true bottom, not 1 cm above the floor.
    half = np.asarray(get_asset(name).size, float) / 2
    pieces = [np.clip(v, -half, half) for v in pieces]
    if get_asset(name).category in TWO_WHEELED:
        pieces.append(_stand(name))
    return pieces


def write(name: str, pieces: list[np.ndarray]) -> Path:
    lines = [f"# dynclevr collision shape of {name}: {len(pieces)} convex pieces; mesh sha256 {mesh_digest(name)}"]
    offset = 1
    for k, v in enumerate(pieces):
        hull = ConvexHull(v)
        lines.append(f"o piece{k}")
        lines += [f"v {x:.6f} {y:.6f} {z:.6f}" for x, y, z in v]
        lines += ["f " + " ".join(str(offset + i) for i in tri) for tri in hull.simplices]
        offset += len(v)
    out = path(name)
    out.parent.mkdir(parents=True, exist_ok=True)
    tmp = out.with_suffix(".tmp")
    tmp.write_text("\n".join(lines) + "\n")
    tmp.replace(out)
    return out


@functools.lru_cache(maxsize=None)
def load(name: str) -> tuple[np.ndarray, ...]:
    """The convex pieces of a sub-type's collision shape (vertex arrays), checked against its mesh."""
    f = path(name)
    if not f.exists():
        raise CollisionShapeError(f"{f} is missing: run `python -m dynclevr.assets.collision` to make it")
    text = f.read_text().splitlines()
    if not text or mesh_digest(name) not in text[0]:
        raise CollisionShapeError(f"{f} was made from another mesh of '{name}': run "
                                  f"`python -m dynclevr.assets.collision {name}` to remake it")
    return tuple(_read_pieces(text))


def _read_pieces(lines: list[str]) -> list[np.ndarray]:
    """The vertices of each object ('o') of an OBJ file."""
    pieces: list[list] = []
    for line in lines:
        if line.startswith("o "):
            pieces.append([])
        elif line.startswith("v ") and pieces:
            pieces[-1].append([float(x) for x in line.split()[1:4]])
    return [np.array(v, float) for v in pieces if len(v) >= 4]


def main(names: list[str]) -> None:
    for name in names or list(SUBTYPES):
        pieces = decompose(name)
        print(f"{name}: {len(pieces)} pieces -> {write(name, pieces)}")


if __name__ == "__main__":
    main(sys.argv[1:])
