"""Collision events from the estimated scene (REFERENCE.md section 2.2: "collisions come from the engine while it
predicts"; issue 11: and from the estimated trajectories).

While the filter runs, the physics engine's prediction step gives, for every pair of confirmed tracks, the gap
between their collision shapes and the velocity change of any contact it resolves (`Candidates`). Neither alone is
reliable: estimated hulls are decimetres off, so the engine touches pairs that pass close by and misses pairs
that touch; the images show what happened next (both objects change motion at once), but a detection's depth is
noisy. A candidate contact is where the engine touched the pair or their hulls came within CONTACT_GAP (one per
approach, by the truth's merge rule); a small classifier (`CollisionModel`, a two-layer perceptron over features
of the pair around the candidate) decides which were collisions, trained on parser runs over the train split
against the truth's events (`dynclevr train collisions`); it never sees the truth at run time.

Causality: the score at frame t reads frames up to t + AFTER (= the events' merge window), so the events complete
by the last observed frame are decided from the observed frames alone.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from dynclevr import WEIGHTS_DIR, DynclevrError
from dynclevr.artifacts import file_digest

DEFAULT_DIR = WEIGHTS_DIR / "collision"
WEIGHTS_FILE, MANIFEST = "collision.json", "manifest.json"
BEFORE, AFTER = 8, 5        # frames of the motion before and after a candidate frame that its features read
FAR = 0.5                   # metres: the gap a pair further apart is recorded at (no candidate)
CONTACT_GAP = 0.05          # metres: estimated hulls this close touch (or the engine made them touch)
NEAR_GAP = 0.25             # metres: a pair this close is near each other ...
RECENT = 20                 # ... and the frames of the last RECENT it was near are a feature
# per frame of a pair near each other
FEATURES = ("gap", "min_gap", "engine_dv", "engine_dv_window", "overlap", "hinge_dv", "hinge_ok", "filter_dv",
            "max_own_dv", "min_own_dv", "closing_speed", "min_seen", "aeroplane", "log_mass_ratio", "centre_dist")
# per candidate contact: its frame's FEATURES, then summaries of the frames around it
CONTACT_FEATURES = FEATURES + ("window_min_gap", "window_max_engine_dv", "window_touching", "window_overlap",
                               "window_max_hinge_dv", "window_max_filter_dv", "window_max_closing_speed",
                               "recent_near_frames")


class CollisionWeightsError(DynclevrError):
    pass


def collision_digest(weights_dir: Path = DEFAULT_DIR) -> str:
    path = Path(weights_dir) / MANIFEST
    return file_digest(path) if path.exists() else "missing"


@dataclass
class Candidates:
    """Per pair (track ids, a < b) and frame: the hull gap and the engine's contact velocity change."""
    gap: dict = field(default_factory=dict)          # (a, b) -> {frame: metres}
    engine: dict = field(default_factory=dict)       # (a, b) -> {frame: m/s}

    def add_gap(self, t: int, a: int, b: int, gap: float) -> None:
        self.gap.setdefault((min(a, b), max(a, b)), {})[t] = gap

    def add_contact(self, t: int, a: int, b: int, dv: float) -> None:
        d = self.engine.setdefault((min(a, b), max(a, b)), {})
        d[t] = d.get(t, 0.0) + dv


@dataclass
class TrackMotion:
    """One confirmed track's motion over the video's frames (NaN before it starts and after it ends)."""
    position: np.ndarray      # [T, 3] the filter's estimate
    measured: np.ndarray      # [T, 3] the placed detections (NaN where there was none)
    velocity: np.ndarray      # [T, 3] the filter's velocity (or the fit's, without the prior)
    mass: float
    aeroplane: bool


def _line_velocity(p: np.ndarray, lo: int, hi: int, fps: int, min_points: int = 3) -> np.ndarray | None:
    idx = np.arange(max(lo, 0), min(hi, len(p)))
    idx = idx[np.isfinite(p[idx, 0])]
    if len(idx) < min_points:
        return None
    A = np.stack([np.ones(len(idx)), idx / fps], 1)
    return np.linalg.lstsq(A, p[idx], rcond=None)[0][1]


