"""The object head: its window geometry, its training targets, the cascade, and its weights and settings."""

import math

import numpy as np
import pytest
import torch
from hypothesis import given, settings
from hypothesis import strategies as st

from dynclevr.config import Config, ConfigError
from dynclevr.perception.detector import N_COL, N_SUB, STRIDE, Detection
from dynclevr.perception.detector_data import LABEL_COLUMNS
from dynclevr.perception.detector_train import COL
from dynclevr.perception.object_head import (CHANNELS, OUT, ROI, SIZE, SPAN, ObjectNet, TwoStage, refine, roi_grid,
                                             sample, window_scale)
from dynclevr.perception.object_head_train import (ObjectHeadWeightsError, fx_of, load_object_head, load_two_stage,
                                                   losses, windows)

FX = 350.0


def _coordinate_map(h: int = 60, w: int = 80) -> torch.Tensor:
    """A feature map [1, 2, h, w] whose channels are the frame x and y of each cell's centre (stride 4)."""
    ys, xs = np.mgrid[0:h, 0:w] * STRIDE + STRIDE / 2
    return torch.from_numpy(np.stack([xs, ys])[None].astype(np.float32))


@settings(max_examples=25, deadline=None)
@given(st.floats(80, 240), st.floats(70, 170), st.floats(0.6, 2.0))
def test_the_window_samples_an_even_grid_centred_on_its_point_at_its_scale(u, v, scale):
    roi = sample(_coordinate_map(), np.array([0]), roi_grid(np.array([u]), np.array([v]), np.array([scale]),
                                                            320, 240))[0].numpy()
    step = SIZE / scale / ROI
    assert abs(roi[0].mean() - u) < 1e-3 and abs(roi[1].mean() - v) < 1e-3
    np.testing.assert_allclose(np.diff(roi[0], axis=1), step, atol=1e-3)
    np.testing.assert_allclose(np.diff(roi[1], axis=0), step, atol=1e-3)


def test_the_window_spans_span_metres_at_the_detections_distance():
    for dist in (5.0, 11.0, 20.0):
        assert math.isclose(SIZE / window_scale(FX, dist), FX * SPAN / dist)


def test_training_targets_point_from_the_window_back_to_the_true_object():
    lab = np.zeros((200, len(LABEL_COLUMNS)), np.float32)
    lab[:, COL["u"]], lab[:, COL["v"]], lab[:, COL["logdist"]] = 160.0, 110.0, math.log(9.0)
    lab[:, COL["subtype"]], lab[:, COL["color"]], lab[:, COL["alpha"]], lab[:, COL["height"]] = 3, 2, 0.4, 0.6
    u, v, scale, tg = windows(lab, FX, np.random.default_rng(0))
    np.testing.assert_allclose(u + tg[:, 0] / scale, 160.0, atol=1e-3)
    np.testing.assert_allclose(v + tg[:, 1] / scale, 110.0, atol=1e-3)
    np.testing.assert_allclose(scale * FX * SPAN / SIZE * np.exp(tg[:, 2]), 9.0, rtol=1e-5)   # window dist x ratio
    assert (tg[:, 3] == 3).all() and (tg[:, 4] == 2).all() and np.allclose(tg[:, 5], math.sin(0.4))
    assert 1.0 < np.median(np.abs(tg[:, :2])) < 3.0          # a few window pixels off, as the head is


class _Shift(torch.nn.Module):
    """A stand-in head that always answers: 2 window pixels right, the distance 10% nearer, sub-type 5."""

    def eval(self):
        return self

    def forward(self, x):
        out = torch.zeros(len(x), OUT)
        out[:, CHANNELS["offset"]] = torch.tensor([2.0, 0.0])
        out[:, CHANNELS["logratio"]] = math.log(0.9)
        out[:, CHANNELS["subtype"].start + 5] = 10.0
        out[:, CHANNELS["alpha"]] = torch.tensor([1.0, 0.0])
        return out


def test_the_cascade_moves_a_detection_by_each_passs_answer_at_that_passs_scale():
    det = Detection(u=100.0, v=80.0, score=0.8, subtype_logp=np.zeros(N_SUB), color_logp=np.zeros(N_COL),
                    alpha=0.0, dist=10.0, height=0.5)
    hidden = torch.zeros(2, 4, 60, 80)
    out = refine(_Shift(), hidden, [[det], []], FX, passes=2)
    s1, s2 = window_scale(FX, 10.0), window_scale(FX, 9.0)
    assert out[1] == [] and len(out[0]) == 1
    d = out[0][0]
    assert math.isclose(d.u, 100.0 + 2.0 / s1 + 2.0 / s2) and math.isclose(d.v, 80.0)
    assert math.isclose(d.dist, 10.0 * 0.81) and math.isclose(d.alpha, math.pi / 2)
    assert int(np.argmax(d.subtype_logp)) == 5 and d.score == 0.8


def test_the_losses_fall_on_one_batch():
    torch.manual_seed(0)
    net = ObjectNet(4, 12)
    x = torch.rand(6, 4, ROI, ROI)
    g = torch.tensor([[1.0, -2.0, 0.05, 3, 1, 0.0, 1.0, 0.5]] * 6)
    opt = torch.optim.Adam(net.parameters(), 1e-2)
    first = None
    for _ in range(30):
        loss = sum(losses(net(x), g).values())
        first = float(loss.detach()) if first is None else first
        opt.zero_grad()
        loss.backward()
        opt.step()
    assert float(loss.detach()) < 0.5 * first


def test_without_the_object_head_detection_is_the_heads_alone():
    cfg = Config.load()
    cfg.data["parser"]["object_head"] = False
    two = load_two_stage(cfg)
    assert isinstance(two, TwoStage) and two.objects is None
    assert math.isclose(fx_of(cfg), 350.0)


def test_missing_or_altered_object_head_weights_are_one_clear_line(tmp_path):
    with pytest.raises(ObjectHeadWeightsError, match="missing.*dynclevr train object-head"):
        load_object_head(tmp_path)
    cfg = Config.load()
    cfg.data["parser"]["object_head"] = "yes"
    with pytest.raises(ConfigError, match="parser.object_head"):
        load_two_stage(cfg)
