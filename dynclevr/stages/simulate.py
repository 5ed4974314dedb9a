"""Stage simulate: sample a scene from its seed, simulate it in PyBullet, and write the truth (paper, section 3 and
the appendix's physics table; REFERENCE.md section 1).

Reads: pipeline.toml ([video], [physics], [scene], [render], [labels]) and the scene seed.
Writes: `sim/<scene>.mcap` (Scene4D, kind "truth": object catalogue, camera, per-frame 4D states, collisions,
future collisions, counterfactual outcomes, Foxglove channels) and the split-level `objects.parquet`.

Scene sampling (every draw from one `np.random.default_rng(seed)`):
- 4 to 6 objects (scene.min/max_objects), sub-types uniform over the catalogue, colours uniform over the 8;
- velocity classes: at least one static, one slow and one fast object, the rest uniform over the three;
- (x, y): polar, the radius a Beta(position_beta) draw inside scene.static_radius (static objects, near the centre:
  the targets) or scene.moving_radius (moving objects, near the edge), as fractions of arena_radius; rejection
  sampling keeps spawns apart (footprints and height ranges must not overlap);
- heading: moving objects face the centre with uniform noise of +-heading_noise_deg (so most paths cross the
  static objects in the middle: collisions are common); static objects face any direction;
- z: on the ground, or uniform in plane_height for aeroplanes;
- engine on with p_engine_on for moving objects only: a static object stays "static" (it is the counterfactual
  "accelerating" that starts it); aeroplanes float with p_floating, otherwise fall.
"""

from __future__ import annotations

from collections import Counter
from pathlib import Path

import numpy as np
import pyarrow as pa

from dynclevr import DynclevrError
from dynclevr.artifacts import Store, command_options, write_parquet
from dynclevr.assets.catalogue import SUBTYPES, get_asset
from dynclevr.camera import Camera
from dynclevr.colors import COLOR_NAMES
from dynclevr.config import Config, ConfigError
from dynclevr.mcapio import McapIn
from dynclevr.pipeline import SceneJob, Stage
from dynclevr.scene import INTERVENTIONS, SCENE_SCHEMA, SCENE_VERSION, Scene4D, SceneObject

VERSION = 3   # 3: collision shapes that follow the meshes, a fresh world per run, grazes
SPEED_CLASSES = ("static", "slow", "fast")
OBJECTS_SCHEMA, OBJECTS_VERSION = "dynclevr.objects", 1
SPAWN_GAP = 0.3          # metres of free space between spawned footprints
SPAWN_TRIES = 200        # per object, before the whole layout is redrawn


def _check(cfg: Config) -> None:
    sc = cfg["scene"]
    for key in ("static_radius", "moving_radius", "plane_height"):
        lo, hi = sc[key]
        if not 0 <= lo <= hi:
            raise ConfigError(f"'scene.{key}' = {sc[key]!r} must be [low, high] with 0 <= low <= high")
    for key in ("static_radius", "moving_radius"):
        if sc[key][1] > 1:
            raise ConfigError(f"'scene.{key}' = {sc[key]!r}: fractions of arena_radius, at most 1")
    for key in ("p_engine_on", "p_floating"):
        if not 0 <= sc[key] <= 1:
            raise ConfigError(f"'scene.{key}' = {sc[key]!r} must lie in [0, 1]")
    if min(sc["position_beta"]) <= 0 or sc["arena_radius"] <= 0:
        raise ConfigError("'scene.position_beta' and 'scene.arena_radius' must be positive")
    for key in ("focal_length_mm", "sensor_width_mm"):
        if sc[key] <= 0:
            raise ConfigError(f"'scene.{key}' = {sc[key]!r} must be positive")
    for key in ("camera_jitter", "heading_noise_deg"):
        if sc[key] < 0:
            raise ConfigError(f"'scene.{key}' = {sc[key]!r} must not be negative")


# ---- scene sampling -------------------------------------------------------------------------------------------

def _footprint(xy, yaw, size) -> np.ndarray:
    """The 4 ground-plane corners of an object's bounding box, grown by half the spawn gap."""
    half = np.array([size[0], size[1]]) / 2 + SPAWN_GAP / 2
    c, s = np.cos(yaw), np.sin(yaw)
    corners = np.array([[1, 1], [1, -1], [-1, -1], [-1, 1]]) * half
    return corners @ np.array([[c, s], [-s, c]]) + xy


