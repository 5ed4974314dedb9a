"""Language labels from the state arrays: classes, bands, stability, direction in the camera frame, acceleration and
floating, collision merging, config checks."""

import numpy as np
import pytest

from dynclevr.config import Config, ConfigError
from dynclevr.questions.labels import AMBIGUOUS, DIRECTIONS, VELOCITIES, compute_labels, future_events, merge_events
from dynclevr.scene import Collision
from test_programs import AWAY, RIGHT, build_scene, known_scene, obj


@pytest.fixture(scope="module")
def lcfg():
    return Config.load()["labels"]


def one_object(velocity, start=(0, 0, 0.5), size=(3.0, 1.3, 1.0), **events):
    v = np.asarray(velocity, float).reshape(-1, 1, 3)
    return build_scene([obj(0, "sedan", "car", "red", size)], v, [start], **events)


def test_known_scene_labels_at_the_start(lcfg):
    L = compute_labels(known_scene(), lcfg)
    assert [VELOCITIES[k] for k in L.velocity[0]] == ["static", "slow", "fast", "static", "slow", "slow"]
    assert [DIRECTIONS[k] for k in L.direction[0, 1:3]] == ["right", "back"]
    assert DIRECTIONS[L.direction[0, 5]] == "front"
    assert L.direction_ambiguous[0, 0] and L.direction_ambiguous[0, 3]     # static: no direction
    assert DIRECTIONS[L.direction[40, 3]] == "down" and not L.direction_ambiguous[40, 3]
    assert L.accelerating[10].tolist() == [False, False, False, False, True, False]
    assert L.floating[0].tolist() == [False, False, True, False, False, False]
    assert not L.floating_ambiguous[0].any()
    assert L.accel[10, 4] == pytest.approx(1.5)
    assert L.vertical_accel[10, 3] == pytest.approx(-10.0)


@pytest.mark.parametrize("speed,label,ambiguous", [
    (0.0, "static", False), (0.09, "static", False), (0.2, "static", True), (0.4, "slow", True),
    (0.6, "slow", False), (4.9, "slow", False), (5.2, "slow", True), (5.3, "fast", True), (5.6, "fast", False)])
def test_velocity_bands(lcfg, speed, label, ambiguous):
    L = compute_labels(one_object(np.tile([speed, 0, 0], (20, 1))), lcfg)
    assert VELOCITIES[L.velocity[10, 0]] == label
    assert L.velocity_ambiguous[10, 0] == ambiguous


def test_velocity_must_hold_over_a_few_frames(lcfg):
    v = np.zeros((40, 3))
    v[20:, 0] = 6.0        # a static object struck at frame 20
    L = compute_labels(one_object(v), lcfg)
    k = lcfg["stable_frames"]
    assert L.velocity_ambiguous[20 - k: 20 + k, 0].all()
    assert not L.velocity_ambiguous[20 - k - 1, 0] and not L.velocity_ambiguous[20 + k, 0]
    assert L.rows()["velocity"][20] == AMBIGUOUS and L.rows()["velocity"][0] == "static"


@pytest.mark.parametrize("v,direction,ambiguous", [
    (3 * RIGHT, "right", False), (-3 * RIGHT, "left", False), (3 * AWAY, "back", False),
    (-3 * AWAY, "front", False), ([0, 0, 3], "up", False), ([0, 0, -3], "down", False),
    (3 * RIGHT + 2 * AWAY, "right", True),       # not twice the other component
    (3 * RIGHT + 1 * AWAY, "right", False),
    (0.3 * RIGHT, "right", True),                 # too slow to have a direction
])
def test_direction_in_the_camera_frame(lcfg, v, direction, ambiguous):
    L = compute_labels(one_object(np.tile(v, (20, 1)), start=(0, 0, 3)), lcfg)
    assert DIRECTIONS[L.direction[10, 0]] == direction
    assert L.direction_ambiguous[10, 0] == ambiguous


