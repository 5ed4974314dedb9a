"""`dynclevr train detector`: the detection head on frames the generator makes on demand, resumably.

Data: split `parser.detector_split` (fresh seeds, never val or test), `frames_per_video` frames per scene, in shards
(detector_data.py). The last `detector_heldout_shards` shards are held out for the manifest's metrics; shards below
`detector_first_shard` are left out, so that a head trained on them can go on with fresh frames only.
Loss (CenterNet): penalty-reduced focal loss on the centre heatmap; at each object's centre cell (and its 3x3
neighbourhood, weighted by the heatmap, so the neighbours of a peak answer too) L1 on the offset, cross-entropy on
the sub-type and colour, L1 on (sin, cos) of the yaw relative to the ray, on the log distance and on the height.
Objects with fewer than MIN_PIXELS visible pixels are neither positives nor negatives (a vehicle hidden behind
another is no error either way).
Augmentation keeps the geometry honest: horizontal flips (u -> W - u, alpha -> -alpha), brightness, contrast and
saturation jitter (not hue: the colour is a target), blur, and JPEG re-coding at a random quality.
Checkpoints every `checkpoint_minutes`: weights/detector/detector.pt (model, optimiser, step) with manifest.json
(data, steps, wall time, loss curve, held-out metrics) and curve.png. `--resume` continues from there.
`--grow-from DIR` starts a deeper or wider head (`parser.detector_blocks` residual blocks at strides 8 and 16,
`parser.detector_fine_blocks` at stride 4, `parser.detector_width` channels) from the trained one in DIR: it computes
the same at first, so capacity grows on CPU without training from scratch.
`--device cuda --loader-workers N` trains on a GPU, N processes decoding and augmenting the frames. Each training
sample is drawn and augmented from its own seed (the run's seed and its number), so a run's batches are the same
whatever the device or the number of loader processes.
"""

from __future__ import annotations

import io
import json
import math
import platform
import time
from concurrent.futures import ProcessPoolExecutor
from multiprocessing import get_context
from pathlib import Path

import cv2
import numpy as np
import torch
from torch.nn import functional as F

from dynclevr import WEIGHTS_DIR, DynclevrError
from dynclevr.artifacts import atomic_path, file_digest, write_json_atomic
from dynclevr.config import Config, ConfigError
from dynclevr.perception.detector import CHANNELS, STRIDE, DetectNet, decode, run, widened
from dynclevr.perception.detector_data import LABEL_COLUMNS, make_shard, shard_backend, shard_path

DEFAULT_DIR = WEIGHTS_DIR / "detector"
WEIGHTS_FILE, MANIFEST, CURVE = "detector.pt", "manifest.json", "curve.png"
MIN_PIXELS = 25
COL = {c: i for i, c in enumerate(LABEL_COLUMNS)}


class DetectorWeightsError(DynclevrError):
    pass


def load_detector(weights_dir: Path = DEFAULT_DIR) -> DetectNet:
    path, manifest = Path(weights_dir) / WEIGHTS_FILE, Path(weights_dir) / MANIFEST
    if not path.exists() or not manifest.exists():
        raise DetectorWeightsError(f"detector weights missing in {weights_dir}: run `dynclevr train detector`")
    m = json.loads(manifest.read_text())
    if m.get("weights_sha256") != file_digest(path):
        raise DetectorWeightsError(f"{path} does not match its manifest: rerun `dynclevr train detector --resume`")
    s = torch.load(path, weights_only=True, map_location="cpu")
    net = DetectNet(s["width"], s.get("blocks", 0), s.get("fine_blocks", 0))
    net.load_state_dict(s["net"])
    offset = m.get("pixel_offset", (0.0, 0.0))
    if not (isinstance(offset, (list, tuple)) and len(offset) == 2
            and all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in offset)):
        raise DetectorWeightsError(f"{manifest}: 'pixel_offset' = {offset!r} must be two numbers (pixels across and "
                                   "down added to every centre; [0, 0] for a head trained on render version 2)")
    net.pixel_offset = (float(offset[0]), float(offset[1]))
    net.eval()
    return net


