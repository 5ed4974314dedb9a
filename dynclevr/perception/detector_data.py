"""Training frames for the detection head, made on demand by the generator itself (simulate + render), never from
the val or test seeds.

A scene is sampled and simulated exactly as the simulate stage does (its factual run only: the detector needs no
counterfactuals), and `frames_per_video` of its frames are drawn by the render stage's renderer and JPEG-coded as
the video stage codes them, so the detector trains on the pixels it will see. Per frame and object, the targets
come from the truth and the exact instance mask:

| column | meaning |
|---|---|
| frame | row of the shard's frame list |
| u, v | the projected 3D centre, pixels (may lie outside the image for an object partly out of view) |
| pixels | visible pixels in the instance mask (occlusion and the image border included) |
| subtype, color | indices into SUBTYPES and COLOR_NAMES |
| alpha | yaw relative to the camera ray's azimuth (what the image shows of the heading; yaw = alpha + azimuth) |
| logdist | log of the camera-to-centre distance (m) |
| height | the centre's z (m) |
| radius | the object's projected half size, pixels (the heatmap's spread) |

Shards (`<data>/<split>/detector/shard_NNNN.npz`) hold `scenes` of them; a shard is written atomically and reused
when it is there, readable and of the render stage's version, so generation resumes where it stopped. With
`parser.detector_realistic_every` = K, every K-th shard (index K-1 mod K) is path-traced by the realistic backend
instead (`detector-mitsuba/shard_NNNN.npz`), so that the head learns what a vehicle looks like under sky light and
soft shadows, not only TinyRenderer's shading.
"""

from __future__ import annotations

import math
import zipfile
from pathlib import Path
from typing import TYPE_CHECKING

import cv2
import numpy as np

from dynclevr.artifacts import atomic_path
from dynclevr.assets.catalogue import SUBTYPES
from dynclevr.colors import COLOR_NAMES
from dynclevr.config import Config, ConfigError, Split, scene_seed

if TYPE_CHECKING:   # training reads shards alone: a machine without the generator's packages (mcap) trains too
    from dynclevr.scene import Scene4D

LABEL_COLUMNS = ("frame", "u", "v", "pixels", "subtype", "color", "alpha", "logdist", "height", "radius")
SUBTYPE_INDEX = {s: i for i, s in enumerate(SUBTYPES)}
FRAME_STREAM = 0x44455445   # the frame choice draws from its own stream of the scene seed
REALISTIC = "mitsuba"       # the backend of the path-traced shards


def yaw_of(quat: np.ndarray) -> np.ndarray:
    """Heading angle (about z) of quaternions [..., 4] (x, y, z, w)."""
    x, y, z, w = np.moveaxis(np.asarray(quat, float), -1, 0)
    return np.arctan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))


def azimuth(camera_position, points: np.ndarray) -> np.ndarray:
    d = np.asarray(points, float) - np.asarray(camera_position, float)
    return np.arctan2(d[..., 1], d[..., 0])


def frame_labels(truth: Scene4D, t: int, mask: np.ndarray, frame_row: int) -> list[list[float]]:
    cam = truth.camera
    rows = []
    counts = np.bincount(mask[mask >= 0].ravel().astype(np.int64), minlength=max(o.id for o in truth.objects) + 1)
    for i, obj in enumerate(truth.objects):
        pos = truth.position[t, i]
        (u, v), z = cam.project(pos)
        if z < 0.5:
            continue
        dist = float(np.linalg.norm(pos - np.asarray(cam.position)))
        alpha = float(yaw_of(truth.orientation[t, i]) - azimuth(cam.position, pos))
        alpha = math.atan2(math.sin(alpha), math.cos(alpha))
        radius = cam.fx * max(obj.size) / 2 / dist
        rows.append([frame_row, u, v, counts[obj.id], SUBTYPE_INDEX[obj.shape], COLOR_NAMES.index(obj.color),
                     alpha, math.log(dist), pos[2], radius])
    return rows


