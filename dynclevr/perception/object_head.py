"""The object head: a second look at every detection, over the whole object at one scale (two-stage detection, as a
Faster R-CNN box head refines its proposals from the features of their region).

The detection head answers from the features at its heatmap's peak cell, and its centres carry per-vehicle biases
of about 2 px that drift as a vehicle turns and nears; for a ground vehicle 1 px is about 7 cm along the camera
ray, the scale of the position goal. The object head samples the detection head's own last features (stride 4,
frozen) on a ROI x ROI grid over a window SPAN metres wide at the detection's distance (fx * SPAN / dist pixels),
so every vehicle fills the grid alike whatever its distance, and answers for the object at the window's centre: the
offset of its projected 3D centre (window pixels, the window being SIZE of them across), the log ratio of its true
distance to the window's, sub-type and colour logits, the yaw relative to the camera ray as (sin, cos), and the
centre's height. `refine` runs it as a cascade: the second window is centred on the first's answer.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import torch
from torch import nn
from torch.nn import functional as F

from dynclevr.perception.detector import N_COL, N_SUB, STRIDE, Detection, _conv, decode, run

SPAN = 4.0          # metres across the window (a bus side-on overhangs it a little; its centre is what counts)
SIZE = 64           # window pixels: the unit of the offsets
ROI = 32            # feature samples across the window (about one per feature cell at 11 m)
CHANNELS = {"offset": slice(0, 2), "logratio": slice(2, 3), "subtype": slice(3, 3 + N_SUB),
            "color": slice(3 + N_SUB, 3 + N_SUB + N_COL), "alpha": slice(3 + N_SUB + N_COL, 5 + N_SUB + N_COL),
            "height": slice(5 + N_SUB + N_COL, 6 + N_SUB + N_COL)}
OUT = 6 + N_SUB + N_COL


class ObjectNet(nn.Module):
    """[B, features, ROI, ROI] -> [B, OUT]: three stride-2 stages to 4x4 cells, then two linear layers (the offset
    needs where things are in the window, which global pooling would throw away)."""

    def __init__(self, features: int = 48, width: int = 48):
        super().__init__()
        w = self.width = width
        self.features = features
        self.body = nn.Sequential(
            _conv(features, w, 2), _conv(w, 4 * w // 3),                  # 16x16
            _conv(4 * w // 3, 2 * w, 2), _conv(2 * w, 2 * w),              # 8x8
            _conv(2 * w, 8 * w // 3, 2))                                  # 4x4
        self.out = nn.Sequential(nn.Flatten(), nn.Linear(8 * w // 3 * (ROI // 8) ** 2, 256), nn.ReLU(inplace=True),
                                 nn.Linear(256, OUT))

    def forward(self, roi: torch.Tensor) -> torch.Tensor:
        return self.out(self.body(roi))


def window_scale(fx: float, dist: float) -> float:
    """Window pixels per frame pixel at this distance."""
    return SIZE / (fx * SPAN / max(dist, 0.5))


def roi_grid(u: np.ndarray, v: np.ndarray, scale: np.ndarray, width: int, height: int) -> torch.Tensor:
    """grid_sample's grid [B, ROI, ROI, 2] of the windows centred on (u, v) (frame pixels, pixel k's centre at
    k + 0.5) at `scale`, over a feature map that covers the width x height frame."""
    step = (SIZE / np.asarray(scale, np.float64)) / ROI                     # frame pixels between samples
    k = np.arange(ROI) + 0.5 - ROI / 2
    xs = np.asarray(u, np.float64)[:, None] + step[:, None] * k[None]       # [B, ROI]
    ys = np.asarray(v, np.float64)[:, None] + step[:, None] * k[None]
    gx = np.broadcast_to((2 * xs / width - 1)[:, None, :], (len(xs), ROI, ROI))
    gy = np.broadcast_to((2 * ys / height - 1)[:, :, None], (len(ys), ROI, ROI))
    return torch.from_numpy(np.stack([gx, gy], -1).astype(np.float32))


def sample(hidden: torch.Tensor, index: np.ndarray, grid: torch.Tensor) -> torch.Tensor:
    """The ROI x ROI features of each window: hidden [T, C, h, w], index [B] (frame of each window)."""
    return F.grid_sample(hidden[torch.as_tensor(index)].float(), grid, mode="bilinear", padding_mode="zeros",
                         align_corners=False)


@torch.no_grad()
def refine(net: ObjectNet, hidden: torch.Tensor, detections: list[list[Detection]], fx: float,
           passes: int = 2, batch: int = 256) -> list[list[Detection]]:
    """Every detection's centre, distance, sub-type, colour, yaw and height from the object head (`passes` windows,
    each centred on the last answer); the heatmap's score stays the detection's. hidden: the detection head's
    features of the same frames [T, C, h, w]."""
    net.eval()
    flat = [(t, d) for t, dets in enumerate(detections) for d in dets]
    if not flat:
        return [list(d) for d in detections]
    width, height = hidden.shape[-1] * STRIDE, hidden.shape[-2] * STRIDE
    index = np.array([t for t, _ in flat])
    u = np.array([d.u for _, d in flat])
    v = np.array([d.v for _, d in flat])
    dist = np.array([d.dist for _, d in flat])
    outs = None
    for _ in range(passes):
        scale = SIZE / (fx * SPAN / np.maximum(dist, 0.5))
        grid = roi_grid(u, v, scale, width, height)
        outs = torch.cat([net(sample(hidden, index[i:i + batch], grid[i:i + batch]))
                          for i in range(0, len(flat), batch)])
        off = outs[:, CHANNELS["offset"]].numpy().astype(np.float64)
        u, v = u + off[:, 0] / scale, v + off[:, 1] / scale
        dist = dist * np.exp(outs[:, CHANNELS["logratio"]][:, 0].numpy().astype(np.float64))
    sub = F.log_softmax(outs[:, CHANNELS["subtype"]], 1).numpy()
    col = F.log_softmax(outs[:, CHANNELS["color"]], 1).numpy()
    alpha = outs[:, CHANNELS["alpha"]].numpy()
    h = outs[:, CHANNELS["height"]][:, 0].numpy()
    out: list[list[Detection]] = [[] for _ in detections]
    for k, (t, d) in enumerate(flat):
        out[t].append(replace(d, u=float(u[k]), v=float(v[k]), dist=float(dist[k]), subtype_logp=sub[k].copy(),
                              color_logp=col[k].copy(), alpha=float(math.atan2(alpha[k, 0], alpha[k, 1])),
                              height=float(h[k])))
    return out


class TwoStage:
    """Detection as the parser runs it: the detection head's peaks, then (with an object head) the second look."""

    def __init__(self, head, objects: ObjectNet | None = None, passes: int = 2):
        self.head, self.objects, self.passes = head, objects, passes

    def __call__(self, frames: np.ndarray, fx: float, threshold: float, limit: int) -> list[list[Detection]]:
        if self.objects is None:
            return [decode(m, threshold, limit) for m in run(self.head, frames)]
        maps, hidden = run(self.head, frames, hidden=True)
        return refine(self.objects, hidden, [decode(m, threshold, limit) for m in maps], fx, self.passes)
