"""simulate-future: the model's imagination (REFERENCE section 2, item 5).

The estimated state is put into the same physics engine that made the data and simulated forward:
- predictive: from the state estimated at the last observed frame from the frames up to there only (the
  estimate's cut state), simulated to the end of the video; the collisions after the observed frames are the prediction,
  voted over runs from that state perturbed by its uncertainty (`Ensemble`, [imagine] future_*);
- counterfactual: from the estimated initial state with one intervention on one object, over the whole video;
  objects follow their estimated trajectories until the intervention reaches them (perception/imagine.py).
Reads only parsed/ (the model's estimate); never the truth. The per-frame baseline (`--per-frame`) has no physics
engine: its future and counterfactuals are its contact rule on positions extrapolated at constant velocity
(baselines/perframe.py, `imagine`).
"""

from __future__ import annotations

import zlib
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np
import pyarrow as pa
from scipy.spatial.transform import Rotation

from dynclevr.artifacts import read_parquet, write_parquet
from dynclevr.perception.imagine import counterfactual_run
from dynclevr.physics import Body, PhysicsParams, World, catalogue_digest, counterfactual, simulate
from dynclevr.pipeline import SceneJob, Stage
from dynclevr.scene import INTERVENTIONS, Collision, Scene4D

FUTURE_SCHEMA = "dynclevr.future"
FUTURE_VERSION = 2   # 2: scene column; nulls, not -1 and ""
ENSEMBLE_STREAM = 7   # the ensemble's own stream of random draws
FUTURE_FIELDS = pa.schema([
    ("scene", pa.string()),
    ("run", pa.string()),             # future / counterfactual
    ("object", pa.int32()),           # counterfactual: the changed object; future: null
    ("intervention", pa.string()),    # counterfactual: static / slow / fast / accelerating / floating; future: null
    # One collision per row; a counterfactual run with none has one row whose event columns are null, so that
    # "no collision" differs from "not simulated".
    ("frame", pa.int32()), ("a", pa.int32()), ("b", pa.int32()),
    ("x", pa.float64()), ("y", pa.float64()), ("z", pa.float64()),   # contact point, m
    ("impulse", pa.float64()),
])


def _bodies(scene: Scene4D, t: np.ndarray, ids: list[int]) -> list[Body]:
    """Bodies at per-object frames `t` (one per id), from the estimate."""
    out = []
    for k, oid in enumerate(ids):
        i, f = scene.index(oid), int(t[k])
        o, s = scene.objects[i], scene.state_at(f)
        out.append(Body(o.shape, tuple(s["position"][i]), tuple(s["orientation"][i]), tuple(s["velocity"][i]),
                        tuple(s["angular_velocity"][i]), bool(s["engine"][i]), bool(s["floating"][i]), o.mass))
    return out


def _events(events: list[Collision], ids: list[int], offset: int = 0) -> list[Collision]:
    """Physics events name body indices; the scene names object ids."""
    return [Collision(e.frame + offset, min(ids[e.a], ids[e.b]), max(ids[e.a], ids[e.b]), e.point, e.impulse)
            for e in events]


def initial_bodies(scene: Scene4D) -> tuple[list[Body], list[int]]:
    """Every tracked object at the first frame it was seen, moved back to frame 0 along its velocity (an object
    that enters later was already driving before it came into view)."""
    ids = [o.id for o in scene.objects if scene.visible[:, scene.index(o.id)].any()]
    first = np.array([int(np.argmax(scene.visible[:, scene.index(oid)])) for oid in ids])
    bodies = _bodies(scene, first, ids)
    for k, f in enumerate(first):
        if f:
            b = bodies[k]
            back = np.asarray(b.position) - np.asarray(b.velocity) * f / scene.fps
            back[2] = b.position[2]
            bodies[k] = Body(b.shape, tuple(back), b.orientation, b.velocity, b.angular_velocity, b.engine_on,
                             b.floating, b.mass)
    return bodies, ids