def test_accelerating_band_and_collision_guard(lcfg):
    t = np.arange(60) / 60
    speeding = np.stack([3 + 1.3 * t, 0 * t, 0 * t], -1)
    braking = np.stack([3 - 1.0 * t, 0 * t, 0 * t], -1)
    gentle = np.stack([3 + 0.6 * t, 0 * t, 0 * t], -1)
    for v, label, amb in [(speeding, True, False), (braking, False, False), (gentle, True, True)]:
        L = compute_labels(one_object(v), lcfg)
        assert (L.accelerating[30, 0], L.accelerating_ambiguous[30, 0]) == (label, amb)
    pair = [obj(0, "sedan", "car", "red", (3, 1.3, 1)), obj(1, "suv", "car", "red", (3, 1.3, 1))]
    L = compute_labels(build_scene(pair, np.stack([speeding, speeding], 1), [[0, 0, 0.5], [5, 0, 0.5]],
                                   collisions=[Collision(30, 0, 1)]), lcfg)
    g = lcfg["collision_guard_frames"]
    assert L.accelerating_ambiguous[30 - g: 30 + g + 1].all() and not L.accelerating_ambiguous[30 - g - 1].any()


def test_falling_vertical_speed_is_not_accelerating(lcfg):
    t = np.arange(60) / 60
    L = compute_labels(one_object(np.stack([3 + 0 * t, 0 * t, -10 * t], -1), start=(0, 0, 20)), lcfg)
    assert not L.accelerating[30, 0] and not L.accelerating_ambiguous[30, 0]
    assert not L.floating[30, 0] and not L.floating_ambiguous[30, 0]


@pytest.mark.parametrize("z,az,floating,ambiguous", [
    (3.0, 0.0, True, False), (3.0, -10.0, False, False), (3.0, -4.0, False, True), (3.0, -3.0, True, True),
    (0.5, 0.0, False, False),     # on the ground (bottom at 0)
    (0.8, 0.0, False, True),      # bottom at 0.3: between the ground and the air
])
def test_floating(lcfg, z, az, floating, ambiguous):
    t = np.arange(30) / 60
    v = np.stack([0 * t, 0 * t, az * (t - t[15])], -1)   # vz = 0 at frame 15, where z is the given height
    sc = one_object(v, start=(0, 0, z))
    sc.position[:, 0, 2] += z - sc.position[15, 0, 2]
    L = compute_labels(sc, lcfg)
    assert (L.floating[15, 0], L.floating_ambiguous[15, 0]) == (floating, ambiguous)


def test_merge_events():
    events = [Collision(10, 1, 0), Collision(12, 0, 1), Collision(16, 0, 1), Collision(40, 0, 1), Collision(12, 2, 3)]
    merged = merge_events(events, 5)
    assert [(e.frame, e.a, e.b) for e in merged] == [(10, 0, 1), (12, 2, 3), (40, 0, 1)]


def test_future_events_start_after_the_observed_frames():
    scene = known_scene()     # observed_frames = 30
    scene.collisions += [Collision(28, 2, 3), Collision(31, 2, 3), Collision(33, 3, 5)]
    scene.future_collisions += [Collision(31, 2, 3), Collision(33, 3, 5)]
    assert [(e.frame, e.a, e.b) for e in future_events(scene, 5)] == [(33, 3, 5), (45, 1, 4)]


def test_rows_one_per_frame_and_object(lcfg):
    L = compute_labels(known_scene(), lcfg)
    rows = L.rows()
    assert len(rows["frame"]) == 60 * 6 and rows["object"][:6] == [0, 1, 2, 3, 4, 5]
    assert set(rows["velocity"]) <= set(VELOCITIES) | {AMBIGUOUS}
    assert set(rows["accelerating"]) <= {"true", "false", AMBIGUOUS}


@pytest.mark.parametrize("key,value,message", [
    ("slow_above", 6.0, "'labels.slow_above' = 6.0 must be less than 'labels.slow_below'"),
    ("direction_ratio", 1.0, "'labels.direction_ratio'"),
    ("accel_window", 0, "'labels.accel_window'"),
    ("stable_frames", 1.5, "'labels.stable_frames'"),
])
def test_config_errors_name_the_key(lcfg, key, value, message):
    with pytest.raises(ConfigError, match=message.replace(".", r"\.")):
        compute_labels(known_scene(), {**lcfg, key: value})