def _grown(source: Path, width: int, blocks: int, fine_blocks: int) -> tuple[DetectNet, int]:
    """A head of `width`, `blocks` residual blocks per coarse stage and `fine_blocks` at stride 4 that computes what
    the trained head in `source` does (its weights, widened with copies of its channels, the new blocks' residuals
    at zero), and the step it was trained to."""
    path = Path(source) / WEIGHTS_FILE
    if not path.exists():
        raise DetectorWeightsError(f"nothing to grow from in {source}: --grow-from needs a trained head's directory")
    s = torch.load(path, weights_only=True, map_location="cpu")
    had = (s.get("blocks", 0), s.get("fine_blocks", 0))
    if s["width"] > width or width % 2 or had[0] > blocks or had[1] > fine_blocks:
        raise ConfigError(f"cannot grow the head in {source} (width {s['width']}, {had[0]} + {had[1]} fine blocks) "
                          f"into width {width}, {blocks} + {fine_blocks} fine blocks: set parser.detector_width to "
                          f"an even number of at least {s['width']}, parser.detector_blocks at least {had[0]} and "
                          f"parser.detector_fine_blocks at least {had[1]}")
    trained = DetectNet(s["width"], *had)
    trained.load_state_dict(s["net"])
    if width > s["width"]:
        trained = widened(trained, width, torch.Generator().manual_seed(s["step"]))
    net = DetectNet(width, blocks, fine_blocks)
    missing, unexpected = net.load_state_dict(trained.state_dict(), strict=False)
    if unexpected or not all(".a." in k or ".b." in k for k in missing):
        raise DetectorWeightsError(f"{path} is not a detection head of this design: retrain it with "
                                   "`dynclevr train detector`")
    return net, int(s["step"])


def detector_digest(weights_dir: Path = DEFAULT_DIR) -> str:
    path = Path(weights_dir) / MANIFEST
    return file_digest(path) if path.exists() else "missing"


# ---- data ----------------------------------------------------------------------------------------------------------

class Frames:
    """Every shard's JPEG frames (decoded per batch) and labels, in memory."""

    def __init__(self, paths: list[Path]):
        self.jpeg, self.labels = [], []
        for path in paths:
            z = np.load(path)
            buf, off, lab = z["jpeg"], z["offsets"], z["labels"]
            base = len(self.jpeg)
            self.jpeg += [buf[off[k]:off[k + 1]].copy() for k in range(len(off) - 1)]
            lab = lab.copy()
            lab[:, COL["frame"]] += base
            self.labels.append(lab)
        self.labels = np.concatenate(self.labels) if self.labels else np.zeros((0, len(LABEL_COLUMNS)), np.float32)
        order = np.argsort(self.labels[:, COL["frame"]], kind="stable")
        self.labels = self.labels[order]
        self.starts = np.searchsorted(self.labels[:, COL["frame"]], np.arange(len(self.jpeg) + 1))

    def __len__(self) -> int:
        return len(self.jpeg)

    def get(self, k: int) -> tuple[np.ndarray, np.ndarray]:
        rgb = cv2.cvtColor(cv2.imdecode(self.jpeg[k], cv2.IMREAD_COLOR), cv2.COLOR_BGR2RGB)
        return rgb, self.labels[self.starts[k]:self.starts[k + 1]]


def augment(rgb: np.ndarray, lab: np.ndarray, rng) -> tuple[np.ndarray, np.ndarray]:
    lab = lab.copy()
    if rng.random() < 0.5:
        rgb = rgb[:, ::-1]
        lab[:, COL["u"]] = rgb.shape[1] - lab[:, COL["u"]]
        lab[:, COL["alpha"]] = -lab[:, COL["alpha"]]
    x = rgb.astype(np.float32)
    grey = x.mean(2, keepdims=True)
    x = grey + (x - grey) * rng.uniform(0.75, 1.25)                       # saturation
    mean = x.mean()
    x = (x - mean) * rng.uniform(0.75, 1.25) + mean * rng.uniform(0.75, 1.25)   # contrast, brightness
    x = np.clip(x, 0, 255).astype(np.uint8)
    if rng.random() < 0.25:
        x = cv2.GaussianBlur(x, (0, 0), rng.uniform(0.3, 1.0))
    if rng.random() < 0.3:
        ok, buf = cv2.imencode(".jpg", x, [cv2.IMWRITE_JPEG_QUALITY, int(rng.integers(50, 95))])
        x = cv2.imdecode(buf, cv2.IMREAD_COLOR)
    return np.ascontiguousarray(x), lab