def _hinge(p: np.ndarray, t: int, fps: int) -> np.ndarray | None:
    """Change of velocity at t: a line through the measured positions before t and one from t on."""
    before, after = _line_velocity(p, t - BEFORE, t, fps), _line_velocity(p, t, t + AFTER + 1, fps)
    return None if before is None or after is None else after - before


def _at(x: np.ndarray, t: int) -> np.ndarray:
    return x[min(max(t, 0), len(x) - 1)]


def features(a: TrackMotion, b: TrackMotion, gaps: dict, engine: dict, t: int, fps: int) -> np.ndarray:
    T = len(a.position)
    window = range(max(t - 3, 0), min(t + 4, T))
    gap = gaps.get(t, FAR)
    ha, hb = _hinge(a.measured, t, fps), _hinge(b.measured, t, fps)
    hinge = 0.0 if ha is None or hb is None else float(np.linalg.norm(ha - hb))
    lo, hi = max(t - AFTER, 0), min(t + AFTER, T - 1)
    dva, dvb = a.velocity[hi] - a.velocity[lo], b.velocity[hi] - b.velocity[lo]
    own = sorted(float(np.nan_to_num(np.linalg.norm(x), nan=0.0)) for x in (dva, dvb))
    rel_v = _at(a.velocity, t - 3) - _at(b.velocity, t - 3)
    d = _at(b.position, t) - _at(a.position, t)
    dist = float(np.linalg.norm(d))
    closing = float(np.nan_to_num(rel_v @ d / max(dist, 1e-6)))
    span = slice(max(t - BEFORE, 0), min(t + AFTER + 1, T))
    seen = min(float(np.isfinite(x.measured[span, 0]).mean()) for x in (a, b))
    return np.array([
        gap, min(gaps.get(s, FAR) for s in window),
        np.log1p(engine.get(t, 0.0)), np.log1p(sum(engine.get(s, 0.0) for s in range(t - AFTER, t + AFTER + 1))),
        float(gap < -0.02), min(hinge, 20.0), float(ha is not None and hb is not None),
        min(float(np.nan_to_num(np.linalg.norm(dva - dvb), nan=0.0)), 20.0), min(own[1], 20.0), min(own[0], 20.0),
        float(np.clip(closing, -20, 20)), seen, float(a.aeroplane or b.aeroplane),
        abs(float(np.log(a.mass / b.mass))), min(np.nan_to_num(dist, nan=20.0), 20.0)], np.float32)


def candidate_frames(cands: Candidates, pair: tuple[int, int], T: int, last: int) -> list[int]:
    """Frames at which the pair may have collided: within `AFTER` frames of a recorded gap or contact, and
    complete (their features read up to t + AFTER <= last)."""
    marks = set(cands.gap.get(pair, {})) | set(cands.engine.get(pair, {}))
    out = set()
    for s in marks:
        out.update(range(s - AFTER, s + AFTER + 1))
    return sorted(t for t in out if 0 <= t < T and t + AFTER <= last)


class CollisionModel:
    """A two-layer perceptron over a candidate contact's standardised CONTACT_FEATURES; its score is the
    probability that the pair collided there."""

    def __init__(self, mean, std, w1, b1, w2, b2, threshold: float):
        self.mean, self.std = np.asarray(mean, np.float32), np.asarray(std, np.float32)
        self.w1, self.b1, self.w2, self.b2 = (np.asarray(x, np.float32) for x in (w1, b1, w2, b2))
        self.threshold = float(threshold)

    def score(self, x: np.ndarray) -> np.ndarray:
        h = np.maximum((((x - self.mean) / self.std) @ self.w1) + self.b1, 0.0)
        return 1.0 / (1.0 + np.exp(-(h @ self.w2 + self.b2)))

    def to_json(self) -> dict:
        return {k: np.asarray(getattr(self, k)).tolist() for k in ("mean", "std", "w1", "b1", "w2", "b2")} | {
            "threshold": self.threshold, "features": list(CONTACT_FEATURES)}

    @classmethod
    def load(cls, weights_dir: Path = DEFAULT_DIR) -> "CollisionModel":
        path, manifest = Path(weights_dir) / WEIGHTS_FILE, Path(weights_dir) / MANIFEST
        if not path.exists() or not manifest.exists():
            raise CollisionWeightsError(f"collision weights missing in {weights_dir}: run "
                                        "`dynclevr train collisions --split train`")
        if json.loads(manifest.read_text()).get("weights_sha256") != file_digest(path):
            raise CollisionWeightsError(f"{path} does not match its manifest: rerun "
                                        "`dynclevr train collisions --split train`")
        d = json.loads(path.read_text())
        if d.get("features") != list(CONTACT_FEATURES):
            raise CollisionWeightsError(f"{path} was trained on other features: rerun "
                                        "`dynclevr train collisions --split train`")
        return cls(d["mean"], d["std"], d["w1"], d["b1"], d["w2"], d["b2"], d["threshold"])


