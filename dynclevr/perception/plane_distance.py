"""An aeroplane's distance read again from its own pixels: the detection head's second stage for what flies.

A standing ground vehicle's distance comes from the ground plane (place.py); a flying plane's is the head's alone,
read at one cell of a stride-4 map, and off by a share of its own that holds over the flight (about 2.5% of a
detection's distance at the median: 0.3 m along the ray at 12 m, most of issue 10's position tail). The catalogue
gives each plane's size, so its apparent size tells its distance. A crop of the frame centred on the detection is
scaled so that the plane would fill it as it does at the head's distance (half side MARGIN times the plane's
projected half length); a plane drawn larger than that is nearer. A small CNN reads the log of the correction from
the crop and the head's own values (plane_distance_train.py trains it on fresh frames, never val or test).
"""

from __future__ import annotations

import json
import math
from dataclasses import replace
from pathlib import Path

import cv2
import numpy as np
import torch
from torch import nn

from dynclevr import WEIGHTS_DIR, DynclevrError
from dynclevr.artifacts import file_digest
from dynclevr.assets.catalogue import SUBTYPES
from dynclevr.camera import Camera
from dynclevr.perception.detector import Detection
from dynclevr.perception.place import IS_PLANE, detection_shape

DEFAULT_DIR = WEIGHTS_DIR / "plane_distance"
WEIGHTS_FILE, MANIFEST = "plane_distance.pt", "manifest.json"
CROP = 64          # pixels a side
MARGIN = 1.3       # the crop's half side in the plane's projected half lengths (at the head's distance)
N_FEATURES = 7 + int(IS_PLANE.sum())
SCALE = 0.1        # the output's scale: corrections are a few per cent


class PlaneDistanceWeightsError(DynclevrError):
    pass


def is_plane(det: Detection) -> bool:
    return SUBTYPES[detection_shape(det)][0] == "aeroplane"


def half_side(camera: Camera, det: Detection) -> float:
    """The crop's half side, pixels: MARGIN x the detected plane's half length projected at the head's distance."""
    return MARGIN * camera.fx * SUBTYPES[detection_shape(det)][1][0] / 2 / max(det.dist, 0.5)


def crop(frame: np.ndarray, u: float, v: float, half: float) -> np.ndarray:
    """uint8 [CROP, CROP, 3]: the square of half side `half` around (u, v), resampled (blurred first where it
    shrinks, so that no pixel aliases); outside the frame black."""
    scale = CROP / (2 * half)
    if scale < 1:
        frame = cv2.GaussianBlur(frame, (0, 0), 0.5 / scale)
    m = np.array([[scale, 0, CROP / 2 - scale * u], [0, scale, CROP / 2 - scale * v]], np.float32)
    return cv2.warpAffine(frame, m, (CROP, CROP), flags=cv2.INTER_LINEAR, borderMode=cv2.BORDER_CONSTANT)


def features(camera: Camera, det: Detection) -> np.ndarray:
    """The head's own values beside the crop: its log distance, the crop's size, where the centre lies in the
    image, its height and relative yaw, and its beliefs among the planes."""
    probs = np.exp(det.subtype_logp)[IS_PLANE]
    return np.concatenate([[math.log(max(det.dist, 0.5)) - 2.4, half_side(camera, det) / 100.0,
                            det.u / camera.width - 0.5, det.v / camera.height - 0.5, det.height / 3.0,
                            math.sin(det.alpha), math.cos(det.alpha)], probs / max(probs.sum(), 1e-6)]).astype(np.float32)


def _conv(cin: int, cout: int, stride: int = 1) -> nn.Sequential:
    return nn.Sequential(nn.Conv2d(cin, cout, 3, stride, 1, bias=False), nn.BatchNorm2d(cout), nn.ReLU(inplace=True))


class PlaneDistanceNet(nn.Module):
    """Crop [B, 3, 64, 64] (normalised as the head's input) and features [B, N_FEATURES] -> log correction [B]. The
    4x4 map is kept whole, not pooled: where the plane's nose and wings lie in the crop is its apparent size."""

    def __init__(self):
        super().__init__()
        self.cnn = nn.Sequential(_conv(3, 32), _conv(32, 32, 2), _conv(32, 64), _conv(64, 64, 2), _conv(64, 96, 2),
                                 _conv(96, 128, 2), _conv(128, 128))
        self.mlp = nn.Sequential(nn.Linear(128 * 16 + N_FEATURES, 128), nn.ReLU(inplace=True), nn.Linear(128, 1))

    def forward(self, crops: torch.Tensor, feats: torch.Tensor) -> torch.Tensor:
        return self.mlp(torch.cat([self.cnn(crops).flatten(1), feats], 1))[:, 0] * SCALE


def to_input(crops: np.ndarray) -> torch.Tensor:
    return (torch.from_numpy(np.ascontiguousarray(crops)).permute(0, 3, 1, 2).float() / 255.0 - 0.45) / 0.25


@torch.no_grad()
def refine(net: PlaneDistanceNet, frames: np.ndarray, detections: list[list[Detection]],
           camera: Camera) -> list[list[Detection]]:
    """The detections with every plane's distance read again from its crop; the others as they were."""
    net.eval()
    where = [(t, k) for t, frame in enumerate(detections) for k, d in enumerate(frame) if is_plane(d)]
    if not where:
        return detections
    dets = [detections[t][k] for t, k in where]
    crops = np.stack([crop(frames[t], d.u, d.v, half_side(camera, d)) for (t, _), d in zip(where, dets)])
    feats = torch.from_numpy(np.stack([features(camera, d) for d in dets]))
    log_correction = torch.cat([net(to_input(crops[i:i + 256]), feats[i:i + 256])
                                for i in range(0, len(dets), 256)]).numpy()
    out = [list(frame) for frame in detections]
    for (t, k), d, c in zip(where, dets, log_correction.tolist()):
        out[t][k] = replace(d, dist=d.dist * math.exp(c))
    return out


def load_plane_distance(weights_dir: Path = DEFAULT_DIR) -> PlaneDistanceNet:
    path, manifest = Path(weights_dir) / WEIGHTS_FILE, Path(weights_dir) / MANIFEST
    if not path.exists() or not manifest.exists():
        raise PlaneDistanceWeightsError(f"plane distance weights missing in {weights_dir}: run "
                                        "`dynclevr train plane-distance`, or set parser.plane_distance = false")
    if json.loads(manifest.read_text()).get("weights_sha256") != file_digest(path):
        raise PlaneDistanceWeightsError(f"{path} does not match its manifest: rerun `dynclevr train plane-distance`")
    net = PlaneDistanceNet()
    net.load_state_dict(torch.load(path, weights_only=True, map_location="cpu")["net"])
    return net.eval()


def plane_distance_digest(weights_dir: Path = DEFAULT_DIR) -> str:
    path = Path(weights_dir) / MANIFEST
    return file_digest(path) if path.exists() else "missing"