def targets(lab: np.ndarray, h: int, w: int) -> dict:
    """One frame's heatmap target, ignore mask and per-object centre cells [K, 2] and regression targets."""
    heat = np.zeros((h, w), np.float32)
    ignore = np.zeros((h, w), bool)
    rows, cols = np.mgrid[0:h, 0:w]
    cells, regs = [], []
    for o in lab:
        cu, cv = o[COL["u"]] / STRIDE - 0.5, o[COL["v"]] / STRIDE - 0.5
        c, r = int(np.clip(round(cu), 0, w - 1)), int(np.clip(round(cv), 0, h - 1))
        sigma = max(0.8, o[COL["radius"]] / STRIDE / 3)
        g = np.exp(-((cols - c) ** 2 + (rows - r) ** 2) / (2 * sigma ** 2))
        if o[COL["pixels"]] < MIN_PIXELS:
            ignore |= g > 0.1
            continue
        heat = np.maximum(heat, g)
        heat[r, c] = 1.0
        cells.append((r, c))
        regs.append([cu - c, cv - r, o[COL["subtype"]], o[COL["color"]], math.sin(o[COL["alpha"]]),
                     math.cos(o[COL["alpha"]]), o[COL["logdist"]], o[COL["height"]]])
    ignore &= heat < 1.0
    return {"heat": heat, "ignore": ignore, "cells": np.array(cells, np.int64).reshape(-1, 2),
            "regs": np.array(regs, np.float32).reshape(-1, 8)}


class Samples(torch.utils.data.Dataset):
    """Training sample g (step x batch + slot): a frame drawn, augmented and given its targets from seed (seed, g)."""

    def __init__(self, frames: Frames, seed: int, h: int, w: int):
        self.frames, self.seed, self.h, self.w = frames, seed, h, w

    def __getitem__(self, g: int) -> tuple[np.ndarray, dict]:
        rng = np.random.default_rng([self.seed, g])
        rgb, lab = augment(*self.frames.get(int(rng.integers(len(self.frames)))), rng)
        return rgb, targets(lab, self.h, self.w)


def _collate(items: list) -> tuple[torch.Tensor, list[dict]]:
    """uint8 images [B, H, W, 3] (made [0, 1] floats where the head trains) and the targets."""
    return torch.from_numpy(np.stack([rgb for rgb, _ in items])), [t for _, t in items]


def _batches(samples: Samples, first: int, last: int, batch: int, workers: int):
    """(uint8 images [B, H, W, 3], targets) of steps first..last-1."""
    loader = torch.utils.data.DataLoader(samples, batch_size=batch, sampler=range(first * batch, last * batch),
                                         num_workers=workers, collate_fn=_collate,
                                         prefetch_factor=4 if workers else None)
    return iter(loader)


def focal_loss(logits: torch.Tensor, target: torch.Tensor, ignore: torch.Tensor) -> torch.Tensor:
    p = torch.sigmoid(logits).clamp(1e-4, 1 - 1e-4)
    pos = target >= 1.0
    pos_loss = -((1 - p) ** 2 * torch.log(p))[pos].sum()
    neg = ~pos & ~ignore
    neg_loss = -((1 - target) ** 4 * p ** 2 * torch.log(1 - p))[neg].sum()
    return (pos_loss + neg_loss) / pos.sum().clamp(min=1)


NEIGHBOURS = [(dr, dc) for dr in (-1, 0, 1) for dc in (-1, 0, 1)]


