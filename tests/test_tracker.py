"""The scene parser's filter over time, on synthetic detections of a known trajectory."""

import dataclasses
import math

import numpy as np
import pytest

from dynclevr.camera import Camera
from dynclevr.colors import COLOR_NAMES
from dynclevr.config import Config
from dynclevr.perception.detector import Detection
from dynclevr.perception.detector_data import azimuth, yaw_of
from dynclevr.perception.dynamics import (QuadraticFit, VerticalMotion, break_runs, floating_vz, front_back_heading,
                                          heading_motion, impacts, path_motion, ray_weights, segment_motion, slope,
                                          smoothed_motion, spin)
from dynclevr.perception.model import ParserModel
from dynclevr.perception.place import SUBTYPE_NAMES, resting_height
from dynclevr.perception.tracker import SceneParser, Track, own_height
from dynclevr.physics import Body, PhysicsParams, ground_height, simulate, yaw_quaternion

from conftest import onehot


CAMERA = Camera((8.0, -7.0, 3.2), (0.0, 0.0, 1.3), 35.0, 32.0, 320, 240)
FPS, T = 60, 90


def _detections(positions, yaw, shape, rng, pixel_noise=0.4):
    out = []
    for pos in positions:
        (u, v), _ = CAMERA.project(pos)
        u, v = u + rng.normal(0, pixel_noise), v + rng.normal(0, pixel_noise)
        dist = float(np.linalg.norm(pos - np.asarray(CAMERA.position))) * (1 + rng.normal(0, 0.03))
        out.append([Detection(float(u), float(v), 0.9, onehot(len(SUBTYPE_NAMES), SUBTYPE_NAMES.index(shape)),
                              onehot(len(COLOR_NAMES), 1), yaw - float(azimuth(CAMERA.position, pos)), dist,
                              float(pos[2]))])
    return out


def _engine_car(cfg):
    """A sedan driving at 3 m/s with its engine on, simulated by the data's own physics: positions and accelerations."""
    params = PhysicsParams.from_config(cfg)
    start = (-4.0, 0.5, ground_height("sedan"))
    tr = simulate([Body("sedan", start, yaw_quaternion(0.0), (3.0, 0.0, 0.0), engine_on=True)], params, T)
    return tr.position[:, 0], tr.velocity[:, 0]


# Without the prior the velocity is a fit to the noisy positions alone: the paper's ablation, less exact.
@pytest.mark.parametrize("prior, filt, tol", [(True, "single", 0.25), (True, "particle", 0.25), (False, "single", 0.8)],
                         ids=["physics-prior", "particle-filter", "no-prior"])
def test_filter_recovers_speed_and_acceleration_of_an_accelerating_car(prior, filt, tol):
    cfg = Config.load()
    cfg.data["parser"]["physics_prior"] = prior
    cfg.data["parser"]["filter"] = filt
    pos, vel = _engine_car(cfg)
    accel = slope(vel[20:80], FPS)[0]
    assert accel > 1.0                                      # the engine beats friction (REFERENCE.md section 1)
    dets = _detections(pos, 0.0, "sedan", np.random.default_rng(0))
    est = SceneParser(ParserModel.load(), None, CAMERA, cfg).parse(np.zeros((T, 1, 1, 3), np.uint8), "syn", dets)
    assert len(est.objects) == 1 and est.objects[0].shape == "sedan"
    late = slice(40, T)
    np.testing.assert_allclose(np.linalg.norm(est.velocity[late, 0, :2], axis=1),
                               np.linalg.norm(vel[late, :2], axis=1), atol=tol)
    assert abs(float(np.median(est.acceleration[late, 0, 0])) - accel) < 2 * tol
    assert est.objects[0].engine_on
    assert float(np.median(np.linalg.norm(est.position[late, 0] - pos[late], axis=1))) < 0.15


def test_a_parked_vehicle_stays_static_under_detection_noise():
    cfg = Config.load()
    pos = np.tile([1.0, 1.0, resting_height("suv")], (T, 1))
    dets = _detections(pos, 1.0, "suv", np.random.default_rng(1), pixel_noise=0.8)
    est = SceneParser(ParserModel.load(), None, CAMERA, cfg).parse(np.zeros((T, 1, 1, 3), np.uint8), "syn", dets)
    assert est.objects[0].speed_class == "static"
    assert np.abs(est.velocity[20:, 0]).max() == 0.0


@pytest.mark.parametrize("seed", range(6))
def test_a_parked_vehicle_is_parked_at_the_cut(seed):
    """In the half second before the cut a parked body's wandering detections fit "engine on from rest" about as
    well as "parked"; the generator never gives a static body an engine, so the predictive state is parked."""
    cfg = Config.load()
    pos = np.tile([-1.0, 2.0, resting_height("sedan")], (T, 1))
    rng = np.random.default_rng(seed)
    dets = _detections(pos, 0.5, "sedan", rng, pixel_noise=0.8)
    for d, du in zip(dets, np.linspace(0.0, rng.normal(0, 1.5), T)):   # and a slow wander, in pixels
        d[0].u += du
    est = SceneParser(ParserModel.load(), None, CAMERA, cfg).parse(np.zeros((T, 1, 1, 3), np.uint8), "syn", dets)
    assert not est.cut_state["engine"][0]
    assert np.linalg.norm(est.cut_state["velocity"][0, :2]) == 0.0


def _suv_strikes_parked_sedan(speed: float, lateral: float, n: int):
    """An SUV at `speed` m/s drives into a parked sedan `lateral` metres off its line, simulated by the data's
    physics: the truth and the estimate from noisy detections of both."""
    cfg = Config.load()
    bodies = [Body("suv", (-5.0, 0.0, ground_height("suv")), yaw_quaternion(0.0), (speed, 0.0, 0.0)),
              Body("sedan", (0.0, lateral, ground_height("sedan")), yaw_quaternion(0.0), (0.0, 0.0, 0.0))]
    tr = simulate(bodies, PhysicsParams.from_config(cfg), n)
    rng = np.random.default_rng(3)
    per = [_detections(tr.position[:, i], 0.0, b.shape, rng) for i, b in enumerate(bodies)]
    return tr, SceneParser(ParserModel.load(), None, CAMERA, cfg).parse(np.zeros((n, 1, 1, 3), np.uint8), "syn",
                                                                        [a + b for a, b in zip(*per)])


def test_a_struck_car_slides_to_rest_through_slow_and_a_parked_one_is_static():
    """An SUV at 3 m/s hits a parked sedan, which friction brings to rest: the estimate reads it 0 before the impact
    (a parked body's detections wander) and slow (0.5-0.8 m/s) where the truth is, not 0 from static_speed."""
    tr, est = _suv_strikes_parked_sedan(3.0, 0.0, 150)
    sedan = int(np.argmin([np.linalg.norm(est.position[0, k, :2]) for k in range(len(est.objects))]))
    truth, speed = (np.linalg.norm(v[:, 1 if v is tr.velocity else sedan, :2], axis=1)
                    for v in (tr.velocity, est.velocity))
    hit = tr.collisions[0].frame
    assert (speed[10:hit - 5] == 0).all()
    slow = (truth >= 0.5) & (truth < 0.8)
    assert slow[hit:].sum() > 10 and np.abs(speed[slow] - truth[slow]).max() < 0.15


def test_vehicles_standing_on_their_wheels_have_no_vertical_velocity_through_an_impact():
    """An SUV at 6 m/s hits a parked sedan. Both stay on their wheels, where the estimate places them; before the
    rule the engine's push apart of their overlapping hulls gave them 0.1-0.2 m/s up or down (0.2 at the cut),
    which made "up" the direction of a vehicle whose horizontal speed was read as parked."""
    tr, est = _suv_strikes_parked_sedan(6.0, 0.3, 90)
    assert tr.collisions and tr.collisions[0].frame < 30
    assert len(est.objects) == 2
    for k, o in enumerate(est.objects):
        assert np.abs(est.position[:, k, 2] - resting_height(o.shape)).max() < 1e-6
    assert (est.velocity[:, :, 2] == 0).all() and (est.cut_state["velocity"][:, 2] == 0).all()


def test_a_parked_car_pushed_unnoticed_is_parked_then_struck_not_driving_off():
    """A parked sedan set moving at frame 50 by an impact too gentle for the filter to notice (2.5 m/s, then
    friction): no engine starts a parked body (the generator's rule), so the segment motion reads a parked stretch
    and a struck one; without `parked_split` one motion, an engine from rest, explains both."""
    n, hit, v0 = 120, 50, 2.5
    tau = np.clip(np.arange(n) - hit, 0, None) / FPS
    travel = np.where(tau < v0 / 0.8, v0 * tau - 0.4 * tau ** 2, v0 ** 2 / 1.6)
    pos = np.stack([-1.0 + travel, np.full(n, 0.5), np.full(n, ground_height("sedan"))], 1)
    det = _detections(pos, 0.0, "sedan", np.random.default_rng(0))
    speed, engine = {}, {}
    for split in (True, False):
        cfg = Config.load()
        cfg.data["parser"]["parked_split"] = split
        est = SceneParser(ParserModel.load(), None, CAMERA, cfg).parse(np.zeros((n, 1, 1, 3), np.uint8), "syn", det)
        speed[split], engine[split] = np.linalg.norm(est.velocity[:, 0, :2], axis=1), est.engine[:, 0]
    truth = np.where(tau < v0 / 0.8, v0 - 0.8 * tau, 0.0)
    assert (speed[True][:hit - 3] == 0).all() and not engine[True].any()
    assert np.abs(speed[True][hit + 8:] - truth[hit + 8:]).max() < 0.2
    assert engine[False][10] and speed[False][30] > 0.8


