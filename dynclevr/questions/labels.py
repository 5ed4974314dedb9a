"""Language labels of a 4D scene, per object and frame (paper section 3.2; REFERENCE.md section 1, "Language labels").

Every label comes from Scene4D's state arrays (position, velocity, visibility, collisions) and its camera only: the
model sees nothing but motion, so the same code labels the truth (`sim/`) and the model's estimate (`parsed/`).

Each label has a raw value, defined everywhere (the executor answers with it on any scene), and an ambiguity mask:
where a label sits in a band between classes, flickers within a few frames, or is disturbed by a collision, question
generation asks nothing. Outside the mask the raw value is the label, so an answer generated on the truth is exactly
what the executor returns on the truth.

- velocity: |v| in m/s; static < static_below, slow in [slow_above, slow_below], fast > fast_above; the raw class
  splits each band at its middle.
- direction: v in the camera's horizontal frame plus world z: right/left in the image, back (away from the camera) /
  front (towards it), up/down. Unambiguous only when the object moves (speed >= slow_above) and the dominant
  component exceeds direction_ratio x each other one.
- accelerating: the change of horizontal speed over +-accel_window frames (the paper's velocity/acceleration are
  finite differences smoothed over a short window). "Along the x-axis, objects can either accelerate due to an
  internal engine force or decelerate due to friction" (paper 3.2), so gravity's pull on a falling plane is not
  "accelerating"; that is "not floating". Frames near a collision of the object are ambiguous (an impulse is not
  an engine).
- floating: in the air (bottom of the box above float_height_above) with ~zero vertical acceleration; on the ground,
  falling, or resting on another vehicle (a plane that fell onto a bus) is "not floating".
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.ndimage import maximum_filter1d, minimum_filter1d

from dynclevr.config import ConfigError
from dynclevr.scene import Collision, Scene4D

VELOCITIES = ("static", "slow", "fast")
DIRECTIONS = ("front", "back", "left", "right", "up", "down")
AMBIGUOUS = "ambiguous"

_ORDERED = [("static_below", "slow_above"), ("slow_above", "slow_below"), ("slow_below", "fast_above"),
            ("steady_below", "accelerating_above"), ("ground_height_below", "float_height_above"),
            ("float_az_below", "fall_az_above")]
_POSITIVE = ("static_below", "direction_ratio", "compare_margin", "float_az_below", "support_gap")
_INTS = ("stable_frames", "accel_window", "collision_guard_frames", "collision_merge_frames", "start_frame",
         "min_visible_pixels", "predict_margin")


def check_labels_cfg(cfg: dict) -> dict:
    """Validate the [labels] section where it is read; one line naming the key and the fix."""
    for lo, hi in _ORDERED:
        for k in (lo, hi):
            if k not in cfg:
                raise ConfigError(f"'labels.{k}' is missing: add it to [labels] in pipeline.toml")
        if not cfg[lo] < cfg[hi]:
            raise ConfigError(f"'labels.{lo}' = {cfg[lo]} must be less than 'labels.{hi}' = {cfg[hi]}")
    for k in _POSITIVE:
        if not cfg.get(k, 0) > 0:
            raise ConfigError(f"'labels.{k}' = {cfg.get(k)!r} must be positive")
    if cfg["direction_ratio"] <= 1:
        raise ConfigError(f"'labels.direction_ratio' = {cfg['direction_ratio']} must exceed 1 (dominance)")
    for k in _INTS:
        if not isinstance(cfg.get(k), int) or isinstance(cfg.get(k), bool) or cfg[k] < 0:
            raise ConfigError(f"'labels.{k}' = {cfg.get(k)!r} must be a non-negative integer (frames)")
    if cfg["accel_window"] < 1:
        raise ConfigError("'labels.accel_window' must be at least 1 frame")
    return cfg


def merge_events(events: list[Collision], merge_frames: int) -> list[Collision]:
    """One event per pair within `merge_frames` frames (contacts of one collision span several steps)."""
    out: list[Collision] = []
    last: dict[frozenset, int] = {}
    for e in sorted(events, key=lambda e: (e.frame, min(e.a, e.b), max(e.a, e.b))):
        p = e.pair()
        if p in last and e.frame - last[p] <= merge_frames:
            last[p] = e.frame
            continue
        last[p] = e.frame
        out.append(Collision(e.frame, min(e.a, e.b), max(e.a, e.b), e.point, e.impulse))
    return out


def future_events(scene: Scene4D, merge_frames: int) -> list[Collision]:
    """Collisions that start after the observed frames: a contact that began within them and goes on is no future
    event (merged over the whole timeline first). An estimate's known collisions are those its observed frames
    decide (`cut_collisions`): the events it found in later frames are what the question asks it to predict."""
    known = scene.collisions if scene.cut_collisions is None else scene.cut_collisions
    merged = merge_events(list(known) + list(scene.future_collisions), merge_frames)
    return [e for e in merged if e.frame >= scene.observed_frames]


def _unstable(codes: np.ndarray, k: int) -> np.ndarray:
    """[T, N] int codes -> True where the code changes within +-k frames."""
    if k == 0:
        return np.zeros(codes.shape, bool)
    size = 2 * k + 1
    return (maximum_filter1d(codes, size, axis=0, mode="nearest")
            != minimum_filter1d(codes, size, axis=0, mode="nearest"))


def _window_rate(x: np.ndarray, w: int, dt: float) -> np.ndarray:
    """d x / dt over +-w frames, one-sided at the ends: [T, N] -> [T, N]."""
    T = x.shape[0]
    if T < 2:
        return np.zeros_like(x)
    t = np.arange(T)
    lo, hi = np.clip(t - w, 0, T - 1), np.clip(t + w, 0, T - 1)
    return (x[hi] - x[lo]) / ((hi - lo)[:, None] * dt)


@dataclass
class Labels:
    """Raw labels [T, N] (indices into VELOCITIES / DIRECTIONS, or bools) with ambiguity masks [T, N]."""

    object_ids: list[int]
    speed: np.ndarray
    velocity: np.ndarray
    velocity_ambiguous: np.ndarray
    direction: np.ndarray
    direction_ambiguous: np.ndarray
    accel: np.ndarray                 # d|v_horizontal|/dt, m/s^2
    accelerating: np.ndarray
    accelerating_ambiguous: np.ndarray
    vertical_accel: np.ndarray        # d v_z / dt, m/s^2
    floating: np.ndarray
    floating_ambiguous: np.ndarray

    def rows(self) -> dict[str, list]:
        """The labels/frames/<scene>.parquet columns: one row per (frame, object), ambiguous labels spelled out."""
        T, N = self.speed.shape

        def words(values, amb, names):
            return [AMBIGUOUS if a else names[int(v)] for v, a in zip(values.ravel(), amb.ravel())]

        tf = ("false", "true")
        return {
            "frame": np.repeat(np.arange(T), N).tolist(),
            "object": np.tile(self.object_ids, T).tolist(),
            "speed": self.speed.ravel().astype(np.float32).tolist(),
            "velocity": words(self.velocity, self.velocity_ambiguous, VELOCITIES),
            "direction": words(self.direction, self.direction_ambiguous, DIRECTIONS),
            "accel": self.accel.ravel().astype(np.float32).tolist(),
            "accelerating": words(self.accelerating, self.accelerating_ambiguous, tf),
            "floating": words(self.floating, self.floating_ambiguous, tf),
        }


def _resting_on_another(position: np.ndarray, scene: Scene4D, gap: float) -> np.ndarray:
    """[T, N] bool: the object's bottom is within `gap` above another object's top, over its footprint (bounding
    circles of the horizontal extents: orientation-free, and the same on truth and estimate)."""
    T, N = position.shape[:2]
    out = np.zeros((T, N), bool)
    size = np.array([o.size for o in scene.objects], float).reshape(N, 3)
    reach = np.hypot(size[:, 0], size[:, 1]) / 2
    for i in range(N):
        for j in range(N):
            if i == j:
                continue
            above = (position[:, i, 2] - size[i, 2] / 2) - (position[:, j, 2] + size[j, 2] / 2)
            over = np.linalg.norm(position[:, i, :2] - position[:, j, :2], axis=-1) < max(reach[i], reach[j])
            out[:, i] |= over & (np.abs(above) < gap)
    return out


def compute_labels(scene: Scene4D, cfg: dict) -> Labels:
    c = check_labels_cfg(cfg)
    T, N = scene.num_frames, len(scene.objects)
    dt = 1.0 / scene.fps
    v = np.asarray(scene.velocity, float).reshape(T, N, 3)
    k = c["stable_frames"]

    speed = np.linalg.norm(v, axis=-1)
    velocity = np.digitize(speed, [(c["static_below"] + c["slow_above"]) / 2, (c["slow_below"] + c["fast_above"]) / 2])
    in_band = (((speed >= c["static_below"]) & (speed < c["slow_above"]))
               | ((speed > c["slow_below"]) & (speed <= c["fast_above"])))
    velocity_ambiguous = in_band | _unstable(velocity, k)

    # The camera's right axis is horizontal by construction; its forward axis is tilted down, so flatten it.
    R = scene.camera.world_to_camera[:3, :3]
    right, fwd = R[0], R[2] * np.array([1.0, 1.0, 0.0])
    fwd /= np.linalg.norm(fwd)
    comps = np.stack([v @ right, v @ fwd, v[..., 2]], axis=-1)
    mag = np.abs(comps)
    axis = mag.argmax(-1)
    positive = np.take_along_axis(comps, axis[..., None], -1)[..., 0] > 0
    # axis 0: right/left, 1: away/towards the camera = back/front, 2: up/down (indices into DIRECTIONS)
    direction = np.array([[2, 0, 5], [3, 1, 4]])[positive.astype(int), axis]
    top2 = np.sort(mag, axis=-1)[..., 1:]
    dominant = top2[..., 1] > c["direction_ratio"] * top2[..., 0]
    direction_ambiguous = ~dominant | (speed < c["slow_above"]) | _unstable(direction, k)

    near_collision = np.zeros((T, N), bool)
    index = {o.id: i for i, o in enumerate(scene.objects)}
    g = c["collision_guard_frames"]
    for e in list(scene.collisions) + list(scene.future_collisions):
        for oid in (e.a, e.b):
            if oid in index:
                near_collision[max(0, e.frame - g): e.frame + g + 1, index[oid]] = True

    accel = _window_rate(np.linalg.norm(v[..., :2], axis=-1), c["accel_window"], dt)
    accelerating = accel > (c["steady_below"] + c["accelerating_above"]) / 2
    accelerating_ambiguous = ((accel >= c["steady_below"]) & (accel <= c["accelerating_above"])) | near_collision

    az = _window_rate(v[..., 2], c["accel_window"], dt)
    half_height = np.array([o.size[2] / 2 for o in scene.objects]).reshape(1, N)
    bottom = np.asarray(scene.position, float).reshape(T, N, 3)[..., 2] - half_height
    # A plane that fell and came to rest on another vehicle is high up and still, yet not floating: it fell before
    # and its bottom lies on another's top. (A floating plane never falls: its force cancels gravity.)
    fell = np.maximum.accumulate(az < -c["fall_az_above"], axis=0)
    supported = fell & _resting_on_another(np.asarray(scene.position, float).reshape(T, N, 3), scene,
                                           c["support_gap"])
    floating = ((bottom > (c["ground_height_below"] + c["float_height_above"]) / 2)
                & (np.abs(az) < (c["float_az_below"] + c["fall_az_above"]) / 2)) & ~supported
    clear = (((bottom > c["float_height_above"]) & (np.abs(az) < c["float_az_below"]))
             | (bottom < c["ground_height_below"]) | (az < -c["fall_az_above"]) | supported)
    floating_ambiguous = ~clear | near_collision

    return Labels([o.id for o in scene.objects], speed, velocity, velocity_ambiguous, direction, direction_ambiguous,
                  accel, accelerating, accelerating_ambiguous, az, floating, floating_ambiguous)
