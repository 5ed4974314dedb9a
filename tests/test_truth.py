"""The truth agrees with what a viewer sees (issue: dataset truth): contacts that touch on screen, counterfactual
runs that are pure functions of their initial state, questions only about what is visible, no ambiguous labels."""

import numpy as np
import pytest

from dynclevr.assets import collision
from dynclevr.assets.catalogue import SUBTYPES, get_asset
from dynclevr.camera import Camera
from dynclevr.config import Config
from dynclevr.physics import (Body, PhysicsParams, World, counterfactual, ground_height, simulate,
                              yaw_quaternion)
from dynclevr.questions.evidence import mask_gap, mesh_gap, pixel_counts
from dynclevr.questions.generate import scene_candidates, select
from dynclevr.questions.labels import compute_labels
from dynclevr.questions.programs import Executor
from dynclevr.render import make_renderer
from dynclevr.render.environments import environment
from dynclevr.scene import INTERVENTIONS, Scene4D, SceneObject
from dynclevr.stages.simulate import sample_scene, visibility


@pytest.fixture(scope="module")
def cfg():
    return Config.load()


@pytest.fixture(scope="module")
def params(cfg):
    return PhysicsParams.from_config(cfg)


def test_collision_shapes_are_committed_for_every_subtype_and_hug_the_mesh():
    for name in SUBTYPES:
        pieces = collision.load(name)
        half = np.asarray(get_asset(name).size) / 2
        assert len(pieces) >= 1 and all(np.all(np.abs(p) <= half + 1e-6) for p in pieces)
        # the lowest point is the mesh's bottom: a vehicle stands on its wheels
        assert min(p[:, 2].min() for p in pieces) == pytest.approx(-half[2], abs=1e-6)


def _scene(bodies, tr, camera) -> Scene4D:
    objs = [SceneObject(i, b.shape, SUBTYPES[b.shape][0], "red", get_asset(b.shape).size, 1.0, b.engine_on,
                        b.floating, "slow") for i, b in enumerate(bodies)]
    return Scene4D("000000", 60, camera, objs, tr.position, tr.orientation, tr.velocity, tr.angular_velocity,
                   tr.acceleration, tr.engine, tr.floating, visibility(camera, tr.position), collisions=tr.collisions)


@pytest.mark.parametrize("a,b", [("sedan", "suv"), ("mountain_bike", "school_bus"), ("jet", "truck")])
def test_masks_touch_at_the_collision_frame(params, cfg, a, b):
    """Two vehicles driven into each other in front of the camera: at the event frame their meshes are within a
    few centimetres and their masks touch (within 1 px)."""
    za = 1.2 if SUBTYPES[a][0] == "aeroplane" else ground_height(a)
    bodies = [Body(a, (-3.0, 0.3, za), yaw_quaternion(0.0), (6.0, 0.0, 0.0), floating=za > 1),
              Body(b, (2.0, 0.0, ground_height(b)), yaw_quaternion(np.pi / 2))]
    tr = simulate(bodies, params, 60)
    assert tr.collisions, "the vehicles must collide"
    camera = Camera((0.0, -14.0, 3.0), (0.0, 0.0, 0.8), 35.0, 32.0, 320, 240)
    scene = _scene(bodies, tr, camera)
    event = tr.collisions[0]
    assert mesh_gap(scene, event) < 0.1   # at 6 m/s a frame is 10 cm of travel
    with make_renderer("tiny", scene, camera, environment(0), [0, 0], cfg["render"]) as r:
        _, mask, _ = r.render(event.frame)
    assert mask_gap(mask, event.a, event.b) <= 1.0


def test_each_counterfactual_run_equals_a_clean_rerun_in_a_fresh_world(params, cfg):
    for seed in (11, 12, 13):
        _, bodies, _ = sample_scene(np.random.default_rng(seed), cfg)
        fresh = simulate(bodies, params, 120)
        with World(bodies, params) as world:
            runs = {(i, iv): counterfactual(bodies, i, iv, params, 120, world=world)
                    for i in range(len(bodies)) for iv in INTERVENTIONS}
            again = simulate(bodies, params, 120, world=world)
        np.testing.assert_array_equal(fresh.position, again.position)   # the factual run after all of them
        for (i, iv), run in runs.items():
            clean = counterfactual(bodies, i, iv, params, 120)
            assert (run is None) == (clean is None)
            if run is not None:
                assert (run.collisions, run.grazes) == (clean.collisions, clean.grazes), (seed, i, iv)


def test_pixel_counts_and_mask_gap():
    masks = np.full((2, 6, 8), -1, np.int16)
    masks[0, 1:3, 1:3] = 0
    masks[0, 1:3, 3:5] = 2          # touching object 0
    masks[1, 0:2, 0:2] = 0
    masks[1, 4:6, 6:8] = 2          # far apart
    np.testing.assert_array_equal(pixel_counts(masks, [0, 1, 2]), [[4, 0, 4], [4, 0, 4]])
    assert mask_gap(masks[0], 0, 2) == 0.0
    assert mask_gap(masks[1], 0, 2) > 3
    assert mask_gap(masks[1], 0, 1) == float("inf")


