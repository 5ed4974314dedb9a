"""What a viewer of the video can see: how much of each object is in the frame, and whether two colliding vehicles
visibly touch. Question generation asks only about what is seen (REFERENCE.md section 1: questions are about the
video), and `dynclevr stats` reports how well the physics' contacts agree with the rendered meshes.

Both measures read the rendered instance masks (exact: the renderer draws them from the meshes) or the meshes
themselves, never a centre-in-view test, which calls a bicycle hidden behind a bus "visible".
"""

from __future__ import annotations

from functools import lru_cache

import cv2
import numpy as np
from scipy.spatial import cKDTree

from dynclevr.assets.catalogue import get_asset
from dynclevr.scene import Collision, Scene4D

SURFACE_POINTS = 20000   # per mesh: about 1 cm apart on a car, so a mesh gap is good to about 1 cm


def pixel_counts(masks: np.ndarray, object_ids: list[int]) -> np.ndarray:
    """[T, N] int: the pixels of each object in each frame of instance masks [T, H, W] (object id, -1 background)."""
    T = masks.shape[0]
    flat = masks.reshape(T, -1).astype(np.int64)
    top = max(max(object_ids, default=0), int(flat.max(initial=-1))) + 2
    counts = np.stack([np.bincount(row + 1, minlength=top) for row in flat])   # column 0: background
    return counts[:, np.asarray(object_ids, int) + 1]


def mask_gap(mask: np.ndarray, a: int, b: int) -> float:
    """Pixels between object a's and object b's masks in one frame (0: they touch or one occludes the other);
    inf when either is not in the frame."""
    in_a, in_b = mask == a, mask == b
    if not in_a.any() or not in_b.any():
        return float("inf")
    # Distance of every pixel to the nearest pixel of a, read at b's pixels: 1 for 4-neighbours (touching).
    dist = cv2.distanceTransform((~in_a).astype(np.uint8), cv2.DIST_L2, 5)
    return max(0.0, float(dist[in_b].min()) - 1.0)


@lru_cache(maxsize=None)
def surface(shape: str) -> np.ndarray:
    """Points spread over a sub-type's visual mesh (area-weighted, fixed seed): [SURFACE_POINTS, 3]."""
    mesh = get_asset(shape).mesh
    tri = np.asarray(mesh.triangles)
    area = np.asarray(mesh.area_faces)
    rng = np.random.default_rng(0)
    face = rng.choice(len(tri), size=SURFACE_POINTS, p=area / area.sum())
    u, v = rng.random((2, SURFACE_POINTS))
    flip = u + v > 1
    u, v = np.where(flip, 1 - u, u), np.where(flip, 1 - v, v)
    t = tri[face]
    return t[:, 0] + u[:, None] * (t[:, 1] - t[:, 0]) + v[:, None] * (t[:, 2] - t[:, 0])


def _posed(scene: Scene4D, i: int, t: int) -> np.ndarray:
    x, y, z, w = scene.orientation[t, i]
    R = np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                  [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                  [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])
    return surface(scene.objects[i].shape) @ R.T + scene.position[t, i]


def mesh_gap(scene: Scene4D, event: Collision) -> float:
    """Metres between the two vehicles' visual meshes at the event's frame (about 0 when they visibly touch)."""
    ia, ib = scene.index(event.a), scene.index(event.b)
    pa, pb = _posed(scene, ia, event.frame), _posed(scene, ib, event.frame)
    return float(cKDTree(pa).query(pb, k=1)[0].min())
