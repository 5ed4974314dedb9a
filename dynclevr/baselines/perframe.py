"""The per-frame 3D baseline, in the manner of PO3D-VQA (the paper's Table 1 and its appendix: "a 3D detector ...
reconstructs an explicit 3D scene representation for each frame. We extend the model for VideoQA by computing
dynamic properties from object locations and predicting collisions by filtering the distance between objects").

Our scene parser's per-frame part, with no dynamics model (`--per-frame`, parser.filter = "none"; outputs in
parsed-perframe/, future-perframe/, answers-perframe/):
1. each frame on its own: the detection head's peaks (detector.py), placed in 3D (place.py); two peaks on one object
   (within parser.spawn_pixels in the image or parser.merge_radius in 3D) keep the more confident one;
2. association across frames, as any per-frame model must to answer about objects: each detection goes to the
   object whose last placed position is nearest, within a gate that grows with the frames since it was last seen,
   with appearance (category and colour evidence) in the cost; no motion prediction, no filter. An object is one
   seen in `perframe.min_frames` frames; its sub-type and colour are its detections' summed evidence (within the
   observed frames for an object seen in them), and each of its detections is placed again with that sub-type;
3. dynamics by finite differences of the per-frame positions (missed frames filled linearly between detections):
   velocity over `velocity_window` frames back (`perframe.velocity_window`), acceleration as the difference of those
   velocities over the same window; speeds under `static_speed` read 0 (the threshold ours uses); engine and
   floating from them as dynamics.py does for ours;
4. collisions: a pair comes closer than `contact_gap`: the gap between their oriented bounding boxes (estimated
   position and heading, the catalogue's size of the estimated sub-type), along the footprint's separating axes or
   vertically;
5. predictive and counterfactual questions (`imagine`, for simulate-future): the same contact rule on positions
   extrapolated at constant velocity, no physics engine. Predictive: from each object's last detection within the
   observed frames and its velocity from those frames alone. Counterfactual: from the estimated start (each object
   moved back from its first detection along its first velocity), with the intervention applied as the engine
   would start it (static: at rest; slow / fast: that speed along the heading; accelerating: the engine's net
   forward acceleration; floating, aeroplanes only: the height held); a change that changes nothing gives the
   observed collisions.
It reads the video's RGB frames and its calibration (through parse_scene.py), the detection head's weights and the
asset catalogue (sizes, resting heights, masses), never the truth.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import linear_sum_assignment

from dynclevr.assets.catalogue import CATEGORIES, SUBTYPES, get_asset
from dynclevr.camera import Camera
from dynclevr.colors import COLOR_NAMES
from dynclevr.config import Config, ConfigError
from dynclevr.perception import dynamics
from dynclevr.perception.detections import detect
from dynclevr.perception.detector import Detection
from dynclevr.perception.place import SUBTYPE_NAMES, Measurement, place, resting_height
from dynclevr.perception.render import euler_to_quat
from dynclevr.physics import PhysicsParams, heading
from dynclevr.scene import INTERVENTIONS, Collision, Scene4D, SceneObject

CATEGORY_OF = np.array([[SUBTYPES[s][0] == c for s in SUBTYPES] for c in CATEGORIES], float)   # [5, 21]
IS_PLANE = np.array([SUBTYPES[s][0] == "aeroplane" for s in SUBTYPE_NAMES])


def enabled(cfg: Config) -> bool:
    """The per-frame variant: parser.filter = "none" (no temporal filter at all)."""
    return cfg.data.get("parser", {}).get("filter") == "none"


# The [parser] settings the per-frame model reads (the rest are the filter's): its cache key holds these only, so
# that tuning the tracker does not rerun this baseline.
PARSER_KEYS = ("detect_threshold", "max_detections", "new_track_score", "spawn_pixels", "merge_radius",
               "appearance_weight", "static_speed", "engine_threshold")


def parse_params(cfg: Config) -> dict:
    """What the per-frame parse depends on (parse-scene's params for this variant)."""
    return {"parser": {k: cfg["parser"][k] for k in PARSER_KEYS}, **cfg.digest("physics", "video", "perframe")}


def params(cfg: Config) -> dict:
    p = cfg["perframe"]
    for key in ("velocity_window", "min_frames", "gate", "reach", "max_gap", "static_speed"):
        if p[key] <= 0:
            raise ConfigError(f"'perframe.{key}' = {p[key]!r} must be positive")
    if p["velocity_window"] >= cfg["video"]["observed_frames"]:
        raise ConfigError("'perframe.velocity_window' must be less than 'video.observed_frames'")
    return p


def _appearance(subtype_logp: np.ndarray, color_logp: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    ps, pc = np.exp(subtype_logp - subtype_logp.max()), np.exp(color_logp - color_logp.max())
    return CATEGORY_OF @ (ps / ps.sum()), pc / pc.sum()


def _agreement(a: tuple[np.ndarray, np.ndarray], b: tuple[np.ndarray, np.ndarray]) -> float:
    """Mean Bhattacharyya coefficient of the category and colour distributions: 1 alike, 0 disjoint."""
    return 0.5 * float(np.sqrt(a[0] * b[0]).sum() + np.sqrt(a[1] * b[1]).sum())


class _Object:
    def __init__(self, t: int, m: Measurement):
        self.dets: dict[int, Detection] = {}
        self.subtype_logp = np.zeros(len(SUBTYPE_NAMES))
        self.color_logp = np.zeros(len(COLOR_NAMES))
        self.start, self.last_t, self.last_pos = t, t, m.position

    def add(self, t: int, m: Measurement, observed: int) -> None:
        d = m.detection
        self.dets[t] = d
        self.last_t, self.last_pos = t, m.position
        # attributes from the observed frames for an object seen in them (the predictive questions' objects)
        if t < observed or self.start >= observed:
            self.subtype_logp += d.score * d.subtype_logp
            self.color_logp += d.score * d.color_logp

    @property
    def appearance(self):
        if not self.dets:
            return None
        return _appearance(self.subtype_logp, self.color_logp)


def frame_measurements(dets: list[Detection], camera: Camera, spawn_pixels: float, merge_radius: float
                       ) -> list[Measurement]:
    """One frame's detections placed in 3D, most confident first; a peak near a more confident one is dropped."""
    out: list[Measurement] = []
    for d in sorted(dets, key=lambda d: -d.score):
        m = place(camera, d)
        if any(math.hypot(d.u - o.detection.u, d.v - o.detection.v) < spawn_pixels
               or np.linalg.norm(m.position - o.position) < merge_radius for o in out):
            continue
        out.append(m)
    return out


def associate(measurements: list[list[Measurement]], p: dict, parser: dict, observed: int) -> list[_Object]:
    """Detections to objects frame by frame: nearest last position within a gate, appearance in the cost."""
    objects: list[_Object] = []
    for t, meas in enumerate(measurements):
        live = [o for o in objects if t - o.last_t <= p["max_gap"]]
        used: set[int] = set()
        if live and meas:
            cost = np.full((len(live), len(meas)), 1e6)
            for i, o in enumerate(live):
                gate = p["gate"] + p["reach"] * (t - o.last_t)
                app = o.appearance
                for j, m in enumerate(meas):
                    dist = float(np.linalg.norm(m.position - o.last_pos))
                    if dist < gate:
                        disagree = 1 - _agreement(app, _appearance(m.detection.subtype_logp, m.detection.color_logp))
                        cost[i, j] = dist / gate + parser["appearance_weight"] * disagree
            for i, j in zip(*linear_sum_assignment(cost)):
                if cost[i, j] < 1e6:
                    live[i].add(t, meas[j], observed)
                    used.add(j)
        for j, m in enumerate(meas):
            if j not in used and m.detection.score >= parser["new_track_score"]:
                o = _Object(t, m)
                o.add(t, m, observed)
                objects.append(o)
    return [o for o in objects if len(o.dets) >= p["min_frames"]]


def finite_velocity(pos: np.ndarray, start: int, end: int, w: int, fps: int, upto: int | None = None) -> np.ndarray:
    """[T, 3] velocities of a track spanning frames start..end (positions filled in between): the difference over
    `w` frames back, or over the track's first frames where it is younger (reading at most frame `upto`)."""
    T = len(pos)
    last = end if upto is None else min(end, upto)
    v = np.zeros((T, 3))
    if last <= start:
        return v
    for t in range(start, last + 1):
        a = t - w if t - w >= start else start
        b = t if t - w >= start else min(start + w, last)
        v[t] = (pos[b] - pos[a]) * fps / (b - a)
    v[last + 1:] = v[last]
    v[:start] = v[start]
    return v


def parse(frames: np.ndarray, camera: Camera, detector, cfg: Config, name: str,
          detections: list[list[Detection]] | None = None) -> Scene4D:
    """The per-frame estimate as a Scene4D (the truth's schema). `detections`: per frame, in place of the head's."""
    p, parser = params(cfg), cfg["parser"]
    physics = PhysicsParams.from_config(cfg)
    fps, observed = int(cfg["video"]["fps"]), int(cfg["video"]["observed_frames"])
    if detections is None:
        detections = detect(detector, frames, parser)
    T = len(detections)
    meas = [frame_measurements(d, camera, parser["spawn_pixels"], parser["merge_radius"]) for d in detections]
    objects = sorted(associate(meas, p, parser, observed), key=lambda o: (o.start, min(o.dets)))
    N, w = len(objects), p["velocity_window"]
    pos, quat = np.zeros((T, N, 3)), np.tile([0.0, 0.0, 0.0, 1.0], (T, N, 1))
    vel, acc, ang = np.zeros((T, N, 3)), np.zeros((T, N, 3)), np.zeros((T, N, 3))
    eng, flo, vis = np.zeros((T, N), bool), np.zeros((T, N), bool), np.zeros((T, N), bool)
    out = []
    for i, o in enumerate(objects):
        shape = SUBTYPE_NAMES[int(np.argmax(o.subtype_logp))]
        category, size = SUBTYPES[shape]
        frames_seen = sorted(o.dets)
        placed = {t: place(camera, o.dets[t], shape) for t in frames_seen}
        s, e = frames_seen[0], frames_seen[-1]
        for axis in range(3):   # missed frames: linear between detections; before / after: held
            pos[:, i, axis] = np.interp(np.arange(T), frames_seen, [placed[t].position[axis] for t in frames_seen])
        yaw = np.interp(np.arange(T), frames_seen, np.unwrap([placed[t].yaw for t in frames_seen]))
        quat[:, i] = euler_to_quat(np.stack([yaw, np.zeros(T), np.zeros(T)], 1))
        vis[frames_seen, i] = True
        v = finite_velocity(pos[:, i], s, e, w, fps)
        speed = np.linalg.norm(v, axis=1)
        v[speed < p["static_speed"]] = 0.0
        if category != "aeroplane":
            v[:, 2] = 0.0
        a = np.zeros((T, 3))
        a[s + w:e + 1] = (v[s + w:e + 1] - v[s:e + 1 - w]) * fps / w if e + 1 - w > s else 0.0
        # before it was found it was on its way in at its first velocity; after it was lost it keeps its last place
        back = (np.arange(s) - s)[:, None] / fps
        pos[:s, i] = pos[s, i] + back * np.array([v[s, 0], v[s, 1], 0.0])
        vel[:, i], acc[:, i] = v, a
        for t in range(T):
            eng[t, i] = dynamics.engine_on(v[t], a[t], quat[t, i], parser)
            flo[t, i] = dynamics.floating(category, pos[t, i, 2], size[2] / 2, a[t], physics.gravity)
        ref = min(s + 2 * w, e, observed - 1) if s < observed else min(s + 2 * w, e)
        out.append(SceneObject(
            id=i, shape=shape, category=category, color=COLOR_NAMES[int(o.color_logp.argmax())],
            size=tuple(float(x) for x in size), mass=float(get_asset(shape).mass(physics.density)),
            engine_on=bool(eng[ref, i]), floating=bool(flo[ref, i]),
            speed_class=dynamics.speed_class(float(np.linalg.norm(v[ref, :2])), physics.slow_speed,
                                             physics.fast_speed),
            confidence=float(np.mean([d.score for d in o.dets.values()]))))
    present = np.zeros((T, N), bool)
    for i, o in enumerate(objects):
        present[min(o.dets):max(o.dets) + 1, i] = True
    scene = Scene4D(name, fps, camera, out, pos, quat, vel, ang, acc, eng, flo, vis, observed_frames=observed)
    scene.collisions = contacts(pos, quat, present, out, p["contact_gap"])
    if T > observed:
        scene.cut_collisions = _observed_contacts(scene, frames, camera, cfg, detections)
    return scene


def _observed_contacts(scene: Scene4D, frames, camera: Camera, cfg: Config, detections) -> list[Collision]:
    """The contacts that the observed frames alone show: those of a parse of them (positions between detections
    are interpolated, so the whole video's would read later frames), its objects named as in `scene`. Association is
    frame by frame, so an object of that parse is the one here with its first detection."""
    def first(s: Scene4D, i: int) -> tuple:
        t = int(np.argmax(s.visible[:, i]))
        return t, tuple(np.round(s.position[t, i], 6))

    observed = scene.observed_frames
    seen = parse(frames[:observed], camera, None, cfg, scene.name, detections[:observed])
    here = {first(scene, i): o.id for i, o in enumerate(scene.objects)}
    name = {o.id: here[first(seen, i)] for i, o in enumerate(seen.objects)}
    return [Collision(e.frame, *sorted((name[e.a], name[e.b])), e.point, e.impulse) for e in seen.collisions]


def box_gap(pa: np.ndarray, qa: np.ndarray, sa, pb: np.ndarray, qb: np.ndarray, sb) -> np.ndarray:
    """[T] metres between two oriented bounding boxes (centres [T, 3], orientations [T, 4], sizes l, w, h): the
    largest separation along the four footprint axes (separating axes) or the vertical gap; negative: overlap."""
    fa, fb = heading(qa)[:, :2], heading(qb)[:, :2]
    la, lb = fa[:, ::-1] * [-1.0, 1.0], fb[:, ::-1] * [-1.0, 1.0]   # their left axes
    d = (pb - pa)[:, :2]
    sep = np.full(len(d), -np.inf)
    for ax in (fa, la, fb, lb):
        ra = sa[0] / 2 * np.abs((ax * fa).sum(1)) + sa[1] / 2 * np.abs((ax * la).sum(1))
        rb = sb[0] / 2 * np.abs((ax * fb).sum(1)) + sb[1] / 2 * np.abs((ax * lb).sum(1))
        sep = np.maximum(sep, np.abs((d * ax).sum(1)) - ra - rb)
    return np.maximum(sep, np.abs(pb[:, 2] - pa[:, 2]) - (sa[2] + sb[2]) / 2)


def contacts(pos: np.ndarray, quat: np.ndarray, present: np.ndarray, objects: list[SceneObject], gap: float,
             first: int = 1) -> list[Collision]:
    """Events where a pair comes closer than `gap` (their oriented boxes, catalogue sizes): the frame (>= first) the
    gap drops below it, both objects present in that frame and the one before."""
    events = []
    for i in range(len(objects)):
        for j in range(i + 1, len(objects)):
            near = box_gap(pos[:, i], quat[:, i], objects[i].size, pos[:, j], quat[:, j], objects[j].size) < gap
            both = present[:, i] & present[:, j]
            for t in range(max(first, 1), len(near)):
                if near[t] and not near[t - 1] and both[t] and both[t - 1]:
                    a, b = sorted((objects[i].id, objects[j].id))
                    events.append(Collision(t, a, b, tuple(float(x) for x in (pos[t, i] + pos[t, j]) / 2), 0.0))
    return sorted(events, key=lambda e: (e.frame, e.a, e.b))


# ---- the future and the counterfactuals, at constant velocity (simulate-future) ---------------------------------

def _heading(yaw_quat: np.ndarray, v: np.ndarray) -> np.ndarray:
    """Forward on the ground: along the velocity where it moves, else the estimated yaw."""
    if np.linalg.norm(v[:2]) > 0.5:
        return np.array([*(v[:2] / np.linalg.norm(v[:2])), 0.0])
    return heading(yaw_quat)


def _rollout(p0: np.ndarray, v0: np.ndarray, a0: np.ndarray, frames: np.ndarray, fps: int, floor: np.ndarray
             ) -> np.ndarray:
    """[len(frames), N, 3] positions p0 + v0 t + a0 t^2 / 2 (t from frame 0 of `frames`), never below `floor`."""
    t = (frames - frames[0])[:, None, None] / fps
    pos = p0[None] + v0[None] * t + 0.5 * a0[None] * t * t
    pos[..., 2] = np.maximum(pos[..., 2], floor[None])
    return pos


def imagine(scene: Scene4D, cfg: Config) -> tuple[list[Collision], dict[tuple[int, str], list[Collision]]]:
    """(predicted collisions after the observed frames, counterfactual outcomes): the `contacts` rule on positions
    extrapolated at constant velocity. Reads only the estimate (`parse`'s)."""
    p = params(cfg)
    physics = PhysicsParams.from_config(cfg)
    fps, T, N = scene.fps, scene.num_frames, len(scene.objects)
    cut, w, gap = scene.observed_frames - 1, p["velocity_window"], p["contact_gap"]
    floor = np.array([resting_height(o.shape) for o in scene.objects])
    future: list[Collision] = []
    # predictive: from the last detection within the observed frames, with the velocity of those frames alone
    seen = [i for i in range(N) if scene.visible[:cut + 1, i].any()]
    if seen:
        p0, v0, q0 = np.zeros((len(seen), 3)), np.zeros((len(seen), 3)), np.zeros((len(seen), 4))
        for k, i in enumerate(seen):
            frames_seen = np.flatnonzero(scene.visible[:cut + 1, i])
            s, last = int(frames_seen[0]), int(frames_seen[-1])
            v = finite_velocity(scene.position[:, i], s, last, w, fps, upto=last)[last]
            if np.linalg.norm(v) < p["static_speed"]:
                v = np.zeros(3)
            if scene.objects[i].category != "aeroplane":
                v[2] = 0.0
            p0[k] = scene.position[last, i] + v * (cut - last) / fps
            v0[k], q0[k] = v, scene.orientation[last, i]
        frames = np.arange(cut, T)
        pos = _rollout(p0, v0, np.zeros_like(v0), frames, fps, floor[seen])
        objs = [scene.objects[i] for i in seen]
        quat = np.broadcast_to(q0[None], (len(frames), len(seen), 4))
        future = [Collision(e.frame + cut, e.a, e.b, e.point, e.impulse)
                  for e in contacts(pos, quat, np.ones(pos.shape[:2], bool), objs, gap)]
        future = [e for e in future if e.frame >= scene.observed_frames]
    # counterfactual: from the estimated start, one intervention at a time
    ids = [i for i in range(N) if scene.visible[:, i].any()]
    outcomes: dict[tuple[int, str], list[Collision]] = {}
    if not ids:
        return future, outcomes
    p0, v0, q0 = np.zeros((len(ids), 3)), np.zeros((len(ids), 3)), np.zeros((len(ids), 4))
    fwd = np.zeros((len(ids), 3))
    for k, i in enumerate(ids):
        first = int(np.argmax(scene.visible[:, i]))
        v = scene.velocity[min(first + w, T - 1), i].copy()
        p0[k] = scene.position[first, i] - np.array([v[0], v[1], 0.0]) * first / fps
        v0[k], q0[k] = v, scene.orientation[first, i]
        fwd[k] = _heading(scene.orientation[first, i], v)
    frames = np.arange(T)
    objs = [scene.objects[i] for i in ids]
    quat = np.broadcast_to(q0[None], (T, len(ids), 4))
    friction = physics.object_friction * physics.floor_friction * physics.gravity
    for k, i in enumerate(ids):
        o = scene.objects[i]
        for iv in INTERVENTIONS:
            v, a = v0.copy(), np.zeros_like(v0)
            if iv == "static":
                v[k] = 0.0
            elif iv in ("slow", "fast"):
                speed = physics.slow_speed if iv == "slow" else physics.fast_speed
                v[k] = np.array([*(fwd[k][:2] * speed), v0[k, 2]])
            elif iv == "accelerating":
                if not o.engine_on:
                    a[k] = fwd[k] * max(physics.engine_accel - friction, 0.0)
            elif o.category == "aeroplane":
                v[k, 2] = 0.0
            if np.allclose(v, v0) and not a.any():
                outcomes[(o.id, iv)] = list(scene.collisions)
                continue
            pos = _rollout(p0, v, a, frames, fps, floor[ids])
            outcomes[(o.id, iv)] = contacts(pos, quat, np.ones(pos.shape[:2], bool), objs, gap)
    return future, outcomes
