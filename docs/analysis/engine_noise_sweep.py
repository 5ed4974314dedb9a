"""How precise per-frame detections must be for the cut state's engine: synthetic detections of one sedan, simulated
by the data's physics, with pixel noise of a given size (and 3% noise on the head's distance), parsed by the
tracker from the 30 observed frames; the share of tracks whose engine at the cut is right. `--rho`: the noise is
correlated from frame to frame (AR(1) with this lag-1 correlation, the same size), as the head's is (0.73:
detector_pixel_error.py).

    .venv/bin/python docs/analysis/engine_noise_sweep.py --noise 0.8 1.6 2.5 3.5 --trials 40
    .venv/bin/python docs/analysis/engine_noise_sweep.py --noise 0.8 1.3 --rho 0.73

Headings and positions are random, start speeds 3 and 6 m/s, the engine on for half. An analysis, not a test.
"""

import argparse

import numpy as np

from dynclevr.camera import Camera
from dynclevr.colors import COLOR_NAMES
from dynclevr.config import Config
from dynclevr.perception.detector import Detection
from dynclevr.perception.detector_data import azimuth
from dynclevr.perception.model import ParserModel
from dynclevr.perception.place import SUBTYPE_NAMES
from dynclevr.perception.tracker import SceneParser
from dynclevr.physics import Body, PhysicsParams, ground_height, simulate, yaw_quaternion

ap = argparse.ArgumentParser()
ap.add_argument("--noise", type=float, nargs="+", default=[0.8, 1.6, 2.5, 3.5])
ap.add_argument("--trials", type=int, default=40)
ap.add_argument("--rho", type=float, default=0.0)
args = ap.parse_args()

cfg = Config.load()
params, model = PhysicsParams.from_config(cfg), ParserModel.load()
cut = cfg["video"]["observed_frames"] - 1
camera = Camera((8.0, -7.0, 3.2), (0.0, 0.0, 1.3), 35.0, 32.0, 320, 240)


def onehot(n: int, k: int) -> np.ndarray:
    return np.log(np.where(np.arange(n) == k, 0.97, 0.03 / (n - 1)))


rng = np.random.default_rng(0)
for noise in args.noise:
    right = []
    for trial in range(args.trials):
        yaw, speed, engine = rng.uniform(-np.pi, np.pi), (3.0, 6.0)[trial % 2], bool(trial // 2 % 2)
        heading = np.array([np.cos(yaw), np.sin(yaw)])
        start = rng.uniform(-3, 3, 2) - heading
        tr = simulate([Body("sedan", (*start, ground_height("sedan")), yaw_quaternion(yaw),
                            (*(speed * heading), 0.0), engine_on=engine)], params, cut + 1)
        dets, err = [], rng.normal(0, noise, 2)
        for pos in tr.position[:, 0]:
            err = args.rho * err + np.sqrt(1 - args.rho ** 2) * rng.normal(0, noise, 2)
            (u, v), _ = camera.project(pos)
            dist = float(np.linalg.norm(pos - np.asarray(camera.position))) * (1 + rng.normal(0, 0.03))
            dets.append([Detection(float(u + err[0]), float(v + err[1]), 0.9,
                                   onehot(len(SUBTYPE_NAMES), SUBTYPE_NAMES.index("sedan")),
                                   onehot(len(COLOR_NAMES), 1), yaw - float(azimuth(camera.position, pos)), dist,
                                   float(pos[2]))])
        est = SceneParser(model, None, camera, cfg).parse(np.zeros((cut + 1, 1, 1, 3), np.uint8), "sweep", dets)
        right.append(bool(len(est.objects)) and bool(est.cut_state["engine"][0]) == engine)
    print(f"pixel noise {noise} px (lag-1 correlation {args.rho}): engine at the cut right for {np.mean(right):.3f} of {len(right)} tracks")
