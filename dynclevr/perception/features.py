"""The CNN feature extractor Phi (paper: a ResNet; here a small plain-torch CNN that runs on CPU).

Stride 8: a 320x240 frame gives a 40x30 map of unit feature vectors (the neural meshes' feature space). Dilated
convolutions at the coarse level give each cell about 150 pixels of context, enough to tell the front of a vehicle
from its back. Two small heads share the trunk and give the object proposals: an object-centre heatmap and the
log distance from the camera to the centre (CenterNet style), trained on the truth like the features themselves.
"""

from __future__ import annotations

import numpy as np
import torch
from torch import nn
from torch.nn import functional as F

from dynclevr.perception.render import STRIDE

MEAN = torch.tensor([0.45, 0.45, 0.45]).view(1, 3, 1, 1)
STD = torch.tensor([0.25, 0.25, 0.25]).view(1, 3, 1, 1)


def _block(cin: int, cout: int, stride: int = 1, dilation: int = 1, k: int = 3) -> nn.Sequential:
    return nn.Sequential(nn.Conv2d(cin, cout, k, stride, padding=dilation * (k // 2), dilation=dilation, bias=False),
                         nn.GroupNorm(8, cout), nn.ReLU(inplace=True))


class FeatureNet(nn.Module):
    def __init__(self, dim: int, width: int = 64):
        super().__init__()
        assert STRIDE == 8
        self.trunk = nn.Sequential(
            _block(3, 32, 2, k=5), _block(32, 48, 2), _block(48, width, 2),
            _block(width, width, dilation=2), _block(width, width, dilation=4), _block(width, width))
        self.feature = nn.Conv2d(width, dim, 1)
        self.heads = nn.Conv2d(width, 2, 1)       # centre heatmap logit, log distance (metres)
        nn.init.constant_(self.heads.bias, 0.0)
        with torch.no_grad():
            self.heads.bias[0] = -4.0             # start with "no object" everywhere (focal loss practice)
            self.heads.bias[1] = float(np.log(12.0))

    def forward(self, images: torch.Tensor) -> tuple[torch.Tensor, torch.Tensor, torch.Tensor]:
        """images [B, 3, H, W] in [0, 1] -> (unit features [B, D, H/8, W/8], heat logits [B, H/8, W/8],
        log distance [B, H/8, W/8])."""
        h = self.trunk((images - MEAN) / STD)
        heads = self.heads(h)
        return F.normalize(self.feature(h), dim=1), heads[:, 0], heads[:, 1]


def to_tensor(frames: np.ndarray) -> torch.Tensor:
    """uint8 frames [T, H, W, 3] -> float [T, 3, H, W] in [0, 1]."""
    return torch.from_numpy(np.ascontiguousarray(frames)).permute(0, 3, 1, 2).float().div_(255.0)


@torch.no_grad()
def extract(net: FeatureNet, frames: np.ndarray, batch: int = 16) -> tuple[torch.Tensor, torch.Tensor, torch.Tensor]:
    """Run the CNN over a video in batches (inference)."""
    net.eval()
    outs = [net(to_tensor(frames[i:i + batch])) for i in range(0, len(frames), batch)]
    return tuple(torch.cat(o) for o in zip(*outs))