def _referents(program: str, ex: Executor) -> list[int]:
    """The object ids an "Objects filter... unique" chain of a program picks."""
    tokens, out, chain = program.split(), [], None
    for tok in tokens:
        if tok == "Objects":
            chain = [tok]
        elif chain is not None:
            chain.append(tok)
            if tok == "unique":
                if all(t == "Objects" or t.startswith("filter_attributes") or t == "unique" for t in chain):
                    out.append(_resolve(chain, ex))
                chain = None
    return out


def _resolve(chain: list[str], ex: Executor) -> int:
    from dynclevr.questions.programs import OPS, parse

    value = None
    for name, arg in parse(" ".join(chain)):
        fn = OPS[name].fn
        value = fn(ex.world) if name == "Objects" else (fn(ex.world, value, arg) if arg else fn(ex.world, value))
    return int(value)


def test_no_question_about_an_object_a_viewer_cannot_see(cfg, params):
    """An object hidden behind a bus for the whole video (centre in view, 0 pixels) is never asked about, and no
    question of a real scene refers to an object under the pixel threshold in its frames."""
    camera = Camera((0.0, -14.0, 3.0), (0.0, 0.0, 0.8), 35.0, 32.0, 320, 240)
    bodies = [Body("articulated_bus", (0.0, -2.0, ground_height("articulated_bus"))),
              Body("scooter", (0.0, 0.5, ground_height("scooter")), velocity=(0.3, 0.0, 0.0)),
              Body("sedan", (-4.0, -4.0, ground_height("sedan")), velocity=(3.0, 0.0, 0.0))]
    tr = simulate(bodies, params, 60)
    scene = _scene(bodies, tr, camera)
    with make_renderer("tiny", scene, camera, environment(0), [0, 0, 0], cfg["render"]) as r:
        masks = np.stack([r.render(t)[1] for t in range(60)])
    pixels = pixel_counts(masks, [0, 1, 2])
    assert scene.visible[:, 1].all() and pixels[:, 1].max() < cfg["labels"]["min_visible_pixels"]
    seen = (pixels >= cfg["labels"]["min_visible_pixels"]) & scene.visible
    qs, dropped = scene_candidates(scene, cfg["labels"], seed=0, seen=seen)
    ex = Executor(scene, cfg["labels"])
    assert qs and all(1 not in _referents(q["program"], ex) for q in qs)
    assert dropped and any(reason == "not visible" for _, reason in dropped)
    # the sedan's questions are there: it is seen
    assert any(0 not in _referents(q["program"], ex) and 2 in _referents(q["program"], ex) for q in qs)


def test_a_plane_resting_on_a_bus_is_not_floating(cfg, params):
    bus = Body("double_bus", (0.0, 0.0, ground_height("double_bus")))
    plane = Body("fighter", (0.0, 0.0, get_asset("double_bus").size[2] + 1.0))
    tr = simulate([bus, plane], params, 120)
    camera = Camera((0.0, -14.0, 3.0), (0.0, 0.0, 0.8), 35.0, 32.0, 320, 240)
    labels = compute_labels(_scene([bus, plane], tr, camera), cfg["labels"])
    bottom = tr.position[-1, 1, 2] - get_asset("fighter").size[2] / 2
    assert bottom > 1.5                                     # it lies on the bus's roof, high above the ground
    assert not labels.floating[-30:, 1].any() and not labels.floating_ambiguous[-30:, 1].any()


def test_counterfactual_balance_caps_copying_the_video(cfg):
    """80% of the candidates are answered by copying the video's outcome (as in the raw data); the selection
    keeps that share at most annotate.max_copy_share."""
    rng = np.random.default_rng(0)

    def question(scene: str) -> dict:
        answer = "true" if rng.random() < 0.5 else "false"
        factual = answer if rng.random() < 0.8 else {"true": "false", "false": "true"}[answer]
        return {"id": "", "scene": scene, "type": "counterfactual", "subtype": "collision",
                "family": "counterfactual_static", "text": "?", "program": "Objects exist", "answer": answer,
                "factual": factual}

    rows = {f"{s:06d}": [question(f"{s:06d}") for _ in range(4)] for s in range(60)}
    chosen = [q for q in select(rows, cfg["annotate"], seed=1) if q["family"] == "counterfactual_static"]
    same = np.mean([q["answer"] == q["factual"] for q in chosen])
    assert len(chosen) > 20 and same <= cfg["annotate"]["max_copy_share"] + 1e-9


def test_a_collision_shape_made_from_another_mesh_is_refused(tmp_path, monkeypatch):
    good = collision.path("sedan").read_text().splitlines()
    monkeypatch.setattr(collision, "DIR", tmp_path)
    collision.load.cache_clear()
    try:
        (tmp_path / "sedan.obj").write_text("\n".join(["# mesh sha256 0000", *good[1:]]))
        with pytest.raises(collision.CollisionShapeError, match="made from another mesh.*dynclevr.assets.collision"):
            collision.load("sedan")
        (tmp_path / "sedan.obj").unlink()
        with pytest.raises(collision.CollisionShapeError, match="is missing"):
            collision.load("sedan")
    finally:
        collision.load.cache_clear()
