"""`dynclevr train object-head`: the object head on the detection head's training frames, resumably.

Data: the detection head's shards (`parser.detector_split`, fresh seeds, never val or test; detector_data.py), the
first `object_head_shards` of them, and its held-out shards. The detection head is frozen: its features of every
training frame are computed once and kept in memory (float16, about 0.46 MB a frame), so a step costs only the
object head. Each step draws `object_head_batch` objects with at least MIN_PIXELS visible pixels from all the
frames; a window's centre and distance are the truth's plus noise like the detection head's errors (a few pixels,
a tail of larger misses; a few per cent of distance), so the object head learns to correct what it will be given.
(No augmentation: the frozen head's features of a jittered frame would have to be computed per step.)
Loss: L1 on the centre offset (window pixels) and 5 x the log distance ratio, cross-entropy on sub-type and colour,
L1 on the yaw's (sin, cos) and the height.
Held-out metrics compare, on the detection head's own matched detections, the head's values with the object
head's (`evaluate`): what the second look adds. Checkpoints every `checkpoint_minutes` to
weights/object_head/ (object_head.pt with the optimiser and step, manifest.json, curve.png); `--resume` continues.
"""

from __future__ import annotations

import io
import json
import math
import platform
import time
from dataclasses import replace
from pathlib import Path

import numpy as np
import torch
from torch.nn import functional as F

from dynclevr import WEIGHTS_DIR, DynclevrError
from dynclevr.artifacts import atomic_path, file_digest, write_json_atomic
from dynclevr.config import Config, ConfigError
from dynclevr.perception.detector import STRIDE, decode, run
from dynclevr.perception.detector_train import (COL, MIN_PIXELS, DetectorWeightsError, Frames, generate,
                                                load_detector, match)
from dynclevr.perception.detector_train import DEFAULT_DIR as DETECTOR_DIR
from dynclevr.perception.object_head import CHANNELS, SIZE, SPAN, ObjectNet, TwoStage, refine, roi_grid, sample

DEFAULT_DIR = WEIGHTS_DIR / "object_head"
WEIGHTS_FILE, MANIFEST, CURVE = "object_head.pt", "manifest.json", "curve.png"


class ObjectHeadWeightsError(DynclevrError):
    pass


def load_object_head(weights_dir: Path = DEFAULT_DIR) -> ObjectNet:
    path, manifest = Path(weights_dir) / WEIGHTS_FILE, Path(weights_dir) / MANIFEST
    if not path.exists() or not manifest.exists():
        raise ObjectHeadWeightsError(f"object-head weights missing in {weights_dir}: run `dynclevr train object-head`"
                                     " (or set parser.object_head = false)")
    if json.loads(manifest.read_text()).get("weights_sha256") != file_digest(path):
        raise ObjectHeadWeightsError(f"{path} does not match its manifest: rerun `dynclevr train object-head --resume`")
    s = torch.load(path, weights_only=True)
    net = ObjectNet(s["features"], s["width"])
    net.load_state_dict(s["net"])
    net.eval()
    return net


def object_head_digest(weights_dir: Path = DEFAULT_DIR) -> str:
    path = Path(weights_dir) / MANIFEST
    return file_digest(path) if path.exists() else "missing"


def load_two_stage(cfg: Config, detector_dir: Path = DETECTOR_DIR, object_dir: Path = DEFAULT_DIR) -> TwoStage:
    """The detection head, and the object head where `parser.object_head` is on."""
    p = cfg["parser"]
    if not isinstance(p["object_head"], bool):
        raise ConfigError(f"'parser.object_head' = {p['object_head']!r} must be true or false")
    if not isinstance(p["object_head_passes"], int) or p["object_head_passes"] < 1:
        raise ConfigError(f"'parser.object_head_passes' = {p['object_head_passes']!r} must be a positive integer")
    objects = load_object_head(object_dir) if p["object_head"] else None
    return TwoStage(load_detector(detector_dir), objects, p["object_head_passes"])


def two_stage_digest(cfg: Config, detector_dir: Path = DETECTOR_DIR, object_dir: Path = DEFAULT_DIR) -> str:
    """What a parse depends on of the two heads' weights."""
    from dynclevr.perception.detector_train import detector_digest

    d = detector_digest(detector_dir)
    return d + ("+" + object_head_digest(object_dir) if cfg["parser"]["object_head"] else "")


