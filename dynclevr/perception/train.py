"""`dynclevr train parser`: the feature CNN, neural meshes, clutter model and colour classifier from a split.

Training may read the truth (poses, masks, depth; paper, appendix 3); inference never does. Per training frame:
- each object's mesh points are placed at its true pose and kept where the instance mask and the depth map say
  the point is the visible surface; their grid positions are the foreground samples of their vertices;
- feature cells whose 8x8 pixels are all background are the clutter samples;
- the CNN is trained by a contrastive loss (InfoNCE, temperature tau): a foreground feature against its own vertex
  feature (positive), every other vertex of every sub-type (negatives, except the vertex's close neighbours on the
  same mesh, which look alike) and the clutter features; a background feature against every vertex, with the
  clutter as positives. After every gradient step the vertex and clutter features take a momentum update
  (paper: EM-type learning after CoKe), so the neural textures are not trained by gradient;
- the proposal heads learn the projected object centres (CenterNet focal loss) and the log camera distance;
- the colour classifier learns crops at jittered true poses.
The CNN trains on random grid-aligned crops of the frames (around an object), with the colour channels shuffled
and brightness / contrast jittered, and evaluates on whole frames.
The first `val_fraction` of scenes are held out for the manifest's metrics.
"""

from __future__ import annotations

import platform
import time
from pathlib import Path

import numpy as np
import torch
from scipy.spatial.transform import Rotation
from torch.nn import functional as F

from dynclevr.artifacts import Store
from dynclevr.assets.catalogue import SUBTYPES
from dynclevr.colors import COLOR_NAMES
from dynclevr.config import Config, ConfigError, Split
from dynclevr.perception.color import ColorNet, box, crop
from dynclevr.perception.features import FeatureNet, to_tensor
from dynclevr.perception.model import ParserModel
from dynclevr.perception.neural_mesh import NeuralMeshes
from dynclevr.perception.render import STRIDE
from dynclevr.pipeline import Runner
from dynclevr.scene import Scene4D
from dynclevr.video import Video

VISIBLE_DEPTH_TOL = 0.15   # metres between a point's depth and the depth map for the point to be the visible surface
MIN_PIXELS = 50            # an object with fewer visible pixels is no heatmap target
MIN_COLOR_PIXELS = 150     # nor a colour sample
MAX_FG = 1536              # foreground samples per batch (the InfoNCE logits are samples x all vertices)
MAX_BG = 48                # background cells per frame


def _frame_sample(t, rgb, mask, depth, truth: Scene4D, meshes: NeuralMeshes, rng) -> dict:
    cam = truth.camera
    H, W = mask.shape
    gh, gw = H // STRIDE, W // STRIDE
    mesh_ids, vert_ids, uvs, centres, colors = [], [], [], [], []
    for i, obj in enumerate(truth.objects):
        pix = int((mask == obj.id).sum())
        if pix == 0:
            continue
        m = meshes.index(obj.shape)
        R = Rotation.from_quat(truth.orientation[t, i])
        world = R.apply(meshes.points[m].numpy()) + truth.position[t, i]
        uv, z = cam.project(world)
        x, y = np.floor(uv[:, 0]).astype(int), np.floor(uv[:, 1]).astype(int)
        inside = (x >= 0) & (x < W) & (y >= 0) & (y < H) & (z > 0.1)
        xs, ys = x.clip(0, W - 1), y.clip(0, H - 1)
        vis = inside & (mask[ys, xs] == obj.id) & (np.abs(depth[ys, xs] - z) < VISIBLE_DEPTH_TOL)
        mesh_ids.append(np.full(int(vis.sum()), m))
        vert_ids.append(np.flatnonzero(vis))
        uvs.append(uv[vis] / STRIDE - 0.5)
        (cu, cv), cz = cam.project(truth.position[t, i])
        if pix >= MIN_PIXELS and 0 <= cu < W and 0 <= cv < H and cz > 0.1:
            dist = float(np.linalg.norm(truth.position[t, i] - np.array(cam.position)))
            radius = cam.fx * max(obj.size) / 2 / dist / STRIDE
            centres.append((cu / STRIDE - 0.5, cv / STRIDE - 0.5, np.log(dist), max(0.7, radius / 3)))
        if pix >= MIN_COLOR_PIXELS:
            jitter = Rotation.from_euler("z", rng.normal(0, 0.1)) * R
            pts = jitter.apply(meshes.points[m].numpy()) + truth.position[t, i] + rng.normal(0, 0.1, 3)
            b = box(cam, pts, margin=0.1 + 0.1 * rng.random())
            if b is not None:
                colors.append((np.round(crop(rgb, b) * 255).astype(np.uint8), COLOR_NAMES.index(obj.color)))
    fg_block = (mask >= 0).reshape(gh, STRIDE, gw, STRIDE).any(axis=(1, 3))
    heat = np.zeros((gh, gw), np.float32)
    rows, cols = np.mgrid[0:gh, 0:gw]
    for cu, cv, _, sigma in centres:
        heat = np.maximum(heat, np.exp(-((cols - cu) ** 2 + (rows - cv) ** 2) / (2 * sigma ** 2)))
        heat[int(np.clip(round(cv), 0, gh - 1)), int(np.clip(round(cu), 0, gw - 1))] = 1.0
    return {"rgb": rgb, "mesh": np.concatenate(mesh_ids).astype(np.int64) if mesh_ids else np.zeros(0, np.int64),
            "vert": np.concatenate(vert_ids).astype(np.int64) if vert_ids else np.zeros(0, np.int64),
            "uv": np.concatenate(uvs).astype(np.float32) if uvs else np.zeros((0, 2), np.float32),
            "bg": ~fg_block, "heat": heat, "centres": centres, "colors": colors}


