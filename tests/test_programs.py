"""Every operation of the paper's program table on a hand-built scene with known answers, and the executor's errors."""

from dataclasses import replace

import numpy as np
import pytest

from dynclevr.camera import Camera
from dynclevr.config import Config
from dynclevr.questions.programs import OPS, AmbiguousLabel, Executor, Object, ProgramError, execute, parse
from dynclevr.scene import Collision, Scene4D, SceneObject

CAMERA = Camera((8.0, -7.0, 3.2), (0.0, 0.0, 1.3), 35.0, 32.0, 320, 240)
_R = CAMERA.world_to_camera[:3, :3]
RIGHT = _R[0]                                   # image right, horizontal
AWAY = _R[2] * [1, 1, 0] / np.linalg.norm(_R[2][:2])   # away from the camera, horizontal


def build_scene(objects, velocity, start, visible=None, **events) -> Scene4D:
    """A scene from per-frame velocities [T, N, 3] and start positions [N, 3] (positions integrate the velocity)."""
    velocity = np.asarray(velocity, float)
    T, N, _ = velocity.shape
    position = np.asarray(start, float)[None] + np.cumsum(velocity, axis=0) / 60 - velocity[:1] / 60
    quat = np.zeros((T, N, 4))
    quat[..., 3] = 1
    vis = np.ones((T, N), bool) if visible is None else visible
    return Scene4D("000000", 60, CAMERA, objects, position, quat, velocity, np.zeros((T, N, 3)),
                   np.gradient(velocity, 1 / 60, axis=0), np.zeros((T, N), bool), np.zeros((T, N), bool), vis,
                   **events)


def obj(i, shape, category, color, size, speed_class="static", engine=False, floating=False):
    return SceneObject(i, shape, category, color, size, 10.0, engine, floating, speed_class)


def known_scene() -> Scene4D:
    """0 red sedan: static. 1 yellow school bus: slow (3 m/s) to the image right. 2 blue jet: floating at 2.5 m, fast
    (6 m/s) away from the camera. 3 green fighter: falls from 3 m. 4 purple suv: towards the camera, 2 m/s speeding up
    by 1.5 m/s^2, out of view for its first 5 frames. 5 red school bus: slow, towards the camera."""
    T = 60
    t = np.arange(T)[:, None] / 60
    v = np.zeros((T, 6, 3))
    v[:, 1] = 3.0 * RIGHT
    v[:, 2] = 6.0 * AWAY
    v[:, 3, 2] = -10.0 * t[:, 0]
    v[:, 4] = (2.0 + 1.5 * t) * -AWAY
    v[:, 5] = 3.0 * -AWAY
    objects = [obj(0, "sedan", "car", "red", (3.0, 1.3, 1.0)),
               obj(1, "school_bus", "bus", "yellow", (3.8, 1.3, 1.6), "slow"),
               obj(2, "jet", "aeroplane", "blue", (3.6, 3.2, 1.0), "fast", floating=True),
               obj(3, "fighter", "aeroplane", "green", (3.8, 2.6, 0.9)),
               obj(4, "suv", "car", "purple", (2.8, 1.4, 1.3), "slow", engine=True),
               obj(5, "school_bus", "bus", "red", (3.8, 1.3, 1.6), "slow")]
    start = [[0, 0, 0.5], [-4, 2, 0.8], [3, 3, 2.5], [-2, -3, 9.0], [1, 5, 0.65], [4, -1, 0.8]]
    visible = np.ones((T, 6), bool)
    visible[:5, 4] = False
    return build_scene(objects, v, start, visible,
                       collisions=[Collision(20, 0, 1), Collision(22, 0, 1), Collision(45, 1, 4)],
                       future_collisions=[Collision(45, 1, 4)],
                       counterfactuals={(0, "fast"): [Collision(10, 0, 5)], (4, "static"): [],
                                        (1, "slow"): [Collision(20, 0, 1)], (1, "accelerating"): [Collision(15, 1, 2)],
                                        (3, "floating"): [Collision(50, 3, 2)]},
                       observed_frames=30)


@pytest.fixture(scope="module")
def scene():
    return known_scene()


@pytest.fixture(scope="module")
def lcfg():
    # The hand-built scenes are read "at the start" = frame 0; test_start_is_the_configured_frame covers the default.
    return {**Config.load()["labels"], "start_frame": 0}