def render_frames(cfg: Config, seed: int, frames_per_video: int,
                  backend: str | None = None) -> tuple[list[bytes], list[list[float]]]:
    """One scene: (JPEG bytes per chosen frame, label rows with frame = index into that list), drawn by `backend`
    (None: `render.backend`)."""
    from dynclevr.physics import PhysicsParams, simulate
    from dynclevr.render import make_renderer
    from dynclevr.render.environments import environment
    from dynclevr.scene import Scene4D
    from dynclevr.stages.render import appearance, check
    from dynclevr.stages.simulate import sample_scene, visibility
    from dynclevr.video import encode_rgb

    params = PhysicsParams.from_config(cfg)
    T = cfg["video"]["frames"]
    objects, bodies, camera = sample_scene(np.random.default_rng(seed), cfg)
    tr = simulate(bodies, params, T)
    truth = Scene4D("train", params.fps, camera, objects, tr.position, tr.orientation, tr.velocity,
                    tr.angular_velocity, tr.acceleration, tr.engine, tr.floating, visibility(camera, tr.position))
    r = {**check(cfg), **({"backend": backend} if backend else {})}
    cam = camera.with_resolution(r["width"], r["height"])
    truth.camera = cam
    env_index, variants = appearance(seed, len(objects))
    chosen = np.sort(np.random.default_rng([seed, FRAME_STREAM]).choice(T, frames_per_video, replace=False))
    jpegs, labels = [], []
    with make_renderer(r["backend"], truth, cam, environment(env_index), variants, r) as renderer:
        for t in chosen:
            rgb, mask, _ = renderer.render(int(t))
            labels += frame_labels(truth, int(t), mask, len(jpegs))
            jpegs.append(encode_rgb(rgb))
    return jpegs, labels


def shard_backend(cfg: Config, shard: int) -> str:
    every = cfg["parser"]["detector_realistic_every"]
    if not isinstance(every, int) or isinstance(every, bool) or every < 0:
        raise ConfigError(f"'parser.detector_realistic_every' = {every!r} must be a non-negative integer "
                          "(0: no path-traced shards)")
    return REALISTIC if every and shard % every == every - 1 else cfg["render"]["backend"]


def shard_path(data_dir: Path, split: Split, shard: int, backend: str = "tiny") -> Path:
    folder = "detector" if backend == "tiny" else f"detector-{backend}"
    return Path(data_dir) / split.name / folder / f"shard_{shard:04d}.npz"


def make_shard(cfg: Config, split: Split, data_dir: Path, shard: int, scenes_per_shard: int,
               frames_per_video: int) -> Path:
    from dynclevr.stages.render import VERSION

    backend = shard_backend(cfg, shard)
    out = shard_path(data_dir, split, shard, backend)
    if _made_by(out, VERSION):
        return out
    jpegs, labels = [], []
    for i in range(shard * scenes_per_shard, min((shard + 1) * scenes_per_shard, split.scenes)):
        j, lab = render_frames(cfg, scene_seed(split.seed, i), frames_per_video, backend)
        for row in lab:
            row[0] += len(jpegs)
        jpegs += j
        labels += lab
    offsets = np.cumsum([0] + [len(b) for b in jpegs])
    out.parent.mkdir(parents=True, exist_ok=True)
    with atomic_path(out) as tmp:
        with open(tmp, "wb") as f:
            np.savez(f, jpeg=np.frombuffer(b"".join(jpegs), np.uint8), offsets=offsets, render_version=VERSION,
                     labels=np.array(labels, np.float32).reshape(-1, len(LABEL_COLUMNS)))
    return out


def _made_by(path: Path, render_version: int) -> bool:
    """A readable shard already there from this render stage's version (version 1 drew vehicles half a pixel off);
    anything else is drawn again."""
    try:
        with np.load(path) as z:
            return int(z["render_version"]) == render_version if "render_version" in z.files else render_version == 1
    except (OSError, ValueError, zipfile.BadZipFile):
        return False


def load_shard(path: Path) -> tuple[np.ndarray, np.ndarray]:
    """(frames uint8 [F, H, W, 3], labels [L, len(LABEL_COLUMNS)])."""
    z = np.load(path)
    buf, off = z["jpeg"], z["offsets"]
    frames = np.stack([cv2.cvtColor(cv2.imdecode(buf[off[k]:off[k + 1]], cv2.IMREAD_COLOR), cv2.COLOR_BGR2RGB)
                       for k in range(len(off) - 1)])
    return frames, z["labels"]
