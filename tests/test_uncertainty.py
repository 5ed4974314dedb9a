"""The accuracy table's intervals: a bootstrap over videos whose columns are Table 1's."""

import math

import numpy as np
import pytest

from dynclevr.report import COLUMNS
from dynclevr.stages.answer import table1
from dynclevr.uncertainty import bootstrap, columns, counts, interval, resample_weights

KINDS = [("factual", "velocity"), ("factual", "acceleration"), ("factual", "collision"), ("predictive", ""),
         ("counterfactual", "")]


def answers(seed: int, videos: int = 12, per_video: int = 20, p: float = 0.8) -> list[dict]:
    rng = np.random.default_rng(seed)
    out = []
    for v in range(videos):
        for _ in range(per_video):
            kind, sub = KINDS[rng.integers(len(KINDS))]
            out.append({"scene": f"{v:06d}", "type": kind, "subtype": sub, "correct": bool(rng.random() < p)})
    return out


def test_each_video_once_gives_table1_exactly():
    rows = answers(0)
    videos = sorted({a["scene"] for a in rows})
    got = columns(counts(rows, videos).sum(0))
    want = [table1(rows)[c][0] for c in COLUMNS]
    assert np.allclose(got, want)


def test_resamples_draw_every_video_count_once_in_total_and_are_seeded():
    w = resample_weights(7, 50, seed=3)
    assert w.shape == (50, 7) and (w.sum(1) == 7).all()
    assert np.array_equal(w, resample_weights(7, 50, seed=3)) and not np.array_equal(w, resample_weights(7, 50, 4))


def test_a_row_against_itself_differs_by_exactly_zero_and_an_interval_holds_its_estimate():
    rows = answers(1)
    x = bootstrap({"a": rows, "b": rows}, resamples=200, seed=0)
    lo, hi = interval(x["a"] - x["b"])
    assert (lo == 0).all() and (hi == 0).all()
    lo, hi = interval(x["a"])
    point = [table1(rows)[c][0] for c in COLUMNS]
    assert (lo <= point).all() and (np.array(point) <= hi).all() and (hi - lo > 0).all()


def test_the_difference_of_paired_rows_is_tighter_than_either_row():
    """Two rows that disagree on a few questions: their difference's interval is far narrower than each row's own,
    because both are resampled with the same videos."""
    a = answers(2, videos=30)
    b = [dict(r, correct=r["correct"] if k % 50 else not r["correct"]) for k, r in enumerate(a)]
    x = bootstrap({"a": a, "b": b}, resamples=300, seed=0)
    own = np.subtract(*interval(x["a"]))[::-1]
    diff = np.subtract(*interval(x["a"] - x["b"]))[::-1]
    assert abs(own[0]) > 2 * abs(diff[0])


def test_all_right_is_exactly_100_and_a_type_never_asked_has_no_interval():
    rows = [r for r in answers(3, p=1.0) if r["type"] != "predictive"]
    lo, hi = interval(bootstrap({"a": rows}, resamples=100, seed=0)["a"])
    predictive = COLUMNS.index("Predictive")
    assert math.isnan(lo[predictive]) and math.isnan(hi[predictive])
    assert lo[COLUMNS.index("Vel")] == hi[COLUMNS.index("Vel")] == 100.0
    assert math.isnan(lo[0])   # the average of three types needs all three


@pytest.mark.parametrize("resamples", [1, 17])
def test_the_same_seed_gives_the_same_intervals(resamples):
    rows = answers(4)
    a = bootstrap({"a": rows}, resamples=resamples, seed=9)["a"]
    b = bootstrap({"a": rows}, resamples=resamples, seed=9)["a"]
    assert np.array_equal(a, b, equal_nan=True)