def _overlap(a: np.ndarray, b: np.ndarray) -> bool:
    """Separating-axis test of two convex quads [4, 2]."""
    for poly in (a, b):
        edges = np.roll(poly, -1, axis=0) - poly
        axes = np.stack([-edges[:, 1], edges[:, 0]], axis=1)
        pa_, pb_ = a @ axes.T, b @ axes.T
        if np.any((pa_.max(0) < pb_.min(0)) | (pb_.max(0) < pa_.min(0))):
            return False
    return True


def sample_scene(rng: np.random.Generator, cfg: Config) -> tuple[list[SceneObject], list, Camera]:
    """Objects, their initial physics bodies and the camera of one scene."""
    from dynclevr.physics import Body, PhysicsParams, ground_height, heading, yaw_quaternion

    sc, params = cfg["scene"], PhysicsParams.from_config(cfg)
    n = int(rng.integers(sc["min_objects"], sc["max_objects"] + 1))
    shapes = [str(s) for s in rng.choice(list(SUBTYPES), size=n)]
    colors = [str(c) for c in rng.choice(COLOR_NAMES, size=n)]
    classes = list(SPEED_CLASSES) + [str(c) for c in rng.choice(SPEED_CLASSES, size=n - 3)]
    classes = [classes[k] for k in rng.permutation(n)]
    engine = [c != "static" and bool(rng.random() < sc["p_engine_on"]) for c in classes]
    planes = [SUBTYPES[s][0] == "aeroplane" for s in shapes]
    floating = [pl and bool(rng.random() < sc["p_floating"]) for pl in planes]
    sizes = [get_asset(s).size for s in shapes]
    z = [float(rng.uniform(*sc["plane_height"])) if pl else ground_height(s) for pl, s in zip(planes, shapes)]
    noise = np.deg2rad(sc["heading_noise_deg"])

    def place(spread: float):
        placed = []  # (centre, bounding radius, footprint, z range)
        poses = [None] * n
        # Static objects first: they share the small centre area, so a layout that cannot fit fails early.
        for i in sorted(range(n), key=lambda k: classes[k] != "static"):
            static = classes[i] == "static"
            lo, hi = sc["static_radius" if static else "moving_radius"]
            hi = min(1.0, hi + spread)
            zr = (z[i] - sizes[i][2] / 2, z[i] + sizes[i][2] / 2)
            reach = float(np.hypot(sizes[i][0], sizes[i][1])) / 2 + SPAWN_GAP
            r = sc["arena_radius"] * (lo + (hi - lo) * rng.beta(*sc["position_beta"], size=SPAWN_TRIES))
            phi = rng.uniform(-np.pi, np.pi, size=SPAWN_TRIES)
            yaw = rng.uniform(-np.pi, np.pi, size=SPAWN_TRIES) if static else \
                phi + np.pi + rng.uniform(-noise, noise, size=SPAWN_TRIES)
            xy = r[:, None] * np.stack([np.cos(phi), np.sin(phi)], axis=1)
            for k in range(SPAWN_TRIES):
                fp = _footprint(xy[k], yaw[k], sizes[i])
                # Cheap tests first: bounding circles, then height ranges (an aeroplane may fly over a car).
                if not any(np.hypot(*(xy[k] - c)) < reach + rr and zr[0] < zz[1] + SPAWN_GAP
                           and zz[0] < zr[1] + SPAWN_GAP and _overlap(fp, f) for c, rr, f, zz in placed):
                    placed.append((xy[k], reach, fp, zr))
                    poses[i] = (xy[k], float(yaw[k]))
                    break
            else:
                return None
        return poses

    # A crowded draw (say three long static buses) may not fit its ranges: widen them a little per failed layout.
    for attempt in range(100):
        poses = place(0.02 * attempt)
        if poses is not None:
            break
    else:
        raise ConfigError("cannot place the objects without overlaps: raise 'scene.arena_radius' or lower "
                          "'scene.max_objects'")

    bodies, objects = [], []
    for i, ((xy, yaw), cls) in enumerate(zip(poses, classes)):
        speed = {"static": 0.0, "slow": params.slow_speed, "fast": params.fast_speed}[cls]
        quat = yaw_quaternion(yaw)
        v = heading(np.array(quat)) * speed
        body = Body(shapes[i], (float(xy[0]), float(xy[1]), z[i]), quat, (float(v[0]), float(v[1]), 0.0),
                    engine_on=engine[i], floating=floating[i])
        bodies.append(body)
        objects.append(SceneObject(i, shapes[i], SUBTYPES[shapes[i]][0], colors[i], tuple(sizes[i]),
                                   round(body.mass_with(params.density), 6), engine[i], floating[i], cls))

    jitter = rng.uniform(-sc["camera_jitter"], sc["camera_jitter"], size=3)
    cam_pos = tuple(float(round(v, 6)) for v in np.asarray(sc["camera_position"], float) + jitter)
    camera = Camera(cam_pos, tuple(map(float, sc["camera_look_at"])), float(sc["focal_length_mm"]),
                    float(sc["sensor_width_mm"]), int(cfg["render"]["width"]), int(cfg["render"]["height"]))
    return objects, bodies, camera


