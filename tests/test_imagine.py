"""Counterfactual imagination by replay (dynclevr/perception/imagine.py): exact where the estimate is exact, and
immune to errors of the objects the intervention does not reach."""

from dataclasses import replace

import numpy as np
import pytest

from dynclevr.camera import Camera
from dynclevr.config import Config
from dynclevr.perception.imagine import counterfactual_run
from dynclevr.physics import Body, PhysicsParams, World, counterfactual, ground_height, simulate, yaw_quaternion
from dynclevr.scene import Scene4D, SceneObject
from dynclevr.stages.simulate_future import Ensemble, predict_future

CAMERA = Camera((8.0, -7.0, 3.2), (0.0, 0.0, 1.3), 35.0, 32.0, 320, 240)
T = 120


@pytest.fixture(scope="module")
def params():
    return PhysicsParams.from_config(Config.load())


def _car(x, y, vx, yaw=0.0, shape="sedan"):
    return Body(shape, (x, y, ground_height(shape)), yaw_quaternion(yaw), (vx, 0.0, 0.0))


def _scene(bodies, params) -> Scene4D:
    """A simulated video as a Scene4D (object ids = body indices)."""
    tr = simulate(bodies, params, T)
    objs = [SceneObject(i, b.shape, "car", "red", (4.0, 1.8, 1.4), b.mass_with(params.density), False, False, "slow")
            for i, b in enumerate(bodies)]
    return Scene4D("syn", params.fps, CAMERA, objs, tr.position, tr.orientation, tr.velocity, tr.angular_velocity,
                   tr.acceleration, tr.engine, tr.floating, np.ones((T, len(bodies)), bool), collisions=tr.collisions)


def test_replay_on_the_true_state_equals_a_re_simulation(params):
    """Two cars meet head-on at about 1 s; a third crosses far away. Stopping the first, speeding the third: the
    replay's collisions are the re-simulation's."""
    bodies = [_car(-5.0, 0.0, 4.0), _car(5.0, 0.0, -4.0, yaw=np.pi), _car(-8.0, 6.0, 3.0)]
    scene = _scene(bodies, params)
    assert {e.pair() for e in scene.collisions} == {frozenset({0, 1})}
    with World(bodies, params) as world:
        for index, iv in [(0, "static"), (2, "fast"), (1, "accelerating")]:
            got = counterfactual_run(scene, bodies, [0, 1, 2], index, iv, params, world)
            want = counterfactual(bodies, index, iv, params, T, world=world).collisions
            assert [(e.frame, e.pair()) for e in got] == [(e.frame, e.pair()) for e in want], iv
        assert counterfactual_run(scene, bodies, [0, 1, 2], 0, "floating", params, world) is None   # not a plane


def test_errors_of_objects_the_intervention_never_reaches_do_not_matter(params):
    """A third car parked beside the road is estimated 2.7 m off, on the road: stopping car 1, a re-simulation
    from that estimate imagines car 0 hitting it; the replay keeps it where the video shows it, out of the way."""
    bodies = [_car(-5.0, 0.0, 4.0), _car(5.0, 0.0, -4.0, yaw=np.pi), _car(0.0, 3.5, 0.0)]
    scene = _scene(bodies, params)
    assert {e.pair() for e in scene.collisions} == {frozenset({0, 1})}
    wrong = list(bodies)
    wrong[2] = _car(0.0, 0.8, 0.0)               # the estimate of car 2
    with World(bodies, params) as world:
        resim = counterfactual(wrong, 1, "static", params, T, world=world).collisions
        replay = counterfactual_run(scene, wrong, [0, 1, 2], 1, "static", params, world)
    assert any(2 in (e.a, e.b) for e in resim)
    assert not any(2 in (e.a, e.b) for e in replay)


def test_an_observed_collision_with_a_reached_object_hands_the_other_to_the_engine(params):
    """Car 0 hits parked car 1 in the video. Stop car 0: car 1, replayed up to the (now missing) impact, is then
    simulated from its own state before it and stays where it was; no collision."""
    bodies = [_car(-6.0, 0.0, 5.0), _car(0.0, 0.0, 0.0)]
    scene = _scene(bodies, params)
    assert [e.pair() for e in scene.collisions] == [frozenset({0, 1})]
    with World(bodies, params) as world:
        replay = counterfactual_run(scene, bodies, [0, 1], 0, "static", params, world)
    assert replay == []


def _future(scene, params, ensemble, seed=0):
    return [(e.frame, e.pair()) for e in predict_future(scene, params, ensemble, np.random.default_rng(seed))]


def test_the_future_ensemble_votes_over_perturbed_runs(params):
    """Two cars meet head-on after the observed frames; a third drives 6 m beside them. The vote keeps the
    sure collision and no other, one run equals the single run from the cut state, unperturbed runs vote for exactly
    that run, and the same draws give the same future."""
    bodies = [_car(-9.0, 0.0, 5.0), _car(9.0, 0.0, -5.0, yaw=np.pi), _car(-9.0, 6.0, 5.0)]
    scene = _scene(bodies, params)
    single = _future(scene, params, Ensemble())
    assert [pair for _, pair in single] == [frozenset({0, 1})] and single[0][0] >= scene.observed_frames
    assert _future(scene, params, Ensemble(samples=8)) == single
    noisy = Ensemble(samples=12, vote=0.5, velocity_sigma=0.6, position_sigma=0.2, yaw_sigma=np.deg2rad(8))
    voted = _future(scene, params, noisy, seed=3)
    assert [pair for _, pair in voted] == [frozenset({0, 1})]
    assert abs(voted[0][0] - single[0][0]) <= 6
    assert _future(scene, params, noisy, seed=3) == voted
    # a glancing pair meets in some of the runs: predicted where any run is enough, not where all must agree
    glancing = _scene([_car(-9.0, 0.0, 5.0), _car(9.0, 1.9, -5.0, yaw=np.pi)], params)
    assert _future(glancing, params, replace(noisy, vote=1 / 12), seed=3)
    assert not _future(glancing, params, replace(noisy, vote=1.0), seed=3)
