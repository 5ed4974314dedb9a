"""`dynclevr train plane-distance`: the plane distance refiner (plane_distance.py) on the shipped head's detections.

Data: `parser.detector_split`'s shards from `plane_distance_first_shard` on (fresh scenes: no head trained on them,
never val or test), made by detector_data.py as the head's are. The head reads every frame as parse-scene reads it
(detections.detect), and each of its plane detections within a few pixels of a plane the truth shows (60 pixels or
more) becomes one crop, kept beside its shard (`shard_NNNN.planes.npz`, remade when the head changes); the target is
the log of the true distance over the head's. The last `plane_distance_heldout_shards` shards are held out.
Augmentation: mirroring (the centre's column and the relative yaw mirrored), brightness and a colour cast, and a
zoom of up to 6% about the centre, which is a head's distance that much further off (the target moves by its log).
The manifest records the data, the loss and held-out curves and the time; `--resume` goes on from the checkpoint.
"""

from __future__ import annotations

import io
import json
import math
import platform
import time
from pathlib import Path

import numpy as np
import torch
from torch.nn import functional as F

from dynclevr.artifacts import atomic_path, file_digest, write_json_atomic
from dynclevr.camera import Camera
from dynclevr.config import Config, ConfigError
from dynclevr.perception.detector_data import LABEL_COLUMNS, load_shard
from dynclevr.perception.detector_train import DEFAULT_DIR as DETECTOR_DIR, detector_digest, generate, load_detector
from dynclevr.perception.place import IS_PLANE
from dynclevr.perception.detections import detect
from dynclevr.perception.plane_distance import (DEFAULT_DIR, MANIFEST, N_FEATURES, WEIGHTS_FILE, PlaneDistanceNet,
                                                PlaneDistanceWeightsError, crop, features, half_side, is_plane,
                                                to_input)

COL = {c: i for i, c in enumerate(LABEL_COLUMNS)}
MIN_PIXELS = 60     # a plane this visible is one the head's distance must place
MATCH_PIXELS = 6.0  # a detection this near a plane's projected centre (or a quarter of its radius) is that plane
ZOOM = 0.06         # the augmentation's largest zoom, as a log


def shard_crops(shard: Path, head, parser: dict, camera) -> Path:
    """The shard's plane crops (x uint8 [N, 64, 64, 3], f float32 [N, N_FEATURES], y: log true / head distance),
    made once per head."""
    out = shard.with_suffix(".planes.npz")
    key = detector_digest(DETECTOR_DIR)
    try:
        with np.load(out) as z:
            if str(z["head"]) == key:
                return out
    except (OSError, ValueError, KeyError):
        pass
    frames, labels = load_shard(shard)
    plane = np.array([is_plane_subtype(int(s)) for s in labels[:, COL["subtype"]]], bool)
    labels = labels[plane & (labels[:, COL["pixels"]] >= MIN_PIXELS)]
    x, f, y = [], [], []
    for start in range(0, len(frames), 48):
        for t, dets in enumerate(detect(head, frames[start:start + 48], parser), start=start):
            lab = labels[labels[:, COL["frame"]] == t]
            for d in dets:
                if not len(lab) or not is_plane(d):
                    continue
                gap = np.hypot(lab[:, COL["u"]] - d.u, lab[:, COL["v"]] - d.v)
                j = int(np.argmin(gap))
                if gap[j] > max(MATCH_PIXELS, 0.25 * lab[j, COL["radius"]]):
                    continue
                x.append(crop(frames[t], d.u, d.v, half_side(camera, d)))
                f.append(features(camera, d))
                y.append(lab[j, COL["logdist"]] - math.log(max(d.dist, 0.5)))
    with atomic_path(out) as tmp:
        with open(tmp, "wb") as fh:
            np.savez(fh, head=key, x=np.array(x, np.uint8).reshape(-1, 64, 64, 3),
                     f=np.array(f, np.float32).reshape(-1, N_FEATURES), y=np.array(y, np.float32))
    return out


def is_plane_subtype(index: int) -> bool:
    return bool(IS_PLANE[index])


def _load(paths: list[Path]) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    zs = [np.load(p) for p in paths]
    return tuple(np.concatenate([z[k] for z in zs]) for k in ("x", "f", "y"))


