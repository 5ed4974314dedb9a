"""Render-and-compare: the rendering likelihood of poses given a frame's features, and its maximisation with the
physics prior (REFERENCE.md section 2.1-2.2).

log p(F | O_s, pose, B) - log p(F | B everywhere)
    = kappa * sum over foreground cells (f_i . T_s(i) - max_k f_i . B_k + bias)
(the unit-feature form of the paper's Gaussian likelihoods; `bias` is the gap between the foreground and background
Gaussians' log normalisers, which differ when their variances do. It matters: at stride 8 the cells on an object's
outline look half like background, and without it the likelihood prefers an object shrunk inside its outline,
i.e. moved away from the camera). Each frame's similarity of every needed vertex feature
to every cell, minus the clutter score, is computed once (`Evidence`), so one optimisation step only samples it.
The physics prior adds -|pose - PE(previous estimate)|^2 / (2 sigma^2) (paper eq. 4, sigma^2 = 3).

In the optimisation each object's rendering term is divided by its visible foreground area at the starting pose
(a constant per frame), i.e. it is the mean log-likelihood ratio per foreground cell, as NeMo's implementation
normalises its loss; with kappa = 1 that puts the likelihood in cosine units, the scale at which the paper's
sigma^2 = 3 is a prior of useful strength (a 1 m deviation costs as much as 0.17 of mean cosine similarity).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import torch

from dynclevr.perception.neural_mesh import NeuralMeshes
from dynclevr.perception.render import GridCamera, bilinear, cell_area, transform, visible

MAX_TILT = 0.25  # radians: pitch and roll stay small (collisions tip vehicles a little; the pose noise of a
                 # looser limit tilts hulls into the floor and the physics prior then ploughs them)
FLOOR_SLACK = 0.05     # metres a centre may sit below its resting height (a tilted body rests lower)
GROUND_HOP = 0.3       # metres above its resting height that a ground vehicle's centre may reach (tilted in a crash)
GRADIENT_SCALE = 0.2  # Adam's epsilon (mean log-likelihood ratio per cell per metre or radian); see fit()
VISIBILITY_EVERY = 4   # optimisation steps between z-buffer passes (steps move a pose by centimetres)


@dataclass
class Evidence:
    """One frame's per-vertex log-likelihood-ratio maps for a set of sub-types."""

    maps: torch.Tensor          # [B * V, H * W]
    block: torch.Tensor         # mesh index -> block number in maps (-1: not computed)
    W: int
    H: int

    @classmethod
    def compute(cls, feats: torch.Tensor, meshes: NeuralMeshes, mesh_ids: list[int], kappa: float,
                bias: float = 0.0) -> "Evidence":
        """feats [D, H, W] unit features of one frame; bias: the foreground / background log-normaliser gap."""
        D, H, W = feats.shape
        fmap = feats.reshape(D, H * W)
        clutter = (meshes.clutter @ fmap).max(0).values
        sims = meshes.features[mesh_ids].reshape(-1, D) @ fmap
        block = torch.full((len(meshes.subtypes),), -1, dtype=torch.long)
        block[mesh_ids] = torch.arange(len(mesh_ids))
        return cls(kappa * (sims - clutter + bias), block, W, H)


def score(poses: torch.Tensor, mesh_idx: torch.Tensor, ev: Evidence, meshes: NeuralMeshes, cam: GridCamera,
          joint: bool, weight: torch.Tensor | None = None) -> tuple[torch.Tensor, torch.Tensor]:
    """Per pose: (log-likelihood ratio, visible foreground area in cells). joint: the poses are the objects of one
    frame and occlude each other; otherwise independent hypotheses. `weight`: the points' visible areas [N, V]
    from `weights()` at a nearby pose (visibility is held fixed over a few steps); None computes them here."""
    V = meshes.vertices
    world = transform(meshes.points[mesh_idx], poses)
    uv, depth = cam.project(world)
    if weight is None:
        weight = _weights(uv, depth, mesh_idx, ev, meshes, cam, joint)
    rows = ev.block[mesh_idx][:, None] * V + torch.arange(V)
    ll = bilinear(ev.maps, rows, uv, ev.W, ev.H)
    return (weight * ll).sum(1), weight.sum(1)


