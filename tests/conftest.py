import numpy as np
import pytest

from dynclevr.camera import Camera
from dynclevr.scene import Collision, Scene4D, SceneObject


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
