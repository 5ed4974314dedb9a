"""The simulate stage: scene sampling, the truth it writes, caching and reruns, clear errors."""

import json
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from dynclevr import SCHEMA_DIR
from dynclevr.artifacts import ArtifactError, Store, read_parquet
from dynclevr.config import Config, ConfigError, scene_seed
from dynclevr.mcapio import McapIn, McapOut
from dynclevr.physics import PhysicsParams, World
from dynclevr.pipeline import Runner, parse_scenes
from dynclevr.scene import INTERVENTIONS, SCENE_SCHEMA, SCENE_VERSION, Scene4D
from dynclevr.stages import simulate

# Short videos keep the test quick; everything else is pipeline.toml's.
USER_TOML = """
[splits.t]
seed = 11
scenes = 6

[video]
frames = 60
observed_frames = 20
"""


def make_config(tmp_path, extra: str = "") -> Config:
    path = tmp_path / "user.toml"
    path.write_text(USER_TOML + extra)
    return Config.load(path)


def run(cfg: Config, data_dir, scenes: str | None = None, force: bool = False) -> list[str]:
    said = []
    r = Runner(cfg, cfg.split("t"), data_dir, echo=said.append)
    r.run("simulate", parse_scenes(scenes, r.split), force)
    return said


@pytest.fixture(scope="module")
def simulated(tmp_path_factory):
    """The t split simulated once: (config, data dir, what the runner said)."""
    tmp = tmp_path_factory.mktemp("sim")
    cfg = make_config(tmp)
    return cfg, tmp / "data", run(cfg, tmp / "data")


def test_cache_skip_and_rerun_rules(simulated, tmp_path):
    cfg, data, said = simulated
    assert said[0] == "simulate: 6 to run, 0 cached (unchanged inputs, params and version)"
    assert "simulate: wrote objects.parquet" in said
    assert run(cfg, data) == ["simulate: 0 to run, 6 cached (unchanged inputs, params and version)"]
    # A copy, so the module's data stays as first simulated.
    data2 = tmp_path / "data"
    shutil.copytree(data, data2)
    store = Store(data2, "t")
    before = {s: store.path("simulate", s, ".mcap").stat().st_mtime_ns for s in ("000000", "000004")}
    assert run(cfg, data2, "3-5", force=True)[0].startswith("simulate: 3 to run, 0 cached")
    assert store.path("simulate", "000000", ".mcap").stat().st_mtime_ns == before["000000"]
    assert store.path("simulate", "000004", ".mcap").stat().st_mtime_ns != before["000004"]
    # A changed physics parameter reruns every scene; a parameter of another stage does not, the image size does.
    changed = make_config(tmp_path, "\n[physics]\nfloor_friction = 0.5\n")
    assert run(changed, data2)[0].startswith("simulate: 6 to run, 0 cached")
    other = make_config(tmp_path, "\n[physics]\nfloor_friction = 0.5\n[labels]\nfast_above = 5.6\n")
    assert run(other, data2)[0].startswith("simulate: 0 to run, 6 cached")
    smaller = make_config(tmp_path, "\n[physics]\nfloor_friction = 0.5\n[render]\nwidth = 160\n")
    assert run(smaller, data2, "2")[0].startswith("simulate: 1 to run, 0 cached")


def test_same_seed_gives_identical_bytes(simulated, tmp_path):
    cfg, data, _ = simulated
    run(cfg, tmp_path / "again")
    a, b = Store(data, "t"), Store(tmp_path / "again", "t")
    for s in cfg.split("t").scene_names():
        assert a.path("simulate", s, ".mcap").read_bytes() == b.path("simulate", s, ".mcap").read_bytes()
    assert a.split_file("objects.parquet").read_bytes() == b.split_file("objects.parquet").read_bytes()


def _conforms(value, schema: dict, where: str) -> None:
    """The JSON Schema subset our schemas use: types, required keys, no extra keys, enums, fixed-size arrays."""
    if "enum" in schema:
        assert value in schema["enum"], where
        return
    kind = schema.get("type")
    if kind == "object":
        assert set(value) == set(schema["required"]) == set(schema["properties"]), where
        for k, v in value.items():
            _conforms(v, schema["properties"][k], f"{where}.{k}")
    elif kind == "array":
        assert isinstance(value, list), where
        assert schema.get("minItems", 0) <= len(value) <= schema.get("maxItems", 10**9), where
        for i, v in enumerate(value):
            _conforms(v, schema["items"], f"{where}[{i}]")
    else:
        py = {"integer": int, "number": (int, float), "boolean": bool, "string": str}[kind]
        assert isinstance(value, py) and (kind == "boolean" or not isinstance(value, bool)), where


