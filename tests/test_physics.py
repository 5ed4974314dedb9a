"""Physics invariants of dynclevr.physics: forces, friction, collision events, interventions, clean resets."""

import numpy as np
import pytest

from dynclevr import physics
from dynclevr.assets.catalogue import get_asset
from dynclevr.config import Config, ConfigError
from dynclevr.physics import (Body, PhysicsParams, World, counterfactual, intervene, simulate,
                              yaw_quaternion)


@pytest.fixture(scope="module")
def params() -> PhysicsParams:
    return PhysicsParams.from_config(Config.load())


def ground(shape: str, x: float, y: float = 0.0, yaw: float = 0.0, speed: float = 0.0, **kw) -> Body:
    """A vehicle resting on the floor, facing `yaw`, moving forwards at `speed`."""
    h = get_asset(shape).size[2] / 2 + 1e-3
    return Body(shape, (x, y, h), yaw_quaternion(yaw), (speed * np.cos(yaw), speed * np.sin(yaw), 0.0), **kw)


def speed(tr, i):
    return np.linalg.norm(tr.velocity[:, i, :2], axis=-1)


def test_falling_plane_accelerates_at_gravity(params):
    tr = simulate([Body("jet", (0.0, 0.0, 3.0))], params, 30)
    # 3 m takes ~0.77 s = 46 frames to fall: frames 1-25 are free fall.
    np.testing.assert_allclose(tr.acceleration[1:25, 0, 2], -params.gravity, atol=0.05)
    assert tr.position[25, 0, 2] < 3.0 - 0.5 * params.gravity * (24 / 60) ** 2 + 0.05


def test_floating_plane_holds_its_height_and_speed(params):
    tr = simulate([Body("airliner", (0.0, 0.0, 2.0), velocity=(3.0, 0.0, 0.0), floating=True)], params, 120)
    np.testing.assert_allclose(tr.position[:, 0, 2], 2.0, atol=1e-3)
    np.testing.assert_allclose(speed(tr, 0), 3.0, atol=1e-3)   # no friction, no drag in the air
    assert tr.floating.all() and not tr.engine.any()


def test_static_car_stays_put(params):
    tr = simulate([ground("sedan", 0.0)], params, 120)
    np.testing.assert_allclose(tr.position, tr.position[:1].repeat(120, 0), atol=1e-3)
    assert np.abs(tr.velocity).max() < 1e-2
    assert tr.collisions == []   # the floor is no collision partner


def test_engine_on_car_speeds_up_and_engine_off_car_slows_by_friction(params):
    tr = simulate([ground("suv", 0.0, 0.0, speed=3.0, engine_on=True),
                   ground("suv", 0.0, 10.0, speed=3.0)], params, 120)
    friction = params.object_friction * params.floor_friction * params.gravity   # Bullet multiplies frictions
    on = (speed(tr, 0)[100] - speed(tr, 0)[20]) / (80 / 60)
    off = (speed(tr, 1)[100] - speed(tr, 1)[20]) / (80 / 60)
    assert on == pytest.approx(params.engine_accel - friction, abs=0.3)
    assert off == pytest.approx(-friction, abs=0.3)
    assert tr.engine[:, 0].all() and not tr.engine[:, 1].any()
    # Heading kept: the cars drive straight.
    assert np.abs(tr.position[:, :, 1] - tr.position[:1, :, 1]).max() < 0.05


def head_on(params, **kw):
    """A car driving at 6 m/s into a resting one 6 m ahead."""
    return [ground("sedan", 0.0), ground("wagon", -6.0, speed=params.fast_speed, **kw)]


def test_collision_event_matches_contacts(params):
    bodies = head_on(params)
    tr = simulate(bodies, params, 120)
    assert len(tr.collisions) == 1   # one event per impact, not one per substep or frame
    ev = tr.collisions[0]
    assert (ev.a, ev.b) == (0, 1)
    # The gap is 6 - 1.5 - 1.5 = 3 m at 6 m/s minus friction: contact after ~0.52 s.
    assert 28 <= ev.frame <= 35
    assert ev.point[0] == pytest.approx(tr.position[ev.frame, 0, 0] - 1.5, abs=0.1)
    assert ev.impulse > 0
    # The raw contacts frame by frame: the event starts at the first one, and every one belongs to the event.
    with World(bodies, params) as world:
        frames = [t for t in range(1, 120) if world.step_frame()]
    assert frames[0] == ev.frame
    assert all(b - a <= params.merge_frames for a, b in zip(frames, frames[1:]))
    # Momentum went from the striker to the struck car.
    assert speed(tr, 0)[ev.frame + 5] > 1.0 and speed(tr, 1)[ev.frame + 5] < speed(tr, 1)[ev.frame - 1]


