"""Object proposals and identity from the model itself (no ground truth anywhere).

1. The CNN's centre heatmap gives peaks. On each peak's camera ray, a ground vehicle's centre is where the ray
   meets the plane at the sub-type's half height; an aeroplane's is at the distance the CNN's distance head gives.
2. Every sub-type's neural mesh is scored there over a coarse grid of headings (render-and-compare, each hypothesis
   alone); the best heading of each of the `detect_subtypes` most likely sub-types is refined by gradient ascent,
   and the sub-type with the highest likelihood wins (paper: "shape = the mesh model with the highest likelihood").
3. A proposal is kept when its mean log-likelihood ratio per foreground cell is high enough, and when no better
   proposal (or existing track) already explains the same place: rendered together with them it must still show
   at least half of its surface.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import torch
from torch.nn import functional as F

from dynclevr.assets.catalogue import SUBTYPES
from dynclevr.perception.neural_mesh import NeuralMeshes
from dynclevr.perception.pose import Evidence, fit, score
from dynclevr.perception.render import GridCamera


@dataclass
class Proposal:
    pose: np.ndarray        # [6]
    mesh: int               # index into NeuralMeshes.subtypes
    loglik: float
    quality: float          # mean log-likelihood ratio per visible foreground cell


def peaks(heat: torch.Tensor, threshold: float, limit: int) -> list[tuple[int, int, float]]:
    """Local maxima of the heatmap logits [H, W] above `threshold` (probability): (row, col, probability)."""
    prob = torch.sigmoid(heat)
    is_max = prob == F.max_pool2d(prob[None, None], 5, 1, 2)[0, 0]
    rows, cols = torch.nonzero(is_max & (prob > threshold), as_tuple=True)
    order = prob[rows, cols].argsort(descending=True)[:limit]
    return [(int(rows[i]), int(cols[i]), float(prob[rows[i], cols[i]])) for i in order]


def propose(feats: torch.Tensor, heat: torch.Tensor, logdist: torch.Tensor, meshes: NeuralMeshes, cam: GridCamera,
            p: dict, tracked: list[tuple[np.ndarray, int]] = ()) -> list[Proposal]:
    """Proposals in one frame, given the tracked objects' (pose, mesh index). A peak is skipped when its centre lies
    within `track_radius` (metres) of a tracked object or its cell within `track_cells` of one's projection."""
    centres = [np.asarray(pose[:3]) for pose, _ in tracked]
    found = []
    if centres:
        seen_uv, _ = cam.project(torch.tensor(np.array(centres), dtype=torch.float32))
    M, Y = len(meshes.subtypes), p["yaw_grid"]
    half = meshes.half_heights.numpy()
    flying = np.array([SUBTYPES[s][0] == "aeroplane" for s in meshes.subtypes])
    eye = np.asarray(cam.camera.position, float)
    for row, col, _ in peaks(heat, p["heatmap_threshold"], p["max_proposals"]):
        ray = cam.ray(col, row)
        centre = eye + ray * float(math.exp(logdist[row, col]))
        if any(np.linalg.norm(centre - c) < p["track_radius"] for c in centres):
            continue
        if centres and float((seen_uv - torch.tensor([col, row])).norm(dim=1).min()) < p["track_cells"]:
            continue
        # per sub-type: a ground vehicle's centre is where the ray meets the plane at its half height; an
        # aeroplane's (in the air, at any height) is at the distance the CNN's distance head gives
        reach = (half - eye[2]) / min(ray[2], -1e-3)
        ground = eye + reach[:, None] * ray
        found.append(np.where(flying[:, None] | (reach[:, None] <= 0), centre, ground))
    if not found:
        return []
    ev = Evidence.compute(feats, meshes, list(range(M)), p["kappa"], p["foreground_bias"])
    P = len(found)
    # coarse search: every peak x sub-type x heading, each hypothesis alone
    yaws = torch.arange(Y) * (2 * math.pi / Y) - math.pi
    pose = torch.zeros(P, M, Y, 6)
    pose[..., :3] = torch.tensor(np.array(found), dtype=torch.float32)[:, :, None]
    pose[..., 3] = yaws
    mesh_idx = torch.arange(M)[None, :, None].expand(P, M, Y).reshape(-1)
    ll, _ = score(pose.reshape(-1, 6), mesh_idx, ev, meshes, cam, joint=False)
    best_ll, best_yaw = ll.view(P, M, Y).max(2)
    K = min(p["detect_subtypes"], M)
    subs = best_ll.topk(K, 1).indices                                     # [P, K] most likely sub-types
    start = pose[torch.arange(P)[:, None], subs, best_yaw.gather(1, subs)].reshape(-1, 6)
    mesh_idx = subs.reshape(-1)
    poses, ll, area = fit(start, mesh_idx, ev, meshes, cam, p["detect_iterations"], p["learning_rate"], joint=False)
    ll, area = ll.view(P, K), area.view(P, K)
    out = []
    for i in range(P):
        j = int(ll[i].argmax())
        quality = float(ll[i, j] / area[i, j].clamp(min=1.0))
        if quality >= p["min_quality"]:
            out.append(Proposal(poses[i * K + j].numpy().astype(float), int(mesh_idx[i * K + j]), float(ll[i, j]),
                                quality))
    # Greedy, best explanation first: a proposal must not sit on a kept one, and must still show most of its
    # surface when rendered together with the tracked and kept objects (else it explains pixels already explained).
    out.sort(key=lambda q: -q.loglik)
    kept: list[Proposal] = []
    for q in out:
        others = list(tracked) + [(k.pose, k.mesh) for k in kept]
        if any(np.linalg.norm(q.pose[:3] - np.asarray(o[:3])) < p["track_radius"] for o, _ in others):
            continue
        if others:
            poses = torch.tensor(np.array([o for o, _ in others] + [q.pose]), dtype=torch.float32)
            idx = torch.tensor([m for _, m in others] + [q.mesh])
            _, joint_area = score(poses, idx, ev, meshes, cam, joint=True)
            _, own_area = score(poses[-1:], idx[-1:], ev, meshes, cam, joint=True)
            if float(joint_area[-1]) < 0.5 * float(own_area[0]):
                continue
        kept.append(q)
    return kept
