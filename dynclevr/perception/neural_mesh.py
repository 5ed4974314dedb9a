"""3D neural mesh models O_s = (M_s, T_s), one per sub-type, and the clutter (background) model B.

M_s: points spread evenly over the catalogue mesh's surface (farthest-point sampling of a dense uniform sample),
each standing for an equal share of the surface area. T_s: one unit feature per point. B: K unit features.
T_s and B are not trained by gradient: after every gradient step of the CNN they move towards the mean CNN feature
observed at their points (or on background cells) by a momentum update (paper, appendix 3, after CoKe).
"""

from __future__ import annotations

import zlib

import numpy as np
import torch
from torch.nn import functional as F

from dynclevr.assets import SUBTYPES, get_asset


def surface_points(subtype: str, count: int) -> tuple[np.ndarray, float]:
    """`count` points spread evenly over the sub-type's mesh surface, and the area (m^2) each stands for."""
    import trimesh

    mesh = get_asset(subtype).mesh
    seed = zlib.crc32(subtype.encode())   # the same points on every machine
    dense, _ = trimesh.sample.sample_surface(mesh, count * 16, seed=seed)
    chosen = np.empty(count, dtype=int)
    chosen[0] = 0
    dist = np.linalg.norm(dense - dense[0], axis=1)
    for i in range(1, count):
        chosen[i] = int(dist.argmax())
        dist = np.minimum(dist, np.linalg.norm(dense - dense[chosen[i]], axis=1))
    return dense[chosen].astype(np.float32), float(mesh.area) / count


class NeuralMeshes:
    """All sub-types' neural meshes stacked: points [M, V, 3], area [M], features [M, V, D]; clutter [K, D]."""

    def __init__(self, subtypes: list[str], points: torch.Tensor, area: torch.Tensor, features: torch.Tensor,
                 clutter: torch.Tensor):
        self.subtypes = list(subtypes)
        self.points, self.area, self.features, self.clutter = points, area, features, clutter

    @classmethod
    def build(cls, subtypes: list[str], vertices: int, dim: int, clutter: int, seed: int) -> "NeuralMeshes":
        pts, areas = zip(*(surface_points(s, vertices) for s in subtypes))
        g = torch.Generator().manual_seed(seed)
        feats = F.normalize(torch.randn(len(subtypes), vertices, dim, generator=g), dim=-1)
        clut = F.normalize(torch.randn(clutter, dim, generator=g), dim=-1)
        return cls(subtypes, torch.tensor(np.stack(pts)), torch.tensor(areas, dtype=torch.float32), feats, clut)

    @property
    def half_heights(self) -> torch.Tensor:
        """[M] half the height of each sub-type's box: the lowest its centre can be (resting on the floor)."""
        return torch.tensor([SUBTYPES[s][1][2] / 2 for s in self.subtypes], dtype=torch.float32)

    @property
    def flying(self) -> torch.Tensor:
        """[M] bool: aeroplanes, the only sub-types whose centre may be anywhere above the floor."""
        return torch.tensor([SUBTYPES[s][0] == "aeroplane" for s in self.subtypes])

    @property
    def vertices(self) -> int:
        return self.points.shape[1]

    def index(self, subtype: str) -> int:
        return self.subtypes.index(subtype)

    @torch.no_grad()
    def momentum_update(self, mesh_idx: torch.Tensor, vertex_idx: torch.Tensor, feats: torch.Tensor,
                        background: torch.Tensor, momentum: float) -> None:
        """Move each observed vertex feature towards the mean of its observations, and each clutter feature towards
        the mean of the background features nearest to it (online k-means), then renormalise."""
        V = self.vertices
        flat = self.features.view(-1, self.features.shape[-1])
        key = mesh_idx * V + vertex_idx
        sums = torch.zeros_like(flat).index_add_(0, key, feats)
        counts = torch.zeros(flat.shape[0]).index_add_(0, key, torch.ones(len(key)))
        seen = counts > 0
        flat[seen] = F.normalize(momentum * flat[seen] + (1 - momentum) * sums[seen] / counts[seen, None], dim=-1)
        if len(background):
            nearest = (background @ self.clutter.T).argmax(1)
            sums = torch.zeros_like(self.clutter).index_add_(0, nearest, background)
            counts = torch.zeros(len(self.clutter)).index_add_(0, nearest, torch.ones(len(nearest)))
            seen = counts > 0
            self.clutter[seen] = F.normalize(
                momentum * self.clutter[seen] + (1 - momentum) * sums[seen] / counts[seen, None], dim=-1)

    def state(self) -> dict:
        return {"subtypes": self.subtypes, "points": self.points, "area": self.area, "features": self.features,
                "clutter": self.clutter}

    @classmethod
    def from_state(cls, s: dict) -> "NeuralMeshes":
        return cls(s["subtypes"], s["points"], s["area"], s["features"], s["clutter"])