def test_engine_stops_at_first_collision(params):
    tr = simulate(head_on(params, engine_on=True), params, 120)
    first = tr.collisions[0].frame
    assert tr.engine[first - 1, 1] and not tr.engine[first:, 1].any()


def test_static_counterfactual_freezes_the_object(params):
    bodies = head_on(params)
    changed = intervene(bodies, 1, "static", params)
    tr = simulate(changed, params, 120)
    np.testing.assert_allclose(tr.position[:, 1], tr.position[:1, 1].repeat(120, 0), atol=1e-3)
    assert counterfactual(bodies, 1, "static", params, 120).collisions == []
    # Making the struck car fast instead (it faces +x, away from the striker) still ends in no collision.
    assert counterfactual(bodies, 0, "fast", params, 120).collisions == []


def test_interventions(params):
    plane = Body("fighter", (0.0, 5.0, 2.0), yaw_quaternion(np.pi / 2), (0.0, 3.0, 0.0))
    bodies = head_on(params) + [plane]
    assert intervene(bodies, 0, "static", params) is None          # already static: nothing to simulate
    assert intervene(bodies, 1, "fast", params) is None
    assert intervene(bodies, 0, "floating", params) is None        # floating is for aeroplanes only
    slow = intervene(bodies, 0, "slow", params)[0]
    np.testing.assert_allclose(slow.velocity, (params.slow_speed, 0.0, 0.0), atol=1e-9)
    assert intervene(bodies, 1, "accelerating", params)[1].engine_on
    assert intervene(bodies, 2, "floating", params)[2].floating
    with pytest.raises(ValueError, match="unknown intervention"):
        intervene(bodies, 0, "teleport", params)


def test_world_reuse_is_a_clean_start(params):
    bodies = head_on(params) + [Body("jet", (2.0, 3.0, 1.6), velocity=(0.0, -3.0, 0.0))]
    fresh = simulate(bodies, params, 90)
    with World(bodies[:1], params) as world:
        simulate(intervene(bodies, 0, "fast", params), params, 90, world=world)
        again = simulate(bodies, params, 90, world=world)
    np.testing.assert_array_equal(fresh.position, again.position)
    assert fresh.collisions == again.collisions


def test_worlds_without_a_renderer_simulate_the_same(params, monkeypatch):
    """Worlds unload pybullet's renderer (it made building them slow): the physics must not notice."""
    bodies = head_on(params, engine_on=True) + [Body("jet", (2.0, 3.0, 1.6), velocity=(0.0, -3.0, 0.0))]
    with World(bodies, params) as world:
        with pytest.raises(physics.p.error):   # no renderer, no visual shapes
            world.client.getVisualShapeData(world.ids[0])
        lean = simulate(bodies, params, 90, world=world)
    monkeypatch.setattr(physics.p, "unloadPlugin", lambda *args, **kw: None)
    with World(bodies, params) as world:
        assert world.client.getVisualShapeData(world.ids[0])
        full = simulate(bodies, params, 90, world=world)
    for a, b in ((lean.position, full.position), (lean.velocity, full.velocity), (lean.engine, full.engine)):
        np.testing.assert_array_equal(a, b)
    assert (lean.collisions, lean.grazes) == (full.collisions, full.grazes) and lean.collisions


def test_world_step_from_a_state(params):
    """The parse-scene prior: one frame from a given state."""
    bodies = [ground("sedan", 0.0, speed=3.0)]
    with World(bodies, params) as world:
        s = world.states()
        world.step_frame()
        after = world.states()
        world.set_state(s.position, s.orientation, s.velocity, s.angular_velocity)
        world.step_frame()
        np.testing.assert_allclose(world.states().position, after.position, atol=1e-9)
    assert after.position[0, 0] == pytest.approx(3.0 / 60, abs=2e-3)
    assert world.client is None   # closed by the context manager


def test_bad_physics_values(tmp_path):
    cfg = Config.load()
    cfg.data["physics"]["engine_accel"] = -1.0
    with pytest.raises(ConfigError, match="'physics.engine_accel' = -1.0 must be positive"):
        PhysicsParams.from_config(cfg)
    with pytest.raises(KeyError, match="unknown sub-type"):
        World([Body("hovercraft", (0.0, 0.0, 1.0))], PhysicsParams.from_config(Config.load()))
