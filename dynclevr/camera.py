"""The pinhole camera of a scene (public generator: ~(8, -7, 3.2) looking at (0, 0, 1.3), 35 mm lens, 32 mm sensor).

World frame: z up, metres. Camera frame (OpenCV): x right, y down, z forward.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass

import numpy as np


@dataclass(frozen=True)
class Camera:
    position: tuple[float, float, float]
    look_at: tuple[float, float, float]
    focal_mm: float
    sensor_width_mm: float
    width: int
    height: int

    @property
    def fx(self) -> float:
        return self.focal_mm / self.sensor_width_mm * self.width

    @property
    def K(self) -> np.ndarray:
        f = self.fx
        return np.array([[f, 0, self.width / 2], [0, f, self.height / 2], [0, 0, 1.0]])

    @property
    def world_to_camera(self) -> np.ndarray:
        """4x4 extrinsics: rows are the camera's right, down and forward axes in world coordinates."""
        eye, target = np.asarray(self.position, float), np.asarray(self.look_at, float)
        fwd = target - eye
        fwd /= np.linalg.norm(fwd)
        right = np.cross(fwd, [0.0, 0.0, 1.0])
        right /= np.linalg.norm(right)
        down = np.cross(fwd, right)
        R = np.stack([right, down, fwd])
        T = np.eye(4)
        T[:3, :3] = R
        T[:3, 3] = -R @ eye
        return T

    def to_camera(self, points: np.ndarray) -> np.ndarray:
        T = self.world_to_camera
        return np.asarray(points, float) @ T[:3, :3].T + T[:3, 3]

    def project(self, points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """World points [..., 3] -> (pixels [..., 2], depth along the optical axis [...])."""
        pc = self.to_camera(points)
        z = pc[..., 2]
        uv = pc[..., :2] / np.maximum(z, 1e-6)[..., None] * self.fx + np.array([self.width / 2, self.height / 2])
        return uv, z

    def with_resolution(self, width: int, height: int) -> "Camera":
        return Camera(self.position, self.look_at, self.focal_mm, self.sensor_width_mm, width, height)

    def to_dict(self) -> dict:
        return asdict(self)

    @classmethod
    def from_dict(cls, d: dict) -> "Camera":
        return cls(tuple(d["position"]), tuple(d["look_at"]), float(d["focal_mm"]), float(d["sensor_width_mm"]),
                   int(d["width"]), int(d["height"]))