def visibility(camera: Camera, position: np.ndarray) -> np.ndarray:
    """[T, N] bool: the object's centre is in front of the camera and projects inside the image."""
    uv, depth = camera.project(position)
    return ((depth > 0) & (uv[..., 0] >= 0) & (uv[..., 0] < camera.width)
            & (uv[..., 1] >= 0) & (uv[..., 1] < camera.height))


# ---- the stage ------------------------------------------------------------------------------------------------

_worlds: dict = {}   # PhysicsParams -> the World this process simulates its scenes in


def _world(params):
    """This process's engine client for `params`, kept from scene to scene: a connection costs 13 ms, a
    hundredth of a scene. Nothing else carries over: every run empties and rebuilds the world (World.set_bodies)."""
    from dynclevr.physics import World

    if params not in _worlds:
        for world in _worlds.values():
            world.close()
        _worlds.clear()
        # Empty: the first run builds its bodies in it (a world made with them would be rebuilt at once).
        _worlds[params] = World([], params)
    return _worlds[params]


def simulate_scene(name: str, seed: int, cfg: Config) -> Scene4D:
    from dynclevr.physics import PhysicsParams, counterfactual, simulate

    _check(cfg)
    params = PhysicsParams.from_config(cfg)
    frames, observed = cfg["video"]["frames"], cfg["video"]["observed_frames"]
    objects, bodies, camera = sample_scene(np.random.default_rng(seed), cfg)
    world = _world(params)
    tr = simulate(bodies, params, frames, world=world)
    cfs, cf_grazes = {}, {}
    for i, o in enumerate(objects):
        for iv in INTERVENTIONS:
            run = counterfactual(bodies, i, iv, params, frames, world=world)
            if run is not None:
                cfs[(o.id, iv)] = run.collisions
                if run.grazes:
                    cf_grazes[(o.id, iv)] = run.grazes
    return Scene4D(name, params.fps, camera, objects, tr.position, tr.orientation, tr.velocity, tr.angular_velocity,
                   tr.acceleration, tr.engine, tr.floating, visibility(camera, tr.position),
                   collisions=tr.collisions, future_collisions=[c for c in tr.collisions if c.frame >= observed],
                   counterfactuals=cfs, observed_frames=observed, grazes=tr.grazes,
                   counterfactual_grazes=cf_grazes)


def run_scene(job: SceneJob) -> None:
    simulate_scene(job.scene, job.seed, job.cfg).write(job.outputs[0], kind="truth")


def _read(path: Path, *topics: str) -> dict:
    src = McapIn(path, SCENE_SCHEMA, SCENE_VERSION)
    out = {}
    for topic, _, msg in src.messages(*topics):
        out.setdefault(topic, msg)
    return out


OBJECTS_FIELDS = pa.schema([
    ("scene", pa.string()), ("id", pa.int32()), ("shape", pa.string()), ("category", pa.string()),
    ("color", pa.string()), ("mass", pa.float64()), ("speed_class", pa.string()), ("engine_on", pa.bool_()),
    ("floating", pa.bool_()), ("length", pa.float64()), ("width", pa.float64()), ("height", pa.float64())])


def finalize(store: Store, cfg: Config, scenes: list[str]) -> list[Path]:
    """Split-level objects.parquet: one row per object of every scene (its initial, static attributes)."""
    rows = {f.name: [] for f in OBJECTS_FIELDS}
    for scene in scenes:
        for o in _read(store.path("simulate", scene, ".mcap"), "/scene/objects")["/scene/objects"]["objects"]:
            for k, v in zip(rows, (scene, o["id"], o["shape"], o["category"], o["color"], o["mass"],
                                   o["speed_class"], o["engine_on"], o["floating"], *o["size"])):
                rows[k].append(v)
    path = store.split_file("objects.parquet")
    write_parquet(pa.table(rows, schema=OBJECTS_FIELDS), path, OBJECTS_SCHEMA, OBJECTS_VERSION)
    return [path]