def losses(maps: torch.Tensor, tg: list[dict]) -> dict:
    B, _, h, w = maps.shape
    dev = maps.device
    heat = torch.from_numpy(np.stack([t["heat"] for t in tg])).to(dev)
    ignore = torch.from_numpy(np.stack([t["ignore"] for t in tg])).to(dev)
    out = {"heat": focal_loss(maps[:, 0], heat, ignore)}
    idx, reg, wts = [], [], []
    for b, t in enumerate(tg):
        for (r, c), g in zip(t["cells"], t["regs"]):
            for dr, dc in NEIGHBOURS:
                rr, cc = r + dr, c + dc
                if 0 <= rr < h and 0 <= cc < w:
                    wgt = 1.0 if dr == dc == 0 else float(t["heat"][rr, cc])
                    if wgt > 0.3:
                        idx.append((b, rr, cc))
                        reg.append(np.concatenate([[g[0] - dc, g[1] - dr], g[2:]]))
                        wts.append(wgt)
    if not idx:
        zero = maps.sum() * 0
        return {**out, **{k: zero for k in ("offset", "subtype", "color", "alpha", "logdist", "height")}}
    ix = torch.tensor(idx, device=dev)
    v = maps[ix[:, 0], :, ix[:, 1], ix[:, 2]]                         # [K, OUT]
    g = torch.from_numpy(np.array(reg, np.float32)).to(dev)
    wt = torch.tensor(wts, device=dev)
    wt = wt / wt.sum()

    def wmean(x):
        return (x * wt).sum()

    out["offset"] = wmean((v[:, CHANNELS["offset"]] - g[:, :2]).abs().sum(1))
    out["subtype"] = wmean(F.cross_entropy(v[:, CHANNELS["subtype"]], g[:, 2].long(), reduction="none"))
    out["color"] = wmean(F.cross_entropy(v[:, CHANNELS["color"]], g[:, 3].long(), reduction="none"))
    out["alpha"] = wmean((v[:, CHANNELS["alpha"]] - g[:, 4:6]).abs().sum(1))
    out["logdist"] = wmean((v[:, CHANNELS["logdist"]][:, 0] - g[:, 6]).abs()) * 5
    out["height"] = wmean((v[:, CHANNELS["height"]][:, 0] - g[:, 7]).abs())
    return out


# ---- held-out metrics ----------------------------------------------------------------------------------------------

@torch.no_grad()
def evaluate(net: DetectNet, frames: Frames, threshold: float = 0.3, limit: int | None = None) -> dict:
    """Per-frame detection against the labels: a detection matches the nearest unmatched true centre within
    max(8 px, half the object's projected size)."""
    n = len(frames) if limit is None else min(limit, len(frames))
    tp = fp = fn = 0
    sub, col, flip, dyaw, ddist, dh = [], [], [], [], [], []
    for s in range(0, n, 16):
        batch = [frames.get(k) for k in range(s, min(n, s + 16))]
        maps = run(net, np.stack([b[0] for b in batch]))
        for (rgb, lab), m in zip(batch, maps):
            lab = lab[lab[:, COL["pixels"]] >= MIN_PIXELS]
            dets = decode(m, threshold)
            used = set()
            for d in dets:
                dist = np.hypot(lab[:, COL["u"]] - d.u, lab[:, COL["v"]] - d.v) if len(lab) else np.zeros(0)
                ok = [j for j in np.argsort(dist) if j not in used and dist[j] <= max(8.0, lab[j, COL["radius"]] / 2)]
                if not ok:
                    fp += 1
                    continue
                j = ok[0]
                used.add(j)
                tp += 1
                sub.append(int(np.argmax(d.subtype_logp)) == int(lab[j, COL["subtype"]]))
                col.append(int(np.argmax(d.color_logp)) == int(lab[j, COL["color"]]))
                e = abs((d.alpha - lab[j, COL["alpha"]] + math.pi) % (2 * math.pi) - math.pi)
                dyaw.append(math.degrees(e))
                flip.append(e > math.radians(135))
                ddist.append(d.dist - math.exp(lab[j, COL["logdist"]]))
                dh.append(d.height - lab[j, COL["height"]])
            fn += len(lab) - len(used)
    return {"frames": n, "precision": tp / max(tp + fp, 1), "recall": tp / max(tp + fn, 1),
            "subtype_acc": float(np.mean(sub)) if sub else float("nan"),
            "color_acc": float(np.mean(col)) if col else float("nan"),
            "yaw_err_median_deg": float(np.median(dyaw)) if dyaw else float("nan"),
            "yaw_flip_rate": float(np.mean(flip)) if flip else float("nan"),
            "dist_err_median_m": float(np.median(np.abs(ddist))) if ddist else float("nan"),
            "dist_bias_m": float(np.mean(ddist)) if ddist else float("nan"),
            "height_err_median_m": float(np.median(np.abs(dh))) if dh else float("nan")}


# ---- training ------------------------------------------------------------------------------------------------------

def _shard_job(args):
    cfg_data, split, data_dir, shard, per, fpv = args
    torch.set_num_threads(1)
    return str(make_shard(Config(cfg_data), split, data_dir, shard, per, fpv))


