import subprocess
import sys

import pytest

from dynclevr.config import Config, ConfigError, scene_seed
from dynclevr.pipeline import parse_scenes


def write(tmp_path, text):
    p = tmp_path / "user.toml"
    p.write_text(text)
    return p


def test_user_split_and_override(tmp_path):
    cfg = Config.load(write(tmp_path, "[splits.mine]\nseed = 5\nscenes = 4\n[physics]\ngravity = 9\n"))
    assert cfg.split("mine").scenes == 4
    assert cfg["physics"]["gravity"] == 9.0 and isinstance(cfg["physics"]["gravity"], float)
    assert cfg.split("mine").scene_names() == ["000000", "000001", "000002", "000003"]


def test_the_shipped_realistic_config_renders_the_small_scenes_path_traced():
    """configs/realistic.toml (the README's realistic row) merges cleanly: the same scenes, another renderer."""
    from pathlib import Path

    base, real = Config.load(), Config.load(Path(__file__).parent.parent / "configs" / "realistic.toml")
    assert real["render"]["backend"] == "mitsuba" and base["render"]["backend"] == "tiny"
    assert real.split("small") == base.split("small")       # same seed and count: the same scenes
    assert real["scene"] == base["scene"] and real["physics"] == base["physics"]


def test_scene_seeds_depend_on_split_seed_and_index():
    assert scene_seed(1, 0) != scene_seed(2, 0)
    assert scene_seed(1, 0) != scene_seed(1, 1)
    assert scene_seed(1, 3) == scene_seed(1, 3)


@pytest.mark.parametrize("text, message", [
    ("[physics]\ngravty = 9.0\n", "unknown config key 'physics.gravty'"),
    ("[physics]\ngravity = 'strong'\n", "'physics.gravity' = 'strong' has the wrong type"),
    ("[physics]\nrestitution = 1.5\n", "'physics.restitution' = 1.5 must lie in \\[0, 1\\]"),
    ("[splits.x]\nseed = 1\nscenes = 0\n", "scenes = 0 must be a positive integer"),
    ("[render]\nbackend = 'povray'\n", "use 'tiny' or 'mitsuba'"),
    ("[imagine]\nfuture_samples = 0\n", "'imagine.future_samples' = 0 must be a positive integer"),
    ("[imagine]\nfuture_vote = 0.0\n", "'imagine.future_vote' = 0.0 must lie in \\(0, 1\\]"),
    ("[imagine]\nfuture_velocity_sigma = -0.1\n", "'imagine.future_velocity_sigma' = -0.1 must not be negative"),
    ("[report]\nbootstrap_resamples = -1\n", "'report.bootstrap_resamples' = -1 must not be negative"),
    ("[physics\n", "not valid TOML"),
])
def test_bad_config_values(tmp_path, text, message):
    with pytest.raises(ConfigError, match=message):
        Config.load(write(tmp_path, text))


def test_unknown_split():
    with pytest.raises(ConfigError, match="unknown split 'nope'"):
        Config.load().split("nope")


def test_scene_ranges():
    split = Config.load().split("small")
    assert parse_scenes("3-5", split) == [3, 4, 5]
    assert parse_scenes("0,2,7-8", split) == [0, 2, 7, 8]
    with pytest.raises(Exception, match="has scenes 0-"):
        parse_scenes("0-999", split)


def test_cli_bad_config_is_one_line(tmp_path):
    """A bad config value reaches the user as one clear line, not a traceback."""
    cfg = write(tmp_path, "[physics]\ngravity = 'strong'\n")
    out = subprocess.run([sys.executable, "-m", "dynclevr.cli", "status", "--config", str(cfg)],
                         capture_output=True, text=True)
    assert out.returncode == 2
    lines = out.stderr.strip().splitlines()
    assert len(lines) == 1 and "physics.gravity" in lines[0], out.stderr