RED_SEDAN = "Objects filter_attributes[red] filter_attributes[sedan] unique"
BUS = "Objects filter_attributes[yellow] unique"
JET = "Objects filter_attributes[jet] unique"
FIGHTER = "Objects filter_attributes[fighter] unique"
SUV = "Objects filter_attributes[suv] unique"
RED_BUS = "Objects filter_attributes[red] filter_attributes[bus] unique"

CASES = [
    # input + filter + query_attributes
    ("Objects filter_attributes[red] filter_attributes[car] unique query_attributes[shape]", "sedan"),
    ("Objects filter_attributes[aeroplane] filter_attributes[blue] unique query_attributes[shape]", "jet"),
    (f"{SUV} query_attributes[color]", "purple"),
    ("Objects filter_attributes[school_bus] exist", "true"),
    ("Objects filter_attributes[cyan] exist", "false"),
    # velocity: is_static, query_moving_velocity, filter_static, filter_moving_velocity
    (f"{RED_SEDAN} start is_static", "true"),
    (f"{BUS} start is_static", "false"),
    (f"{BUS} start query_moving_velocity", "slow"),
    (f"{JET} start query_moving_velocity", "fast"),
    (f"{FIGHTER} start query_moving_velocity", "static"),
    (f"{BUS} start is_moving_velocity[slow]", "true"),
    (f"{JET} start is_moving_velocity[slow]", "false"),
    (f"{JET} start is_moving_velocity[fast]", "true"),
    (f"{FIGHTER} Events {RED_SEDAN} filter_collision unique get_frame query_moving_velocity", "slow"),  # frame 20
    ("Objects start filter_static filter_attributes[car] unique query_attributes[color]", "red"),
    ("Objects start filter_moving_velocity[fast] unique query_attributes[shape]", "jet"),
    ("Objects start filter_moving_velocity filter_attributes[school_bus] filter_attributes[red] exist", "true"),
    ("Objects start filter_moving_velocity[slow] filter_attributes[aeroplane] exist", "false"),
    # direction
    (f"{BUS} start query_moving_direction", "right"),
    (f"{JET} start query_moving_direction", "back"),
    (f"{RED_BUS} start query_moving_direction", "front"),
    (f"{FIGHTER} {SUV} come_in_frame query_moving_direction", "down"),
    # comparison
    (f"{JET} {BUS} start faster_velocity", "true"),
    (f"{JET} {BUS} start slower_velocity", "false"),
    (f"{RED_SEDAN} {BUS} start slower_velocity", "true"),
    # acceleration and floating
    (f"{SUV} {SUV} come_in_frame is_accelerating", "true"),
    (f"{BUS} start is_accelerating", "false"),
    (f"{JET} start is_floating", "true"),
    (f"{FIGHTER} start is_floating", "false"),
    (f"{RED_SEDAN} start is_floating", "false"),
    ("Objects start filter_floating unique query_attributes[color]", "blue"),
    ("Objects start filter_accelerating unique query_attributes[shape]", "suv"),
    # events: Events (merged: the two sedan-bus contacts are one collision), futureEvents, partners, frames
    (f"Events {RED_SEDAN} filter_collision {BUS} filter_collision exist", "true"),
    (f"Events {BUS} get_all_col_partners filter_attributes[suv] unique query_attributes[color]", "purple"),
    (f"Events {SUV} get_all_col_partners unique query_attributes[shape]", "school_bus"),
    (f"futureEvents {RED_SEDAN} filter_collision exist", "false"),
    (f"futureEvents {SUV} filter_collision {BUS} filter_collision exist", "true"),
    (f"{BUS} Events {BUS} filter_collision {RED_SEDAN} filter_collision unique get_frame query_moving_velocity",
     "slow"),
    # counterfactuals
    (f"{RED_SEDAN} Counterfactual_moving_fast {RED_BUS} filter_collision exist", "true"),
    (f"{SUV} Counterfactual_static {BUS} filter_collision exist", "false"),
    (f"{BUS} Counterfactual_moving_slow {RED_SEDAN} get_all_col_partners unique query_attributes[shape]",
     "school_bus"),
    (f"{BUS} Counterfactual_accelerating {JET} filter_collision exist", "true"),
    (f"{FIGHTER} Counterfactual_floating {JET} get_all_col_partners unique query_attributes[color]", "green"),
]