def augment(x: np.ndarray, f: np.ndarray, y: np.ndarray, gen: torch.Generator):
    """A batch as tensors, mirrored, zoomed and lit at random (see the module's text)."""
    crops, f, y = to_input(x), torch.from_numpy(f).clone(), torch.from_numpy(y).clone()
    n = len(y)
    zoom = torch.exp((torch.rand(n, generator=gen) * 2 - 1) * ZOOM)
    mirror = torch.rand(n, generator=gen) < 0.5
    theta = torch.zeros(n, 2, 3)
    theta[:, 0, 0] = torch.where(mirror, -1.0, 1.0) / zoom
    theta[:, 1, 1] = 1 / zoom
    crops = F.grid_sample(crops, F.affine_grid(theta, list(crops.shape), align_corners=False), align_corners=False,
                          padding_mode="border")
    y -= torch.log(zoom)                    # drawn larger: the head's distance was that much too far
    f[:, 0] += torch.log(zoom)
    f[:, 1] /= zoom
    f[mirror, 2] *= -1                      # the centre's column and the relative yaw's sine, mirrored
    f[mirror, 5] *= -1
    crops = crops * (0.8 + 0.4 * torch.rand(n, 1, 1, 1, generator=gen)) + 0.4 * (torch.rand(n, 3, 1, 1, generator=gen) - 0.5)
    return crops, f, y


@torch.no_grad()
def evaluate(net: PlaneDistanceNet, x, f, y) -> dict:
    net.eval()
    pred = torch.cat([net(to_input(x[i:i + 256]), torch.from_numpy(f[i:i + 256])) for i in range(0, len(y), 256)])
    net.train()
    err = y - pred.numpy()
    return {"head_median": float(np.median(np.abs(y))), "refined_median": float(np.median(np.abs(err))),
            "head_p90": float(np.quantile(np.abs(y), 0.9)), "refined_p90": float(np.quantile(np.abs(err), 0.9)),
            "head_bias": float(np.mean(y)), "refined_bias": float(np.mean(err))}


def shard_numbers(cfg: Config) -> list[int]:
    """The shards a run reads, the last `plane_distance_heldout_shards` held out."""
    p = cfg["parser"]
    first, n, held = p["plane_distance_first_shard"], p["plane_distance_shards"], p["plane_distance_heldout_shards"]
    for key in ("plane_distance_first_shard", "plane_distance_shards", "plane_distance_heldout_shards",
                "plane_distance_epochs", "plane_distance_batch"):
        if not isinstance(p[key], int) or isinstance(p[key], bool) or p[key] < (0 if key.endswith("first_shard") else 1):
            raise ConfigError(f"'parser.{key}' = {p[key]!r} must be a positive integer")
    if first + held >= n:
        raise ConfigError(f"'parser.plane_distance_shards' = {n} leaves no training shard after "
                          f"plane_distance_first_shard = {first} and {held} held out: raise it")
    split, per = cfg.split(p["detector_split"]), p["detector_scenes_per_shard"]
    if n * per > split.scenes:
        raise ConfigError(f"'parser.plane_distance_shards' = {n} shards of {per} scenes needs {n * per} scenes, but "
                          f"split '{split.name}' has {split.scenes}: raise 'splits.{split.name}.scenes'")
    return list(range(first, n))


def calibration(cfg: Config) -> Camera:
    """The renderer's intrinsics (all a crop's size reads); the pose does not matter here."""
    sc = cfg["scene"]
    return Camera(tuple(sc["camera_position"]), tuple(sc["camera_look_at"]), float(sc["focal_length_mm"]),
                  float(sc["sensor_width_mm"]), int(cfg["render"]["width"]), int(cfg["render"]["height"]))