def test_smoothed_motion_uses_both_sides_and_never_crosses_an_impact():
    """Constant acceleration is recovered exactly where the window is full (a quadratic fit), a few frames into a
    segment too (a causal fit has few samples there); across an impact (a break) each side keeps its own motion;
    too few samples give NaN."""
    t = np.arange(40) / FPS
    z = np.stack([1.0 + 3.0 * t + 0.5 * 2.0 * t * t, -2.0 * t, np.zeros_like(t)], 1)
    z[25:] = z[25] + np.outer(t[25:] - t[25], [-4.0, 0.0, 0.0])   # an impact at frame 25: from there -4 m/s in x
    z[30:33] = np.nan                                             # a missed stretch
    x, v = smoothed_motion(z, [25], FPS, 12, 8)
    np.testing.assert_allclose(x[4:10], z[4:10], atol=1e-6)
    np.testing.assert_allclose(v[4:10, 0], 3.0 + 2.0 * t[4:10], atol=1e-6)
    assert np.abs(v[:25, 0] - (3.0 + 2.0 * t[:25])).max() < 0.25   # the edges: a linear fit, 0.2 s of lag at most
    np.testing.assert_allclose(v[:25, 1], -2.0, atol=1e-6)
    np.testing.assert_allclose(v[25:, 0], -4.0, atol=1e-6)        # neighbours bridge the gap
    assert np.isnan(smoothed_motion(z[:5], [], FPS, 12, 8)[1]).all()   # 5 samples < 8: no velocity


def test_a_long_contact_is_one_impact_and_the_positions_go_on_through_it():
    """Bodies in contact give a break every frame: cut at each, no window holds enough measurements for a fit (the
    positions stayed the filter's there); as one impact (`break_runs`: its first frame and the frame after its
    last) the fits on either side reach through it."""
    breaks = [2] + list(range(20, 41)) + [90]
    assert break_runs(breaks, 100, 16) == [(2, 3), (20, 41), (90, 91)]
    assert break_runs(breaks, 100, 20) == [(2, 41), (90, 91)]
    assert impacts(breaks, 100, 16) == [2, 20, 90]
    t = np.arange(60) / FPS
    z = np.stack([2.0 * t, np.ones_like(t), np.zeros_like(t)], 1)
    assert np.isnan(smoothed_motion(z, list(range(20, 41)), FPS, 12, 8)[0][25:36]).all()
    x = smoothed_motion(z, impacts(list(range(20, 41)), 60, 16), FPS, 12, 8)[0]
    np.testing.assert_allclose(x, z, atol=1e-9)


def _ray_measurements(path, bias, rng):
    """Measured positions of a path [n, 3]: its camera ray to within a centimetre, its distance scaled by 1 + bias
    [n] with 2% noise (the head's, for a plane in the air)."""
    eye = np.asarray(CAMERA.position)
    ray = path - eye
    z = eye + ray * (1 + bias + rng.normal(0, 0.02, len(path)))[:, None]
    return z + rng.normal(0, 0.01, z.shape)


def test_path_motion_averages_the_distance_over_the_whole_flight():
    """A floating plane struck in the air at frame 40. Straight at a constant velocity on either side of the
    impact and continuous at it, the path is fixed by the rays up to about one scale about the camera, which the
    distances of every frame set: (1) their frame-to-frame noise averages out; (2) read 10% too far after the
    impact (tumbling), the path shares that bias with the stretch before (which the rays tie to it): less off
    after, a little off before; (3) a stretch whose measurements the path misses (no constant acceleration
    explains a weave across the ray) has none there; (4) a stretch with too few measurements has no path."""
    rng = np.random.default_rng(0)
    eye = np.asarray(CAMERA.position)
    n, hit = 100, 40
    t = np.arange(n) / FPS
    path = np.stack([-3.0 + 4.0 * t, 1.0 + 0.0 * t, 2.5 + 0.0 * t], 1)
    path[hit:] = path[hit] + np.outer(t[hit:] - t[hit], [1.0, -3.0, 0.8])
    dist = np.linalg.norm(path - eye, axis=1)

    def fit(z):
        return path_motion(z, eye, FPS, [0, hit, n], np.zeros((2, 3)), np.full(2, 0.3), 0.06, 0.6, 8)

    z = _ray_measurements(path, np.zeros(n), rng)
    assert np.median(np.linalg.norm(fit(z) - path, axis=1)) < 0.3 * np.median(np.linalg.norm(z - path, axis=1))
    z = _ray_measurements(path, np.where(np.arange(n) >= hit, 0.10, 0.0), rng)
    scale = ((fit(z) - path) * (path - eye)).sum(1) / dist ** 2      # relative error along the ray
    assert np.median(scale[hit:]) < 0.09 and 0.005 < np.median(scale[:hit]) < 0.04
    across = np.cross(path[hit] - eye, [0.0, 0.0, 1.0])
    weave = path + np.outer(np.where(np.arange(n) >= hit, np.sin(2 * np.pi * (t - t[hit])), 0.0),
                            across / np.linalg.norm(across))
    est = fit(_ray_measurements(weave, np.zeros(n), rng))
    assert np.isfinite(est[:hit]).all() and np.isnan(est[hit:]).all()
    z[hit:hit + 55] = np.nan
    assert fit(z) is None


def test_a_car_seen_from_its_start_has_its_speed_there_and_a_causal_cut_state():
    """A car driving at 5 m/s from frame 0: the factual arrays give its speed at the start (they may use later
    frames); the cut state, from which the predictive questions start, differs from them only by what the frames
    after the cut would add, and parse-scene's output keeps it (Scene4D round trip)."""
    cfg = Config.load()
    params = PhysicsParams.from_config(cfg)
    start = (-4.0, 0.5, ground_height("sedan"))
    tr = simulate([Body("sedan", start, yaw_quaternion(0.0), (5.0, 0.0, 0.0))], params, T)
    dets = _detections(tr.position[:, 0], 0.0, "sedan", np.random.default_rng(3))
    est = SceneParser(ParserModel.load(), None, CAMERA, cfg).parse(np.zeros((T, 1, 1, 3), np.uint8), "syn", dets)
    first = cfg["labels"]["start_frame"]
    assert abs(np.linalg.norm(est.velocity[first, 0, :2]) - np.linalg.norm(tr.velocity[first, 0, :2])) < 0.3
    cut = est.observed_frames - 1
    causal = SceneParser(ParserModel.load(), None, CAMERA, cfg).parse(np.zeros((cut + 1, 1, 1, 3), np.uint8),
                                                                      "syn", dets[:cut + 1])
    np.testing.assert_allclose(est.cut_state["velocity"], causal.cut_state["velocity"])
    np.testing.assert_allclose(est.cut_state["position"], causal.cut_state["position"])
    assert np.linalg.norm(est.cut_state["position"][0] - causal.position[cut, 0]) < 0.2
    assert est.state_at(cut) is est.cut_state and est.state_at(cut - 1)["velocity"] is not est.cut_state["velocity"]


@pytest.mark.parametrize("enters", [0, 27], ids=["from-the-start", "just-before-the-cut"])
def test_a_confirmed_track_is_seen_from_its_first_detection_and_the_cut_keeps_to_the_observed_frames(enters):
    """A parked car detected from frame `enters` on is an object once `confirm_frames` detections confirm it, and is
    then seen from its first detection (issue 11: a track's start is its first confident frame), not from the frame
    that confirmed it. One that comes into sight at frame 27 is confirmed only after the cut (frame 29): the
    observed frames alone do not know it, so the parse shows it from frame 30 on (the predictive questions' parse,
    which reads the observed frames' visibility, leaves it out)."""
    cfg = Config.load()
    pos = np.tile([0.5, 1.0, ground_height("sedan")], (T, 1))
    dets = [[] if t < enters else d for t, d in enumerate(_detections(pos, 0.0, "sedan", np.random.default_rng(5)))]
    est = SceneParser(ParserModel.load(), None, CAMERA, cfg).parse(np.zeros((T, 1, 1, 3), np.uint8), "syn", dets)
    assert len(est.objects) == 1
    first, cut = int(np.argmax(est.visible[:, 0])), est.observed_frames - 1
    confirmed = enters + cfg["parser"]["confirm_frames"] - 1
    assert first == (enters if confirmed <= cut else cut + 1) and est.visible[first:, 0].all()


def test_slope_of_a_linear_signal_is_exact():
    v = 2.0 + 1.5 * np.arange(12)[:, None] / FPS * np.array([1.0, -2.0, 0.0])
    np.testing.assert_allclose(slope(v, FPS), [1.5, -3.0, 0.0], atol=1e-9)
    assert math.isclose(float(slope(np.arange(5.0), 1)), 1.0)


@pytest.mark.parametrize("falls", [True, False], ids=["falling", "floating"])
def test_a_falling_plane_is_not_floating_at_the_start_and_a_floating_one_is(falls):
    """With the prior, an aeroplane's floating is decided once from its measured heights: a plane falling from rest
    is "not floating" at the start (the prior no longer holds it up), a floating one stays floating."""
    from dynclevr.questions.labels import compute_labels

    cfg = Config.load()
    params = PhysicsParams.from_config(cfg)
    tr = simulate([Body("jet", (1.0, 2.0, 3.4), yaw_quaternion(0.5), (2.0, 0.0, 0.0), floating=not falls)], params, 40)
    dets = _detections(tr.position[:, 0], 0.5, "jet", np.random.default_rng(2))
    est = SceneParser(ParserModel.load(), None, CAMERA, cfg).parse(np.zeros((40, 1, 1, 3), np.uint8), "syn", dets)
    labels = compute_labels(est, cfg["labels"])
    start = cfg["labels"]["start_frame"]
    assert bool(labels.floating[start, 0]) is not falls
    assert bool(est.floating[start, 0]) is not falls