@dataclass(frozen=True)
class Ensemble:
    """The predictive future as a vote over perturbed runs. The cut state is an estimate, and whether two bodies meet
    seconds later flips with small errors in it: the future is simulated `samples` times, the first from the estimate
    and the rest from it perturbed by the parser's typical errors at the cut (horizontal velocity and position,
    heading), and a pair collides in the prediction when it does in at least `vote` of the runs (Monte Carlo over the
    cut state's uncertainty instead of one point estimate). `samples` 1 is the single run from the estimate."""

    samples: int = 1
    vote: float = 0.5
    velocity_sigma: float = 0.0   # m/s
    position_sigma: float = 0.0   # m
    yaw_sigma: float = 0.0        # radians

    @classmethod
    def from_config(cls, cfg) -> "Ensemble":
        im = cfg["imagine"]
        return cls(int(im["future_samples"]), float(im["future_vote"]), float(im["future_velocity_sigma"]),
                   float(im["future_position_sigma"]), float(np.deg2rad(im["future_yaw_sigma"])))

    def perturb(self, b: Body, rng: np.random.Generator) -> Body:
        v, p = np.array(b.velocity, float), np.array(b.position, float)
        v[:2] += rng.normal(0.0, self.velocity_sigma, 2)
        p[:2] += rng.normal(0.0, self.position_sigma, 2)
        q = Rotation.from_euler("z", rng.normal(0.0, self.yaw_sigma)) * Rotation.from_quat(b.orientation)
        return replace(b, position=tuple(p), orientation=tuple(q.as_quat()), velocity=tuple(v))


def future_rng(scene: str) -> np.random.Generator:
    """The ensemble's draws for a scene, seeded by its name, not its seed: the model never holds what made the truth."""
    return np.random.default_rng([ENSEMBLE_STREAM, zlib.crc32(scene.encode())])


