"""The detection head's peaks in every frame of a video (detector.py), computed once per video and kept.

parse-scene's rows (the model, its ablation without the prior, the particle filter, the per-frame baseline) and
`dynclevr train collisions` all read the same head on the same frames, and the head is most of parse-scene's time
(about 10 of 13 s a video on 2 threads, read twice with `parser.detector_flip`). So a video's detections are kept in
`<data>/.cache/<split>/detections/<scene>.npz` under a key of everything they depend on: the video file, the head's
weights and the decode settings. A missing, unreadable or stale file is recomputed and replaced atomically. It is a
cache that only parse-scene reads (its outputs' own cache keys already cover the video, the weights and the params),
so it has no manifest, and it lives outside the split's folder of artifacts: deleting `<data>/.cache` loses nothing
but time. The detections are the video's RGB frames read through the head, never the truth.
"""

from __future__ import annotations

import zipfile
from pathlib import Path
from typing import Callable

import numpy as np

from dynclevr.artifacts import Store, atomic_path, file_digest
from dynclevr.config import stable_digest
from dynclevr.perception.detector import Detection, decode, run

PARAMS = ("detect_threshold", "max_detections", "detector_flip")
_SCALARS = ("u", "v", "score", "alpha", "dist", "height")


def detect(net, frames: np.ndarray, parser: dict) -> list[list[Detection]]:
    """Per frame, the head's detections as `parser` (the [parser] section) decodes them."""
    maps = run(net, frames, flip=parser["detector_flip"])
    return [decode(m, parser["detect_threshold"], parser["max_detections"], offset=net.pixel_offset) for m in maps]


def cache_path(store: Store, scene: str) -> Path:
    return Path(store.data_dir) / ".cache" / store.split / "detections" / f"{scene}.npz"


def cache_key(video: Path, detector: str, parser: dict) -> str:
    """`detector`: the head's digest (detector_train.detector_digest)."""
    return stable_digest({"video": file_digest(video), "detector": detector, **{k: parser[k] for k in PARAMS}})


def cached(path: Path, key: str, compute: Callable[[], list[list[Detection]]]) -> list[list[Detection]]:
    """The detections stored at `path` under `key`; else `compute()`'s, stored there."""
    found = load(path, key)
    if found is not None:
        return found
    detections = compute()
    save(path, key, detections)
    return detections


def save(path: Path, key: str, detections: list[list[Detection]]) -> None:
    flat = [(t, d) for t, frame in enumerate(detections) for d in frame]
    n_sub, n_col = _sizes(flat)
    with atomic_path(path) as tmp:
        with open(tmp, "wb") as f:
            np.savez(f, key=key, frames=len(detections),
                     frame=np.array([t for t, _ in flat], np.int64),
                     **{k: np.array([getattr(d, k) for _, d in flat], np.float64) for k in _SCALARS},
                     subtype_logp=np.array([d.subtype_logp for _, d in flat], np.float32).reshape(len(flat), n_sub),
                     color_logp=np.array([d.color_logp for _, d in flat], np.float32).reshape(len(flat), n_col))


def load(path: Path, key: str) -> list[list[Detection]] | None:
    """None where the file is missing, unreadable or of another key."""
    try:
        with np.load(path) as z:
            if str(z["key"]) != key:
                return None
            out = [[] for _ in range(int(z["frames"]))]
            cols = {k: z[k] for k in (*_SCALARS, "frame", "subtype_logp", "color_logp")}
    except (OSError, ValueError, KeyError, zipfile.BadZipFile, EOFError):
        return None
    for n, t in enumerate(cols["frame"].tolist()):
        out[t].append(Detection(**{k: float(cols[k][n]) for k in _SCALARS},
                                subtype_logp=cols["subtype_logp"][n].copy(), color_logp=cols["color_logp"][n].copy()))
    return out


def _sizes(flat: list) -> tuple[int, int]:
    if not flat:
        return 0, 0
    d = flat[0][1]
    return len(d.subtype_logp), len(d.color_logp)