def load_samples(store: Store, scenes: list[str], meshes: NeuralMeshes, stride: int, rng) -> list[dict]:
    out = []
    for scene in scenes:
        truth = Scene4D.read(store.path("simulate", scene, ".mcap"))
        video = Video.read(store.path("render", scene, ".mcap"))
        sl = slice(int(rng.integers(stride)), video.num_frames, stride)
        rgb, mask, depth = video.frames(sl), video.masks(sl), video.depth(sl)
        for j, t in enumerate(range(video.num_frames)[sl]):
            out.append(_frame_sample(t, rgb[j], mask[j], depth[j], truth, meshes, rng))
    return out


def crop_sample(s: dict, rng, width: int, height: int) -> dict:
    """A random crop (grid-aligned, around a random visible object when there is one) of a training frame: the CNN
    is fully convolutional, so training on crops costs a fraction of a frame and sees more scenes per second."""
    gw, gh = width // STRIDE, height // STRIDE
    H, W = s["bg"].shape
    if s["centres"]:
        cu, cv = s["centres"][rng.integers(len(s["centres"]))][:2]
        c0 = int(np.clip(round(cu) - rng.integers(2, gw - 2), 0, W - gw))
        r0 = int(np.clip(round(cv) - rng.integers(2, gh - 2), 0, H - gh))
    else:
        c0, r0 = int(rng.integers(W - gw + 1)), int(rng.integers(H - gh + 1))
    uv = s["uv"] - np.array([c0, r0], np.float32)
    keep = (uv[:, 0] >= 0) & (uv[:, 0] <= gw - 1) & (uv[:, 1] >= 0) & (uv[:, 1] <= gh - 1)
    centres = [(cu - c0, cv - r0, ld, sg) for cu, cv, ld, sg in s["centres"]
               if 0 <= round(cu) - c0 < gw and 0 <= round(cv) - r0 < gh]
    x0, y0 = c0 * STRIDE, r0 * STRIDE
    return {"rgb": s["rgb"][y0:y0 + height, x0:x0 + width], "mesh": s["mesh"][keep], "vert": s["vert"][keep],
            "uv": uv[keep], "bg": s["bg"][r0:r0 + gh, c0:c0 + gw], "heat": s["heat"][r0:r0 + gh, c0:c0 + gw],
            "centres": centres, "colors": []}


def augment(rgb: np.ndarray, rng) -> np.ndarray:
    """Appearance changes that keep the geometry: a random order of the colour channels (vehicles come in any of 8
    colours, so what tells a vertex apart must be shape, not hue), brightness and contrast."""
    x = rgb[..., rng.permutation(3)].astype(np.float32)
    mean = x.mean()
    x = (x - mean) * rng.uniform(0.7, 1.3) + mean * rng.uniform(0.7, 1.3)
    return np.clip(x, 0, 255).astype(np.uint8)


def neighbours(meshes: NeuralMeshes, radius: float) -> torch.Tensor:
    """[M, V, V] bool: other vertices of the same mesh closer than `radius` (not negatives of each other)."""
    d = torch.cdist(meshes.points, meshes.points)
    return (d < radius) & ~torch.eye(meshes.vertices, dtype=torch.bool)


def focal_loss(logits: torch.Tensor, target: torch.Tensor) -> torch.Tensor:
    """CenterNet's penalty-reduced focal loss on heatmap logits."""
    p = torch.sigmoid(logits).clamp(1e-4, 1 - 1e-4)
    pos = target >= 1.0
    pos_loss = -((1 - p) ** 2 * torch.log(p))[pos].sum()
    neg_loss = -((1 - target) ** 4 * p ** 2 * torch.log(1 - p))[~pos].sum()
    return (pos_loss + neg_loss) / pos.sum().clamp(min=1)