def test_two_floating_planes_struck_in_the_air_float_on_at_a_constant_vertical_speed():
    """Two floating planes collide at different heights and leave the impact climbing and sinking: nothing but
    an impact changes a floating body's vertical velocity, so after it the estimate's is constant and its labels
    say "floating" (local fits to noisy heights read a vertical acceleration there, and "not floating")."""
    from dynclevr.questions.labels import compute_labels

    cfg = Config.load()
    params = PhysicsParams.from_config(cfg)
    bodies = [Body("jet", (-3.0, 0.0, 2.6), yaw_quaternion(0.0), (4.0, 0.0, 0.0), floating=True),
              Body("fighter", (3.0, 0.0, 3.4), yaw_quaternion(math.pi), (-4.0, 0.0, 0.0), floating=True)]
    tr = simulate(bodies, params, T)
    impact = tr.collisions[0].frame
    assert all(abs(tr.velocity[-1, i, 2]) > 1.0 for i in range(2))     # one sinks, one climbs
    rng = np.random.default_rng(3)
    per = [_detections(tr.position[:, i], yaw, b.shape, rng) for i, (b, yaw) in enumerate(zip(bodies, (0.0, math.pi)))]
    est = SceneParser(ParserModel.load(), None, CAMERA, cfg).parse(np.zeros((T, 1, 1, 3), np.uint8), "syn",
                                                                   [a + b for a, b in zip(*per)])
    labels = compute_labels(est, cfg["labels"])
    after = slice(impact + 8, T)
    for i in range(2):
        j = int(np.argmin([np.linalg.norm(est.position[0, j] - tr.position[0, i]) for j in range(len(est.objects))]))
        assert np.abs(est.velocity[after, j, 2] - tr.velocity[after, i, 2]).max() < 0.2
        assert labels.floating[after, j].mean() > 0.9


@pytest.mark.parametrize("kick, at", [(0.6, 40), (-0.9, 70), (0.0, None)], ids=["climbs", "sinks", "held"])
def test_a_floating_planes_vertical_speed_changes_where_an_unfound_impact_kicked_it(kick, at):
    """A floating plane starts without vertical velocity and keeps whatever an impact gives it: heights held, then
    on a line from an impact the parser did not find, read through the head's drift (0.1 m/s), its noise, missing
    frames and a detection placed 1.5 m off give that line's slope after the impact and none before it; a plane
    that only drifts stays level."""
    rng = np.random.default_rng(1)
    t = np.arange(120) / FPS
    kicked = np.zeros(120) if at is None else np.where(t > at / FPS, kick * (t - at / FPS), 0.0)
    z = 2.3 + 0.1 * t + kicked + rng.normal(0.0, 0.03, 120)
    z[rng.random(120) < 0.1] = np.nan
    z[5] += 1.5
    vz = floating_vz(z, FPS, 16, held=True)
    if at is None:
        assert np.abs(vz).max() == 0.0
    else:
        assert np.abs(vz[:at - 10]).max() == 0.0
        assert np.abs(vz[at + 10:] - kick).max() < 0.2


@pytest.mark.parametrize("falls", [True, False], ids=["falling", "floating"])
def test_vertical_motion_tells_a_fall_from_a_drifting_floating_plane(falls):
    """The head's heights of a floating plane drift smoothly by decimetres (its distance error moves the centre
    along the camera ray): a free quadratic reads that drift as a fall, the prior's two motions (held, or fallen
    from rest at frame 0) do not; a falling plane's start height and velocity come out of the fall."""
    rng = np.random.default_rng(0)
    frames = np.arange(2, 26)
    t = frames / FPS
    rest = resting_height("jet")
    if falls:
        z = np.maximum(2.6 - 0.5 * 10.0 * t ** 2, rest) + rng.normal(0, 0.05, len(t))
    else:   # held at 2.3 m, measured 0.5 m low at first and rising towards it (full-test's airliners look like this)
        z = 2.3 - 0.5 * np.exp(-t / 0.1) + rng.normal(0, 0.02, len(t))
    samples = [(int(f), np.array([0.0, 0.0, h])) for f, h in zip(frames, z)]
    vm = VerticalMotion(samples, FPS, 10.0, rest)
    assert vm.floating is not falls
    if falls:
        assert abs(vm.z0 - 2.6) < 0.1
        assert vm.vz(12) == pytest.approx(-2.0, abs=0.2) and vm.vz(119) is None   # landed by then
    else:
        assert vm.vz(50) == 0.0
        assert QuadraticFit(samples, FPS, 16).acceleration[2] < -5.0    # what the free fit would have said


def test_a_head_on_collision_is_found_at_its_frame_and_a_near_miss_is_not():
    """Two cars simulated by the data's physics, seen through noisy detections: the collision classifier
    (weights/collision/) reports the crash within 3 frames of the truth's event and nothing for cars that pass."""
    from dynclevr.perception.collisions import CollisionModel
    from dynclevr.questions.labels import merge_events

    cfg = Config.load()
    params = PhysicsParams.from_config(cfg)
    z = ground_height("sedan")
    for lateral, crash in ((0.3, True), (4.0, False)):
        bodies = [Body("sedan", (-4.0, 0.0, z), yaw_quaternion(0.0), (5.0, 0.0, 0.0)),
                  Body("suv", (4.0, lateral, ground_height("suv")), yaw_quaternion(math.pi), (-5.0, 0.0, 0.0))]
        tr = simulate(bodies, params, T)
        truth = merge_events(tr.collisions, cfg["labels"]["collision_merge_frames"])
        assert bool(truth) is crash
        rng = np.random.default_rng(3)
        per = [_detections(tr.position[:, i], yaw, b.shape, rng) for i, (b, yaw) in enumerate(zip(bodies, (0.0, math.pi)))]
        dets = [a + b for a, b in zip(*per)]
        est = SceneParser(ParserModel.load(), None, CAMERA, cfg, CollisionModel.load()).parse(
            np.zeros((T, 1, 1, 3), np.uint8), "syn", dets)
        assert len(est.objects) == 2
        events = merge_events(est.collisions, cfg["labels"]["collision_merge_frames"])
        if crash:
            assert len(events) == 1 and abs(events[0].frame - truth[0].frame) <= 3
        else:
            assert events == []


@pytest.mark.parametrize("start", [2.5, 5.0], ids=["crash at frame 14", "crash at frame 46"])
def test_the_collisions_known_at_the_cut_are_those_the_observed_frames_decide(start):
    """The predictive questions merge the estimate's cut_collisions with the predicted future: they equal the
    collisions of a parse of the observed frames alone (truncating the video changes nothing), and a crash the
    later frames show is in the factual collisions only, so that it is predicted, not read off the video."""
    from dynclevr.perception.collisions import CollisionModel
    from dynclevr.questions.labels import future_events, merge_events

    cfg = Config.load()
    params = PhysicsParams.from_config(cfg)
    bodies = [Body("sedan", (-start, 0.0, ground_height("sedan")), yaw_quaternion(0.0), (5.0, 0.0, 0.0)),
              Body("suv", (start, 0.3, ground_height("suv")), yaw_quaternion(math.pi), (-5.0, 0.0, 0.0))]
    tr = simulate(bodies, params, T)
    rng = np.random.default_rng(3)
    per = [_detections(tr.position[:, i], yaw, b.shape, rng) for i, (b, yaw) in enumerate(zip(bodies, (0.0, math.pi)))]
    dets = [a + b for a, b in zip(*per)]

    def parse(n):
        return SceneParser(ParserModel.load(), None, CAMERA, cfg, CollisionModel.load()).parse(
            np.zeros((n, 1, 1, 3), np.uint8), "syn", dets[:n])

    est, cut = parse(T), cfg["video"]["observed_frames"]
    merge = cfg["labels"]["collision_merge_frames"]
    crash = merge_events(tr.collisions, merge)[0].frame
    assert [e.frame for e in merge_events(est.collisions, merge)] and abs(
        merge_events(est.collisions, merge)[0].frame - crash) <= 3
    assert est.cut_collisions == parse(cut).collisions
    # (no future predicted here: simulate-future's run is what would add one)
    if crash < cut - 10:
        assert est.cut_collisions and future_events(est, merge) == []   # seen: no future event
    else:
        assert crash > cut and est.cut_collisions == [] and future_events(est, merge) == []


def test_particle_filter_keeps_the_hypothesis_of_an_unseen_impact():
    """A car at 4 m/s that the engine believes keeps going stops dead at frame 30 (hit by something the engine
    did not see): the particles that were kicked explain the detections, so the estimate follows within a few
    frames and is not dragged along the old motion."""
    from dynclevr.perception.particles import ParticleCloud

    p = {"process_position": 0.01, "process_velocity": 0.015, "jump_rate": 0.02, "maneuver_speed": 2.0}
    rng = np.random.default_rng(0)
    dt = 1 / FPS
    R = 0.05 ** 2 * np.eye(3)
    cloud = ParticleCloud.start(np.zeros(3), np.diag([0.01] * 3 + [1.0] * 3), 32)
    x = np.zeros(3)
    for t in range(1, 60):
        est = cloud.estimate()
        # the engine's step of the estimate: constant velocity on the ground
        cloud.predict(est[3:] * dt, np.zeros(3), dt, p, rng)
        if t < 30:
            x = x + np.array([4.0, 0.0, 0.0]) * dt
        cloud.update(x + rng.normal(0, 0.02, 3) * [1, 1, 0], R, 0.1, rng)
        if t == 29:
            assert abs(cloud.estimate()[3] - 4.0) < 0.5
    assert abs(cloud.estimate()[3]) < 0.5 and np.linalg.norm(cloud.estimate()[:3] - x) < 0.1
    assert math.isclose(cloud.weight.sum(), 1.0)


