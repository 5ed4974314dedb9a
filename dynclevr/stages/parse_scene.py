"""Stage parse-scene: the NS-4DPhysics scene parser (REFERENCE.md section 2.1-2.4; dynclevr/perception/).

Reads: `video/<scene>.mcap` through `Video.frames()` and `.camera` only (RGB frames and the calibration: never the
masks or depth that the same file carries for training and tests), the detection head (weights/detector/), the
scene-parser weights (weights/parser/: feature CNN and neural meshes), the collision classifier
(weights/collision/) and the asset catalogue. Params: [parser], [physics] (the engine of the prior), [video], [labels].
Writes: `parsed/<scene>.mcap`, a Scene4D of kind "estimate" in the truth's schema (objects with confidence,
per-frame 4D states, collisions), so the executor runs on it unchanged; its /tf and /scene/vehicles channels show
the estimate beside the truth in Foxglove. With parser.physics_prior = false (`--no-physics-prior`) this is the
paper's ablation, written to parsed-noprior/; with parser.filter = "none" (`--per-frame`) the per-frame 3D baseline
(baselines/perframe.py: the detection head and the placement only, frame by frame), written to parsed-perframe/.
"""

from __future__ import annotations

from functools import lru_cache

from dynclevr.artifacts import Store
from dynclevr.baselines import perframe
from dynclevr.perception import detections
from dynclevr.perception.collisions import DEFAULT_DIR as COLLISION_DIR
from dynclevr.perception.collisions import CollisionModel, collision_digest
from dynclevr.perception.detector_train import DEFAULT_DIR as DETECTOR_DIR
from dynclevr.perception.detector_train import detector_digest, load_detector
from dynclevr.perception.model import DEFAULT_DIR, ParserModel, manifest_digest
from dynclevr.perception.tracker import parse_video
from dynclevr.physics import catalogue_digest
from dynclevr.pipeline import SceneJob, Stage
from dynclevr.video import Video

VERSION = 50  # 5: collisions from the learned classifier (weights/collision/); 6: smoothed factual arrays, cut state;
              # 7: robust smoothing; 8: smoothed velocities only where the filter converges; 9: segment motion;
              # 10: start speeds, the cut state from the segment motion of the observed frames; 11: slow to rest;
              # 12: cut_collisions, the collisions the observed frames decide (the predictive questions read them);
              # 13: no slow speeds before the first impact; 14: cut_collisions only between tracks confirmed by the cut
              # 15: no engine from a static start; 16: track stitching, a falling plane's flight as segment motion;
              # 17: a plane's flight before its first impact along its heading, at the cut; 18: segment motion's
              # line direction weighted by the measurements' noise across and along the camera ray; 19: an aeroplane's
              # floating from the prior's two vertical motions (held, or fallen from rest), its vertical velocity theirs;
              # 20: a knocked-over two-wheeler placed at its own height, not its resting height; 21: a landed
              # aeroplane placed on its resting-height plane, not at the head's distance; 22: a floating plane's
              # vertical velocity constant between impacts; 23: only after an impact (a plane found too late for its
              # floating to be decided is not given a line before one); 24: the head reads each frame mirrored too;
              # 25: stitching within a share of the vehicle's length, after long gaps by sub-type, across the cut;
              # 26: stitching one pair at a time, so that a vehicle lost twice is one object; 27: detections under
              # the start bar start a track where they persist (parser.weak_track_*); 28: the reported heading holds
              # through the head's front/back flips (parser.heading_support); 29: a first stretch that no parked
              # start explains may be parked, then struck (parser.parked_split); 30: a ground vehicle standing on
              # its wheels has no vertical velocity; 31: after a long gap, the only other track of a vehicle's kind
              # and colour is the same vehicle; 32: a confirmed track is seen from its first detection, not from
              # the frame that confirmed it; 33: a first stretch's engine decided under the generator's prior
              # (parser.engine_prior), not by the likelihood alone; 34: a confident detection never pairs with a
              # track whose category or colour it contradicts (parser.veto_score); 35: of two tracks that converge,
              # the one without a detection in the frame ends, not always the younger; 36: a track that missed its
              # last detections pairs only with one that looks like it (parser.coast_frames); 37: ... also in the
              # frames just after it was found again (parser.coast_window); 38: the spin is the heading's fitted
              # slope since the last impact where significant, else 0 (parser.spin_window); 39: at the cut a plane's
              # line may turn from the head's heading under a Gaussian prior (parser.heading_motion_sd); 40: at the
              # cut, a stretch begun by a landing and too short for a fit goes on from the flight's velocity
              # 41: reported positions through long contacts, an aeroplane's in the air its flight path
              # 42: ... but not in a stretch the path misses; 43: a plane's flight before its first impact along
              # its heading from a start speed seen whole too, not at the cut alone; 44: a reading facing against
              # the heading counts half a confusion against it (parser.heading_flip_weight); 45: two alike ground
              # tracks whose footprints overlap while both are detected are one vehicle (parser.duplicate_*)
              # 46: a stitch within a few frames and stitch_radius needs one category, not one colour
              # (parser.stitch_near_frames); 47: a bicycle and a motorbike are one kind to a stitch (tracker.KINDS)
              # 48: a detection whose distance misses its track's by over a factor exp(parser.depth_gate) cannot pair
              # 49: a floating plane's vertical speed changes where an impact the parser did not find kicked it; a
              # landed plane has no vertical velocity; 50: a standing car or bus whose head's heights disagree with
              # its sub-type's resting height is placed at them (tracker.own_height)


