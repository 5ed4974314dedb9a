import numpy as np
import pytest
from mcap.reader import make_reader
from mcap.writer import CompressionType, Writer

from dynclevr.camera import Camera
from dynclevr.scene import Collision, Scene4D, SceneObject
from dynclevr.video import CALIBRATION, IMAGE, POSE, TF


@pytest.fixture
def tiny_scene() -> Scene4D:
    """Two cars: object 0 static, object 1 driving at 3 m/s along +x into it, colliding at frame 20."""
    T, N = 40, 2
    pos = np.zeros((T, N, 3))
    pos[:, 0] = [2.0, 0.0, 0.5]
    pos[:, 1, 0] = -2.0 + 3.0 * np.arange(T) / 60
    pos[:, 1, 2] = 0.5
    quat = np.zeros((T, N, 4))
    quat[..., 3] = 1
    vel = np.zeros((T, N, 3))
    vel[:, 1, 0] = 3.0
    objs = [SceneObject(0, "sedan", "car", "red", (3.0, 1.3, 1.0), 10.0, False, False, "static"),
            SceneObject(1, "school_bus", "bus", "yellow", (3.8, 1.3, 1.6), 20.0, True, False, "slow")]
    cam = Camera((8.0, -7.0, 3.2), (0.0, 0.0, 1.3), 35.0, 32.0, 320, 240)
    return Scene4D("000000", 60, cam, objs, pos, quat, vel, np.zeros((T, N, 3)), np.zeros((T, N, 3)),
                   np.zeros((T, N), bool), np.zeros((T, N), bool), np.ones((T, N), bool),
                   collisions=[Collision(20, 0, 1, (1.0, 0.0, 0.5), 12.0)],
                   future_collisions=[Collision(20, 0, 1, (1.0, 0.0, 0.5), 12.0)],
                   counterfactuals={(1, "static"): []}, observed_frames=10)


def strip_video(src, dst) -> None:
    """Copy a rendered video's MCAP keeping only what a model may read: the RGB frames and the camera."""
    keep = {IMAGE, POSE, CALIBRATION, TF}
    with open(src, "rb") as f_in, open(dst, "wb") as f_out:
        reader = make_reader(f_in)
        w = Writer(f_out, compression=CompressionType.ZSTD)
        w.start(profile="", library="test")
        for m in reader.iter_metadata():
            w.add_metadata(m.name, m.metadata)
        channels = {}
        for schema, channel, msg in reader.iter_messages(topics=sorted(keep)):
            if channel.topic not in channels:
                sid = w.register_schema(schema.name, schema.encoding, schema.data) if schema else 0
                channels[channel.topic] = w.register_channel(channel.topic, channel.message_encoding, sid)
            w.add_message(channels[channel.topic], msg.log_time, msg.data, msg.publish_time, msg.sequence)
        w.finish()


def onehot(n: int, k: int) -> np.ndarray:
    """Log-probabilities of a sure choice of k among n (a synthetic detection's sub-type or colour)."""
    v = np.full(n, -20.0)
    v[k] = 0.0
    return v