def test_collision_classifier_trains_from_a_split_and_loads(tmp_path):
    """`dynclevr train collisions` end to end on the tiny split: rows cached per video, weights and manifest that
    load, held-out metrics at both tolerances; a second run reuses the rows and gives the same weights. The videos are
    cut to 60 frames: the same path, half the parse."""
    from dynclevr.perception.collision_train import train_collisions
    from dynclevr.perception.collisions import CollisionModel

    (tmp_path / "short.toml").write_text("[video]\nframes = 60\n")
    cfg = Config.load(tmp_path / "short.toml")
    out = tmp_path / "weights"
    manifest = train_collisions(cfg, tmp_path / "data", cfg.split("tiny"), out, workers=1, echo=lambda *a: None)
    assert sorted(p.name for p in (tmp_path / "data" / "tiny" / "collision_rows").iterdir()) == \
        ["000000.npz", "000001.npz", "000002.npz"]
    assert set(manifest["metrics_heldout"]) == {"within_3_frames", "within_6_frames"}
    model = CollisionModel.load(out)
    assert 0 < model.threshold < 1
    first = (out / "collision.json").read_bytes()
    train_collisions(cfg, tmp_path / "data", cfg.split("tiny"), out, workers=1, echo=lambda *a: None)
    assert (out / "collision.json").read_bytes() == first


def test_smoothed_motion_ignores_a_bad_detection():
    """A detection 2 m off (placed on a neighbour) in the middle of a steady drive changes no fit around it."""
    t = np.arange(40) / FPS
    z = np.stack([3.0 * t, np.zeros_like(t), np.zeros_like(t)], 1)
    z[20] += [0.0, 2.0, 0.0]
    x, v = smoothed_motion(z, [], FPS, 12, 8)
    np.testing.assert_allclose(v[:, :2], np.tile([3.0, 0.0], (40, 1)), atol=1e-6)


@pytest.mark.parametrize("accel, v0, tol", [(-0.8, 3.0, 0.08), (2.2, 4.0, 0.08), (0.0, 6.0, 0.08), (-0.8, 0.0, 0.4)],
                         ids=["sliding-to-rest", "engine", "floating", "parked"])
def test_segment_motion_recovers_the_start_speed_under_noise_and_a_bad_detection(accel, v0, tol):
    """A body on a line whose speed changes at a known rate (stopping when friction has taken it all): from
    detections 10 cm noisy, one of them 2 m off and a missed stretch, the speed at every frame is good to a few
    centimetres per second, so its change over a sixth of a second (the "accelerating" label) has the truth's sign.
    A parked body's noise reads as a creep well under the tracker's static_speed (reported as 0). The motion under
    the true rate costs less than under the other hypothesis (engine or none), which decides the engine."""
    rng = np.random.default_rng(4)
    t = np.arange(100) / FPS
    speed = np.maximum(v0 + accel * t, 0.0)
    along = np.concatenate([[0.0], np.cumsum((speed[1:] + speed[:-1]) / 2 / FPS)])
    u = np.array([0.6, -0.8])
    z = np.concatenate([np.outer(along, u) + [1.0, 2.0], np.full((100, 1), 0.7)], 1)
    z[:, :2] += rng.normal(0, 0.1, (100, 2))
    z[50] += [2.0, 0.0, 0.0]
    z[60:70] = np.nan
    vel, cost = segment_motion(z, FPS, accel, 8)
    np.testing.assert_allclose(np.linalg.norm(vel[:, :2], axis=1), speed, atol=tol)
    if v0 > 0:
        np.testing.assert_allclose(vel[5, :2] / np.linalg.norm(vel[5, :2]), u, atol=0.02)
    assert (vel[:, 2] == 0).all()
    other = {-0.8: 2.2, 2.2: -0.8, 0.0: 3.0}[accel]        # the other hypothesis: an engine, or none
    assert cost < segment_motion(z, FPS, other, 8)[1]
    assert segment_motion(z[:10], FPS, accel, 8) is None          # 10 measurements < 2 x 8: no fit


@pytest.mark.parametrize("v0, rate, flipped", [(6.0, 0.0, False), (3.0, 3.0, True), (0.0, 0.0, False)],
                         ids=["fast-floating", "slow-engine-flipped-heading", "parked"])
def test_heading_motion_reads_a_planes_speed_across_the_ray(v0, rate, flipped):
    """A plane seen for the observed half second, 12 m away, flying at 45 degrees to the camera ray, whose
    measured distance is 0.7 m noisy along the ray (the head's alone) and 6 cm across it: a line fitted to the
    positions is decimetres per second off, but along the heading (its axis either way round: a flipped detection)
    the start speed and the engine's rate that explain the measurements are the truth's, out of the generator's
    few, and so is the velocity."""
    rng = np.random.default_rng(0)
    eye = np.array([0.0, 0.0, 3.0])
    ray = np.array([1.0, 0.0])
    u = np.array([np.cos(np.pi / 4), np.sin(np.pi / 4)])
    t0 = 4 / FPS                                    # found at frame 4
    t = t0 + np.arange(26) / FPS
    travel = v0 * t + 0.5 * rate * t ** 2
    z = np.concatenate([[12.0, 0.0] + np.outer(travel, u), np.full((26, 1), 2.5)], 1)
    z[:, :2] += np.outer(rng.normal(0, 0.7, 26), ray) + np.outer(rng.normal(0, 0.06, 26), [0.0, 1.0])
    starts = [(0.0, 0.0), (3.0, 0.0), (6.0, 0.0), (3.0, 3.0), (6.0, 3.0)]
    axis = np.array([*(-u if flipped else u), 0.0])
    W = ray_weights(z, eye, 0.06, 0.6)
    vel, n = heading_motion(z, W, FPS, axis, t0, starts, 8)
    assert starts[n] == (v0, rate)
    np.testing.assert_allclose(vel[-1, :2], (v0 + rate * t[-1]) * u, atol=1e-9)
    assert np.linalg.norm(np.polyfit(t, z[:, :2], 1)[0] - (v0 + rate * t[-1]) * u) > 0.2
    assert heading_motion(z[:10], W[:10], FPS, axis, t0, starts, 8) is None


def test_heading_motion_turns_from_a_wrong_heading_where_the_motion_crosses_the_ray():
    """The same kind of plane flying across the camera ray at 6 m/s, whose heading the head reads 20 degrees off:
    along that heading exactly the velocity is 20 degrees off (2 m/s). With a Gaussian prior of 4 degrees around
    it, the measurements across the ray (good to 6 cm) turn the line towards the truth, part of the way (the
    prior and the measurements meet between), and the start speed stays the truth's."""
    rng = np.random.default_rng(1)
    eye = np.array([0.0, 0.0, 3.0])
    u = np.array([0.0, 1.0])                        # across the ray (which runs along x)
    t = np.arange(30) / FPS
    z = np.concatenate([[12.0, -1.5] + np.outer(6.0 * t, u), np.full((30, 1), 2.5)], 1)
    z[:, :2] += np.outer(rng.normal(0, 0.7, 30), [1.0, 0.0]) + np.outer(rng.normal(0, 0.06, 30), [0.0, 1.0])
    starts = [(0.0, 0.0), (3.0, 0.0), (6.0, 0.0), (3.0, 3.0), (6.0, 3.0)]
    off = np.radians(20)
    axis = np.array([np.sin(off), np.cos(off), 0.0])
    W = ray_weights(z, eye, 0.06, 0.6)
    along, _ = heading_motion(z, W, FPS, axis, 0.0, starts, 8)
    turned, n = heading_motion(z, W, FPS, axis, 0.0, starts, 8, heading_sd=np.radians(4))
    assert np.linalg.norm(along[-1, :2] - 6.0 * u) > 1.5
    assert starts[n] == (6.0, 0.0)
    assert np.linalg.norm(turned[-1, :2] - 6.0 * u) < np.linalg.norm(along[-1, :2] - 6.0 * u) - 0.5
    assert abs(np.degrees(np.arctan2(turned[-1, 0], turned[-1, 1]))) < 15


@pytest.mark.parametrize("speed, engine", [(3.0, True), (6.0, False), (3.0, False)])
def test_the_cut_state_decides_the_engine_from_the_observed_frames(speed, engine):
    """A car simulated by the data's own physics, seen from frame 0: from the 30 observed frames alone (10 cm of
    depth noise a frame) the cut state has its engine, and its speed there within 0.3 m/s (the engine's motion
    from one of the generator's start speeds)."""
    cfg = Config.load()
    params = PhysicsParams.from_config(cfg)
    start = (-4.0, 0.5, ground_height("sedan"))
    tr = simulate([Body("sedan", start, yaw_quaternion(0.0), (speed, 0.0, 0.0), engine_on=engine)], params, T)
    dets = _detections(tr.position[:, 0], 0.0, "sedan", np.random.default_rng(5))
    cut = cfg["video"]["observed_frames"] - 1
    est = SceneParser(ParserModel.load(), None, CAMERA, cfg).parse(np.zeros((cut + 1, 1, 1, 3), np.uint8), "syn",
                                                                  dets[:cut + 1])
    assert bool(est.cut_state["engine"][0]) == engine
    assert abs(np.linalg.norm(est.cut_state["velocity"][0, :2]) - np.linalg.norm(tr.velocity[cut, 0, :2])) < 0.3


def test_a_falling_plane_keeps_its_horizontal_speed_in_the_air():
    """In the air only an engine changes a body's horizontal speed, falling or floating: through the head's noisy
    distances a falling plane's horizontal speed is one start speed, not a wander that reads as accelerating."""
    from dynclevr.questions.labels import compute_labels

    cfg = Config.load()
    params = PhysicsParams.from_config(cfg)
    tr = simulate([Body("jet", (0.0, 1.0, 3.4), yaw_quaternion(0.3), (3.0 * math.cos(0.3), 3.0 * math.sin(0.3), 0.0),
                        floating=False)], params, 40)
    assert (tr.position[:, 0, 2] > 1.0).all()                      # still in the air at the last frame
    dets = _detections(tr.position[:, 0], 0.3, "jet", np.random.default_rng(5))
    est = SceneParser(ParserModel.load(), None, CAMERA, cfg).parse(np.zeros((40, 1, 1, 3), np.uint8), "syn", dets)
    speed = np.linalg.norm(est.velocity[5:, 0, :2], axis=1)
    np.testing.assert_allclose(speed, 3.0, atol=0.3)
    assert np.ptp(speed) < 1e-9
    assert not compute_labels(est, cfg["labels"]).accelerating[cfg["labels"]["start_frame"], 0]


