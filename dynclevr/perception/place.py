"""3D placement from geometry: a detection's centre pixel, the camera calibration and the head's values -> a 3D
measurement (DESIGN.md: place).

The centre pixel fixes the camera ray. A ground vehicle rests on the ground plane, so its centre is where the ray
meets the plane z = its resting height (a sub-pixel centre pins it to centimetres across the ray and about a
decimetre along it); an aeroplane flies, so its centre is at the head's distance along the ray, until it has landed
on the ground, where its resting-height plane pins it as a ground vehicle's. The heading is
the head's yaw relative to the ray plus the ray's azimuth. The measurement's uncertainty is anisotropic: tight
across the ray, looser along it (`Measurement.covariance`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from dynclevr.assets.catalogue import SUBTYPES
from dynclevr.camera import Camera
from dynclevr.perception.detector import Detection

SUBTYPE_NAMES = list(SUBTYPES)
IS_PLANE = np.array([SUBTYPES[s][0] == "aeroplane" for s in SUBTYPE_NAMES])


@lru_cache(maxsize=None)
def resting_height(shape: str) -> float:
    from dynclevr.physics import ground_height

    return ground_height(shape)


@dataclass
class Measurement:
    position: np.ndarray      # [3] world, metres
    yaw: float                # world heading, radians
    ray: np.ndarray           # [3] unit camera ray through the centre
    flying: bool
    detection: Detection
    confidence: float | None = None   # the rendering likelihood, where render-and-compare refined it
    lying: bool = False       # a ground vehicle placed at a height of its own, not its resting height
    landed: bool = False      # an aeroplane on the ground, placed on its resting-height plane

    def covariance(self, across: float, along: float) -> np.ndarray:
        """3x3: `across` metres of standard deviation across the ray, `along` (per 10 m of distance) along it."""
        along_sd = along * max(self.detection.dist, 1.0) / 10.0
        return across ** 2 * np.eye(3) + (along_sd ** 2 - across ** 2) * np.outer(self.ray, self.ray)

    def noise(self, p: dict) -> np.ndarray:
        """The covariance with the parser's noise along the ray: a standing ground vehicle's, or the looser one of
        a centre the ground plane does not pin (in the air, or at a height read from the head)."""
        standing = not self.flying and not self.lying
        return self.covariance(p["measure_across"], p["measure_along"] if standing else p["measure_along_flying"])


def camera_ray(camera: Camera, u: float, v: float) -> np.ndarray:
    R = camera.world_to_camera[:3, :3]
    d = np.array([(u - camera.width / 2) / camera.fx, (v - camera.height / 2) / camera.fx, 1.0])
    w = R.T @ d
    return w / np.linalg.norm(w)


def detection_shape(det: Detection) -> str:
    """The detection's own sub-type: the likeliest plane where planes hold over half its belief, else the likeliest
    ground vehicle."""
    flying = float(np.exp(det.subtype_logp)[IS_PLANE].sum()) > 0.5
    return SUBTYPE_NAMES[int(np.argmax(np.where(IS_PLANE == flying, det.subtype_logp, -np.inf)))]


def place(camera: Camera, det: Detection, shape: str | None = None, height: float | None = None) -> Measurement:
    """`shape`: the sub-type to place it as (a track's, from all its frames); None: the detection's own.
    `height`: the plane its centre lies in where it is not a standing ground vehicle's resting height (a track's
    own height: a two-wheeler knocked over, an aeroplane landed; `tracker.own_height`)."""
    eye = np.asarray(camera.position, float)
    ray = camera_ray(camera, det.u, det.v)
    shape = detection_shape(det) if shape is None else shape
    flying = SUBTYPES[shape][0] == "aeroplane"
    centre = eye + ray * det.dist
    if flying and height is None and centre[2] < resting_height(shape):
        height = resting_height(shape)   # under the floor: the distance is too long, and the ray meets the ground first
    if not flying or height is not None:
        reach = ((resting_height(shape) if height is None else height) - eye[2]) / min(ray[2], -1e-3)
        # a ray that never meets the plane in front (the centre above the horizon) falls back to the distance
        centre = eye + ray * (reach if 0 < reach < 3 * det.dist else det.dist)
    yaw = det.alpha + math.atan2(centre[1] - eye[1], centre[0] - eye[0])
    return Measurement(centre, math.atan2(math.sin(yaw), math.cos(yaw)), ray, flying, det,
                       lying=not flying and height is not None, landed=flying and height is not None)