def _sample_grid(feats: torch.Tensor, uv: torch.Tensor) -> torch.Tensor:
    """Bilinear features [P, D] at grid positions uv [P, 2] (cell units) of one frame's map [D, H, W]."""
    D, H, W = feats.shape
    g = torch.stack([(2 * uv[:, 0] + 1) / W - 1, (2 * uv[:, 1] + 1) / H - 1], -1)
    f = F.grid_sample(feats[None], g[None, None], align_corners=False)[0, :, 0].T
    return F.normalize(f, dim=-1)


def contrastive_step(net, meshes, batch, neigh, p, rng, opt=None) -> dict:
    """One batch: losses and diagnostics; with an optimiser, also the gradient step and the momentum update."""
    tau = p["temperature"]
    feats, heat_logits, logdist = net(to_tensor(np.stack([s["rgb"] for s in batch])))
    fg, tgt_mesh, tgt_vert, bg = [], [], [], []
    for b, s in enumerate(batch):
        if len(s["uv"]):
            fg.append(_sample_grid(feats[b], torch.from_numpy(s["uv"])))
            tgt_mesh.append(torch.from_numpy(s["mesh"]))
            tgt_vert.append(torch.from_numpy(s["vert"]))
        cells = np.flatnonzero(s["bg"])
        if len(cells):
            cells = rng.choice(cells, min(MAX_BG, len(cells)), replace=False)
            bg.append(feats[b].flatten(1)[:, torch.from_numpy(cells)].T)
    M, V, D = meshes.features.shape
    verts = meshes.features.reshape(-1, D)
    out = {}
    loss = 0.0
    if fg:
        fg, tgt_mesh, tgt_vert = torch.cat(fg), torch.cat(tgt_mesh), torch.cat(tgt_vert)
        if len(fg) > MAX_FG:
            keep = torch.from_numpy(rng.choice(len(fg), MAX_FG, replace=False))
            fg, tgt_mesh, tgt_vert = fg[keep], tgt_mesh[keep], tgt_vert[keep]
        logits = torch.cat([fg @ verts.T, fg @ meshes.clutter.T], 1) / tau
        mask = torch.zeros(len(fg), M, V, dtype=torch.bool)
        mask[torch.arange(len(fg)), tgt_mesh] = neigh[tgt_mesh, tgt_vert]
        logits = logits.masked_fill(torch.cat([mask.view(len(fg), -1),
                                               torch.zeros(len(fg), len(meshes.clutter), dtype=torch.bool)], 1),
                                    float("-inf"))
        target = tgt_mesh * V + tgt_vert
        loss = loss + F.cross_entropy(logits, target)
        with torch.no_grad():
            pred = logits.argmax(1)
            pm, pv = pred // V, pred % V
            close = neigh[tgt_mesh, tgt_vert].gather(1, pv[:, None])[:, 0]
            near = (pm == tgt_mesh) & ((pv == tgt_vert) | close)
            out["vertex_acc"] = float(near.float().mean())
            out["subtype_acc"] = float((pm == tgt_mesh).float().mean())
        out["loss_fg"] = float(F.cross_entropy(logits.detach(), target))
    if bg:
        bg = torch.cat(bg)
        lc, lv = bg @ meshes.clutter.T / tau, bg @ verts.T / tau
        loss_bg = (torch.logsumexp(torch.cat([lv, lc], 1), 1) - torch.logsumexp(lc, 1)).mean()
        loss = loss + loss_bg
        out["loss_bg"] = float(loss_bg.detach())
    heat_t = torch.from_numpy(np.stack([s["heat"] for s in batch]))
    loss_heat = focal_loss(heat_logits, heat_t)
    dist_err = []
    for b, s in enumerate(batch):
        for cu, cv, ld, _ in s["centres"]:
            r, c = int(np.clip(round(cv), 0, heat_t.shape[1] - 1)), int(np.clip(round(cu), 0, heat_t.shape[2] - 1))
            dist_err.append(logdist[b, r, c] - ld)
    loss_dist = torch.stack(dist_err).abs().mean() if dist_err else torch.zeros(())
    loss = loss + p["heatmap_weight"] * loss_heat + loss_dist
    out.update(loss_heat=float(loss_heat.detach()), dist_err=float(loss_dist.detach()))
    if opt is not None:
        opt.zero_grad()
        loss.backward()
        opt.step()
        if len(fg):
            meshes.momentum_update(tgt_mesh, tgt_vert, fg.detach(), bg.detach() if len(bg) else bg,
                                   p["momentum"])
    return out


