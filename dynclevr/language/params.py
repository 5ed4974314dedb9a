"""The [qparser] section of pipeline.toml, checked where it is read."""

from __future__ import annotations

from dataclasses import asdict, dataclass

from dynclevr.config import Config, ConfigError


@dataclass(frozen=True)
class QParserParams:
    embedding: int
    hidden: int
    layers: int
    dropout: float
    word_dropout: float
    epochs_max: int
    patience: int
    lr: float
    batch_size: int
    seed: int
    members: int
    max_decode_len: int
    examples_per_epoch: int
    val_examples: int
    max_unknown_words: int
    max_unknown_attention: float
    min_confidence: float

    def to_dict(self) -> dict:
        return asdict(self)

    @classmethod
    def from_dict(cls, d: dict) -> "QParserParams":
        names = set(cls.__dataclass_fields__)
        missing, unknown = names - set(d), set(d) - names
        if missing or unknown:
            raise ConfigError(f"[qparser]: missing keys {sorted(missing)}, unknown keys {sorted(unknown)}: "
                              "compare with pipeline.toml")
        ints = {"embedding": 1, "hidden": 1, "layers": 1, "epochs_max": 1, "patience": 1, "batch_size": 1,
                "seed": 0, "members": 1, "max_decode_len": 1, "max_unknown_words": 0, "examples_per_epoch": 1,
                "val_examples": 1}
        for key, low in ints.items():
            v = d[key]
            if not isinstance(v, int) or isinstance(v, bool) or v < low:
                raise ConfigError(f"'qparser.{key}' = {v!r} must be an integer >= {low}")
        for key, lo, hi in [("dropout", 0, 0.9), ("word_dropout", 0, 0.5), ("lr", 1e-6, 1.0),
                            ("min_confidence", 0, 1), ("max_unknown_attention", 0, 1)]:
            v = d[key]
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not lo <= v <= hi:
                raise ConfigError(f"'qparser.{key}' = {v!r} must be a number in [{lo}, {hi}]")
        return cls(**{k: d[k] for k in names})


def qparser_params(cfg: Config) -> QParserParams:
    try:
        section = cfg["qparser"]
    except KeyError:
        raise ConfigError("pipeline.toml has no [qparser] section: restore it from the repository") from None
    return QParserParams.from_dict(section)