@pytest.mark.parametrize("program,answer", CASES)
def test_operation_answers(scene, lcfg, program, answer):
    assert execute(program, scene, lcfg) == answer
    assert execute(program.split(), scene, lcfg) == answer   # a token list runs the same


def test_every_operation_is_exercised():
    used = {name for program, _ in CASES for name, _ in parse(program)}
    assert used == set(OPS)


def test_frames_of_events(scene, lcfg):
    # A FrameID is no answer: read it off the falling fighter, whose speed is 10 m/s^2 x t.
    ex = f"Events {BUS} filter_collision {SUV} filter_collision unique get_frame"
    assert execute(f"{FIGHTER} {ex} query_moving_velocity", scene, lcfg) == "fast"          # frame 45: 7.5 m/s
    assert execute(f"{FIGHTER} {SUV} come_in_frame query_moving_velocity", scene, lcfg) == "slow"   # 5: 0.83 m/s
    assert execute(f"{FIGHTER} start query_moving_velocity", scene, lcfg) == "static"


@pytest.mark.parametrize("program,message", [
    (f"{RED_SEDAN} start", "leaves 2 values"),
    (f"Events {RED_SEDAN} filter_collision unique get_frame {BUS} query_attributes[color]", "leaves 2 values"),
    ("Objects", "ends in a ObjectSet"),
    (f"{RED_SEDAN} {BUS} filter_collision exist", "input 1 must be a CollisionEventSet"),
    (f"start {RED_SEDAN} is_static", "input 1 must be a Object"),
    ("start is_static", "needs 2 inputs"),
    ("Objects filter_attributes[banana]", "takes another argument"),
    ("Objects filter_attributes", "needs an argument"),
    ("Objects query_attributes[size]", "another argument"),
    ("Events[red]", "takes no argument"),
    ("Objects fly", "unknown token 'fly'"),
    ("", "empty program"),
    (f"{JET} Counterfactual_static {BUS} filter_collision exist", "no counterfactual run"),
])
def test_unrunnable_programs_raise_program_error(scene, lcfg, program, message):
    with pytest.raises(ProgramError, match=message):
        execute(program, scene, lcfg)


@pytest.mark.parametrize("program", [
    "Objects filter_attributes[school_bus] unique query_attributes[color]",
    "Objects filter_attributes[cyan] unique query_attributes[color]",
    "Objects unique start is_static",
])
def test_strict_references_must_be_unique(scene, lcfg, program):
    with pytest.raises(ProgramError, match="unique: [0-9] objects match"):
        execute(program, scene, lcfg, strict=True)


def test_strict_collision_moment_must_exist(scene, lcfg):
    program = f"Events {RED_SEDAN} filter_collision {FIGHTER} filter_collision unique get_frame {FIGHTER} is_static"
    with pytest.raises(ProgramError, match="unique: 0 collisions"):
        execute(program, scene, lcfg, strict=True)


@pytest.mark.parametrize("program,answer", [
    ("Objects filter_attributes[school_bus] unique query_attributes[color]", "red"),  # two: the more confident
    ("Objects filter_attributes[yellow] filter_attributes[regular_bus] unique query_attributes[shape]",
     "school_bus"),   # right colour and category, wrong sub-type: half a miss beats every other object
    ("Objects filter_attributes[purple] filter_attributes[sedan] unique query_attributes[shape]", "suv"),
    ("Objects filter_attributes[blue] filter_attributes[fighter] unique query_attributes[color]", "blue"),
])
def test_estimates_resolve_a_reference_to_the_closest_description(scene, lcfg, program, answer):
    """An estimated scene may match a description with no object or several; unique then takes the object with
    the fewest failed filters (a sub-type of the right category fails by half), then the most confident."""
    estimate = build_scene([replace(o, confidence=0.9 if o.id == 5 else 0.5) for o in scene.objects],
                           scene.velocity, scene.position[0], scene.visible)
    assert execute(program, estimate, lcfg) == answer


def test_start_is_the_configured_frame(scene):
    """'At the start' is labels.start_frame: the falling fighter, at rest in frame 0, is 1/6 s later 1.7 m/s fast."""
    lcfg = Config.load()["labels"]
    assert execute(f"{FIGHTER} start query_moving_velocity", scene, {**lcfg, "start_frame": 0}) == "static"
    assert lcfg["start_frame"] == 10
    assert execute(f"{FIGHTER} start query_moving_velocity", scene, lcfg) == "slow"


