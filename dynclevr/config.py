"""pipeline.toml, merged with a user TOML, checked key by key against the defaults' types."""

from __future__ import annotations

import copy
import hashlib
import json
import tomllib
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from dynclevr import ROOT, DynclevrError

DEFAULT_CONFIG = ROOT / "pipeline.toml"


class ConfigError(DynclevrError):
    pass


def _load_toml(path: Path) -> dict:
    try:
        with open(path, "rb") as f:
            return tomllib.load(f)
    except FileNotFoundError:
        raise ConfigError(f"config file {path} not found: pass an existing TOML file to --config") from None
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as e:
        raise ConfigError(f"config file {path} is not valid TOML ({e}): fix the syntax") from None
    except OSError as e:   # a directory, no permission
        raise ConfigError(f"config file {path} cannot be read ({e.strerror}): pass a readable TOML file to --config") \
            from None


def _same_kind(default, value) -> bool:
    if isinstance(default, bool) or isinstance(value, bool):
        return isinstance(default, bool) and isinstance(value, bool)
    if isinstance(default, int):   # counts of frames, pixels, objects, steps: 2.5 of them means nothing
        return isinstance(value, int)
    if isinstance(default, float):
        return isinstance(value, (int, float))
    if isinstance(default, list):
        return isinstance(value, list) and len(value) == len(default) and all(
            _same_kind(d, v) for d, v in zip(default, value))
    return type(default) is type(value)


def _merge(base: dict, user: dict, where: str, source: Path) -> None:
    for key, value in user.items():
        name = f"{where}{key}"
        if where == "splits." and key not in base:
            if not isinstance(value, dict):
                raise ConfigError(f"{source}: '{name}' must be a table with seed and scenes")
            base[key] = dict(value)  # a new split: Config._check checks its shape
            continue
        if key not in base:
            raise ConfigError(f"{source}: unknown config key '{name}': remove it or check its spelling")
        if isinstance(base[key], dict):
            if not isinstance(value, dict):
                raise ConfigError(f"{source}: '{name}' must be a table")
            _merge(base[key], value, name + ".", source)
        elif not _same_kind(base[key], value):
            raise ConfigError(f"{source}: '{name}' = {value!r} has the wrong type: expected something like "
                              f"{base[key]!r}")
        else:
            base[key] = type(base[key])(value) if isinstance(base[key], float) else value


@dataclass(frozen=True)
class Split:
    name: str
    seed: int
    scenes: int

    def scene_names(self) -> list[str]:
        return [scene_name(i) for i in range(self.scenes)]


def scene_name(index: int) -> str:
    return f"{index:06d}"


def scene_seed(split_seed: int, index: int) -> int:
    """The one seed of scene `index`; every random draw of that scene comes from a generator seeded with it."""
    return int(np.random.SeedSequence([split_seed, index]).generate_state(1, dtype=np.uint64)[0])


class Config:
    """The merged configuration; sections are plain dicts (read-only by convention)."""

    def __init__(self, data: dict):
        self.data = data
        self._check()

    @classmethod
    def load(cls, user: Path | None = None) -> "Config":
        data = _load_toml(DEFAULT_CONFIG)
        if user is not None:
            _merge(data, _load_toml(Path(user)), "", Path(user))
        return cls(data)

    def __getitem__(self, section: str) -> dict:
        return self.data[section]

    def split(self, name: str | None) -> Split:
        name = name or self.data["default_split"]
        if name not in self.data["splits"]:
            known = ", ".join(sorted(self.data["splits"]))
            raise ConfigError(f"unknown split '{name}': use one of {known}, or add [splits.{name}] to a --config file")
        s = self.data["splits"][name]
        return Split(name, int(s["seed"]), int(s["scenes"]))

    def digest(self, *sections: str) -> dict:
        """The params a stage depends on (a deep copy, so a stage can store it in its manifest)."""
        return {s: copy.deepcopy(self.data[s]) for s in sections}

    def _check(self) -> None:
        for name, s in self.data["splits"].items():
            if set(s) != {"seed", "scenes"}:
                raise ConfigError(f"split '{name}' must have exactly 'seed' and 'scenes' (got {sorted(s)})")
            if not isinstance(s["scenes"], int) or isinstance(s["scenes"], bool) or s["scenes"] < 1:
                raise ConfigError(f"split '{name}': scenes = {s['scenes']!r} must be a positive integer")
            if not isinstance(s["seed"], int) or isinstance(s["seed"], bool) or s["seed"] < 0:
                raise ConfigError(f"split '{name}': seed = {s['seed']!r} must be a non-negative integer")
        positive = [("video", "fps"), ("video", "frames"), ("video", "observed_frames"), ("physics", "physics_hz"),
                    ("physics", "density"), ("render", "width"), ("render", "height"), ("scene", "min_objects")]
        for sec, key in positive:
            if self.data[sec][key] <= 0:
                raise ConfigError(f"'{sec}.{key}' = {self.data[sec][key]!r} must be positive")
        for sec, key in [("physics", "object_friction"), ("physics", "floor_friction"), ("physics", "restitution")]:
            if not 0 <= self.data[sec][key] <= 1:
                raise ConfigError(f"'{sec}.{key}' = {self.data[sec][key]!r} must lie in [0, 1]")
        if self.data["physics"]["physics_hz"] % self.data["video"]["fps"]:
            raise ConfigError("'physics.physics_hz' must be a multiple of 'video.fps' (whole substeps per frame)")
        if self.data["scene"]["max_objects"] < self.data["scene"]["min_objects"]:
            raise ConfigError("'scene.max_objects' must be at least 'scene.min_objects'")
        if self.data["scene"]["min_objects"] < 3:
            raise ConfigError("'scene.min_objects' must be at least 3 (one static, one slow, one fast object)")
        if self.data["video"]["observed_frames"] >= self.data["video"]["frames"]:
            raise ConfigError("'video.observed_frames' must be less than 'video.frames'")
        if self.data["imagine"]["counterfactuals"] not in ("replay", "resimulate"):
            raise ConfigError(f"'imagine.counterfactuals' = {self.data['imagine']['counterfactuals']!r}: use 'replay' "
                              "or 'resimulate'")
        im = self.data["imagine"]
        if not isinstance(im["future_samples"], int) or isinstance(im["future_samples"], bool) or \
                im["future_samples"] < 1:
            raise ConfigError(f"'imagine.future_samples' = {im['future_samples']!r} must be a positive integer")
        if not 0 < im["future_vote"] <= 1:
            raise ConfigError(f"'imagine.future_vote' = {im['future_vote']!r} must lie in (0, 1]")
        for key in ("future_velocity_sigma", "future_position_sigma", "future_yaw_sigma"):
            if im[key] < 0:
                raise ConfigError(f"'imagine.{key}' = {im[key]!r} must not be negative")
        for key in ("bootstrap_resamples", "bootstrap_seed"):
            if self.data["report"][key] < 0:
                raise ConfigError(f"'report.{key}' = {self.data['report'][key]!r} must not be negative")
        if self.data["render"]["backend"] not in ("tiny", "mitsuba"):
            raise ConfigError(f"'render.backend' = {self.data['render']['backend']!r}: use 'tiny' or 'mitsuba'")


def stable_digest(obj) -> str:
    """sha256 of a JSON-able object with sorted keys: the params part of a cache key."""
    return hashlib.sha256(json.dumps(obj, sort_keys=True, separators=(",", ":")).encode()).hexdigest()
