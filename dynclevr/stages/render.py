"""Stage render: draw each simulated scene as the camera sees it (paper, section 3: the DynSuperCLEVR videos).

Reads: `sim/<scene>.mcap` (the objects, their per-frame poses and the camera that simulate sampled); it never
re-simulates. Params: [render] (backend, resolution, supersampling, shadows, Mitsuba samples).
Writes: `video/<scene>.mcap` (dynclevr/video.py: RGB frames, instance masks, depth, calibration, camera pose).

Appearance per scene, from one generator seeded by the scene seed: the environment (one of
environments.NUM_ENVIRONMENTS: sky, skyline, ground material, sun) and each object's colour variant (one of 6).
"""

from __future__ import annotations

import json
import os

import numpy as np

from dynclevr.config import Config, ConfigError
from dynclevr.pipeline import SceneJob, Stage
from dynclevr.render import BACKENDS, make_renderer
from dynclevr.render.appearance import choose_variants
from dynclevr.render.environments import choose, environment
from dynclevr.scene import Scene4D
from dynclevr.video import VideoWriter

VERSION = 2  # 2: vehicles, masks and shadows where the calibration projects them (half a pixel)
# The render draws use their own stream of the scene seed, so they are independent of simulate's draws.
STREAM = 0x52454E44


def check(cfg: Config) -> dict:
    r = cfg["render"]
    if r["backend"] not in BACKENDS:
        raise ConfigError(f"'render.backend' = {r['backend']!r}: use one of {', '.join(BACKENDS)}")
    if not isinstance(r["supersample"], int) or not 1 <= r["supersample"] <= 4:
        raise ConfigError(f"'render.supersample' = {r['supersample']!r}: use 1 (none) to 4")
    if r["mitsuba_spp"] < 1:
        raise ConfigError(f"'render.mitsuba_spp' = {r['mitsuba_spp']!r} must be at least 1")
    return r


def appearance(seed: int, num_objects: int) -> tuple[int, list[int]]:
    """(environment index, colour variant per object) of a scene."""
    rng = np.random.default_rng([seed, STREAM])
    return choose(rng), choose_variants(rng, num_objects)


def render_scene(scene: Scene4D, seed: int, cfg: Config, out) -> None:
    r = check(cfg)
    camera = scene.camera.with_resolution(r["width"], r["height"])
    env_index, variants = appearance(seed, len(scene.objects))
    env = environment(env_index)
    with VideoWriter(out, camera, scene.fps, scene.num_frames, scene=scene.name, backend=r["backend"],
                     environment=env.name, variants=json.dumps(variants)) as video, \
            make_renderer(r["backend"], scene, camera, env, variants, r) as renderer:
        for t in range(scene.num_frames):
            video.add(*renderer.render(t))


def run_scene(job: SceneJob) -> None:
    if os.environ.get("OMP_NUM_THREADS") == "1":   # a pool worker: one core each, the pool is the parallelism
        import cv2

        cv2.setNumThreads(1)
    render_scene(Scene4D.read(job.inputs["simulate"][0]), job.seed, job.cfg, job.outputs[0])


# Keys that change the frames of each backend: tuning one backend never reruns the other's videos.
BACKEND_KEYS = {"tiny": ("backend", "width", "height", "supersample", "shadows"),
                "mitsuba": ("backend", "width", "height", "mitsuba_spp", "denoise")}


def params(cfg: Config) -> dict:
    r = check(cfg)
    return {"render": {k: r[k] for k in BACKEND_KEYS[r["backend"]]}}


STAGE = Stage("render", VERSION, inputs=("simulate",), params=params, outputs=(".mcap",), run_scene=run_scene)