def shards(cfg: Config) -> list[int]:
    """The shards a run reads: from `detector_first_shard` to `detector_shards`, the last `detector_heldout_shards`
    of them held out."""
    p = cfg["parser"]
    n, held, first = p["detector_shards"], p["detector_heldout_shards"], p["detector_first_shard"]
    for key in ("detector_shards", "detector_heldout_shards"):
        if p[key] <= 0:
            raise ConfigError(f"'parser.{key}' = {p[key]!r} must be positive")
    if held >= n:
        raise ConfigError("'parser.detector_heldout_shards' must be fewer than 'parser.detector_shards'")
    if not isinstance(first, int) or isinstance(first, bool) or not 0 <= first < n - held:
        raise ConfigError(f"'parser.detector_first_shard' = {first!r} must be an integer from 0 to {n - held - 1} "
                          "(below the held-out shards)")
    per, split = p["detector_scenes_per_shard"], cfg.split(p["detector_split"])
    if n * per > split.scenes:     # a shard past the split's last scene would hold no frames
        raise ConfigError(f"'parser.detector_shards' = {n} shards of {per} scenes needs {n * per} scenes, but split "
                          f"'{split.name}' has {split.scenes}: raise 'splits.{split.name}.scenes' or ask for fewer")
    return list(range(first, n))


def generate(cfg: Config, data_dir: Path, workers: int, which: list[int], echo=print) -> list[Path]:
    p = cfg["parser"]
    split = cfg.split(p["detector_split"])
    per, fpv = p["detector_scenes_per_shard"], p["detector_frames_per_video"]
    paths = [shard_path(data_dir, split, s, shard_backend(cfg, s)) for s in which]
    # a round's processes make shards of one backend (a path-traced shard takes about 4x a TinyRenderer one)
    todo = sorted((s for s, path in zip(which, paths) if not path.exists()), key=lambda s: (shard_backend(cfg, s), s))
    if todo:
        echo(f"train detector: making {len(todo)} shard(s) of {per} scenes x {fpv} frames (split {split.name})")
        jobs = [(cfg.data, split, Path(data_dir), s, per, fpv) for s in todo]
        # Fresh processes for every round of shards, even for one worker: pybullet's renderer keeps tens of MB per
        # scene after disconnecting, so one process making dozens of shards grows until the machine runs out of
        # memory. (Not max_tasks_per_child: with it, Python 3.11's pool can hang once a worker retires.)
        size = max(1, workers)
        for i in range(0, len(jobs), size):
            with ProcessPoolExecutor(size, mp_context=get_context("spawn")) as pool:
                for k, _ in enumerate(pool.map(_shard_job, jobs[i:i + size]), start=i):
                    echo(f"  shard {k + 1}/{len(todo)}")
    return paths


def _save(net, opt, step, out_dir: Path, manifest: dict) -> None:
    def cpu(x, moments=False):     # a checkpoint loads on any machine, whatever device trained it
        if isinstance(x, torch.Tensor):
            # Adam's moments in bfloat16 (float32's range, half its bytes): a width-64 head's checkpoint 27 -> 18 MB;
            # load_state_dict casts them back to the parameters' float32
            return x.cpu().to(torch.bfloat16) if moments and x.is_floating_point() and x.dim() else x.cpu()
        return {k: cpu(v, moments) for k, v in x.items()} if isinstance(x, dict) else x

    buf = io.BytesIO()
    torch.save({"net": cpu(net.state_dict()), "opt": cpu(opt.state_dict(), True), "step": step, "width": net.width,
                "blocks": net.blocks, "fine_blocks": net.fine_blocks,
                "schedule_start": manifest.get("schedule_start", 0)}, buf)
    out = Path(out_dir) / WEIGHTS_FILE
    with atomic_path(out) as tmp:
        tmp.write_bytes(buf.getvalue())
    write_json_atomic(Path(out_dir) / MANIFEST, {**manifest, "weights_sha256": file_digest(out)})
    _plot(manifest, Path(out_dir) / CURVE)