def predict_future(scene: Scene4D, params: PhysicsParams, ensemble: Ensemble = Ensemble(),
                   rng: np.random.Generator | None = None) -> list[Collision]:
    """The collisions after the observed frames, simulated from the state at the last of them of every object they
    show; with an ensemble (`rng` draws its perturbations, by default the scene's own stream), each pair that
    collides in enough of its runs, at the median of its first contacts' frames."""
    rng = future_rng(scene.name) if rng is None else rng
    last = scene.observed_frames - 1
    seen = [o.id for o in scene.objects if scene.visible[: last + 1, scene.index(o.id)].any()]
    if not seen:
        return []
    bodies = _bodies(scene, np.full(len(seen), last), seen)
    runs = []
    with World([], params) as world:
        for k in range(ensemble.samples):
            run = simulate(bodies if k == 0 else [ensemble.perturb(b, rng) for b in bodies], params,
                           scene.num_frames - last, world=world, record=False)
            runs.append([e for e in _events(run.collisions, seen, offset=last) if e.frame >= scene.observed_frames])
    if ensemble.samples == 1:
        return runs[0]
    firsts: dict[tuple[int, int], list[Collision]] = {}   # each pair's first contact in each run
    for events in runs:
        first: dict[tuple[int, int], Collision] = {}
        for e in events:
            first.setdefault((e.a, e.b), e)
        for pair, e in first.items():
            firsts.setdefault(pair, []).append(e)
    voted = [sorted(events, key=lambda e: e.frame)[len(events) // 2] for events in firsts.values()
             if len(events) >= ensemble.vote * ensemble.samples]
    return sorted(voted, key=lambda e: (e.frame, e.a, e.b))


def predict(scene: Scene4D, params: PhysicsParams, replay: bool = True, ensemble: Ensemble = Ensemble(),
            rng: np.random.Generator | None = None
            ) -> tuple[list[Collision], dict[tuple[int, str], list[Collision]]]:
    """The future after the observed frames, and every counterfactual run's collisions. `replay`: objects follow
    their estimated trajectories until the intervention reaches them (perception/imagine.py); False: the paper's
    re-simulation of everything from the estimated initial state."""
    future = predict_future(scene, params, ensemble, rng)
    outcomes: dict[tuple[int, str], list[Collision]] = {}
    bodies, ids = initial_bodies(scene)
    if bodies:
        with World([], params) as world:   # empty: every run builds its own bodies in it (World.set_bodies)
            for k, oid in enumerate(ids):
                for iv in INTERVENTIONS:
                    if replay:
                        events = counterfactual_run(scene, bodies, ids, k, iv, params, world)
                    else:
                        run = counterfactual(bodies, k, iv, params, scene.num_frames, world=world)
                        events = None if run is None else _events(run.collisions, ids)
                    # An intervention that changes nothing (the object already is static, say) leaves the video
                    # as it was seen: its outcome is the observed collisions.
                    outcomes[(oid, iv)] = scene.collisions if events is None else events
    return future, outcomes


def run_scene(job: SceneJob) -> None:
    from dynclevr.baselines import perframe

    scene = Scene4D.read(job.inputs["parse-scene"][0])
    if perframe.enabled(job.cfg):   # the per-frame baseline: constant velocity, no physics engine
        future, outcomes = perframe.imagine(scene, job.cfg)
    else:
        future, outcomes = predict(scene, PhysicsParams.from_config(job.cfg),
                                   job.cfg["imagine"]["counterfactuals"] == "replay", Ensemble.from_config(job.cfg),
                                   future_rng(job.scene))
    rows = [("future", None, None, e) for e in future]
    rows += [("counterfactual", oid, iv, e) for (oid, iv), events in sorted(outcomes.items()) for e in events]
    rows += [("counterfactual", oid, iv, None) for (oid, iv), events in sorted(outcomes.items()) if not events]
    cols = {f.name: [] for f in FUTURE_FIELDS}
    for run, oid, iv, e in rows:
        vals = [job.scene, run, oid, iv] + ([e.frame, e.a, e.b, *e.point, e.impulse] if e else [None] * 7)
        for f, v in zip(FUTURE_FIELDS, vals):
            cols[f.name].append(v)
    write_parquet(pa.table(cols, schema=FUTURE_FIELDS), job.outputs[0], FUTURE_SCHEMA, FUTURE_VERSION)


def attach(scene: Scene4D, path: Path) -> Scene4D:
    """The estimated scene completed with its simulated future and counterfactual outcomes."""
    t = read_parquet(path, FUTURE_SCHEMA, FUTURE_VERSION).to_pylist()
    scene.future_collisions = [_row_event(r) for r in t if r["run"] == "future"]
    scene.counterfactuals = {}
    for r in t:
        if r["run"] == "counterfactual":
            events = scene.counterfactuals.setdefault((r["object"], r["intervention"]), [])
            if r["frame"] is not None:
                events.append(_row_event(r))
    return scene


def _row_event(r: dict) -> Collision:
    return Collision(r["frame"], r["a"], r["b"], (r["x"], r["y"], r["z"]), r["impulse"])


def _params(cfg) -> dict:
    from dynclevr.baselines import perframe

    if perframe.enabled(cfg):   # the per-frame baseline's future reads these only
        return cfg.digest("physics", "video", "perframe")
    return cfg.digest("physics", "video", "labels", "imagine")


# 4: a scene column and nulls in future/; 5: the counterfactual replay moves only the bodies it has not reached;
# 6: the predictive future voted over an ensemble of perturbed runs
STAGE = Stage("simulate-future", 6, inputs=("parse-scene",),
              params=_params, outputs=(".parquet",), run_scene=run_scene,
              # The bodies are the catalogue's collision shapes: new meshes change the predictions.
              extra_inputs=lambda store, cfg: {"assets": catalogue_digest(cfg)})