def test_a_plane_landed_just_before_the_cut_keeps_the_flights_speed_there():
    """A falling plane simulated by the data's own physics that lands 5 frames before the cut (and bounces): the
    stretch from its landing is too short for a fit of its own, and the cut state's horizontal velocity is the
    truth's within 0.4 m/s: the flight's velocity carried through the landing, less the friction the touchdown
    takes (3 -> 2.6 m/s here, which the rule leaves out). The filter's velocity passes this as well, so the test
    checks the outcome, not the rule: on full-test's detections the filter's lagged the bounce (journal)."""
    cfg = Config.load()
    params = PhysicsParams.from_config(cfg)
    cut = cfg["video"]["observed_frames"] - 1
    tr = simulate([Body("jet", (0.0, 1.0, resting_height("jet") + 0.8), yaw_quaternion(0.3),
                        (3.0 * math.cos(0.3), 3.0 * math.sin(0.3), 0.0), floating=False)], params, cut + 1)
    landed = np.nonzero(tr.position[:, 0, 2] < resting_height("jet") + 0.05)[0]
    assert len(landed) and cut - 12 < landed[0] < cut - 2          # it lands in the last frames before the cut
    dets = _detections(tr.position[:, 0], 0.3, "jet", np.random.default_rng(5))
    est = SceneParser(ParserModel.load(), None, CAMERA, cfg).parse(np.zeros((cut + 1, 1, 1, 3), np.uint8), "syn", dets)
    np.testing.assert_allclose(est.cut_state["velocity"][0, :2], tr.velocity[cut, 0, :2], atol=0.4)


def _bounced_car(lost: range) -> tuple[np.ndarray, list]:
    """A sedan driving at 6 m/s that bounces straight back while no detection sees it (frames `lost`): the filter's
    prediction runs on and the detections come back 2.4 m behind it. Re-acquiring within one gate (not four), the
    tracker alone starts a new track on the same car."""
    turn = lost.start + len(lost) // 2
    t = np.arange(T) / FPS
    x = np.where(np.arange(T) < turn, -4.0 + 6.0 * t, -4.0 + 6.0 * t[turn] - 6.0 * (t - t[turn]))
    pos = np.stack([x, np.full(T, 0.5), np.full(T, resting_height("sedan"))], 1)
    dets = _detections(pos, 0.0, "sedan", np.random.default_rng(3))
    return pos, [[] if f in lost else d for f, d in enumerate(dets)]


@pytest.mark.parametrize("stitch", [True, False])
def test_a_track_lost_and_found_again_is_one_object(stitch):
    cfg = Config.load()
    cfg.data["parser"].update(stitch=stitch, reacquire=1.0)
    pos, dets = _bounced_car(range(40, 64))
    est = SceneParser(ParserModel.load(), None, CAMERA, cfg).parse(np.zeros((T, 1, 1, 3), np.uint8), "syn", dets)
    if not stitch:                      # without stitching the tracker alone makes two objects of it
        assert len(est.objects) == 2
        return
    assert len(est.objects) == 1
    seen = np.nonzero(est.visible[:, 0])[0]
    assert seen[0] < 10 and seen[-1] == T - 1 and not est.visible[40:64, 0].any()
    late = np.arange(70, T)
    assert float(np.median(np.linalg.norm(est.position[late, 0] - pos[late], axis=1))) < 0.15


def _thrice_lost_car() -> list:
    """A sedan seen in three stretches (frames 0-19, 35-49, 65-89), each time 2.5 m further along (pushed while no
    detection saw it): the tracker alone makes three tracks of it."""
    x = np.where(np.arange(T) < 35, -4.0, np.where(np.arange(T) < 65, -1.5, 1.0))
    pos = np.stack([x, np.full(T, 0.5), np.full(T, resting_height("sedan"))], 1)
    dets = _detections(pos, 0.0, "sedan", np.random.default_rng(6))
    return [[] if 20 <= f < 35 or 50 <= f < 65 else d for f, d in enumerate(dets)]


@pytest.mark.parametrize("stitch, objects", [(False, 3), (True, 1)])
def test_a_vehicle_lost_twice_is_one_object(stitch, objects):
    """Stitching joins one pair at a time and then looks again: the first two fragments, once joined, join the
    third (joining each track at most once left two objects)."""
    cfg = Config.load()
    cfg.data["parser"].update(stitch=stitch, reacquire=1.0)
    est = SceneParser(ParserModel.load(), None, CAMERA, cfg).parse(np.zeros((T, 1, 1, 3), np.uint8), "syn",
                                                                   _thrice_lost_car())
    assert len(est.objects) == objects


def _parked_track(tid: int, start: int, x: float, score: float, color: int = 1, meets: int = 0,
                  shape: str = "sedan") -> Track:
    """A confirmed track of a parked `shape` (heading along x) from frame `start` to T - 1, detected in every frame
    with `score`; 3 m to its side before frame `meets` (from then on at x)."""
    k = Track(tid, start, onehot(len(SUBTYPE_NAMES), SUBTYPE_NAMES.index(shape)) * 20.0,
              onehot(len(COLOR_NAMES), color) * 20.0, confirmed=start)
    for f in range(start, T):
        pose = np.array([x, 1.5 + (3.0 if f < meets else 0.0), resting_height(shape), 0.0, 0.0, 0.0])
        k.pose.append(pose)
        k.z.append(pose[:3].copy())
        k.quat.append(np.array([0.0, 0.0, 0.0, 1.0]))
        k.yaws.append(0.0)
        for name in ("vel", "acc", "fvels"):
            getattr(k, name).append(np.zeros(3))
        k.engine.append(False)
        k.floating.append(False)
        k.seen.append(True)
        k.scores.append(score)
    return k


@pytest.mark.parametrize("older_score, younger_score, younger_color, objects", [
    (0.6, 0.9, 1, "joined"), (0.9, 0.6, 1, "younger gone"), (0.6, 0.9, 2, "two")])
def test_two_tracks_on_one_vehicle_are_one_object(older_score, younger_score, younger_color, objects):
    """Two alike tracks whose footprints overlap (0.8 m apart along a 3 m sedan) while both are detected are one
    vehicle read twice (a second peak at the image's edge): the one whose detections score lower goes. The older
    one, when it is the duplicate, keeps its frames before the younger began. Another colour: two vehicles."""
    cfg = Config.load()
    parser = SceneParser(ParserModel.load(), None, CAMERA, cfg)
    older, younger = _parked_track(0, 0, 1.8, older_score), _parked_track(1, 40, 1.0, younger_score, younger_color)
    parser._duplicates([older, younger])
    if objects == "two":
        assert older.confirmed is not None and younger.confirmed is not None
        return
    assert younger.confirmed is None and older.confirmed is not None and len(older.pose) == T
    x = [pose[0] for pose in older.pose]
    assert x[39] == pytest.approx(1.8) and x[60] == pytest.approx(1.0 if objects == "joined" else 1.8)


@pytest.mark.parametrize("gap, apart, near_frames, objects", [
    (6, 0.5, 8, 1), (6, 0.5, 0, 2), (12, 0.5, 8, 2), (6, 1.5, 8, 2)],
    ids=["misread-colour", "rule-off", "longer-gap", "further-off"])
def test_a_short_gap_joins_a_track_whose_colour_was_misread(gap, apart, near_frames, objects):
    """A parked sedan read blue for 40 frames, then lost, then found again as red `gap` frames later and `apart`
    metres on: one vehicle when the gap is short and the place the same (only the colour disagrees), two
    otherwise."""
    cfg = Config.load()
    cfg.data["parser"]["stitch_near_frames"] = near_frames
    parser = SceneParser(ParserModel.load(), None, CAMERA, cfg)
    older, younger = _parked_track(0, 0, 1.0, 0.9, color=2), _parked_track(1, 40 + gap, 1.0 + apart, 0.9, color=1)
    for name in ("pose", "z", "quat", "yaws", "vel", "acc", "fvels", "engine", "floating", "seen", "scores"):
        setattr(older, name, getattr(older, name)[:40])
    parser._stitch([older, younger])
    assert [older.confirmed is not None, younger.confirmed is not None] == ([True, False] if objects == 1 else
                                                                          [True, True])
    if objects == 1:
        assert len(older.pose) == T and older.pose[-1][0] == pytest.approx(1.0 + apart)


@pytest.mark.parametrize("older_shape, older_color, gap, objects", [
    ("mountain_bike", 2, 6, 1), ("sedan", 2, 6, 2), ("utility_bike", 1, 45, 1), ("utility_bike", 2, 45, 2)],
    ids=["near-misread", "near-car", "later-same-colour", "later-other-colour"])
def test_two_wheelers_read_as_either_kind_are_one_vehicle(older_shape, older_color, gap, objects):
    """A parked scooter read as another two-wheeler for 40 frames, then found again as a scooter `gap` frames later
    and 0.5 m on, is one vehicle: a bicycle and a motorbike are one kind to a stitch (tracker.KINDS). Soon after,
    the colour may be misread too; after a longer gap the colour must agree. A sedan there before it is another
    vehicle."""
    parser = SceneParser(ParserModel.load(), None, CAMERA, Config.load())
    older = _parked_track(0, 0, 1.0, 0.9, color=older_color, shape=older_shape)
    younger = _parked_track(1, 40 + gap, 1.5, 0.9, color=1, shape="scooter")
    for name in ("pose", "z", "quat", "yaws", "vel", "acc", "fvels", "engine", "floating", "seen", "scores"):
        setattr(older, name, getattr(older, name)[:40])
    parser._stitch([older, younger])
    assert (younger.confirmed is None) == (objects == 1) and older.confirmed is not None


