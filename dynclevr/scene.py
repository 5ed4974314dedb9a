"""Scene4D: one scene as objects, per-frame 4D states, collision events, future events and counterfactual outcomes.

The truth (`sim/`) and the model's estimate (`parsed/`, completed by `future/`) use this one representation and the
one MCAP schema below, so the program executor cannot tell them apart.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass, field
from pathlib import Path

import numpy as np

from dynclevr.camera import Camera
from dynclevr.mcapio import McapIn, McapOut, frame_time_ns

SCENE_SCHEMA = "dynclevr.scene4d"
SCENE_VERSION = 2   # 2: grazes
INTERVENTIONS = ("static", "slow", "fast", "accelerating", "floating")


@dataclass
class SceneObject:
    id: int
    shape: str                      # sub-type, e.g. "sedan"
    category: str                   # e.g. "car"
    color: str                      # one of the 8 colour names
    size: tuple[float, float, float]  # bounding box extents (length, width, height), metres
    mass: float
    engine_on: bool                 # engine force at the start
    floating: bool                  # floating force at the start (aeroplanes only)
    speed_class: str                # initial velocity class: static / slow / fast
    confidence: float = 1.0         # the model's confidence; 1 for the truth


@dataclass
class Collision:
    frame: int
    a: int                          # object ids, a < b
    b: int
    point: tuple[float, float, float] = (0.0, 0.0, 0.0)
    impulse: float = 0.0

    def pair(self) -> frozenset:
        return frozenset((self.a, self.b))


@dataclass
class Scene4D:
    name: str
    fps: int
    camera: Camera
    objects: list[SceneObject]
    position: np.ndarray            # [T, N, 3] metres, world frame (z up)
    orientation: np.ndarray         # [T, N, 4] quaternion x, y, z, w
    velocity: np.ndarray            # [T, N, 3] m/s
    angular_velocity: np.ndarray    # [T, N, 3] rad/s
    acceleration: np.ndarray        # [T, N, 3] m/s^2
    engine: np.ndarray              # [T, N] bool: engine force acting
    floating: np.ndarray            # [T, N] bool: floating force acting
    visible: np.ndarray             # [T, N] bool: inside the camera's view (truth) / tracked (estimate)
    collisions: list[Collision] = field(default_factory=list)
    future_collisions: list[Collision] = field(default_factory=list)   # after the observed frames
    counterfactuals: dict[tuple[int, str], list[Collision]] = field(default_factory=dict)
    observed_frames: int = 30
    # Touches too gentle to be collisions (truth only): no collision question is asked about a pair that grazes,
    # since a viewer sees them touch. Per video and per counterfactual run.
    grazes: list[Collision] = field(default_factory=list)
    counterfactual_grazes: dict[tuple[int, str], list[Collision]] = field(default_factory=dict)
    # An estimate's state at the last observed frame from those frames alone (its arrays may use later frames):
    # arrays per object of CUT_FIELDS; None: the arrays' row is that state (the truth, a causal estimate).
    cut_state: dict[str, np.ndarray] | None = None
    # An estimate's collisions as the observed frames alone decide them: the predictive questions merge these, not
    # `collisions` (which later frames decide), with the predicted future. None: `collisions` (the truth).
    cut_collisions: list[Collision] | None = None

    @property
    def num_frames(self) -> int:
        return self.position.shape[0]

    def index(self, object_id: int) -> int:
        return next(i for i, o in enumerate(self.objects) if o.id == object_id)

    # ---- MCAP ----------------------------------------------------------------------------------------------------

    def write(self, path: Path, kind: str) -> None:
        """Write the scene with `dynclevr.*` channels plus Foxglove channels so it plays in Foxglove as is."""
        from dynclevr import foxglove

        with McapOut(path, SCENE_SCHEMA, SCENE_VERSION, scene=self.name, kind=kind) as out:
            out.json("/scene/camera", "dynclevr.Camera", 0, self.camera.to_dict())
            out.json("/scene/objects", "dynclevr.ObjectCatalogue", 0, {
                "fps": self.fps, "observed_frames": self.observed_frames,
                "objects": [asdict(o) for o in self.objects]})
            for t in range(self.num_frames):
                tn = frame_time_ns(t, self.fps)
                out.json("/scene/states", "dynclevr.FrameStates", tn, {"frame": t, "objects": [{
                    "id": o.id,
                    "position": self.position[t, i].tolist(), "orientation": self.orientation[t, i].tolist(),
                    "velocity": self.velocity[t, i].tolist(), "angular_velocity": self.angular_velocity[t, i].tolist(),
                    "acceleration": self.acceleration[t, i].tolist(), "engine": bool(self.engine[t, i]),
                    "floating": bool(self.floating[t, i]), "visible": bool(self.visible[t, i])}
                    for i, o in enumerate(self.objects)]})
                out.proto("/tf", tn, foxglove.frame_transforms(self, t))
                out.proto("/scene/vehicles", tn, foxglove.scene_update(self, t))
            if self.cut_state is not None:
                out.json("/scene/cut_state", "dynclevr.FrameStates", frame_time_ns(self.observed_frames - 1, self.fps),
                         {"frame": self.observed_frames - 1, "objects": [
                             {"id": o.id, **{k: _plain(self.cut_state[k][i]) for k in CUT_FIELDS}}
                             for i, o in enumerate(self.objects)]})
            out.json("/scene/collisions", "dynclevr.CollisionEvents", 0,
                     {"events": [asdict(c) for c in self.collisions]})
            if self.cut_collisions is not None:
                out.json("/scene/cut_collisions", "dynclevr.CollisionEvents", 0,
                         {"events": [asdict(c) for c in self.cut_collisions]})
            out.json("/scene/future_collisions", "dynclevr.CollisionEvents", 0,
                     {"events": [asdict(c) for c in self.future_collisions]})
            out.json("/scene/grazes", "dynclevr.CollisionEvents", 0, {"events": [asdict(c) for c in self.grazes]})
            out.json("/scene/counterfactuals", "dynclevr.CounterfactualOutcomes", 0, {"runs": [
                {"object": oid, "intervention": iv, "events": [asdict(c) for c in events],
                 "grazes": [asdict(c) for c in self.counterfactual_grazes.get((oid, iv), [])]}
                for (oid, iv), events in sorted(self.counterfactuals.items())]})

    @classmethod
    def read(cls, path: Path) -> "Scene4D":
        src = McapIn(path, SCENE_SCHEMA, SCENE_VERSION)
        camera = Camera.from_dict(src.first("/scene/camera"))
        cat = src.first("/scene/objects")
        objects = [SceneObject(**{**o, "size": tuple(o["size"])}) for o in cat["objects"]]
        frames = [m for _, _, m in src.messages("/scene/states")]
        T, N = len(frames), len(objects)

        def stack(key, width=None):
            a = np.array([[s[key] for s in f["objects"]] for f in frames])
            return a.reshape(T, N, width) if width else a.reshape(T, N).astype(bool)

        def events(msg):
            return [Collision(e["frame"], e["a"], e["b"], tuple(e["point"]), e["impulse"]) for e in msg]

        cf = src.first("/scene/counterfactuals")["runs"]
        cut = next((m["objects"] for _, _, m in src.messages("/scene/cut_state")), None)   # optional
        cut_events = next((m["events"] for _, _, m in src.messages("/scene/cut_collisions")), None)   # optional
        return cls(
            name=src.meta.get("scene", Path(path).stem), fps=cat["fps"], camera=camera, objects=objects,
            position=stack("position", 3), orientation=stack("orientation", 4), velocity=stack("velocity", 3),
            angular_velocity=stack("angular_velocity", 3), acceleration=stack("acceleration", 3),
            engine=stack("engine"), floating=stack("floating"), visible=stack("visible"),
            collisions=events(src.first("/scene/collisions")["events"]),
            future_collisions=events(src.first("/scene/future_collisions")["events"]),
            counterfactuals={(r["object"], r["intervention"]): events(r["events"]) for r in cf},
            observed_frames=cat["observed_frames"], grazes=events(src.first("/scene/grazes")["events"]),
            counterfactual_grazes={(r["object"], r["intervention"]): events(r["grazes"]) for r in cf if r["grazes"]},
            cut_state=None if cut is None else {k: np.array([o[k] for o in cut]) for k in CUT_FIELDS},
            cut_collisions=None if cut_events is None else events(cut_events))

    def state_at(self, frame: int) -> dict[str, np.ndarray]:
        """Per-object arrays of CUT_FIELDS at `frame`: the cut state there, where the estimate has one."""
        if self.cut_state is not None and frame == self.observed_frames - 1:
            return self.cut_state
        return {"position": self.position[frame], "orientation": self.orientation[frame],
                "velocity": self.velocity[frame], "angular_velocity": self.angular_velocity[frame],
                "engine": self.engine[frame], "floating": self.floating[frame]}


CUT_FIELDS = ("position", "orientation", "velocity", "angular_velocity", "engine", "floating")


def _plain(x):
    return bool(x) if np.ndim(x) == 0 else np.asarray(x, float).tolist()
