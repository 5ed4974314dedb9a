"""The detection head (CenterNet-style, plain torch): every object's first estimate in every frame.

A small encoder (stride 16, dilated at the coarsest level for ~200 px of context) and a decoder back to stride 4
with skips give, per cell of a 80x60 map (320x240 frames):
- an object-centre heatmap (the projected 3D centre; for an object partly out of view, the nearest cell inside);
- the offset from the cell to that centre, pixels / STRIDE (so out-of-view centres are reachable);
- sub-type logits (21) and colour logits (8);
- the yaw relative to the camera ray, as (sin, cos): a 180-degree flip is a wrong sign, learnable, not a tie;
- log distance from the camera to the centre, and the centre's height above the ground.
`decode` turns the maps of one frame into Detections (peaks above a threshold, with their head values).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import torch
from torch import nn
from torch.nn import functional as F

from dynclevr.assets.catalogue import SUBTYPES
from dynclevr.colors import COLOR_NAMES

STRIDE = 4
N_SUB, N_COL = len(SUBTYPES), len(COLOR_NAMES)
# output channels: heat, offset (2), sub-type, colour, sin/cos alpha, log distance, height
CHANNELS = {"heat": slice(0, 1), "offset": slice(1, 3), "subtype": slice(3, 3 + N_SUB),
            "color": slice(3 + N_SUB, 3 + N_SUB + N_COL), "alpha": slice(3 + N_SUB + N_COL, 5 + N_SUB + N_COL),
            "logdist": slice(5 + N_SUB + N_COL, 6 + N_SUB + N_COL),
            "height": slice(6 + N_SUB + N_COL, 7 + N_SUB + N_COL)}
OUT = 7 + N_SUB + N_COL
MEAN = torch.tensor([0.45, 0.45, 0.45]).view(1, 3, 1, 1)
STD = torch.tensor([0.25, 0.25, 0.25]).view(1, 3, 1, 1)


def _conv(cin: int, cout: int, stride: int = 1, dilation: int = 1, k: int = 3) -> nn.Sequential:
    return nn.Sequential(nn.Conv2d(cin, cout, k, stride, padding=dilation * (k // 2), dilation=dilation, bias=False),
                         nn.BatchNorm2d(cout), nn.ReLU(inplace=True))


class Residual(nn.Module):
    """Two convolutions added to their input. The second's BatchNorm scale starts at zero, so a block appended to a
    trained head leaves its function as it was (`DetectNet(blocks=...)` grows a head without starting over)."""

    def __init__(self, c: int, dilation: int = 1):
        super().__init__()
        self.a = _conv(c, c, dilation=dilation)
        self.b = nn.Sequential(nn.Conv2d(c, c, 3, padding=1, bias=False), nn.BatchNorm2d(c))
        nn.init.zeros_(self.b[1].weight)

    def forward(self, x: torch.Tensor) -> torch.Tensor:
        return F.relu(x + self.b(self.a(x)))


class DetectNet(nn.Module):
    """`blocks`: residual blocks appended at strides 8 and 16 each, where depth is cheap (a 40x30 and a 20x15 map).
    `fine_blocks`: residual blocks at stride 4 before the head, where the centre offset, the yaw and the distance are
    read (a 80x60 map, each block about a third of the head's cost)."""

    def __init__(self, width: int = 32, blocks: int = 0, fine_blocks: int = 0):
        super().__init__()
        w = width
        self.width, self.blocks, self.fine_blocks = width, blocks, fine_blocks
        # pixels added to every decoded centre (the manifest's `pixel_offset`): a head trained on frames whose
        # vehicles lay off their labels reads them off by as much (detector_train.load_detector)
        self.pixel_offset = (0.0, 0.0)
        self.s2 = _conv(3, w // 2, 2, k=5)                                        # 160x120
        self.s4 = nn.Sequential(_conv(w // 2, w, 2), _conv(w, w))                # 80x60
        self.s8 = nn.Sequential(_conv(w, 2 * w, 2), _conv(2 * w, 2 * w),         # 40x30
                                *[Residual(2 * w) for _ in range(blocks)])
        self.s16 = nn.Sequential(_conv(2 * w, 3 * w, 2), _conv(3 * w, 3 * w, dilation=2),
                                 _conv(3 * w, 3 * w, dilation=4), _conv(3 * w, 3 * w),   # 20x15
                                 *[Residual(3 * w, dilation=2 - k % 2) for k in range(blocks)])
        self.up8 = _conv(3 * w + 2 * w, 2 * w)
        self.up4 = _conv(2 * w + w, 3 * w // 2)
        self.fine = nn.Sequential(*[Residual(3 * w // 2) for _ in range(fine_blocks)])
        self.head = nn.Sequential(_conv(3 * w // 2, 3 * w // 2), nn.Conv2d(3 * w // 2, OUT, 1))
        with torch.no_grad():
            self.head[-1].bias.zero_()
            self.head[-1].bias[0] = -4.0             # "no object" everywhere at first (focal-loss practice)
            self.head[-1].bias[CHANNELS["logdist"]] = float(np.log(11.0))
            self.head[-1].bias[CHANNELS["height"]] = 0.8

    def forward(self, images: torch.Tensor) -> torch.Tensor:
        """images [B, 3, H, W] in [0, 1] (H, W multiples of 16) -> maps [B, OUT, H/4, W/4]."""
        x4 = self.s4(self.s2((images - MEAN.to(images.device)) / STD.to(images.device)))
        x8 = self.s8(x4)
        x16 = self.s16(x8)
        y8 = self.up8(torch.cat([F.interpolate(x16, size=x8.shape[-2:], mode="bilinear", align_corners=False), x8], 1))
        y4 = self.up4(torch.cat([F.interpolate(y8, size=x4.shape[-2:], mode="bilinear", align_corners=False), x4], 1))
        return self.head(self.fine(y4))


def widened(net: DetectNet, width: int, generator: torch.Generator, noise: float = 0.01) -> DetectNet:
    """A head of `width` (same blocks) that computes what `net` does (Net2WiderNet): every new channel copies an old
    one of its stage, and the layers reading a copied channel share its weight among its copies. Copies would learn
    alike (Adam scales their equal gradients alike), so their incoming weights get Gaussian noise of `noise` times
    the layer's weight spread; with `noise` 0 the function is exactly the old one's."""
    if width < net.width or width % 2:
        raise ValueError(f"a head of width {net.width} widens only to a larger even width, not {width}")
    new = DetectNet(width, net.blocks, net.fine_blocks)
    w, w2 = net.width, width
    sizes = {"A": (w // 2, w2 // 2), "B": (w, w2), "C": (2 * w, 2 * w2), "D": (3 * w, 3 * w2),
             "E": (3 * w // 2, 3 * w2 // 2)}
    pick = {k: torch.cat([torch.arange(n), torch.randint(0, n, (n2 - n,), generator=generator)])
            for k, (n, n2) in sizes.items()}
    pick["rgb"], pick["out"] = torch.arange(3), torch.arange(OUT)
    share = {k: 1.0 / torch.bincount(g)[g].float() for k, g in pick.items()}

    def joined(*keys):           # a concatenation's channels: each part's copies, offset by the parts before it
        offsets = np.cumsum([0] + [sizes[k][0] for k in keys[:-1]])
        return (torch.cat([pick[k] + int(o) for k, o in zip(keys, offsets)]), torch.cat([share[k] for k in keys]))

    @torch.no_grad()
    def conv(old: nn.Conv2d, fresh: nn.Conv2d, into, out: str) -> None:
        g_in, s_in = into if isinstance(into, tuple) else (pick[into], share[into])
        g_out = pick[out]
        weight = old.weight[g_out][:, g_in] * s_in.view(1, -1, 1, 1)
        copies = torch.arange(len(g_out)) >= old.out_channels
        weight[copies] += noise * float(old.weight.std()) * torch.randn(weight[copies].shape, generator=generator)
        fresh.weight.copy_(weight)
        if old.bias is not None:
            fresh.bias.copy_(old.bias[g_out])

    @torch.no_grad()
    def norm(old: nn.BatchNorm2d, fresh: nn.BatchNorm2d, out: str) -> None:
        for name in ("weight", "bias", "running_mean", "running_var"):
            getattr(fresh, name).copy_(getattr(old, name)[pick[out]])

    def unit(old: nn.Sequential, fresh: nn.Sequential, into, out: str) -> None:     # _conv: conv, norm, relu
        conv(old[0], fresh[0], into, out)
        norm(old[1], fresh[1], out)

    def residual(old: Residual, fresh: Residual, space: str) -> None:
        unit(old.a, fresh.a, space, space)
        unit(old.b, fresh.b, space, space)

    def stage(old: nn.Sequential, fresh: nn.Sequential, into: str, out: str) -> None:
        for k, (a, b) in enumerate(zip(old, fresh)):
            residual(a, b, out) if isinstance(a, Residual) else unit(a, b, into if k == 0 else out, out)

    unit(net.s2, new.s2, "rgb", "A")
    stage(net.s4, new.s4, "A", "B")
    stage(net.s8, new.s8, "B", "C")
    stage(net.s16, new.s16, "C", "D")
    unit(net.up8, new.up8, joined("D", "C"), "C")
    unit(net.up4, new.up4, joined("C", "B"), "E")
    stage(net.fine, new.fine, "E", "E")
    unit(net.head[0], new.head[0], "E", "E")
    conv(net.head[1], new.head[1], "E", "out")
    return new


def to_tensor(frames: np.ndarray) -> torch.Tensor:
    """uint8 frames [T, H, W, 3] -> float [T, 3, H, W] in [0, 1]."""
    return torch.from_numpy(np.ascontiguousarray(frames)).permute(0, 3, 1, 2).float().div_(255.0)


@torch.no_grad()
def run(net: DetectNet, frames: np.ndarray, batch: int = 8, flip: bool = False) -> torch.Tensor:
    """The head's maps for a whole video [T, OUT, H/4, W/4] (on the CPU, wherever the head runs). `flip`: the
    mean with the maps of the mirrored frames, mirrored back (the head trained on mirrored frames too; on its
    held-out frames precision 0.89 -> 0.92, sub-type 0.86 -> 0.88, yaw 6.3 -> 5.3 deg, distance 0.26 -> 0.24 m,
    for twice the arithmetic). Channels-last and batches of 8 run 1.4 times faster on the CPU."""
    net.eval()
    dev = next(net.parameters()).device
    net = net.to(memory_format=torch.channels_last)
    out = []
    for i in range(0, len(frames), batch):
        x = to_tensor(frames[i:i + batch]).to(dev).contiguous(memory_format=torch.channels_last)
        maps = net(x)
        if flip:
            maps = (maps + mirror(net(x.flip(-1)))) / 2
        out.append(maps.cpu())
    return torch.cat(out).contiguous()


def mirror(maps: torch.Tensor) -> torch.Tensor:
    """Maps [B, OUT, h, w] of mirrored frames as maps of the frames: the cells mirrored, the offset across and the
    relative yaw's sine negated (u -> W - u, alpha -> -alpha, as detector_train.augment mirrors the labels)."""
    maps = maps.flip(-1)
    sign = torch.ones(OUT, dtype=maps.dtype, device=maps.device)
    sign[CHANNELS["offset"].start] = sign[CHANNELS["alpha"].start] = -1.0
    return maps * sign.view(1, OUT, 1, 1)


@dataclass
class Detection:
    u: float                 # projected centre, pixels
    v: float
    score: float             # heatmap probability
    subtype_logp: np.ndarray  # [N_SUB]
    color_logp: np.ndarray    # [N_COL]
    alpha: float             # yaw relative to the ray's azimuth, radians
    dist: float              # camera to centre, metres
    height: float            # centre z, metres


def decode(maps: torch.Tensor, threshold: float, limit: int = 20, window: int = 5,
           offset: tuple[float, float] = (0.0, 0.0)) -> list[Detection]:
    """One frame's maps [OUT, h, w] -> detections at the heatmap's local maxima above `threshold`, their centres
    moved by `offset` pixels (DetectNet.pixel_offset)."""
    prob = torch.sigmoid(maps[0])
    is_max = prob == F.max_pool2d(prob[None, None], window, 1, window // 2)[0, 0]
    rows, cols = torch.nonzero(is_max & (prob > threshold), as_tuple=True)
    order = prob[rows, cols].argsort(descending=True)[:limit]
    sub = F.log_softmax(maps[CHANNELS["subtype"]], 0)
    col = F.log_softmax(maps[CHANNELS["color"]], 0)
    out = []
    for k in order.tolist():
        r, c = int(rows[k]), int(cols[k])
        off = maps[CHANNELS["offset"], r, c]
        sa, ca = maps[CHANNELS["alpha"], r, c].tolist()
        out.append(Detection(u=(c + 0.5 + float(off[0])) * STRIDE + offset[0],
                             v=(r + 0.5 + float(off[1])) * STRIDE + offset[1],
                             score=float(prob[r, c]), subtype_logp=sub[:, r, c].numpy().copy(),
                             color_logp=col[:, r, c].numpy().copy(), alpha=float(np.arctan2(sa, ca)),
                             dist=math.exp(float(maps[CHANNELS["logdist"], r, c])),
                             height=float(maps[CHANNELS["height"], r, c])))
    return out