def test_a_duplicate_met_after_the_cut_by_a_track_found_before_it_is_kept():
    """The state at the cut reads no later frame: a younger track found by then whose footprint meets an alike
    track's only after the cut stays an object (decided on the observed frames, where they are 3 m apart)."""
    cfg = Config.load()
    cut = cfg["video"]["observed_frames"] - 1
    parser = SceneParser(ParserModel.load(), None, CAMERA, cfg)
    older, younger = _parked_track(0, 0, 1.8, 0.9), _parked_track(1, cut - 10, 1.0, 0.6, meets=cut + 5)
    parser._duplicates([older, younger])
    assert younger.confirmed is not None
    late = _parked_track(2, cut - 10, 1.0, 0.6)      # overlapping from its first frame: decided by the cut
    parser._duplicates([older, late])
    assert late.confirmed is None


def test_a_track_joined_across_the_cut_keeps_the_cut_state_of_the_observed_frames():
    """A car lost before the cut and found again after it is one object, and the predictive questions' state at the
    last observed frame reads no later frame: it is the state a parse of the observed frames alone gives."""
    cfg = Config.load()
    cfg.data["parser"]["reacquire"] = 1.0
    cut = cfg["video"]["observed_frames"] - 1
    _, dets = _bounced_car(range(cut - 12, cut + 12))
    est = SceneParser(ParserModel.load(), None, CAMERA, cfg).parse(np.zeros((T, 1, 1, 3), np.uint8), "syn", dets)
    assert len(est.objects) == 1
    seen = np.nonzero(est.visible[:, 0])[0]
    assert seen[-1] == T - 1 and not est.visible[cut - 12:cut + 12, 0].any()
    early = SceneParser(ParserModel.load(), None, CAMERA, cfg).parse(np.zeros((cut + 1, 1, 1, 3), np.uint8), "syn",
                                                                     dets[:cut + 1])
    assert set(est.cut_state) == set(early.cut_state)
    for key, value in early.cut_state.items():
        np.testing.assert_array_equal(est.cut_state[key], value, err_msg=key)


def _hidden_car(shape_after: str) -> list:
    """A parked sedan hidden (no detection) for frames 20-79; from frame 80 the detections there read
    `shape_after`."""
    pos = np.tile([1.0, 1.5, resting_height("sedan")], (T, 1))
    dets = _detections(pos, 0.4, "sedan", np.random.default_rng(4))
    late = _detections(pos, 0.4, shape_after, np.random.default_rng(5))
    return [d if f < 20 else [] if f < 80 else late[f] for f, d in enumerate(dets)]


@pytest.mark.parametrize("shape_after, third, objects", [("sedan", False, 1), ("suv", False, 1), ("sedan", True, 2),
                                                          ("suv", True, 3)])
def test_after_a_long_gap_only_the_same_vehicle_joins(shape_after, third, objects):
    """Hidden for a second (60 frames, beyond stitch_frames), a vehicle seen again is re-identified when sub-type
    and colour agree. Where they read another sub-type of its kind and colour, it is the same vehicle only if no
    third vehicle of that kind and colour is in the video (a wagon of its colour parked elsewhere): then only the
    sub-type could tell them apart."""
    cfg = Config.load()
    dets = _hidden_car(shape_after)
    if third:
        pos = np.tile([-2.5, -1.0, resting_height("wagon")], (T, 1))
        dets = [d + w for d, w in zip(dets, _detections(pos, 1.2, "wagon", np.random.default_rng(6)))]
    est = SceneParser(ParserModel.load(), None, CAMERA, cfg).parse(np.zeros((T, 1, 1, 3), np.uint8), "syn", dets)
    assert len(est.objects) == objects


@pytest.mark.parametrize("bus_score, veto_score, minivan_takes_it", [(0.98, 0.9, False), (0.98, 1.0, True),
                                                                     (0.6, 0.9, True)],
                         ids=["confident-vetoed", "no-veto", "weak-not-vetoed"])
def test_a_confident_detection_never_pairs_with_a_track_it_contradicts(bus_score, veto_score, minivan_takes_it):
    """Full-test 000044: a brown minivan's track, coasting while the minivan was hidden behind a green double bus,
    came out beside the bus's detection (score 0.98) while the bus's own track had drifted off, took it, and the two
    tracks swapped for the rest of the video. A detection that sure of itself pairs only with a track whose category
    and colour it does not contradict; a weak one (the head's names are unsure there) still may."""
    cfg = Config.load()
    cfg.data["parser"]["veto_score"] = veto_score
    parser = SceneParser(ParserModel.load(), None, CAMERA, cfg)
    bus = np.array([0.0, 0.0, resting_height("double_bus")])

    def track(i: int, shape: str, colour: str) -> Track:
        return Track(i, 0, 10 * onehot(len(SUBTYPE_NAMES), SUBTYPE_NAMES.index(shape)),
                     10 * onehot(len(COLOR_NAMES), COLOR_NAMES.index(colour)))

    (u, v), _ = CAMERA.project(bus)
    det = Detection(float(u), float(v), bus_score, onehot(len(SUBTYPE_NAMES), SUBTYPE_NAMES.index("double_bus")),
                    onehot(len(COLOR_NAMES), COLOR_NAMES.index("green")), 0.0,
                    float(np.linalg.norm(bus - np.asarray(CAMERA.position))), float(bus[2]))
    tracks = [track(0, "double_bus", "green"), track(1, "minivan", "brown")]
    # the bus track's prediction drifted 6 m off (out of reach), the minivan's 2 cm from the bus's centre
    mu = np.array([[*(bus + [0.0, 6.0, 0.0]), 0, 0, 0], [*(bus + [0.02, 0.0, 0.0]), 0, 0, 0]])
    assert (parser._associate(tracks, mu, [det]).get(1) == 0) == minivan_takes_it


@pytest.mark.parametrize("last_seen, shape, colour, takes_it", [
    ([True] * 6, "road_bike", "blue", True), ([False] * 6, "road_bike", "blue", False),
    ([False] * 5 + [True], "road_bike", "blue", False), ([False] * 6, "fighter", "green", True)],
    ids=["seen-takes-unalike", "coasting-refuses-unalike", "just-found-again-refuses-unalike", "coasting-takes-alike"])
def test_a_coasting_track_pairs_only_with_a_detection_that_looks_like_its_vehicle(last_seen, shape, colour, takes_it):
    """A green fighter's track whose fighter is hidden (no detection in 3 of its last 6 frames) coasts on the engine's
    prediction, or was found again a frame ago; a blue road bike passing within its gate (score 0.85, under the
    veto's bar) is not its vehicle. A track seen in the last frames still takes it (the head's names of one detection
    are unsure), and a coasting one takes a detection that looks like its own vehicle."""
    parser = SceneParser(ParserModel.load(), None, CAMERA, Config.load())
    at = np.array([0.0, 0.0, resting_height("fighter")])
    track = Track(0, 0, 10 * onehot(len(SUBTYPE_NAMES), SUBTYPE_NAMES.index("fighter")),
                  10 * onehot(len(COLOR_NAMES), COLOR_NAMES.index("green")), seen=[True] * 20 + last_seen)
    (u, v), _ = CAMERA.project(at)
    det = Detection(float(u) + 3.0, float(v), 0.85, onehot(len(SUBTYPE_NAMES), SUBTYPE_NAMES.index(shape)),
                    onehot(len(COLOR_NAMES), COLOR_NAMES.index(colour)), 0.0,
                    float(np.linalg.norm(at - np.asarray(CAMERA.position))), float(at[2]))
    assert (parser._associate([track], np.array([[*at, 0, 0, 0]]), [det]).get(0) == 0) == takes_it


@pytest.mark.parametrize("det_dist, depth_gate, takes_it", [(8.6, 0.35, False), (8.6, 0.0, True), (13.5, 0.35, True)],
                         ids=["nearer-plane-refused", "no-gate", "own-distance-noise"])
def test_a_vehicle_passing_in_front_does_not_take_the_track_of_the_one_it_covers(det_dist, depth_gate, takes_it):
    """Full-test 000078: a cyan fighter 14.3 m from the camera is covered by a nearer plane whose peak, which the
    head places 7.8-8.8 m off, falls within the fighter track's pixel gate while the fighter's own peak fades. The
    pixels cannot tell the two apart; the head's distance can: a detection more than a factor exp(depth_gate) off
    the track's distance is not its vehicle, while the head's noise on the fighter (a few per cent) still pairs."""
    cfg = Config.load()
    cfg.data["parser"]["depth_gate"] = depth_gate
    parser = SceneParser(ParserModel.load(), None, CAMERA, cfg)
    eye = np.asarray(CAMERA.position, float)
    ray = np.array([0.0, 0.0, resting_height("fighter")]) - eye
    at = eye + 14.0 * ray / np.linalg.norm(ray)
    fighter, cyan = SUBTYPE_NAMES.index("fighter"), COLOR_NAMES.index("cyan")
    track = Track(0, 0, 10 * onehot(len(SUBTYPE_NAMES), fighter), 10 * onehot(len(COLOR_NAMES), cyan), seen=[True] * 20)
    (u, v), _ = CAMERA.project(at)
    det = Detection(float(u) + 2.0, float(v), 0.9, onehot(len(SUBTYPE_NAMES), fighter), onehot(len(COLOR_NAMES), cyan),
                    0.0, det_dist, 1.0)
    assert (parser._associate([track], np.array([[*at, 0, 0, 0]]), [det]).get(0) == 0) == takes_it