def train_color(samples: list[dict], p: dict, rng, echo) -> tuple[ColorNet, list]:
    crops = np.stack([c for s in samples for c, _ in s["colors"]])
    labels = np.array([k for s in samples for _, k in s["colors"]])
    net = ColorNet()
    opt = torch.optim.Adam(net.parameters(), lr=3e-3)
    x, y = torch.from_numpy(crops).float() / 255, torch.from_numpy(labels)
    for epoch in range(p["color_epochs"]):
        order = torch.from_numpy(rng.permutation(len(x)))
        for i in range(0, len(x), 128):
            idx = order[i:i + 128]
            loss = F.cross_entropy(net(x[idx]), y[idx])
            opt.zero_grad()
            loss.backward()
            opt.step()
    net.eval()
    return net, [x, y]


def train_parser(cfg: Config, data_dir: Path, split: Split, out_dir: Path, workers: int = 1, echo=print) -> dict:
    from dynclevr.perception.tracker import parser_params

    p = parser_params(cfg)
    n = min(p["train_scenes"], split.scenes)
    if n < 2:
        raise ConfigError("'parser.train_scenes' must be at least 2 (one is held out for the metrics)")
    start = time.perf_counter()
    torch.manual_seed(p["seed"])
    rng = np.random.default_rng(p["seed"])
    runner = Runner(cfg, split, data_dir, workers, echo)
    runner.run("simulate", list(range(n)))
    runner.run("render", list(range(n)))
    store = Store(Path(data_dir), split.name)
    scenes = split.scene_names()[:n]
    n_val = max(1, int(round(n * p["val_fraction"])))
    meshes = NeuralMeshes.build(list(SUBTYPES), p["vertices"], p["feature_dim"], p["clutter_features"], p["seed"])
    echo(f"train parser: loading {n} scenes of split {split.name} (every {p['train_frame_stride']}th frame)")
    val = load_samples(store, scenes[:n_val], meshes, p["train_frame_stride"], rng)
    train = load_samples(store, scenes[n_val:], meshes, p["train_frame_stride"], rng)
    neigh = neighbours(meshes, p["neighbour_radius"])
    net = FeatureNet(p["feature_dim"], p["cnn_width"])
    opt = torch.optim.Adam(net.parameters(), lr=p["train_learning_rate"])
    B = p["train_batch"]
    steps = p["train_epochs"] * ((len(train) + B - 1) // B)
    sched = torch.optim.lr_scheduler.OneCycleLR(opt, p["train_learning_rate"], total_steps=steps,
                                                pct_start=0.1)
    for epoch in range(p["train_epochs"]):
        net.train()
        order = rng.permutation(len(train))
        logs = []
        for i in range(0, len(order), B):
            batch = [crop_sample(train[j], rng, *p["train_crop"]) for j in order[i:i + B]]
            for b in batch:
                b["rgb"] = augment(b["rgb"], rng)
            logs.append(contrastive_step(net, meshes, batch, neigh, p, rng, opt))
            sched.step()
        mean = {k: float(np.mean([l[k] for l in logs if k in l])) for k in logs[0]}
        echo(f"  epoch {epoch + 1}/{p['train_epochs']}: " + ", ".join(f"{k} {v:.3f}" for k, v in mean.items())
             + f"  ({time.perf_counter() - start:.0f} s)")
    net.eval()
    metrics = evaluate_features(net, meshes, val, neigh, p, rng)
    color, _ = train_color(train, p, rng, echo)
    metrics["color_acc_val"] = color_accuracy(color, val)
    seconds = time.perf_counter() - start
    echo("  held-out: " + ", ".join(f"{k} {v:.3f}" for k, v in metrics.items()) + f"; {seconds:.0f} s in all")
    model = ParserModel(net, meshes, color, p["feature_dim"], p["cnn_width"])
    manifest = {"split": split.name, "split_seed": split.seed, "scenes_train": scenes[n_val:],
                "scenes_heldout": scenes[:n_val], "frames_train": len(train), "params": p,
                "metrics_heldout": metrics, "training_seconds": round(seconds, 1),
                "machine": f"{platform.machine()}, torch {torch.__version__}, {torch.get_num_threads()} threads",
                "command": f"dynclevr train parser --split {split.name}"}
    model.save(out_dir, manifest)
    echo(f"train parser: weights and manifest written to {out_dir}")
    return manifest


@torch.no_grad()
def evaluate_features(net, meshes, samples, neigh, p, rng) -> dict:
    logs = [contrastive_step(net, meshes, samples[i:i + 8], neigh, p, rng)
            for i in range(0, len(samples), 8)]
    return {f"{k}_val": float(np.mean([l[k] for l in logs if k in l])) for k in logs[0]}


@torch.no_grad()
def color_accuracy(net: ColorNet, samples: list[dict]) -> float:
    crops = [c for s in samples for c, _ in s["colors"]]
    if not crops:
        return float("nan")
    x = torch.from_numpy(np.stack(crops)).float() / 255
    y = torch.tensor([k for s in samples for _, k in s["colors"]])
    return float((net(x).argmax(1) == y).float().mean())
