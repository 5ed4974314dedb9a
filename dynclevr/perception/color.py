"""The colour classifier (paper: "we crop the object's region from the RGB image and train a CNN classifier").

The crop is the box of the object's mesh projected at its pose (estimated at inference, true in training, with
jitter so the classifier tolerates pose error). 8 classes: dynclevr.colors.COLOR_NAMES.
"""

from __future__ import annotations

import cv2
import numpy as np
import torch
from torch import nn

from dynclevr.camera import Camera
from dynclevr.colors import COLOR_NAMES

CROP = 32


class ColorNet(nn.Module):
    def __init__(self):
        super().__init__()
        self.net = nn.Sequential(
            nn.Conv2d(3, 16, 3, 2, 1), nn.ReLU(), nn.Conv2d(16, 32, 3, 2, 1), nn.ReLU(),
            nn.Conv2d(32, 48, 3, 2, 1), nn.ReLU(), nn.AdaptiveAvgPool2d(1), nn.Flatten(),
            nn.Linear(48, len(COLOR_NAMES)))

    def forward(self, crops: torch.Tensor) -> torch.Tensor:
        """crops [B, 3, 32, 32] in [0, 1] -> logits [B, 8]."""
        return self.net(crops - 0.5)


def box(camera: Camera, world_points: np.ndarray, margin: float = 0.1) -> tuple[int, int, int, int] | None:
    """The pixel box (x0, y0, x1, y1) of projected points, clipped to the image; None if nothing is in view."""
    uv, z = camera.project(world_points)
    uv = uv[z > 0.1]
    if len(uv) == 0:
        return None
    lo, hi = uv.min(0), uv.max(0)
    pad = (hi - lo) * margin
    x0, y0 = np.floor(np.maximum(lo - pad, 0)).astype(int)
    x1, y1 = np.ceil(np.minimum(hi + pad, [camera.width, camera.height])).astype(int)
    if x1 - x0 < 2 or y1 - y0 < 2:
        return None
    return int(x0), int(y0), int(x1), int(y1)


def crop(frame: np.ndarray, b: tuple[int, int, int, int]) -> np.ndarray:
    """uint8 [H, W, 3] frame, box -> float32 [3, 32, 32] in [0, 1]."""
    x0, y0, x1, y1 = b
    patch = cv2.resize(frame[y0:y1, x0:x1], (CROP, CROP), interpolation=cv2.INTER_AREA)
    return patch.transpose(2, 0, 1).astype(np.float32) / 255.0