def fx_of(cfg: Config) -> float:
    s = cfg["scene"]
    return s["focal_length_mm"] / s["sensor_width_mm"] * cfg["render"]["width"]


def windows(lab: np.ndarray, fx: float, rng) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Training windows around the objects `lab` [K, len(LABEL_COLUMNS)]: their centres u, v and scales, the truth's
    centre and distance moved by noise like the detection head's errors, and the targets [K, 8]: offset (2, window
    pixels), log distance ratio, sub-type, colour, sin and cos of the yaw, height."""
    K = len(lab)
    dist = np.exp(lab[:, COL["logdist"]].astype(np.float64))
    dist_w = dist * np.exp(rng.normal(0, 0.05, K))
    scale = SIZE / (fx * SPAN / np.maximum(dist_w, 0.5))
    # window pixels (about 2 frame pixels at 11 m): the head's usual error, and its tail
    miss = np.choose(np.searchsorted([0.5, 0.85], rng.random(K)), [1.0, 2.5, 6.0])
    d = rng.normal(0, 1, (K, 2)) * miss[:, None]
    u, v = lab[:, COL["u"]] + d[:, 0] / scale, lab[:, COL["v"]] + d[:, 1] / scale
    alpha = lab[:, COL["alpha"]]
    tg = np.stack([-d[:, 0], -d[:, 1], np.log(dist / dist_w), lab[:, COL["subtype"]], lab[:, COL["color"]],
                   np.sin(alpha), np.cos(alpha), lab[:, COL["height"]]], 1)
    return u, v, scale, tg.astype(np.float32)


class HeadFeatures:
    """The frozen detection head's features of every frame of some shards (float16, in memory) and the labels of
    the objects in them with at least MIN_PIXELS visible pixels."""

    def __init__(self, detector, frames: Frames, echo=print):
        maps = []
        for s in range(0, len(frames), 32):
            rgb = np.stack([frames.get(k)[0] for k in range(s, min(len(frames), s + 32))])
            maps.append(run(detector, rgb, hidden=True)[1].half())
            if (s // 32) % 50 == 0:
                echo(f"  the detection head's features: {s + len(rgb)}/{len(frames)} frames")
        self.hidden = torch.cat(maps)
        self.labels = frames.labels[frames.labels[:, COL["pixels"]] >= MIN_PIXELS]


def losses(pred: torch.Tensor, g: torch.Tensor) -> dict:
    return {"offset": (pred[:, CHANNELS["offset"]] - g[:, :2]).abs().sum(1).mean(),
            "logratio": (pred[:, CHANNELS["logratio"]][:, 0] - g[:, 2]).abs().mean() * 5,
            "subtype": F.cross_entropy(pred[:, CHANNELS["subtype"]], g[:, 3].long()),
            "color": F.cross_entropy(pred[:, CHANNELS["color"]], g[:, 4].long()),
            "alpha": (pred[:, CHANNELS["alpha"]] - g[:, 5:7]).abs().sum(1).mean(),
            "height": (pred[:, CHANNELS["height"]][:, 0] - g[:, 7]).abs().mean()}


@torch.no_grad()
def evaluate(net: ObjectNet, detector, frames: Frames, fx: float, threshold: float = 0.3,
             limit: int | None = None) -> dict:
    """The detection head's detections matched to the truth (detector_train.match), their values as the head gives
    them ("head_") and as the object head refines them ("object_")."""
    n = len(frames) if limit is None else min(limit, len(frames))
    errs: dict[str, list] = {}
    for s in range(0, n, 16):
        batch = [frames.get(k) for k in range(s, min(n, s + 16))]
        maps, hidden = run(detector, np.stack([b[0] for b in batch]), hidden=True)
        dets = [decode(m, threshold) for m in maps]
        refined = refine(net, hidden, dets, fx)
        # "both": the object head's place and pose, the two heads' sub-type and colour evidence summed
        both = [[replace(r, subtype_logp=r.subtype_logp + d.subtype_logp, color_logp=r.color_logp + d.color_logp)
                 for r, d in zip(rs, ds)] for rs, ds in zip(refined, dets)]
        for name, ds in (("head", dets), ("object", refined), ("both", both)):
            for (_, lab), d in zip(batch, ds):
                for det, o in match(d, lab[lab[:, COL["pixels"]] >= MIN_PIXELS]):
                    e = errs.setdefault(name, {"px": [], "sub": [], "col": [], "yaw": [], "dist": []})
                    e["px"].append(math.hypot(det.u - o[COL["u"]], det.v - o[COL["v"]]))
                    e["sub"].append(int(np.argmax(det.subtype_logp)) == int(o[COL["subtype"]]))
                    e["col"].append(int(np.argmax(det.color_logp)) == int(o[COL["color"]]))
                    e["yaw"].append(abs((det.alpha - o[COL["alpha"]] + math.pi) % (2 * math.pi) - math.pi))
                    e["dist"].append(det.dist - math.exp(o[COL["logdist"]]))
    out = {"frames": n, "matched": len(errs.get("head", {}).get("px", []))}
    for name, e in errs.items():
        yaw = np.degrees(e["yaw"])
        out.update({f"{name}_centre_px_median": float(np.median(e["px"])),
                    f"{name}_centre_px_p90": float(np.percentile(e["px"], 90)),
                    f"{name}_subtype_acc": float(np.mean(e["sub"])), f"{name}_color_acc": float(np.mean(e["col"])),
                    f"{name}_yaw_median_deg": float(np.median(yaw)), f"{name}_yaw_flips": float(np.mean(yaw > 135)),
                    f"{name}_dist_err_median_m": float(np.median(np.abs(e["dist"]))),
                    f"{name}_dist_bias_m": float(np.mean(e["dist"]))})
    return out


def _save(net, opt, step, out_dir: Path, manifest: dict) -> None:
    buf = io.BytesIO()
    torch.save({"net": net.state_dict(), "opt": opt.state_dict(), "step": step, "width": net.width,
                "features": net.features}, buf)
    out = Path(out_dir) / WEIGHTS_FILE
    out.parent.mkdir(parents=True, exist_ok=True)
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
    for key, style in (("subtype_acc", "o"), ("centre_px_median", "s")):
        for who, ls in (("head", "--"), ("object", "-")):
            b.plot([h["step"] for h in held], [h[f"{who}_{key}"] for h in held], ls, marker=style,
                   label=f"{who} {key}")
    b.set(xlabel="step", title="held-out detections (head vs object head)")
    b.legend(fontsize=7)
    fig.tight_layout()
    with atomic_path(path) as tmp:
        fig.savefig(tmp, format="png", dpi=90)
    plt.close(fig)


def train_object_head(cfg: Config, data_dir: Path, out_dir: Path = DEFAULT_DIR, workers: int = 1,
                      resume: bool = False, steps: int | None = None, minutes: float | None = None,
                      detector_dir: Path = DETECTOR_DIR, echo=print) -> dict:
    p = cfg["parser"]
    for key in ("object_head_shards", "object_head_batch", "object_head_width", "object_head_steps"):
        if not isinstance(p[key], int) or p[key] <= 0:
            raise ConfigError(f"'parser.{key}' = {p[key]!r} must be a positive integer")
    n, held = p["detector_shards"], p["detector_heldout_shards"]
    if p["object_head_shards"] > n - held:
        raise ConfigError(f"'parser.object_head_shards' = {p['object_head_shards']} is more than the detection "
                          f"head's {n - held} training shards: raise parser.detector_shards too")
    heldout = list(range(n - held, n))
    paths = generate(cfg, data_dir, workers, heldout + list(range(p["object_head_shards"])), echo)
    val, train = Frames(paths[:held]), Frames(paths[held:])
    try:
        detector = load_detector(detector_dir)
    except DetectorWeightsError as e:
        raise ObjectHeadWeightsError(f"the object head's held-out metrics need the detection head: {e}") from None
    fx = fx_of(cfg)
    echo(f"train object-head: {len(train)} training frames, {len(val)} held-out frames")
    feats = HeadFeatures(detector, train, echo)
    del train
    total = steps or p["object_head_steps"]
    torch.manual_seed(p["seed"])
    features = 3 * detector.width // 2
    net, step, opt_state, manifest = ObjectNet(features, p["object_head_width"]), 0, None, None
    ckpt = Path(out_dir) / WEIGHTS_FILE
    if resume:
        if not ckpt.exists():
            raise ObjectHeadWeightsError(f"nothing to resume in {out_dir}: run `dynclevr train object-head` "
                                         "without --resume")
        s = torch.load(ckpt, weights_only=True)
        net = ObjectNet(s["features"], s["width"])
        net.load_state_dict(s["net"])
        opt_state, step = s["opt"], s["step"]
        manifest = json.loads((Path(out_dir) / MANIFEST).read_text())
        echo(f"train object-head: resuming at step {step}")
    if step >= total:
        raise ConfigError(f"the object head is at step {step} already: ask for more with --steps (now {total})")
    lr0 = p["object_head_learning_rate"]
    opt = torch.optim.AdamW(net.parameters(), lr=lr0, weight_decay=1e-4)
    if opt_state is not None:
        opt.load_state_dict(opt_state)
    manifest = manifest or {"loss_curve": [], "heldout_curve": [], "training_seconds": 0.0}
    manifest.update({
        "split": p["detector_split"], "split_seed": cfg.split(p["detector_split"]).seed,
        "shards_train": [x.name for x in paths[held:]], "shards_heldout": [x.name for x in paths[:held]],
        "frames_train": len(feats.hidden), "objects_train": len(feats.labels), "frames_heldout": len(val), "steps_planned": total,
        "params": {"width": net.width, "features": net.features, "batch": p["object_head_batch"], "lr": lr0,
                   "min_pixels": MIN_PIXELS},
        "detector_weights": file_digest(Path(detector_dir) / "detector.pt"),
        "machine": f"{platform.machine()}, torch {torch.__version__}, {torch.get_num_threads()} threads",
        "command": "dynclevr train object-head [--resume] [--steps N] [--minutes M]"})
    rng = np.random.default_rng([p["seed"], step, 0x0B7EC7])
    start = last_save = time.perf_counter()
    base_seconds, first_step, running = manifest["training_seconds"], step, []
    net.train()
    while step < total:
        if minutes is not None and time.perf_counter() - start > minutes * 60:
            break
        lr = lr0 * 0.5 * (1 + math.cos(math.pi * step / total)) * min(1.0, (step + 1) / 200)
        for g in opt.param_groups:
            g["lr"] = lr
        lab = feats.labels[rng.integers(len(feats.labels), size=p["object_head_batch"])]
        u, v, scale, tg = windows(lab, fx, rng)
        grid = roi_grid(u, v, scale, feats.hidden.shape[-1] * STRIDE, feats.hidden.shape[-2] * STRIDE)
        parts = losses(net(sample(feats.hidden, lab[:, COL["frame"]].astype(np.int64), grid)), torch.from_numpy(tg))
        loss = sum(parts.values())
        opt.zero_grad()
        loss.backward()
        opt.step()
        step += 1
        running.append({k: float(v.detach()) for k, v in parts.items()})
        if step % 50 == 0:
            mean = {k: float(np.mean([r[k] for r in running])) for k in running[0]}
            manifest["loss_curve"].append({"step": step, "loss": sum(mean.values()), **mean})
            echo(f"  step {step}/{total}: loss {sum(mean.values()):.3f} ("
                 + ", ".join(f"{k} {v:.3f}" for k, v in mean.items()) + f") lr {lr:.5f}")
            running = []
        now = time.perf_counter()
        if now - last_save > p["checkpoint_minutes"] * 60:
            manifest["heldout_curve"].append({"step": step, **evaluate(net, detector, val, fx, limit=150)})
            manifest["training_seconds"] = round(base_seconds + now - start, 1)
            manifest["steps_done"] = step
            _save(net, opt, step, out_dir, manifest)
            net.train()
            last_save = now
            echo(f"  checkpoint at step {step}: held-out {manifest['heldout_curve'][-1]}")
    manifest["metrics_heldout"] = evaluate(net, detector, val, fx)
    manifest["heldout_curve"].append({"step": step, **evaluate(net, detector, val, fx, limit=150)})
    manifest["training_seconds"] = round(base_seconds + time.perf_counter() - start, 1)
    manifest["steps_done"] = step
    manifest.setdefault("runs", []).append({"from_step": first_step, "to_step": step, "steps_planned": total,
                                            "seconds": round(time.perf_counter() - start, 1)})
    _save(net, opt, step, out_dir, manifest)
    echo(f"train object-head: step {step}, held-out {manifest['metrics_heldout']}; written to {out_dir}")
    return manifest