def pair_features(tracks: dict[int, TrackMotion], cands: Candidates, fps: int, last: int
                  ) -> list[tuple[tuple[int, int], int, np.ndarray]]:
    """(pair, frame, features) of every candidate frame."""
    T = len(next(iter(tracks.values())).position) if tracks else 0
    out = []
    for pair in sorted(set(cands.gap) | set(cands.engine)):
        a, b = pair
        if a not in tracks or b not in tracks:
            continue
        gaps, engine = cands.gap.get(pair, {}), cands.engine.get(pair, {})
        for t in candidate_frames(cands, pair, T, last):
            out.append((pair, t, features(tracks[a], tracks[b], gaps, engine, t, fps)))
    return out


def contacts(rows: list[tuple[tuple[int, int], int, np.ndarray]], merge: int
             ) -> list[tuple[tuple[int, int], int, np.ndarray]]:
    """The candidate events and what the classifier reads of each: (pair, frame, CONTACT_FEATURES).

    A candidate is where the engine touched the pair or their hulls came within CONTACT_GAP, the first such frame
    after more than `merge` frames without one (the truth's merge rule). Its features summarise the per-frame
    `features` of the AFTER frames up to it (each reads AFTER frames ahead), so it reads frames up to its own +
    AFTER only."""
    col = {name: i for i, name in enumerate(FEATURES)}
    by_pair: dict[tuple[int, int], dict[int, np.ndarray]] = {}
    for pair, t, x in rows:
        by_pair.setdefault(pair, {})[t] = x
    out = []
    for pair, frames in sorted(by_pair.items()):
        last = None
        for t in sorted(frames):
            x = frames[t]
            if not (x[col["engine_dv"]] > 0 or x[col["gap"]] < CONTACT_GAP):
                continue
            start = last is None or t - last > merge
            last = t
            if not start:
                continue
            win = np.stack([frames[u] for u in range(t - AFTER, t + 1) if u in frames])
            recent = [frames[u] for u in range(t - RECENT, t + 1) if u in frames]
            touching = (win[:, col["engine_dv"]] > 0) | (win[:, col["gap"]] < CONTACT_GAP)
            out.append((pair, t, np.concatenate([x, [
                win[:, col["gap"]].min(), win[:, col["engine_dv"]].max(), touching.mean(),
                win[:, col["overlap"]].mean(), win[:, col["hinge_dv"]].max(), win[:, col["filter_dv"]].max(),
                win[:, col["closing_speed"]].max(),
                sum(float(r[col["gap"]] < NEAR_GAP) for r in recent)]]).astype(np.float32)))
    return out


def events(rows: list[tuple[tuple[int, int], int, np.ndarray]], model: CollisionModel, merge: int
           ) -> list[tuple[int, int, int, np.ndarray]]:
    """(frame, a, b, features) of the candidate contacts whose score reaches the model's threshold."""
    cands = contacts(rows, merge)
    if not cands:
        return []
    scores = model.score(np.stack([c[2] for c in cands]))
    return [(t, a, b, x) for ((a, b), t, x), sc in zip(cands, scores) if sc >= model.threshold]
