"""The causal filter: frame-by-frame render-and-compare with the physics prior (REFERENCE.md section 2.1-2.3).

For each frame t (paper, appendix 3; a single-particle Bayes filter):
1. predict: put the previous estimates (pose, fitted velocity, inferred engine / floating) into the physics
   engine and step one frame: mu_t = PE(S_{t-1}); the engine's contacts during that step are the collision events
   (in both variants: without the prior the engine still checks the estimates for contacts, its prediction unused);
2. correct: maximise rendering likelihood x N(mu_t, sigma^2 I) over every tracked object's pose, starting at mu_t;
   without the prior (the paper's ablation) start at S_{t-1} and maximise the likelihood alone;
3. every `detect_every` frames, propose objects the tracks do not explain (objects that come into view);
4. update each track's dynamics, and its colour during its first `color_frames` frames.
Nothing at frame t reads a frame after t, so the state at frame 30 is the same whatever follows.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import torch
from torch.nn import functional as F

from dynclevr.assets.catalogue import SUBTYPES, get_asset
from dynclevr.camera import Camera
from dynclevr.colors import COLOR_NAMES
from dynclevr.config import Config, ConfigError
from dynclevr.perception import dynamics
from dynclevr.perception.color import box, crop
from dynclevr.perception.detect import propose
from dynclevr.perception.features import extract
from dynclevr.perception.model import ParserModel
from dynclevr.perception.pose import Evidence, fit
from dynclevr.perception.render import GridCamera, euler_to_quat, quat_to_euler, transform
from dynclevr.physics import Body, ContactEvents, PhysicsParams, World
from dynclevr.scene import Collision, Scene4D, SceneObject


def parser_params(cfg: Config) -> dict:
    """cfg["parser"], checked."""
    p = cfg["parser"]
    for key in ("prior_sigma2", "kappa", "foreground_bias", "learning_rate", "iterations", "detect_iterations",
                "detect_every", "yaw_grid", "detect_subtypes", "max_proposals", "track_radius", "track_cells",
                "merge_radius", "fit_window", "min_fit_frames", "min_velocity_frames", "angular_window",
                "confirm_frames", "color_frames", "lost_frames", "min_area"):
        if p[key] <= 0:
            raise ConfigError(f"'parser.{key}' = {p[key]!r} must be positive")
    if not 0 < p["heatmap_threshold"] < 1:
        raise ConfigError(f"'parser.heatmap_threshold' = {p['heatmap_threshold']!r} must lie in (0, 1)")
    if p["fit_window"] > cfg["video"]["observed_frames"]:
        raise ConfigError("'parser.fit_window' must not exceed 'video.observed_frames': the object-level "
                          "engine / floating flags must be decided within the observed frames")
    return p


@dataclass
class Track:
    id: int
    mesh: int
    start: int
    confidence: float
    mass: float
    pose: list = field(default_factory=list)        # [6] per frame from start
    quat: list = field(default_factory=list)
    vel: list = field(default_factory=list)
    acc: list = field(default_factory=list)
    ang: list = field(default_factory=list)
    engine: list = field(default_factory=list)
    floating: list = field(default_factory=list)
    seen: list = field(default_factory=list)         # the likelihood found the object in this frame
    color_logp: np.ndarray = field(default_factory=lambda: np.zeros(len(COLOR_NAMES)))
    lost: int = 0
    confirmed: int | None = None                     # frame from which it is reported (seen confirm_frames times)
    segment: int = 0                                 # the motion fit starts here (its last collision)
    end: int | None = None                           # first frame it is no longer tracked


class SceneParser:
    def __init__(self, model: ParserModel, camera: Camera, cfg: Config):
        self.model, self.camera, self.cfg = model, camera, cfg
        self.p = parser_params(cfg)
        self.physics = PhysicsParams.from_config(cfg)
        self.fps = int(cfg["video"]["fps"])
        self.observed = int(cfg["video"]["observed_frames"])
        self.gcam = GridCamera(camera)
        self.subtypes = model.meshes.subtypes
        self.world: World | None = None

    # ---- the filter ----------------------------------------------------------------------------------------------

    def parse(self, frames: np.ndarray, name: str) -> Scene4D:
        feats, heat, logdist = extract(self.model.net, frames)
        tracks: list[Track] = []
        contacts: list[tuple[int, dict]] = []
        try:
            for t in range(len(frames)):
                active = [k for k in tracks if k.end is None]
                if active:
                    self._track(t, active, feats[t], contacts)
                if t % self.p["detect_every"] == 0:
                    tracked = [(k.pose[-1], k.mesh) for k in tracks if k.end is None]
                    for q in propose(feats[t], heat[t], logdist[t], self.model.meshes, self.gcam, self.p, tracked):
                        mass = get_asset(self.subtypes[q.mesh]).mass(self.physics.density)
                        k = Track(len(tracks), q.mesh, t, float(np.clip(q.quality, 0.0, 1.0)), mass)
                        self._record(k, q.pose, True)
                        tracks.append(k)
                for k in tracks:
                    if k.end is None or k.end == t + 1:
                        self._update(k, t, frames[t])
        finally:
            if self.world is not None:
                self.world.close()
                self.world = None
        return self._scene(name, tracks, contacts, len(frames))

    def _track(self, t: int, active: list[Track], feats: torch.Tensor, contacts: list) -> None:
        prev = torch.tensor(np.array([k.pose[-1] for k in active]), dtype=torch.float32)
        predicted, touched = self._predict(active)
        # contacts count between objects the image confirmed in the last frame (not between stale, lost tracks)
        # and only between confirmed tracks (a short-lived false track's contacts are as false as it is)
        touched = {(a, b): v for (a, b), v in touched.items() if active[a].seen[-1] and active[b].seen[-1]
                   and active[a].confirmed is not None and active[b].confirmed is not None}
        if touched:
            contacts.append((t, {(active[a].id, active[b].id): v for (a, b), v in touched.items()}))
            for (a, b), (_, impulse) in touched.items():
                # an impact (not a graze or resting contact) breaks the motion: the fits restart after it
                if impulse * (1 / active[a].mass + 1 / active[b].mass) >= self.physics.min_impact_speed:
                    for k in (active[a], active[b]):
                        k.segment = t - k.start
        prior = bool(self.p["physics_prior"])
        mesh_idx = torch.tensor([k.mesh for k in active])
        ev = Evidence.compute(feats, self.model.meshes, sorted(set(mesh_idx.tolist())), self.p["kappa"],
                              self.p["foreground_bias"])
        poses, ll, area = fit(predicted if prior else prev, mesh_idx, ev, self.model.meshes, self.gcam,
                              self.p["iterations"], self.p["learning_rate"], joint=True,
                              prior_mean=predicted if prior else None, sigma2=self.p["prior_sigma2"])
        for i, k in enumerate(active):
            seen = float(area[i]) >= self.p["min_area"] and float(ll[i] / area[i]) >= self.p["min_quality"]
            self._record(k, poses[i].numpy().astype(float), seen)
            k.lost = 0 if seen else k.lost + 1
            if k.lost >= self.p["lost_frames"]:
                k.end = t + 1
        # two tracks that converged on one object: the younger one ends
        for i, a in enumerate(active):
            for b in active[i + 1:]:
                if a.end is None and b.end is None and \
                        np.linalg.norm(a.pose[-1][:3] - b.pose[-1][:3]) < self.p["merge_radius"]:
                    b.end = t + 1

    def _predict(self, active: list[Track]) -> tuple[torch.Tensor, dict]:
        """mu_t = PE(S_{t-1}): one physics-engine frame from the previous estimates; and the contacts of that step."""
        bodies = [Body(self.subtypes[k.mesh], tuple(k.pose[-1][:3]), tuple(k.quat[-1]), tuple(k.vel[-1]),
                       tuple(k.ang[-1]), k.engine[-1], k.floating[-1]) for k in active]
        if self.world is None:
            self.world = World(bodies, self.physics)
        else:
            self.world.set_bodies(bodies)
        touched = self.world.step_frame()
        s = self.world.states()
        mu = np.concatenate([s.position, quat_to_euler(s.orientation)], 1)
        return torch.tensor(mu, dtype=torch.float32), touched

    def _record(self, k: Track, pose: np.ndarray, seen: bool) -> None:
        k.pose.append(pose)
        k.quat.append(euler_to_quat(pose[3:]))
        k.seen.append(seen)
        if k.confirmed is None and sum(k.seen) >= self.p["confirm_frames"]:
            k.confirmed = k.start + len(k.seen) - 1

    def _update(self, k: Track, t: int, frame: np.ndarray) -> None:
        """The track's dynamics at frame t (from its poses up to t), and its colour evidence."""
        p = self.p
        pos, quats = np.array(k.pose)[:, :3], np.array(k.quat)
        category, size = SUBTYPES[self.subtypes[k.mesh]]
        first = max(k.segment, len(pos) - p["fit_window"])
        if len(pos) - first < p["min_fit_frames"]:
            # too few frames since the last impact for a fit of their own: bridge it with a linear fit over the last
            # min_fit_frames (a velocity averaged across the impact beats none: zero reads as static, and the prior
            # then holds the object where it was)
            first = max(0, len(pos) - p["min_fit_frames"])
        vel, acc = dynamics.motion(pos[first:], self.fps, p["min_fit_frames"], p["min_velocity_frames"])
        if np.linalg.norm(vel) < p["static_speed"]:
            vel = np.zeros(3)
        k.vel.append(vel)
        k.acc.append(acc)
        k.ang.append(dynamics.angular_velocity(quats, self.fps, p["angular_window"]))
        k.engine.append(dynamics.engine_on(vel, acc, quats[-1], p))
        k.floating.append(dynamics.floating(category, pos[-1, 2], size[2] / 2, acc, self.physics.gravity))
        early = t - k.start < p["color_frames"] and (t < self.observed or k.start >= self.observed)
        if early and k.seen[-1]:
            pose = torch.tensor(np.array(k.pose[-1:]), dtype=torch.float32)
            world = transform(self.model.meshes.points[k.mesh], pose)
            b = box(self.camera, world[0].numpy())
            if b is not None:
                with torch.no_grad():
                    logits = self.model.color(torch.from_numpy(crop(frame, b))[None])
                k.color_logp += F.log_softmax(logits, 1)[0].numpy()

    # ---- the estimate as a Scene4D -------------------------------------------------------------------------------

    def _scene(self, name: str, tracks: list[Track], contacts: list, T: int) -> Scene4D:
        # Only confirmed tracks are objects, reported from the frame they were confirmed on (causal: whether an
        # object exists at frame t depends on frames <= t), in the order of confirmation (so the objects confirmed
        # by frame t keep their places whatever follows). Duplicates and drifting tracks rarely last that long.
        masses = [k.mass for k in tracks]                # by track id (the contacts' ids)
        tracks = sorted((k for k in tracks if k.confirmed is not None), key=lambda k: (k.confirmed, k.id))
        N = len(tracks)
        pos, quat = np.zeros((T, N, 3)), np.tile([0.0, 0.0, 0.0, 1.0], (T, N, 1))
        vel, ang, acc = np.zeros((T, N, 3)), np.zeros((T, N, 3)), np.zeros((T, N, 3))
        eng, flo, vis = np.zeros((T, N), bool), np.zeros((T, N), bool), np.zeros((T, N), bool)
        objects = []
        for i, k in enumerate(tracks):
            n = len(k.pose)
            sl = slice(k.start, k.start + n)
            pos[sl, i], quat[sl, i] = np.array(k.pose)[:, :3], np.array(k.quat)
            vel[sl, i], acc[sl, i], ang[sl, i] = np.array(k.vel), np.array(k.acc), np.array(k.ang)
            eng[sl, i], flo[sl, i] = k.engine, k.floating
            vis[sl, i] = np.array(k.seen) & (np.arange(k.start, k.start + n) >= k.confirmed)
            # before it is found and after it is lost, an object keeps its first / last estimate
            pos[:k.start, i], quat[:k.start, i] = pos[k.start, i], quat[k.start, i]
            pos[k.start + n:, i], quat[k.start + n:, i] = pos[k.start + n - 1, i], quat[k.start + n - 1, i]
            # object-level attributes are read once the first fit window is full, but within the observed frames
            # for an object found in them: the predictive questions never depend on later frames
            a = k.start + self.p["fit_window"] - 1
            if k.start < self.observed:
                a = min(a, self.observed - 1)
            a = min(a, k.start + n - 1) - k.start
            shape = self.subtypes[k.mesh]
            category, size = SUBTYPES[shape]
            objects.append(SceneObject(
                id=k.id, shape=shape, category=category, color=COLOR_NAMES[int(k.color_logp.argmax())],
                size=tuple(float(s) for s in size), mass=float(k.mass),
                engine_on=bool(k.engine[a]), floating=bool(k.floating[a]),
                speed_class=dynamics.speed_class(float(np.linalg.norm(k.vel[a][:2])), self.physics.slow_speed,
                                                 self.physics.fast_speed),
                confidence=k.confidence))
        events = ContactEvents(self.physics.merge_frames, masses, self.physics.min_impact_speed)
        for t, touched in contacts:
            events.add(t, touched)
        collisions = [Collision(c.frame, c.a, c.b, c.point, c.impulse) for c in events.done()]
        return Scene4D(name, self.fps, self.camera, objects, pos, quat, vel, ang, acc, eng, flo, vis,
                       collisions=collisions, observed_frames=self.observed)


def parse_video(frames: np.ndarray, camera: Camera, model: ParserModel, cfg: Config, name: str) -> Scene4D:
    return SceneParser(model, camera, cfg).parse(frames, name)
