"""How far the accuracy table's numbers would move on another split of the same size: a bootstrap over its videos.

A split's questions are not independent draws. The questions about one video share its parse and its future, so one
bad parse turns many answers at once; resampling single questions would give intervals too narrow. Here whole videos
are resampled with replacement (a cluster bootstrap), each resample's columns computed as Table 1 computes them
(`stages.answer.table1`), and the 2.5th and 97.5th percentiles over the resamples are a 95% interval. Two rows
compared (a gain, an ablation) are resampled with the same videos, so the interval of their difference sees only the
questions where they differ: a paired comparison, much tighter than the two rows' own intervals.
"""

from __future__ import annotations

import warnings

import numpy as np

# The question groups Table 1's columns are made of, by (type, factual subtype).
GROUPS = (("factual", None), ("factual", "velocity"), ("factual", "acceleration"), ("factual", "collision"),
          ("predictive", None), ("counterfactual", None))
LEVEL = 0.95


def counts(answers: list[dict], videos: list[str]) -> np.ndarray:
    """[videos, groups, 2]: each video's questions right and asked, per group."""
    index = {v: k for k, v in enumerate(videos)}
    c = np.zeros((len(videos), len(GROUPS), 2))
    for a in answers:
        for g, (kind, sub) in enumerate(GROUPS):
            if a["type"] == kind and (sub is None or a["subtype"] == sub):
                c[index[a["scene"]], g] += (bool(a["correct"]), 1)
    return c


def columns(c: np.ndarray) -> np.ndarray:
    """Summed counts [..., groups, 2] -> Table 1's columns [..., 7] in % (report.COLUMNS; NaN where none asked)."""
    with np.errstate(invalid="ignore", divide="ignore"):
        acc = 100.0 * c[..., 0] / c[..., 1]
    average = acc[..., [0, 4, 5]].mean(-1, keepdims=True)   # the mean of the three question types, as Table 1's
    return np.concatenate([average, acc], -1)


def resample_weights(videos: int, resamples: int, seed: int) -> np.ndarray:
    """[resamples, videos]: how often each video is drawn in each resample (videos drawn with replacement)."""
    rng = np.random.default_rng(seed)
    draws = rng.integers(0, videos, size=(resamples, videos))
    return np.stack([np.bincount(d, minlength=videos) for d in draws]).astype(float)


def bootstrap(rows: dict[str, list[dict]], resamples: int, seed: int) -> dict[str, np.ndarray]:
    """Each row's columns [resamples, 7] over the same resampled videos (one set of draws for all rows: paired)."""
    videos = sorted({a["scene"] for answers in rows.values() for a in answers})
    w = resample_weights(len(videos), resamples, seed)
    return {name: columns(np.einsum("bv,vgk->bgk", w, counts(answers, videos))) for name, answers in rows.items()}


def interval(samples: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """[resamples, k] -> (low, high) [k] at LEVEL (Table 1's columns, or any figures); NaN for one that no resample
    has."""
    tail = 100.0 * (1.0 - LEVEL) / 2
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)   # an all-NaN column: its interval is NaN
        lo, hi = np.nanpercentile(samples, [tail, 100.0 - tail], axis=0)
    return lo, hi