def _plot(manifest: dict, path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (a, b) = plt.subplots(1, 2, figsize=(9, 3.2))
    curve = manifest["loss_curve"]
    if curve:
        a.plot([c["step"] for c in curve], [c["loss"] for c in curve])
    a.set(xlabel="step", ylabel="training loss", yscale="log", title="loss")
    held = manifest["heldout_curve"]
    for key in ("recall", "precision", "subtype_acc", "color_acc"):
        b.plot([h["step"] for h in held], [h[key] for h in held], marker="o", label=key)
    b.set(xlabel="step", ylim=(0, 1), title="held-out frames")
    b.legend(fontsize=7)
    fig.tight_layout()
    with atomic_path(path) as tmp:
        fig.savefig(tmp, format="png", dpi=90)
    plt.close(fig)


def train_detector(cfg: Config, data_dir: Path, out_dir: Path = DEFAULT_DIR, workers: int = 1, resume: bool = False,
                   steps: int | None = None, minutes: float | None = None, grow_from: Path | None = None,
                   device: str = "cpu", loader_workers: int = 0, echo=print) -> dict:
    """`resume`: go on with the checkpoint in `out_dir` (its own width and blocks). `grow_from`: start a new run in
    `out_dir` from the trained head in `grow_from`, grown to `parser.detector_width`, `detector_blocks` and
    `detector_fine_blocks` (function-preserving), with a fresh
    optimiser and a cosine of its own from the head's step to `steps`. `device`: where the head trains ("cpu",
    "cuda"); `loader_workers`: processes making the batches (0: this one)."""
    if loader_workers < 0:
        raise ConfigError(f"--loader-workers {loader_workers}: use 0 (this process) or more")
    if device != "cpu" and not (device.startswith("cuda") and torch.cuda.is_available()):
        raise ConfigError(f"--device {device}: no such device here; use cpu"
                          + (" or cuda" if torch.cuda.is_available() else ""))
    p = cfg["parser"]
    for key in ("detector_batch", "detector_width"):
        if p[key] <= 0:
            raise ConfigError(f"'parser.{key}' = {p[key]!r} must be positive")
    blocks, fine_blocks = p.get("detector_blocks", 0), p.get("detector_fine_blocks", 0)
    for key, value in (("detector_blocks", blocks), ("detector_fine_blocks", fine_blocks)):
        if not isinstance(value, int) or isinstance(value, bool) or value < 0:
            raise ConfigError(f"'parser.{key}' = {value!r} must be a non-negative integer")
    if resume and grow_from is not None:
        raise ConfigError("--resume and --grow-from exclude each other: grow once, then resume the grown head")
    held = p["detector_heldout_shards"]
    paths = generate(cfg, data_dir, workers, shards(cfg), echo)
    train, val = Frames(paths[:-held]), Frames(paths[-held:])
    echo(f"train detector: {len(train)} training frames, {len(val)} held-out frames")
    total = steps or p["detector_steps"]
    torch.manual_seed(p["seed"])
    net = DetectNet(p["detector_width"], blocks, fine_blocks)
    step, manifest, schedule_start, opt_state = 0, None, 0, None
    ckpt = Path(out_dir) / WEIGHTS_FILE
    if resume:
        if not ckpt.exists():
            raise DetectorWeightsError(f"nothing to resume in {out_dir}: run `dynclevr train detector` without --resume")
        s = torch.load(ckpt, weights_only=True, map_location="cpu")
        if "opt" not in s:
            raise DetectorWeightsError(f"{ckpt} holds no optimiser state to resume: start a run from it with "
                                       f"`--grow-from {out_dir} --out NEW_DIR`")
        net = DetectNet(s["width"], s.get("blocks", 0), s.get("fine_blocks", 0))
        net.load_state_dict(s["net"])
        opt_state, step, schedule_start = s["opt"], s["step"], s.get("schedule_start", 0)
        manifest = json.loads((Path(out_dir) / MANIFEST).read_text())
        # the manifest's pixel_offset is for frames of render version 1 (load_detector); training on, the frames
        # have their vehicles on their labels
        for key in ("pixel_offset", "pixel_offset_why"):
            manifest.pop(key, None)
        echo(f"train detector: resuming at step {step}")
    elif grow_from is not None:
        net, step = _grown(grow_from, p["detector_width"], blocks, fine_blocks)
        schedule_start = step
        source = json.loads((Path(grow_from) / MANIFEST).read_text())
        manifest = {k: source[k] for k in ("loss_curve", "heldout_curve", "training_seconds", "runs")}
        manifest["grown"] = {"from": str(grow_from), "step": step, "width_from": source["params"].get("width"),
                             "width": net.width, "blocks": blocks, "fine_blocks": fine_blocks,
                             "metrics_heldout_before": source.get("metrics_heldout")}
        echo(f"train detector: the step-{step} head in {grow_from} grown to width {net.width}, {blocks} residual "
             f"blocks per coarse stage and {fine_blocks} at stride 4")
    if step >= total:
        raise ConfigError(f"the head is at step {step} already: ask for more with --steps (now {total})")
    net = net.to(device)
    opt = torch.optim.AdamW(net.parameters(), lr=p["detector_learning_rate"], weight_decay=1e-4)
    if opt_state is not None:
        opt.load_state_dict(opt_state)
    manifest = manifest or {"loss_curve": [], "heldout_curve": [], "training_seconds": 0.0}
    manifest["schedule_start"] = schedule_start
    manifest.update({
        "split": p["detector_split"], "split_seed": cfg.split(p["detector_split"]).seed,
        "shards_train": [f"{x.parent.name}/{x.name}" for x in paths[:-held]],
        "shards_heldout": [f"{x.parent.name}/{x.name}" for x in paths[-held:]],
        "frames_train": len(train), "frames_heldout": len(val), "steps_planned": total,
        "params": {"width": net.width, "blocks": net.blocks, "fine_blocks": net.fine_blocks,
                   "batch": p["detector_batch"], "lr": p["detector_learning_rate"],
                   "frames_per_video": p["detector_frames_per_video"], "min_pixels": MIN_PIXELS,
                   "realistic_every": p["detector_realistic_every"]},
        "machine": f"{platform.machine()}, torch {torch.__version__}, {torch.get_num_threads()} threads"
                   + (f", {torch.cuda.get_device_name(device)}" if device != "cpu" else ""),
        "command": "dynclevr train detector [--resume | --grow-from DIR]"
                   + (f" --device {device} --loader-workers {loader_workers}" if device != "cpu" else "")})
    B = p["detector_batch"]
    first_step = step
    # Draws are with replacement: past about one per frame the curve's end is frames seen before, and a head with
    # room to spare learns those frames rather than the scenes (journal: "A wider head")
    views = (total - step) * B / len(train)
    echo(f"train detector: {total - step} steps of {B} frames draw each of the {len(train)} frames {views:.1f} "
         "times on average" + (": more shards would make the draws fresh frames" if views > 1.2 else ""))
    h, w = (x // STRIDE for x in train.get(0)[0].shape[:2])
    batches = _batches(Samples(train, p["seed"], h, w), step, total, B, loader_workers)
    start = time.perf_counter()
    last_save = start
    base_seconds = manifest["training_seconds"]
    running = []
    net.train()
    while step < total:
        if minutes is not None and time.perf_counter() - start > minutes * 60:
            break
        done = step - schedule_start
        lr = (p["detector_learning_rate"] * 0.5 * (1 + math.cos(math.pi * done / (total - schedule_start)))
              * min(1.0, (done + 1) / 200))
        for g in opt.param_groups:
            g["lr"] = lr
        x, tg = next(batches)
        parts = losses(net(x.to(device).permute(0, 3, 1, 2).float().div_(255.0)), tg)
        loss = sum(parts.values())
        opt.zero_grad()
        loss.backward()
        opt.step()
        step += 1
        running.append(torch.stack([v.detach() for v in parts.values()]))   # no device sync every step
        if step % 50 == 0:
            mean = dict(zip(parts, torch.stack(running).mean(0).tolist()))
            manifest["loss_curve"].append({"step": step, "loss": sum(mean.values()), **mean})
            echo(f"  step {step}/{total}: loss {sum(mean.values()):.3f} ("
                 + ", ".join(f"{k} {v:.3f}" for k, v in mean.items()) + f") lr {lr:.5f}")
            running = []
        now = time.perf_counter()
        if now - last_save > p["checkpoint_minutes"] * 60 or step == total:
            manifest["heldout_curve"].append({"step": step, **evaluate(net, val, limit=200)})
            manifest["training_seconds"] = round(base_seconds + now - start, 1)
            manifest["steps_done"] = step
            _save(net, opt, step, out_dir, manifest)
            net.train()
            last_save = now
            echo(f"  checkpoint at step {step}: held-out {manifest['heldout_curve'][-1]}")
    net.eval()
    manifest["metrics_heldout"] = evaluate(net, val)
    manifest["training_seconds"] = round(base_seconds + time.perf_counter() - start, 1)
    manifest["steps_done"] = step
    manifest.setdefault("runs", []).append({"from_step": first_step, "to_step": step, "steps_planned": total,
                                            "seconds": round(time.perf_counter() - start, 1),
                                            "draws_per_frame": round((step - first_step) * B / len(train), 2)})
    _save(net, opt, step, out_dir, manifest)
    echo(f"train detector: step {step}, held-out {manifest['metrics_heldout']}; written to {out_dir}")
    return manifest