def test_truth_content_and_schemas(simulated):
    cfg, data, _ = simulated
    store = Store(data, "t")
    total = 0
    for s in cfg.split("t").scene_names():
        path = store.path("simulate", s, ".mcap")
        scene = Scene4D.read(path)
        n = len(scene.objects)
        total += n
        assert cfg["scene"]["min_objects"] <= n <= cfg["scene"]["max_objects"]
        assert {"static", "slow", "fast"} <= {o.speed_class for o in scene.objects}
        assert scene.position.shape == (60, n, 3) and scene.visible.shape == (60, n)
        assert scene.future_collisions == [c for c in scene.collisions if c.frame >= 20]
        for o in scene.objects:
            i = scene.index(o.id)
            v0 = np.linalg.norm(scene.velocity[0, i, :2])
            assert v0 == pytest.approx({"static": 0.0, "slow": 3.0, "fast": 6.0}[o.speed_class], abs=1e-6)
            assert not (o.speed_class == "static" and o.engine_on)
            assert not (o.floating and o.category != "aeroplane")
            lo, hi = cfg["scene"]["plane_height"]
            z = scene.position[0, i, 2]
            assert lo <= z <= hi if o.category == "aeroplane" else z == pytest.approx(o.size[2] / 2, abs=2e-3)
            # Each intervention that changes the object has its run; floating only for aeroplanes.
            expect = {iv for iv in INTERVENTIONS if iv != o.speed_class}
            expect -= {"accelerating"} if o.engine_on else set()
            expect -= {"floating"} if o.category != "aeroplane" or o.floating else set()
            assert {iv for (oid, iv) in scene.counterfactuals if oid == o.id} == expect
        # Every dynclevr.* message conforms to its JSON Schema; the Foxglove channels hold one message per frame.
        src = McapIn(path, SCENE_SCHEMA, SCENE_VERSION)
        counts = {}
        for topic, _, msg in src.messages():
            counts[topic] = counts.get(topic, 0) + 1
            if isinstance(msg, dict):
                name = {"/scene/camera": "Camera", "/scene/objects": "ObjectCatalogue", "/scene/states": "FrameStates",
                        "/scene/collisions": "CollisionEvents", "/scene/future_collisions": "CollisionEvents",
                        "/scene/grazes": "CollisionEvents",
                        "/scene/counterfactuals": "CounterfactualOutcomes"}[topic]
                _conforms(msg, json.loads((SCHEMA_DIR / f"dynclevr.{name}.json").read_text()), topic)
        assert counts["/tf"] == counts["/scene/vehicles"] == counts["/scene/states"] == 60
    table = read_parquet(store.split_file("objects.parquet"), simulate.OBJECTS_SCHEMA, simulate.OBJECTS_VERSION)
    assert table.num_rows == total and table.schema.remove_metadata() == simulate.OBJECTS_FIELDS


def test_spawns_do_not_overlap_and_collisions_are_common():
    cfg = Config.load()
    params = PhysicsParams.from_config(cfg)
    collided = 0   # scenes with a contact within the first second
    for i in range(12):
        objects, bodies, camera = simulate.sample_scene(np.random.default_rng(scene_seed(5, i)), cfg)
        with World(bodies, params) as world:
            world.client.performCollisionDetection()
            touching = [c for c in world.client.getContactPoints() if c[1] in world.ids and c[2] in world.ids]
            assert touching == []
            collided += any(world.step_frame() for _ in range(59))
        # Objects start in or near the view.
        assert simulate.visibility(camera, np.array([b.position for b in bodies])).mean() >= 0.5
    assert collided >= 6


def test_stats_table(simulated):
    cfg, data, _ = simulated
    table = simulate.stats(Store(data, "t"), cfg)
    assert "| videos with >= 1 collision |" in table and "| counterfactual runs whose collision set differs |" in table
    assert "| scenes | 6 |" in table


def test_corrupt_and_wrong_version_files_give_clear_errors(simulated, tmp_path):
    cfg, data, _ = simulated
    shutil.copytree(data, tmp_path / "data")
    store = Store(tmp_path / "data", "t")
    path = store.path("simulate", "000001", ".mcap")
    path.write_bytes(path.read_bytes()[:5000])
    with pytest.raises(ArtifactError, match=r"000001.mcap is (not a readable MCAP file|corrupt).*"
                                            r"rerun `dynclevr simulate --split t --scenes 1 --data-dir ") as e:
        simulate.stats(store, cfg)
    assert "\n" not in str(e.value)
    with McapOut(path, SCENE_SCHEMA, SCENE_VERSION + 1):
        pass
    with pytest.raises(ArtifactError,
                       match=rf"v{SCENE_VERSION + 1}, expected dynclevr.scene4d v{SCENE_VERSION}: rerun `dynclevr "
                             r"simulate --split t --scenes 1 --data-dir "):
        simulate.stats(store, cfg)


def test_bad_config_value_is_one_line(tmp_path):
    with pytest.raises(ConfigError, match=r"'scene.p_engine_on' = 1.5 must lie in \[0, 1\]"):
        simulate.params(make_config(tmp_path, "\n[scene]\np_engine_on = 1.5\n"))
    (tmp_path / "bad.toml").write_text(USER_TOML + "\n[physics]\nfast_speed = 2.0\n")
    out = subprocess.run([str(Path(sys.executable).parent / "dynclevr"), "simulate", "--split", "t", "--config",
                          str(tmp_path / "bad.toml"), "--data-dir", str(tmp_path / "d")],
                         capture_output=True, text=True)
    assert out.returncode == 2
    assert out.stderr.strip() == "error: 'physics.fast_speed' must be greater than 'physics.slow_speed'"
