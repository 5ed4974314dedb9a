"""The video artifact (`video/<scene>.mcap`): what a camera saw, and the only thing the model may look at.

Channels (log time = frame / fps; every frame message carries the same timestamp):

| topic                | schema                     | content                                                      |
|----------------------|----------------------------|--------------------------------------------------------------|
| /camera/image        | foxglove.CompressedImage   | RGB frame, JPEG quality 92 with 4:4:4 chroma (see below)     |
| /camera/instances    | foxglove.CompressedImage   | 16-bit grey PNG: object id + 1 per pixel, 0 = no vehicle     |
| /camera/depth        | foxglove.CompressedImage   | 16-bit grey PNG: depth along the optical axis in millimetres; |
|                      |                            | 0 = no surface (sky), 65535 = 65.535 m or farther            |
| /camera/calibration  | foxglove.CameraCalibration | K, P, R (identity), no distortion, frame_id "camera"         |
| /camera/pose         | dynclevr.Camera            | Camera.to_dict(): intrinsics and extrinsics (once, at t = 0) |
| /tf                  | foxglove.FrameTransforms   | world -> camera (OpenCV axes: x right, y down, z forward)    |

Why JPEG for the frames: the scene parser and colour classifier learn from these pixels, so they must not be
smeared; quality 92 without chroma subsampling keeps colour edges and hues (the error is a few grey levels) at a
tenth of PNG's size, which matters for the 1,000-video split. Masks and depth are exact (lossless PNG) because tests
and training targets compare them pixel for pixel. A reader that wants only frames decodes only /camera/image.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import cv2
import numpy as np
from foxglove_schemas_protobuf.CameraCalibration_pb2 import CameraCalibration
from foxglove_schemas_protobuf.CompressedImage_pb2 import CompressedImage
from foxglove_schemas_protobuf.FrameTransforms_pb2 import FrameTransforms
from google.protobuf.timestamp_pb2 import Timestamp

from dynclevr.artifacts import ArtifactError, rerun_hint
from dynclevr.camera import Camera
from dynclevr.mcapio import McapIn, McapOut, frame_time_ns

VIDEO_SCHEMA = "dynclevr.video"
VIDEO_VERSION = 1

IMAGE, INSTANCES, DEPTH = "/camera/image", "/camera/instances", "/camera/depth"
CALIBRATION, POSE, TF = "/camera/calibration", "/camera/pose", "/tf"
FRAME_ID = "camera"
JPEG_QUALITY = 92
DEPTH_MAX_MM = 65535


def _stamp(t_ns: int) -> Timestamp:
    return Timestamp(seconds=t_ns // 10**9, nanos=t_ns % 10**9)


def _png(image: np.ndarray, strategy: int = cv2.IMWRITE_PNG_STRATEGY_DEFAULT) -> bytes:
    # Level 1: the fastest deflate; the file's zstd chunks squeeze a little more out afterwards.
    ok, buf = cv2.imencode(".png", image, [cv2.IMWRITE_PNG_COMPRESSION, 1, cv2.IMWRITE_PNG_STRATEGY, strategy])
    assert ok
    return buf.tobytes()


def encode_rgb(rgb: np.ndarray) -> bytes:
    ok, buf = cv2.imencode(".jpg", cv2.cvtColor(rgb, cv2.COLOR_RGB2BGR), [
        cv2.IMWRITE_JPEG_QUALITY, JPEG_QUALITY, cv2.IMWRITE_JPEG_SAMPLING_FACTOR, cv2.IMWRITE_JPEG_SAMPLING_FACTOR_444])
    assert ok
    return buf.tobytes()


def encode_instances(mask: np.ndarray) -> bytes:
    # Run-length coding suits a few flat regions: 2-3x faster than the default, and smaller.
    return _png((mask.astype(np.int32) + 1).astype(np.uint16), cv2.IMWRITE_PNG_STRATEGY_RLE)


def encode_depth(depth: np.ndarray) -> bytes:
    mm = np.where(np.isfinite(depth), np.clip(np.round(depth * 1000), 1, DEPTH_MAX_MM), 0)
    return _png(mm.astype(np.uint16))


def calibration(camera: Camera, t_ns: int) -> CameraCalibration:
    K = camera.K
    P = np.hstack([K, np.zeros((3, 1))])
    return CameraCalibration(timestamp=_stamp(t_ns), frame_id=FRAME_ID, width=camera.width, height=camera.height,
                             distortion_model="plumb_bob", D=[0.0] * 5, K=K.ravel().tolist(),
                             R=np.eye(3).ravel().tolist(), P=P.ravel().tolist())


def camera_transform(camera: Camera, t_ns: int) -> FrameTransforms:
    """world -> camera: the camera's pose in the world (camera-to-world rotation, its position)."""
    from scipy.spatial.transform import Rotation

    R_wc = camera.world_to_camera[:3, :3].T
    msg = FrameTransforms()
    tf = msg.transforms.add(timestamp=_stamp(t_ns), parent_frame_id="world", child_frame_id=FRAME_ID)
    tf.translation.x, tf.translation.y, tf.translation.z = map(float, camera.position)
    q = Rotation.from_matrix(R_wc).as_quat()
    tf.rotation.x, tf.rotation.y, tf.rotation.z, tf.rotation.w = map(float, q)
    return msg


