"""The differentiable renderer of vertex features: a point splatter on the stride-8 feature grid.

The paper renders the neural mesh with soft rasterisation and compares the rendered feature map with the CNN's map
pixel by pixel (REFERENCE.md section 2.1). Here each mesh is a set of surface points that each stand for an equal
share of the surface; a visible point contributes its patch's projected area (in feature cells) times the
log-likelihood ratio at its projection. Summed over points this approximates the paper's sum over foreground
pixels, and it is differentiable in the pose through the bilinear sampling of the per-vertex similarity maps.
Visibility (self-occlusion and occlusion between objects) comes from a z-buffer on the feature grid and is held
fixed within one gradient step, as soft rasterisation's hard limit would.
"""

from __future__ import annotations

import numpy as np
import torch
from scipy.spatial.transform import Rotation

from dynclevr.camera import Camera

STRIDE = 8                 # the feature map's stride in pixels (features.FeatureNet)
POSE_DIM = 6               # x, y, z (metres, world), yaw, pitch, roll (radians; R = Rz(yaw) Ry(pitch) Rx(roll))
OCCLUSION_MARGIN = 0.3     # metres behind the nearest surface in a feature cell that still count as visible


def euler_to_quat(euler: np.ndarray) -> np.ndarray:
    """[..., 3] yaw, pitch, roll -> [..., 4] quaternion (x, y, z, w)."""
    e = np.asarray(euler, float)
    return Rotation.from_euler("ZYX", e.reshape(-1, 3)).as_quat().reshape(*e.shape[:-1], 4)


def quat_to_euler(quat: np.ndarray) -> np.ndarray:
    """[..., 4] quaternion (x, y, z, w) -> [..., 3] yaw, pitch, roll."""
    q = np.asarray(quat, float)
    return Rotation.from_quat(q.reshape(-1, 4)).as_euler("ZYX").reshape(*q.shape[:-1], 3)


def rotation(poses: torch.Tensor) -> torch.Tensor:
    """[N, 6] poses -> [N, 3, 3] rotation matrices R = Rz(yaw) Ry(pitch) Rx(roll)."""
    y, p, r = poses[:, 3], poses[:, 4], poses[:, 5]
    cy, sy, cp, sp, cr, sr = y.cos(), y.sin(), p.cos(), p.sin(), r.cos(), r.sin()
    return torch.stack([
        torch.stack([cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr], -1),
        torch.stack([sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr], -1),
        torch.stack([-sp, cp * sr, cp * cr], -1)], -2)


class GridCamera:
    """The scene camera in torch, projecting onto the feature grid (cell units: cell j spans pixels 8j..8j+8)."""

    def __init__(self, camera: Camera, stride: int = STRIDE):
        T = camera.world_to_camera
        self.camera = camera
        self.R = torch.tensor(T[:3, :3], dtype=torch.float32)
        self.t = torch.tensor(T[:3, 3], dtype=torch.float32)
        self.f = camera.fx / stride
        self.cx, self.cy = camera.width / 2 / stride - 0.5, camera.height / 2 / stride - 0.5
        self.W, self.H = camera.width // stride, camera.height // stride
        self.position = torch.tensor(camera.position, dtype=torch.float32)

    def project(self, world: torch.Tensor) -> tuple[torch.Tensor, torch.Tensor]:
        """World points [..., 3] -> (grid coordinates [..., 2] as (column, row), depth [...])."""
        pc = world @ self.R.T + self.t
        z = pc[..., 2].clamp(min=1e-3)
        uv = torch.stack([pc[..., 0] / z * self.f + self.cx, pc[..., 1] / z * self.f + self.cy], -1)
        return uv, pc[..., 2]

    def ray(self, col: float, row: float) -> np.ndarray:
        """The unit world direction through a grid position."""
        d = np.array([(col - self.cx) / self.f, (row - self.cy) / self.f, 1.0])
        w = self.R.numpy().T.astype(float) @ d
        return w / np.linalg.norm(w)


def transform(points: torch.Tensor, poses: torch.Tensor) -> torch.Tensor:
    """Object-frame points [N, V, 3] (or [V, 3] shared) at poses [N, 6] -> world points [N, V, 3]."""
    R = rotation(poses)
    if points.dim() == 2:
        points = points.expand(poses.shape[0], -1, -1)
    return points @ R.transpose(1, 2) + poses[:, None, :3]


def visible(uv: torch.Tensor, depth: torch.Tensor, W: int, H: int, joint: bool) -> torch.Tensor:
    """[N, V] mask of points inside the grid and within OCCLUSION_MARGIN of the nearest surface in their cell.

    joint=True: all N objects share one z-buffer (they are the objects of one frame and occlude each other);
    joint=False: each is a separate hypothesis and only occludes itself."""
    with torch.no_grad():
        N, V = depth.shape
        col, row = uv[..., 0].round().long(), uv[..., 1].round().long()
        inside = (col >= 0) & (col < W) & (row >= 0) & (row < H) & (depth > 0.1)
        cell = row.clamp(0, H - 1) * W + col.clamp(0, W - 1)
        group = torch.zeros_like(cell) if joint else torch.arange(N)[:, None].expand(N, V)
        key = group * (H * W) + cell
        z = torch.where(inside, depth, torch.full_like(depth, float("inf")))
        nearest = torch.full((int(key.max()) + 1,), float("inf")).scatter_reduce(
            0, key.flatten(), z.flatten(), "amin")
        return inside & (depth <= nearest[key] + OCCLUSION_MARGIN)


def cell_area(area: torch.Tensor, depth: torch.Tensor, f: float) -> torch.Tensor:
    """The feature-grid area (cells) that a surface patch of `area` m^2 covers at `depth` m, seen face on.

    Surface patches are not oriented here (the part meshes need not have consistent normals), so the expected
    foreshortening of a random orientation (1/2) stands in for |cos|."""
    return 0.5 * area * (f / depth.clamp(min=0.5)) ** 2


def bilinear(maps: torch.Tensor, rows: torch.Tensor, uv: torch.Tensor, W: int, H: int) -> torch.Tensor:
    """Sample per-point maps: maps [R, H*W], rows [N, V] (which map each point reads), uv [N, V, 2] -> [N, V].

    Differentiable in uv. Points outside the grid read 0 (no evidence either way)."""
    x, y = uv[..., 0], uv[..., 1]
    x0, y0 = x.detach().floor(), y.detach().floor()
    wx, wy = x - x0, y - y0
    xi = x0.long()[..., None] + torch.tensor([0, 1, 0, 1])
    yi = y0.long()[..., None] + torch.tensor([0, 0, 1, 1])
    ok = (xi >= 0) & (xi < W) & (yi >= 0) & (yi < H)
    idx = rows[..., None] * (H * W) + yi.clamp(0, H - 1) * W + xi.clamp(0, W - 1)
    values = maps.reshape(-1)[idx] * ok
    w = torch.stack([(1 - wx) * (1 - wy), wx * (1 - wy), (1 - wx) * wy, wx * wy], -1)
    return (w * values).sum(-1)
