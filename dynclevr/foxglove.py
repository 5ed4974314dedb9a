"""Foxglove messages (protobuf) that let a person play a scene in Foxglove: transforms and one box per vehicle."""

from __future__ import annotations

from foxglove_schemas_protobuf.CubePrimitive_pb2 import CubePrimitive
from foxglove_schemas_protobuf.FrameTransform_pb2 import FrameTransform
from foxglove_schemas_protobuf.FrameTransforms_pb2 import FrameTransforms
from foxglove_schemas_protobuf.SceneEntity_pb2 import SceneEntity
from foxglove_schemas_protobuf.SceneUpdate_pb2 import SceneUpdate
from google.protobuf.timestamp_pb2 import Timestamp

from dynclevr.colors import COLORS


def _stamp(t: int, fps: int) -> Timestamp:
    ns = round(t * 1e9 / fps)
    return Timestamp(seconds=ns // 10**9, nanos=ns % 10**9)


def frame_transforms(scene, t: int) -> FrameTransforms:
    msg = FrameTransforms()
    for i, o in enumerate(scene.objects):
        tf = msg.transforms.add(timestamp=_stamp(t, scene.fps), parent_frame_id="world",
                                child_frame_id=f"object_{o.id}")
        tf.translation.x, tf.translation.y, tf.translation.z = map(float, scene.position[t, i])
        q = scene.orientation[t, i]
        tf.rotation.x, tf.rotation.y, tf.rotation.z, tf.rotation.w = map(float, q)
    return msg


def scene_update(scene, t: int) -> SceneUpdate:
    msg = SceneUpdate()
    for i, o in enumerate(scene.objects):
        e = msg.entities.add(timestamp=_stamp(t, scene.fps), frame_id=f"object_{o.id}", id=f"object_{o.id}")
        e.metadata.add(key="shape", value=o.shape)
        e.metadata.add(key="color", value=o.color)
        cube = e.cubes.add()
        cube.size.x, cube.size.y, cube.size.z = map(float, o.size)
        cube.pose.orientation.w = 1.0  # an object's position is the centre of its bounding box
        r, g, b = COLORS.get(o.color, (128, 128, 128))
        cube.color.r, cube.color.g, cube.color.b, cube.color.a = r / 255, g / 255, b / 255, 0.8
    return msg