def params(cfg: Config) -> dict:
    """The config the truth depends on; checked here, before any scene runs, so a bad value is one clear error."""
    from dynclevr.physics import PhysicsParams

    _check(cfg)
    PhysicsParams.from_config(cfg)
    out = cfg.digest("video", "physics", "scene")
    # Only the keys the truth reads from sections other stages own: the image size (the camera, visibility) and
    # the event merging. A new render backend or label threshold must not rerun the simulation.
    out["render"] = {k: cfg["render"][k] for k in ("width", "height")}
    out["labels"] = {"collision_merge_frames": cfg["labels"]["collision_merge_frames"]}
    return out


def extra_inputs(store: Store, cfg: Config) -> dict[str, str]:
    """The collision shapes and masses of the catalogue: new meshes rerun the simulation."""
    from dynclevr.physics import catalogue_digest

    return {"assets": catalogue_digest(cfg)}


STAGE = Stage("simulate", VERSION, inputs=(), params=params, outputs=(".mcap",), run_scene=run_scene,
              finalize=finalize, extra_inputs=extra_inputs)


# ---- statistics -----------------------------------------------------------------------------------------------

def stats(store: Store, cfg: Config) -> str:
    """A Markdown table of the split's simulated scenes (`dynclevr stats`)."""
    split = cfg.split(store.split)
    paths = [store.path("simulate", s, ".mcap") for s in split.scene_names()]
    paths = [p for p in paths if p.exists()]
    if not paths:
        raise DynclevrError(f"no simulated scenes under {store.stage_dir('simulate')}: run `dynclevr simulate --split "
                            f"{split.name}{command_options(store.data_dir)}`")
    per_scene, classes, cats = [], Counter(), Counter()
    engine = floating = falling = 0
    n_col, with_col, with_future, cf_runs, cf_changed, cf_any = [], 0, 0, 0, 0, 0
    for path in paths:
        d = _read(path, "/scene/objects", "/scene/collisions", "/scene/future_collisions", "/scene/counterfactuals")
        objs = d["/scene/objects"]["objects"]
        per_scene.append(len(objs))
        classes.update(o["speed_class"] for o in objs)
        cats.update(o["category"] for o in objs)
        engine += sum(o["engine_on"] for o in objs)
        floating += sum(o["floating"] for o in objs)
        falling += sum(o["category"] == "aeroplane" and not o["floating"] for o in objs)
        events = d["/scene/collisions"]["events"]
        n_col.append(len(events))
        with_col += bool(events)
        with_future += bool(d["/scene/future_collisions"]["events"])
        factual = {frozenset((e["a"], e["b"])) for e in events}
        for run in d["/scene/counterfactuals"]["runs"]:
            pairs = {frozenset((e["a"], e["b"])) for e in run["events"]}
            cf_runs += 1
            cf_changed += pairs != factual
            cf_any += bool(pairs)
    n_obj = sum(per_scene)
    rows = [
        ("scenes", f"{len(paths)}"),
        ("objects per scene (mean, min-max)", f"{np.mean(per_scene):.2f} ({min(per_scene)}-{max(per_scene)})"),
        *((f"objects {c}", f"{classes[c]} ({classes[c] / n_obj:.0%})") for c in SPEED_CLASSES),
        *((f"objects {c}", f"{cats[c]} ({cats[c] / n_obj:.0%})") for c in sorted(cats)),
        ("engine on", f"{engine} ({engine / n_obj:.0%} of objects)"),
        ("aeroplanes floating / falling", f"{floating} / {falling}"),
        ("collisions per video (mean, min-max)", f"{np.mean(n_col):.2f} ({min(n_col)}-{max(n_col)})"),
        ("videos with >= 1 collision", f"{with_col / len(paths):.0%}"),
        ("videos with a collision after the observed frames", f"{with_future / len(paths):.0%}"),
        ("counterfactual runs", f"{cf_runs} ({cf_runs / len(paths):.1f} per video)"),
        ("counterfactual runs whose collision set differs", f"{cf_changed / max(cf_runs, 1):.0%}"),
        ("counterfactual runs with >= 1 collision", f"{cf_any / max(cf_runs, 1):.0%}"),
    ]
    head = f"### Simulated scenes, split {split.name}\n\n| statistic | value |\n|---|---|\n"
    return head + "".join(f"| {k} | {v} |\n" for k, v in rows)