def test_estimates_resolve_a_missed_collision_to_the_closest_approach(scene, lcfg):
    """An estimate without the contact still answers "when X collides with Y" (the moment they come closest) and
    "what does X collide with" (the object that comes closest)."""
    estimate = build_scene(scene.objects, scene.velocity, scene.position[0], scene.visible)   # no collisions
    w = Executor(estimate, lcfg).world
    pair = OPS["filter_collision"].fn(w, OPS["filter_collision"].fn(w, w.events, Object(0)), Object(1))
    assert OPS["unique"].fn(w, pair).frame == w.closest(0, 1)[0]
    nearest = min((o for o in scene.objects if o.id != 0), key=lambda o: w.closest(0, o.id)[1])
    program = f"Events {RED_SEDAN} get_all_col_partners unique query_attributes[shape]"
    assert execute(program, estimate, lcfg) == nearest.shape
    with pytest.raises(ProgramError):   # strict mode (question generation) never resolves
        execute(program, estimate, lcfg, strict=True)


def test_estimates_take_the_first_of_several_collision_partners(scene, lcfg):
    """An estimate that gives an object several partners answers "what did X collide with" by the first of them,
    whatever the objects' ids and confidences; a filter after it still narrows the partners."""
    estimate = build_scene(scene.objects, scene.velocity, scene.position[0], scene.visible,
                           collisions=[Collision(20, 1, 4), Collision(45, 0, 1), Collision(50, 1, 4)])
    assert execute(f"Events {BUS} get_all_col_partners unique query_attributes[shape]", estimate, lcfg) == "suv"
    assert execute(f"Events {BUS} get_all_col_partners filter_attributes[sedan] unique query_attributes[color]",
                   estimate, lcfg) == "red"
    with pytest.raises(ProgramError):   # strict mode (question generation) asks only of an object with one partner
        execute(f"Events {BUS} get_all_col_partners unique query_attributes[shape]", estimate, lcfg, strict=True)


def test_frame_outside_the_scene(scene, lcfg):
    short = build_scene(scene.objects, scene.velocity[:10], scene.position[0], collisions=[Collision(45, 1, 4)])
    with pytest.raises(ProgramError, match="outside the scene"):
        execute(f"{BUS} Events {BUS} filter_collision unique get_frame is_static", short, lcfg)


def test_strict_mode_refuses_ambiguous_and_unseen(scene, lcfg):
    # the suv is out of view at frame 0; the sedan-bus collision guard makes "accelerating" ambiguous at frame 20
    with pytest.raises(AmbiguousLabel, match="out of view"):
        execute(f"{SUV} start query_moving_velocity", scene, lcfg, strict=True)
    assert execute(f"{SUV} start query_moving_velocity", scene, lcfg) == "slow"
    at_collision = f"Events {BUS} filter_collision {RED_SEDAN} filter_collision unique get_frame"
    with pytest.raises(AmbiguousLabel, match="accelerating"):
        execute(f"{BUS} {at_collision} is_accelerating", scene, lcfg, strict=True)
    # a filter over all objects touches every object's label: the unseen suv makes it unanswerable
    with pytest.raises(AmbiguousLabel):
        execute("Objects start filter_static unique query_attributes[color]", scene, lcfg, strict=True)
    # the bus (3 m/s) and the suv (2 m/s at frame 5) differ by less than the 1 m/s margin
    with pytest.raises(AmbiguousLabel, match="similar speeds"):
        execute(f"{BUS} {SUV} {SUV} come_in_frame faster_velocity", scene, lcfg, strict=True)
    assert execute(f"{BUS} {SUV} {SUV} come_in_frame faster_velocity", scene, lcfg) == "true"
    assert execute(f"{JET} {BUS} start faster_velocity", scene, lcfg, strict=True) == "true"


def test_truth_and_estimate_through_one_schema(scene, lcfg, tmp_path):
    """The executor reads a Scene4D: an estimate written as kind 'estimate' answers exactly as the truth."""
    scene.write(tmp_path / "e.mcap", kind="estimate")
    estimate = Scene4D.read(tmp_path / "e.mcap")
    for program, answer in CASES:
        assert execute(program, estimate, lcfg) == answer