def _weights(uv, depth, mesh_idx, ev: Evidence, meshes: NeuralMeshes, cam: GridCamera, joint: bool) -> torch.Tensor:
    vis = visible(uv, depth, ev.W, ev.H, joint)
    return (cell_area(meshes.area[mesh_idx][:, None], depth, cam.f) * vis).detach()


@torch.no_grad()
def weights(poses: torch.Tensor, mesh_idx: torch.Tensor, ev: Evidence, meshes: NeuralMeshes, cam: GridCamera,
            joint: bool) -> torch.Tensor:
    uv, depth = cam.project(transform(meshes.points[mesh_idx], poses))
    return _weights(uv, depth, mesh_idx, ev, meshes, cam, joint)


def wrap(angle: torch.Tensor) -> torch.Tensor:
    return torch.remainder(angle + math.pi, 2 * math.pi) - math.pi


def fit(poses: torch.Tensor, mesh_idx: torch.Tensor, ev: Evidence, meshes: NeuralMeshes, cam: GridCamera,
        iterations: int, lr: float, joint: bool, prior_mean: torch.Tensor | None = None,
        sigma2: float = 3.0) -> tuple[torch.Tensor, torch.Tensor, torch.Tensor]:
    """Maximise likelihood (x prior) by Adam from `poses` [N, 6]; returns (poses, log-likelihood ratio, area)."""
    # Adam written out: torch.optim's first use imports torch._dynamo (seconds), and a few lines do. Its epsilon
    # is GRADIENT_SCALE rather than ~0: plain Adam takes full steps along directions where the likelihood is flat
    # (the distance to the camera of a thin aeroplane), a random walk that the velocity estimate then reads as
    # motion; with it, steps shrink in proportion where the gradient is small.
    p = poses.detach().clone().requires_grad_(True)
    m, v = torch.zeros_like(p), torch.zeros_like(p)
    b1, b2 = 0.9, 0.999
    norm = None
    # nothing sinks into the floor, and only aeroplanes leave it (a vehicle hit hard may hop a little)
    floor = meshes.half_heights[mesh_idx] - FLOOR_SLACK
    ceiling = torch.where(meshes.flying[mesh_idx], torch.tensor(float("inf")), floor + GROUND_HOP)
    for i in range(iterations):
        if i % VISIBILITY_EVERY == 0:
            w = weights(p, mesh_idx, ev, meshes, cam, joint)
        ll, area = score(p, mesh_idx, ev, meshes, cam, joint, w)
        if norm is None:
            norm = area.clamp(min=1.0)
        loss = -(ll / norm).sum()
        if prior_mean is not None:
            d = p - prior_mean
            d = torch.cat([d[:, :3], wrap(d[:, 3:])], 1)
            loss = loss + (d ** 2).sum() / (2 * sigma2)
        g, = torch.autograd.grad(loss, p)
        with torch.no_grad():
            m.mul_(b1).add_(g, alpha=1 - b1)
            v.mul_(b2).addcmul_(g, g, value=1 - b2)
            step = lr * (1.0 - i / iterations) / (1 - b1 ** (i + 1))
            p -= step * m / ((v / (1 - b2 ** (i + 1))).sqrt() + GRADIENT_SCALE)
            p[:, 4:].clamp_(-MAX_TILT, MAX_TILT)
            p[:, 2] = torch.minimum(torch.maximum(p[:, 2], floor), ceiling)
            p[:, 3] = wrap(p[:, 3])
    with torch.no_grad():
        ll, area = score(p, mesh_idx, ev, meshes, cam, joint)
    return p.detach(), ll, area
