"""Sub-types, their categories and sizes, and the Asset record every stage reads.

Conventions (shared by physics, render and the scene parser):
- metres; the vehicle faces +x, its left is +y, up is +z;
- the mesh is centred on its bounding-box centre, which is the object's position in Scene4D;
- sizes are scaled as in Super-CLEVR (all vehicles comparable, 1.5 to 4.6 m long) so that every sub-type is
  readable in the same 320x240 view; proportions within a vehicle are realistic.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property, lru_cache

import numpy as np
import trimesh

# sub-type -> (category, (length, width, height) in metres)
SUBTYPES: dict[str, tuple[str, tuple[float, float, float]]] = {
    "airliner": ("aeroplane", (4.2, 4.0, 1.2)),
    "fighter": ("aeroplane", (3.8, 2.6, 0.9)),
    "jet": ("aeroplane", (3.6, 3.2, 1.0)),
    "biplane": ("aeroplane", (3.0, 3.4, 1.1)),
    "mountain_bike": ("bicycle", (1.8, 0.6, 1.1)),
    "tandem_bike": ("bicycle", (2.6, 0.6, 1.1)),
    "utility_bike": ("bicycle", (1.8, 0.6, 1.2)),
    "road_bike": ("bicycle", (1.8, 0.5, 1.0)),
    "articulated_bus": ("bus", (4.6, 1.3, 1.5)),
    "double_bus": ("bus", (3.6, 1.3, 2.1)),
    "school_bus": ("bus", (3.8, 1.3, 1.6)),
    "regular_bus": ("bus", (3.8, 1.3, 1.5)),
    "minivan": ("car", (2.9, 1.3, 1.3)),
    "sedan": ("car", (3.0, 1.3, 1.0)),
    "suv": ("car", (2.8, 1.4, 1.3)),
    "truck": ("car", (3.2, 1.4, 1.4)),
    "wagon": ("car", (3.0, 1.3, 1.1)),
    "chopper": ("motorbike", (2.2, 0.7, 1.0)),
    "cruiser": ("motorbike", (2.1, 0.8, 1.1)),
    "dirtbike": ("motorbike", (1.9, 0.7, 1.1)),
    "scooter": ("motorbike", (1.6, 0.6, 1.0)),
}
CATEGORIES = ("aeroplane", "bicycle", "bus", "car", "motorbike")
DENSITY = 2.7  # (paper) mass = 2.7 x mesh volume; pipeline.toml's physics.density overrides it in simulation

# The part names a renderer colours: only "body" takes the object colour.
PARTS = ("body", "wheels", "windows", "lights")


@dataclass(frozen=True)
class Asset:
    name: str
    category: str
    size: tuple[float, float, float]
    parts: dict[str, trimesh.Trimesh]   # part name -> mesh, in the object frame

    # Derived meshes are cached on the instance (get_asset caches the instance), so physics, rendering and the scene
    # parser build each at most once per process. cached_property writes the instance __dict__ directly, which a
    # frozen dataclass allows.
    @cached_property
    def mesh(self) -> trimesh.Trimesh:
        """All parts as one mesh (for silhouettes and the scene parser)."""
        return trimesh.util.concatenate([self.parts[p] for p in PARTS if p in self.parts])

    @cached_property
    def hull(self) -> trimesh.Trimesh:
        """Convex hull of the whole vehicle: the collision shape and the volume."""
        return self.mesh.convex_hull

    @property
    def volume(self) -> float:
        """Volume of the convex hull: the part meshes overlap and are not watertight, so their own volume is
        undefined; the hull is the solid the physics engine simulates anyway."""
        return float(self.hull.volume)

    def mass(self, density: float = DENSITY) -> float:
        return density * self.volume

    @property
    def collision_hull(self) -> np.ndarray:
        """Vertices of the convex hull used as the physics collision shape (pybullet GEOM_MESH)."""
        return np.asarray(self.hull.vertices)


@lru_cache(maxsize=None)
def get_asset(name: str) -> Asset:
    if name not in SUBTYPES:
        raise KeyError(f"unknown sub-type {name!r}; known: {', '.join(SUBTYPES)}")
    from dynclevr.assets.meshes import build_parts   # imports this module for PARTS

    category, size = SUBTYPES[name]
    return Asset(name, category, size, build_parts(name, size))