class VideoWriter:
    """`with VideoWriter(path, camera, fps, num_frames, scene=...) as w: w.add(rgb, mask, depth)` per frame."""

    def __init__(self, path: Path, camera: Camera, fps: int, num_frames: int, **meta: str):
        self.camera, self.fps, self.num_frames, self.t = camera, fps, num_frames, 0
        self._out = McapOut(path, VIDEO_SCHEMA, VIDEO_VERSION, fps=fps, frames=num_frames, width=camera.width,
                            height=camera.height, **meta)

    def __enter__(self) -> "VideoWriter":
        self._out.__enter__()
        self._out.json(POSE, "dynclevr.Camera", 0, self.camera.to_dict())
        return self

    def __exit__(self, exc_type, exc, tb):
        if exc_type is None and self.t != self.num_frames:
            exc_type, exc = ValueError, ValueError(f"wrote {self.t} frames, announced {self.num_frames}")
            self._out.__exit__(exc_type, exc, tb)
            raise exc
        return self._out.__exit__(exc_type, exc, tb)

    def add(self, rgb: np.ndarray, mask: np.ndarray, depth: np.ndarray) -> None:
        """rgb uint8 [H, W, 3]; mask int [H, W] object id or -1; depth float [H, W] metres (inf where nothing)."""
        H, W = self.camera.height, self.camera.width
        if rgb.shape != (H, W, 3) or mask.shape != (H, W) or depth.shape != (H, W):
            raise ValueError(f"frame {self.t}: expected {H}x{W} images, got {rgb.shape}, {mask.shape}, {depth.shape}")
        tn = frame_time_ns(self.t, self.fps)
        out, stamp = self._out, _stamp(tn)
        out.proto(IMAGE, tn, CompressedImage(timestamp=stamp, frame_id=FRAME_ID, data=encode_rgb(rgb), format="jpeg"))
        out.proto(INSTANCES, tn, CompressedImage(timestamp=stamp, frame_id=FRAME_ID, data=encode_instances(mask),
                                                 format="png"))
        out.proto(DEPTH, tn, CompressedImage(timestamp=stamp, frame_id=FRAME_ID, data=encode_depth(depth),
                                             format="png"))
        out.proto(CALIBRATION, tn, calibration(self.camera, tn))
        out.proto(TF, tn, camera_transform(self.camera, tn))
        self.t += 1


@dataclass
class Video:
    """A rendered video: `Video.read(path)`, then `.camera`, `.fps`, `.num_frames`, `.frames()`; the dataset's
    `.masks()` and `.depth()` are ground truth (tests, training targets), never inputs of the model."""

    path: Path
    camera: Camera
    fps: int
    num_frames: int
    scene: str
    meta: dict          # the file's metadata: backend, environment, colour variants, ...

    @classmethod
    def read(cls, path: Path) -> "Video":
        src = McapIn(path, VIDEO_SCHEMA, VIDEO_VERSION)
        return cls(Path(path), Camera.from_dict(src.first(POSE)), int(src.meta["fps"]), int(src.meta["frames"]),
                   src.meta.get("scene", Path(path).stem), dict(src.meta))

    def _images(self, topic: str, flags: int, frames: slice | None) -> list[np.ndarray]:
        src = McapIn(self.path, VIDEO_SCHEMA, VIDEO_VERSION)
        wanted = range(self.num_frames)[frames] if frames is not None else None
        out = []
        for i, (_, _, msg) in enumerate(src.messages(topic)):
            if wanted is None or i in wanted:
                img = cv2.imdecode(np.frombuffer(msg.data, np.uint8), flags)
                if img is None:
                    raise ArtifactError(f"{self.path}: frame {i} of '{topic}' does not decode: "
                                        f"{rerun_hint(self.path)}")
                out.append(img)
        if not out and self.num_frames:
            raise ArtifactError(f"{self.path} has no '{topic}' frames: {rerun_hint(self.path)}")
        return out

    def frames(self, frames: slice | None = None) -> np.ndarray:
        """uint8 [T, H, W, 3] RGB."""
        imgs = self._images(IMAGE, cv2.IMREAD_COLOR, frames)
        return np.stack([cv2.cvtColor(i, cv2.COLOR_BGR2RGB) for i in imgs])

    def masks(self, frames: slice | None = None) -> np.ndarray:
        """int16 [T, H, W]: object id, -1 where no vehicle."""
        imgs = self._images(INSTANCES, cv2.IMREAD_UNCHANGED, frames)
        return (np.stack(imgs).astype(np.int32) - 1).astype(np.int16)

    def depth(self, frames: slice | None = None) -> np.ndarray:
        """float32 [T, H, W]: metres along the optical axis; inf where no surface (sky); 65.535 means that or more."""
        mm = np.stack(self._images(DEPTH, cv2.IMREAD_UNCHANGED, frames)).astype(np.float32)
        return np.where(mm > 0, mm / 1000, np.inf).astype(np.float32)