def train_plane_distance(cfg: Config, data_dir: Path, out_dir: Path = DEFAULT_DIR, workers: int = 1,
                         resume: bool = False, echo=print) -> dict:
    p = cfg["parser"]
    which = shard_numbers(cfg)
    held = p["plane_distance_heldout_shards"]
    if p["plane_distance_learning_rate"] <= 0:
        raise ConfigError(f"'parser.plane_distance_learning_rate' = {p['plane_distance_learning_rate']!r} must be "
                          "positive")
    shards = generate(cfg, data_dir, workers, which, echo)
    head, camera = load_detector(DETECTOR_DIR), calibration(cfg)
    echo(f"train plane-distance: reading {len(shards)} shard(s) through the head")
    crops = [shard_crops(s, head, p, camera) for s in shards]
    x, f, y = _load(crops[:-held])
    hx, hf, hy = _load(crops[-held:])
    echo(f"train plane-distance: {len(y)} training crops, {len(hy)} held out")
    torch.manual_seed(p["seed"])
    gen = torch.Generator().manual_seed(p["seed"])
    net = PlaneDistanceNet()
    B, epochs = p["plane_distance_batch"], p["plane_distance_epochs"]
    per_epoch = len(y) // B
    if per_epoch == 0:
        raise ConfigError(f"{len(y)} training crops make no batch of {B}: raise 'parser.plane_distance_shards'")
    lr, total_steps = p["plane_distance_learning_rate"], epochs * per_epoch
    opt = torch.optim.AdamW(net.parameters(), lr=lr, weight_decay=1e-4)
    epoch, manifest = 0, {"loss_curve": [], "heldout_curve": [], "training_seconds": 0.0}
    ckpt = Path(out_dir) / WEIGHTS_FILE
    if resume:
        if not ckpt.exists():
            raise PlaneDistanceWeightsError(f"nothing to resume in {out_dir}: run `dynclevr train plane-distance` "
                                            "without --resume")
        state = torch.load(ckpt, weights_only=True, map_location="cpu")
        if "opt" not in state:
            raise PlaneDistanceWeightsError(f"{ckpt} holds no optimiser state to resume")
        net.load_state_dict(state["net"])
        opt.load_state_dict(state["opt"])
        epoch, gen_state = state["epoch"], state["generator"]
        gen.set_state(gen_state)
        manifest = json.loads((Path(out_dir) / MANIFEST).read_text())
        echo(f"train plane-distance: resuming after epoch {epoch}")
    if epoch >= epochs:
        raise ConfigError(f"the refiner has trained {epoch} epochs already: raise 'parser.plane_distance_epochs'")
    manifest.update({
        "split": p["detector_split"], "split_seed": cfg.split(p["detector_split"]).seed,
        "shards_train": [x.name for x in shards[:-held]], "shards_heldout": [x.name for x in shards[-held:]],
        "head": detector_digest(DETECTOR_DIR), "crops_train": len(y), "crops_heldout": len(hy),
        "epochs_planned": epochs,
        "params": {"batch": B, "lr": p["plane_distance_learning_rate"], "zoom": ZOOM, "crop": 64,
                   "min_pixels": MIN_PIXELS, "match_pixels": MATCH_PIXELS},
        "machine": f"{platform.machine()}, torch {torch.__version__}, {torch.get_num_threads()} threads",
        "command": "dynclevr train plane-distance [--resume]"})
    order = np.random.default_rng(p["seed"])
    for _ in range(epoch):          # the epochs already trained drew these orders
        order.permutation(len(y))
    net.train()
    while epoch < epochs:
        start, total = time.time(), 0.0
        perm = order.permutation(len(y))
        for i in range(per_epoch):
            for group in opt.param_groups:
                group["lr"] = learning_rate(lr, epoch * per_epoch + i, total_steps)
            idx = np.sort(perm[i * B:(i + 1) * B])
            crops_b, feats, target = augment(x[idx], f[idx], y[idx], gen)
            loss = F.smooth_l1_loss(net(crops_b, feats), target, beta=0.02)
            opt.zero_grad()
            loss.backward()
            opt.step()
            total += loss.item()
        epoch += 1
        held_out = evaluate(net, hx, hf, hy)
        manifest["loss_curve"].append({"epoch": epoch, "loss": total / per_epoch})
        manifest["heldout_curve"].append({"epoch": epoch, **held_out})
        manifest["training_seconds"] += time.time() - start
        manifest["metrics_heldout"] = held_out
        _save(net, opt, gen, epoch, Path(out_dir), manifest)
        echo(f"train plane-distance: epoch {epoch}/{epochs}, loss {total / per_epoch:.4f}, held-out |log error| "
             f"median {held_out['refined_median']:.4f} (the head's {held_out['head_median']:.4f})")
    return manifest


def learning_rate(top: float, step: int, total: int) -> float:
    """A short linear warm-up, then a cosine to zero at the planned step (raising the epochs on resume stretches
    what is left of it)."""
    warm = max(1, total // 20)
    if step < warm:
        return top * (step + 1) / warm
    return top * 0.5 * (1 + math.cos(math.pi * min(1.0, (step - warm) / max(1, total - warm))))


def _save(net, opt, gen, epoch: int, out_dir: Path, manifest: dict) -> None:
    out_dir.mkdir(parents=True, exist_ok=True)
    buf = io.BytesIO()
    torch.save({"net": net.state_dict(), "opt": opt.state_dict(), "generator": gen.get_state(), "epoch": epoch},
               buf)
    out = out_dir / WEIGHTS_FILE
    with atomic_path(out) as tmp:
        tmp.write_bytes(buf.getvalue())
    write_json_atomic(out_dir / MANIFEST, {**manifest, "weights_sha256": file_digest(out)})