@lru_cache(maxsize=1)
def _model():
    return ParserModel.load(DEFAULT_DIR), _detector()


@lru_cache(maxsize=1)
def _collision_model():
    return CollisionModel.load(COLLISION_DIR)


def run_scene(job: SceneJob) -> None:
    import torch

    torch.set_num_threads(1)   # the runner's process pool is the parallelism
    video = Video.read(job.inputs["render"][0])
    frames, cfg = video.frames(), job.cfg
    dets = scene_detections(job.store, job.scene, frames, cfg)
    if perframe.enabled(cfg):   # the per-frame 3D baseline (`--per-frame`): the detection head alone
        scene = perframe.parse(frames, video.camera, _detector(), cfg, job.scene, dets)
    else:
        scene = parse_video(frames, video.camera, *_model(), cfg, job.scene, _collision_model(), dets)
    scene.write(job.outputs[0], kind="estimate")


def scene_detections(store: Store, scene: str, frames, cfg) -> list:
    """The head's detections of a video, shared by every row of the model and the per-frame baseline
    (perception/detections.py)."""
    parser = cfg["parser"]
    key = detections.cache_key(store.path("render", scene, ".mcap"), detector_digest(DETECTOR_DIR), parser)
    return detections.cached(detections.cache_path(store, scene), key,
                             lambda: detections.detect(_detector(), frames, parser))


@lru_cache(maxsize=1)
def _detector():
    return load_detector(DETECTOR_DIR)


def _params(cfg) -> dict:
    if perframe.enabled(cfg):   # the settings the per-frame baseline reads (tuning the tracker does not rerun it)
        return perframe.parse_params(cfg)
    return cfg.digest("parser", "physics", "video", "labels")


STAGE = Stage(
    name="parse-scene",
    version=VERSION,
    inputs=("render",),
    params=_params,
    outputs=(".mcap",),
    run_scene=run_scene,
    # The neural meshes and the prior's bodies come from the catalogue: new meshes change the estimate.
    extra_inputs=lambda store, cfg: {"weights": manifest_digest(DEFAULT_DIR), "detector": detector_digest(DETECTOR_DIR),
                                     "collision": collision_digest(COLLISION_DIR), "assets": catalogue_digest(cfg)},
)
