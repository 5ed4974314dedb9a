"""The detection cache (perception/detections.py): exact round trip, reuse under its key, recovery from bad files."""

import numpy as np
import pytest
import torch

from dynclevr.perception import detections
from dynclevr.perception.detector import DetectNet, decode, run

from conftest import onehot


def _frames():
    rng = np.random.default_rng(0)
    return rng.integers(0, 255, (3, 48, 64, 3), dtype=np.uint8)


def _head():
    torch.manual_seed(0)
    net = DetectNet(width=8)
    with torch.no_grad():   # a head with peaks: the heatmap's bias up, so decode finds several per frame
        net.head[-1].bias[0] = 3.0
    return net


PARSER = {"detect_threshold": 0.3, "max_detections": 5, "detector_flip": True}


def _same(a, b):
    assert len(a) == len(b)
    for fa, fb in zip(a, b):
        assert len(fa) == len(fb)
        for da, db in zip(fa, fb):
            for k in ("u", "v", "score", "alpha", "dist", "height"):
                assert getattr(da, k) == getattr(db, k)
            np.testing.assert_array_equal(da.subtype_logp, db.subtype_logp)
            np.testing.assert_array_equal(da.color_logp, db.color_logp)


def test_detect_is_the_heads_decoded_maps():
    net, frames = _head(), _frames()
    dets = detections.detect(net, frames, PARSER)
    maps = run(net, frames, flip=True)
    _same(dets, [decode(m, 0.3, 5) for m in maps])
    assert sum(map(len, dets)) > 0


def test_cached_detections_round_trip_exactly_and_are_reused(tmp_path):
    net, frames = _head(), _frames()
    path, calls = tmp_path / "detections" / "000000.npz", []

    def compute():
        calls.append(1)
        return detections.detect(net, frames, PARSER)

    first = detections.cached(path, "k1", compute)
    again = detections.cached(path, "k1", compute)
    assert len(calls) == 1
    _same(first, again)
    detections.cached(path, "k2", compute)       # another video, head or setting: computed afresh
    assert len(calls) == 2 and detections.load(path, "k1") is None


def test_a_video_without_detections_round_trips(tmp_path):
    empty = [[], []]
    detections.save(tmp_path / "d.npz", "k", empty)
    assert detections.load(tmp_path / "d.npz", "k") == empty


@pytest.mark.parametrize("content", [b"", b"not a zip file", b"PK\x03\x04 truncated"])
def test_a_corrupt_cache_file_is_recomputed_and_replaced(tmp_path, content):
    path = tmp_path / "d.npz"
    path.write_bytes(content)
    det = [[detections.Detection(u=1.0, v=2.0, score=0.9, subtype_logp=onehot(3, 1), color_logp=onehot(2, 0),
                                 alpha=0.1, dist=5.0, height=0.4)]]
    assert detections.load(path, "k") is None
    _same(detections.cached(path, "k", lambda: det), det)
    _same(detections.load(path, "k"), det)


def test_the_key_holds_the_video_the_head_and_the_decode_settings(tmp_path):
    video = tmp_path / "v.mcap"
    video.write_bytes(b"frames")
    key = detections.cache_key(video, "head1", PARSER)
    assert key == detections.cache_key(video, "head1", dict(PARSER, refine=True))   # the tracker's own params: no
    assert key != detections.cache_key(video, "head2", PARSER)
    assert key != detections.cache_key(video, "head1", dict(PARSER, detector_flip=False))
    video.write_bytes(b"other frames")
    assert key != detections.cache_key(video, "head1", PARSER)