@pytest.mark.parametrize("older_seen, younger_seen, ended", [(False, True, "older"), (True, False, "younger"),
                                                            (True, True, "younger")])
def test_of_two_converged_tracks_the_one_without_a_detection_ends(older_seen, younger_seen, ended):
    """Two tracks within merge_radius are on one vehicle and one of them ends. Where only one holds a detection in
    the frame, the other (a track coasting where it lost its own vehicle) ends, old or not; else the younger."""
    parser = SceneParser(ParserModel.load(), None, CAMERA, Config.load())
    tracks = [Track(i, i, np.zeros(len(SUBTYPE_NAMES)), np.zeros(len(COLOR_NAMES)), pose=[np.array(at)], seen=[seen])
              for i, (at, seen) in enumerate((([0.0, 0.0, 0.7, 0, 0, 0], older_seen),
                                              ([0.2, 0.1, 0.7, 0, 0, 0], younger_seen)))]
    parser._merge(tracks, 40)
    assert [k.end for k in tracks] == ([41, None] if ended == "older" else [None, 41])


def _weak_bike(score: float, every: int = 1) -> list:
    """A parked mountain bike whose detections all score `score`, under the start bar (0.8), in every `every`-th
    frame only."""
    pos = np.tile([0.5, 1.0, resting_height("mountain_bike")], (T, 1))
    dets = _detections(pos, 0.3, "mountain_bike", np.random.default_rng(8))
    for f, frame in enumerate(dets):
        for d in frame:
            d.score = score
    return [d if f % every == 0 else [] for f, d in enumerate(dets)]


@pytest.mark.parametrize("score, every, weak_frames, objects",
                         [(0.65, 1, 10, 1), (0.65, 1, 0, 0), (0.5, 1, 10, 0), (0.65, 3, 10, 0)],
                         ids=["persistent", "weak-start-off", "under-the-weak-bar", "flickering"])
def test_detections_under_the_start_bar_start_a_track_where_they_persist(score, every, weak_frames, objects):
    """A vehicle the head reads at 0.65 in every frame (a bicycle half behind a car) never reaches the start bar,
    and was never found; 10 such detections within 12 frames, each within a gate of the last, now start its track,
    which is then confirmed and reported at its place. Weaker ones (under weak_track_score) or ones in every third
    frame only (a flickering false peak) start none."""
    cfg = Config.load()
    cfg.data["parser"].update(weak_track_frames=weak_frames)
    est = SceneParser(ParserModel.load(), None, CAMERA, cfg).parse(np.zeros((T, 1, 1, 3), np.uint8), "syn",
                                                                   _weak_bike(score, every))
    assert len(est.objects) == objects
    if objects:
        seen = np.nonzero(est.visible[:, 0])[0]
        assert 9 <= seen[0] <= 20 and seen[-1] == T - 1
        assert est.objects[0].shape == "mountain_bike" and est.objects[0].speed_class == "static"
        assert np.linalg.norm(est.position[-1, 0, :2] - [0.5, 1.0]) < 0.2


@pytest.mark.parametrize("key, value, message", [("stitch_agreement", 1.5, "must lie in"),
                                                 ("stitch_frames", -1, "non-negative integer"),
                                                 ("stitch_near_frames", 3.5, "non-negative integer"),
                                                 ("stitch_radius", 0.0, "must be positive"),
                                                 ("stitch_length_share", -0.5, "must be positive"),
                                                 ("reid_agreement", -0.1, "must lie in"),
                                                 ("stitch", "yes", "must be true or false"),
                                                 ("weak_track_score", 1.2, "must lie in"),
                                                 ("weak_track_frames", 2.5, "non-negative integer"),
                                                 ("heading_support", 0, "must be positive"),
                                                 ("parked_split", 1, "must be true or false"),
                                                 ("engine_prior", 1.0, "must lie in"),
                                                 ("veto_score", 0.0, "must lie in"),
                                                 ("veto_agreement", 1.5, "must lie in"),
                                                 ("duplicate_overlap", 0.0, "must lie in \\(0, 1\\]"),
                                                 ("duplicate_share", 1.5, "must lie in \\(0, 1\\]"),
                                                 ("coast_frames", -2, "non-negative integer"),
                                                 ("coast_agreement", 1.2, "must lie in"),
                                                 ("coast_window", 2, "must be at least"),
                                                 ("spin_window", 0, "must be positive"),
                                                 ("spin_window", 15.5, "non-negative integer"),
                                                 ("spin_significance", -1.0, "must be positive"),
                                                 ("heading_motion_sd", -4.0, "must lie in"),
                                                 ("heading_flip_weight", 0.0, "must lie in"),
                                                 ("heading_flip_weight", 1.5, "must lie in"),
                                                 ("depth_gate", -0.1, "non-negative number")])
def test_a_bad_tracking_value_is_one_clear_line(key, value, message):
    from dynclevr.config import ConfigError

    cfg = Config.load()
    cfg.data["parser"][key] = value
    with pytest.raises(ConfigError, match=f"'parser.{key}' = .* {message}"):
        SceneParser(ParserModel.load(), None, CAMERA, cfg)


def test_a_two_wheeler_lying_still_is_placed_and_held_where_it_lies():
    """A motorbike on its side (its centre 0.3 m under its resting height) with heights that jitter by centimetres:
    from the frames that show it lying, the track places it at its own height, not beyond it along the ray, and it
    reads as static."""
    cfg = Config.load()
    pos = np.tile([1.0, 1.5, resting_height("dirtbike") - 0.3], (T, 1))
    rng = np.random.default_rng(3)
    dets = _detections(pos, 0.4, "dirtbike", rng)
    for d in dets:
        d[0].height += rng.normal(0, 0.03)
    est = SceneParser(ParserModel.load(), None, CAMERA, cfg).parse(np.zeros((T, 1, 1, 3), np.uint8), "syn", dets)
    assert len(est.objects) == 1
    late = slice(30, T)
    assert np.linalg.norm(est.position[late, 0] - pos[late], axis=1).max() < 0.2
    assert est.objects[0].speed_class == "static" and np.linalg.norm(est.velocity[late, 0], axis=1).max() < 0.3


def test_a_landed_plane_is_placed_on_the_ground_though_its_distance_is_biased():
    """A fighter on the ground, its distances read 8% too near in every frame (the head's bias per object is a few
    percent; too far would put it under the floor): the head's heights at its resting height put it on the ground
    plane, where the ray pins it; a plane the heights show in the air stays at the head's distance."""
    cfg = Config.load()
    rng = np.random.default_rng(5)
    for height, within in ((resting_height("fighter"), 0.2), (2.4, None)):
        pos = np.tile([0.5, 2.0, height], (T, 1))
        dets = _detections(pos, -0.6, "fighter", rng)
        for d in dets:
            d[0].dist *= 0.92
            d[0].height += rng.normal(0, 0.03)
        est = SceneParser(ParserModel.load(), None, CAMERA, cfg).parse(np.zeros((T, 1, 1, 3), np.uint8), "syn", dets)
        err = np.median(np.linalg.norm(est.position[10:, 0] - pos[10:], axis=1))
        if within is None:
            assert err > 0.5          # no ground to pin it: the distance's bias stays
        else:
            assert err < within


def test_own_height_votes_over_the_last_detections():
    plane, bike, truck = resting_height("jet"), resting_height("dirtbike"), resting_height("truck")
    assert own_height("truck", [truck + 0.01, truck - 0.02] * 4) is None   # where its sub-type puts it
    assert abs(own_height("wagon", [truck] * 7) - truck) < 1e-9         # a truck read as a wagon: its own height
    assert own_height("jet", [plane + 0.05] * 3) == plane               # a young track: all of them agree
    assert own_height("jet", [plane + 0.05] * 2 + [plane + 1.0]) is None
    assert own_height("jet", [plane + 1.0] * 9 + [plane] * 5 + [plane + 1.0] * 2) == plane   # 5 of the last 7
    assert own_height("jet", [plane] * 4 + [plane + 1.0] * 3) is None
    assert abs(own_height("dirtbike", [bike - 0.3, bike - 0.28, bike - 0.32]) - (bike - 0.3)) < 1e-9
    assert own_height("dirtbike", [bike] * 7) is None


def _flipped_headings(yaws, flipped) -> list:
    """A parked suv whose heading is `yaws[t]`, the head reading it back to front in the frames of `flipped`."""
    pos = np.tile([1.0, 1.0, resting_height("suv")], (T, 1))
    dets = _detections(pos, 0.0, "suv", np.random.default_rng(3))
    for t, frame in enumerate(dets):
        frame[0] = dataclasses.replace(frame[0], alpha=frame[0].alpha + yaws[t] + math.pi * (t in flipped))
    return dets


@pytest.mark.parametrize("spin", [0.0, 0.04], ids=["still", "spinning"])
def test_the_heads_front_back_flips_do_not_turn_the_heading(spin):
    """The head reads a vehicle back to front now and then, the first two frames included; runs of up to 3. A body
    turns a few degrees a frame (0.04 rad a frame is 2.4 rad/s), so the track keeps its heading through the flips,
    and turns round from its flipped start once the readings against it outweigh those for it (a flip counts half:
    the fifth reading against, frame 6)."""
    rng = np.random.default_rng(4)
    flipped = {0, 1} | {int(t) + d for t in rng.choice(np.arange(8, T - 4, 6), 8, replace=False) for d in range(
        int(rng.integers(1, 4)))}
    yaws = 1.0 + spin * np.arange(T)
    est = SceneParser(ParserModel.load(), None, CAMERA, Config.load()).parse(
        np.zeros((T, 1, 1, 3), np.uint8), "syn", _flipped_headings(yaws, flipped))
    err = np.abs(np.angle(np.exp(1j * (yaw_of(est.orientation[:, 0]) - yaws))))
    assert err[:6].min() > 2.5 and err[6:].max() < 0.35


def test_front_back_heading_ignores_short_confusions_and_follows_lasting_ones():
    """Readings 100 degrees off are the head's confusion while those for the heading outnumber them (at most
    `support_cap`, here 5), then a turn the head saw late; a flip is folded back, and lasting flips turn it round."""
    yaws = np.full(40, 0.5)
    yaws[5:8] = 0.5 + np.radians(100)            # 3 confused readings: skipped
    yaws[10] = np.nan                            # no detection: coasts
    yaws[12:14] = 0.5 + np.pi                    # 2 flips: folded back
    yaws[20:] = 0.5 - np.radians(100)            # lasting: followed from the 6th
    out = front_back_heading(yaws, 5, 0.05, 0.3)
    assert np.abs(out[:25] - 0.5).max() < 1e-9
    assert np.abs(out[25:] - yaws[25:]).max() < 1e-9
    turned = front_back_heading(np.r_[np.full(10, 0.5), np.full(10, 0.5 + np.pi)], 5, 0.05, 0.3)
    assert np.abs(turned[:15] - 0.5).max() < 1e-9 and abs(np.angle(np.exp(1j * (turned[-1] - 0.5 - np.pi)))) < 1e-6


def test_a_heading_holds_through_the_heads_flips_after_an_impact_but_follows_a_real_turn():
    """A body seen facing 0.5 rad for 30 frames is struck: the head reads 6 confusions during the impact, then the
    body backwards for 40 frames (it did not turn: the head reads it from its back). Half a count per flip, the
    heading holds (a flip a whole count, as much as a confusion, turns it round after 25); a body that does turn
    round (at 4.5 degrees a frame), through the angles between, is followed; a heading begun on a flipped reading
    still turns round."""
    struck = np.r_[np.full(30, 0.5), 0.5 + np.radians([70, 100, 120, 80, 110, 95]), np.full(40, 0.5 + np.pi)]
    held = front_back_heading(struck, 60, 0.05, 0.3, flip_weight=0.5)
    assert np.abs(np.angle(np.exp(1j * (held[-1] - 0.5)))) < 1e-6
    dragged = front_back_heading(struck, 60, 0.05, 0.3, flip_weight=1.0)
    assert np.abs(np.angle(np.exp(1j * (dragged[-1] - 0.5 - np.pi)))) < 1e-6
    turn = np.r_[np.full(30, 0.5), 0.5 + np.linspace(0.1, np.pi, 40), np.full(30, 0.5 + np.pi)]
    followed = front_back_heading(turn, 60, 0.05, 0.3, flip_weight=0.5)
    assert np.abs(np.angle(np.exp(1j * (followed[-1] - 0.5 - np.pi)))) < 0.2
    wrong_start = front_back_heading(np.r_[0.5 + np.pi, np.full(20, 0.5)], 60, 0.05, 0.3, flip_weight=0.5)
    assert np.abs(np.angle(np.exp(1j * (wrong_start[-1] - 0.5)))) < 1e-6


@pytest.mark.parametrize("rate", [0.0, 1.5, -2.5])
def test_a_body_spins_only_after_an_impact_at_the_rate_its_heading_turns(rate):
    """Before its impact a body has no spin whatever its heading's noise says; after it, the slope of the heading
    once enough frames are seen, and 0 where the slope is the noise's. Causal: a frame's rate reads no later frame."""
    rng = np.random.default_rng(4)
    t = np.arange(60)
    yaw = 3.0 + np.where(t > 20, rate * (t - 20) / FPS, 0.0) + rng.normal(0, np.radians(4), 60)
    quats = np.array([yaw_quaternion(y) for y in yaw])
    seen = np.ones(60, bool)
    seen[40:43] = False
    out = spin(quats, seen, [20], FPS, 15, 3.0, 6)
    assert np.all(out[:26] == 0)                    # before the impact, and until 6 frames after it are seen
    if rate:
        assert np.abs(out[45:] - rate).max() < 0.25 * abs(rate)
    else:
        assert np.mean(out[27:] != 0) < 0.1
    assert np.array_equal(spin(quats[:45], seen[:45], [20], FPS, 15, 3.0, 6), out[:45])
    assert np.all(spin(quats, seen, [], FPS, 15, 3.0, 6) == 0)



def _falling_jet_seen_drifting(engine: bool, drift: float, seed: int) -> tuple[list, bool]:
    """A jet falling from rest at 3.4 m, flying at 3 m/s across the camera ray with its engine on or off, simulated
    by the data's physics, and the head's detections of it whose distance drifts by `drift` of itself per metre
    the jet has dropped (on full-val a falling plane's drift is +0.9% per metre at the median, -2.0% to +3.2%
    between the quartiles). Also: its engine at frame 10."""
    params = PhysicsParams.from_config(Config.load())
    tr = simulate([Body("jet", (0.0, 1.0, 3.4), yaw_quaternion(0.8), (3.0 * math.cos(0.8), 3.0 * math.sin(0.8), 0.0),
                        engine_on=engine, floating=False)], params, 40)
    dets = _detections(tr.position[:, 0], 0.8, "jet", np.random.default_rng(seed))
    drop = 3.4 - tr.position[:, 0, 2]
    return [[dataclasses.replace(d, dist=d.dist * (1 + drift * h)) for d in frame] for frame, h in zip(dets, drop)], \
        bool(tr.engine[10, 0])


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_a_floating_plane_flying_away_with_its_engine_on_reads_accelerating_seen_whole(seed):
    """A floating jet flies away from the camera from 3 m/s with its engine on, and the head reads its distance
    drawn towards 10 m (near planes too far, far ones too near) with 3% noise: along its own line its motion
    fits "holding its speed" about as well. Seen whole as at the cut, its flight before any impact follows its
    heading from a start speed, so the factual arrays read it accelerating at the start, at the truth's speed."""
    from dynclevr.questions.labels import compute_labels

    cfg = Config.load()
    params = PhysicsParams.from_config(cfg)
    yaw = math.atan2(5.0, -6.0)          # along the camera's ray, away from it
    tr = simulate([Body("jet", (2.0, -2.0, 2.5), yaw_quaternion(yaw), (3.0 * math.cos(yaw), 3.0 * math.sin(yaw), 0.0),
                        engine_on=True, floating=True)], params, T)
    rng = np.random.default_rng(seed)
    dets = _detections(tr.position[:, 0], yaw, "jet", rng)
    for (d,), pos in zip(dets, tr.position[:, 0]):
        true = float(np.linalg.norm(pos - np.asarray(CAMERA.position)))
        d.dist = (true + 0.08 * (10.0 - true)) * (1 + rng.normal(0, 0.03))
    est = SceneParser(ParserModel.load(), None, CAMERA, cfg).parse(np.zeros((T, 1, 1, 3), np.uint8), "syn", dets)
    start = cfg["labels"]["start_frame"]
    assert est.engine[start, 0]
    assert abs(np.linalg.norm(est.velocity[start, 0, :2]) - np.linalg.norm(tr.velocity[start, 0, :2])) < 0.3
    assert compute_labels(est, cfg["labels"]).accelerating[start, 0]


def test_a_ground_vehicles_engine_is_decided_under_the_generators_prior():
    """Over a short first stretch a slow car's engine (+2.2 m/s^2 net) and friction (-0.8) part by centimetres, the
    depth noise of a detection: the decision is the generator's prior (`engine_prior`, its share of bodies with an
    engine) against the likelihood. A higher prior never takes an engine away, and between a low and a high one
    the decision moves."""
    params = PhysicsParams.from_config(Config.load())
    reads = {}
    for engine in (False, True):
        tr = simulate([Body("sedan", (-3.0, 1.0, ground_height("sedan")), yaw_quaternion(0.4),
                            (3.0 * math.cos(0.4), 3.0 * math.sin(0.4), 0.0), engine_on=engine)], params, 24)
        for seed in range(4):
            dets = _detections(tr.position[:, 0], 0.4, "sedan", np.random.default_rng(seed), pixel_noise=1.5)
            for prior in (0.2, 0.35, 0.5, 0.8):
                cfg = Config.load()
                cfg.data["parser"]["engine_prior"] = prior
                est = SceneParser(ParserModel.load(), None, CAMERA, cfg).parse(
                    np.zeros((24, 1, 1, 3), np.uint8), "syn", dets)
                reads[engine, seed, prior] = bool(est.engine[10, 0])
    for engine in (False, True):
        for seed in range(4):
            got = [reads[engine, seed, prior] for prior in (0.2, 0.35, 0.5, 0.8)]
            assert got == sorted(got)
    assert sum(reads[True, seed, 0.8] for seed in range(4)) > sum(reads[True, seed, 0.2] for seed in range(4)) \
        or sum(reads[False, seed, 0.8] for seed in range(4)) > sum(reads[False, seed, 0.2] for seed in range(4))


@pytest.mark.parametrize("drift", [0.0, 0.03])
def test_a_falling_planes_engine_is_read_along_its_heading_through_the_distance_drift(drift):
    """While a plane falls the head's distance drifts with its drop, quadratic in time like an engine's motion: along
    the measurements' own line that drift read as an engine in some draws. Along its heading from one of the
    generator's start speeds (the factual arrays as the cut state), its engine is read right in every draw."""
    for engine in (False, True):
        for seed in range(6):
            dets, truth = _falling_jet_seen_drifting(engine, drift, seed)
            assert truth == engine
            est = SceneParser(ParserModel.load(), None, CAMERA, Config.load()).parse(
                np.zeros((40, 1, 1, 3), np.uint8), "syn", dets)
            assert bool(est.engine[10, 0]) == engine
