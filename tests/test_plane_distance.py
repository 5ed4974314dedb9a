"""The plane distance refiner: its crops, what it changes, its augmentation, its weights and its training run."""

import json
import math

import numpy as np
import pytest
import torch

from dynclevr.assets.catalogue import SUBTYPES
from dynclevr.camera import Camera
from dynclevr.colors import COLOR_NAMES
from dynclevr.perception.detector import Detection
from dynclevr.perception.plane_distance import (CROP, MARGIN, SCALE, PlaneDistanceNet, PlaneDistanceWeightsError,
                                                crop, half_side, load_plane_distance, plane_distance_digest, refine)
from dynclevr.perception.plane_distance_train import augment

from conftest import onehot

CAMERA = Camera((8.0, -7.0, 3.2), (0.0, 0.0, 1.3), 35.0, 32.0, 320, 240)
NAMES = list(SUBTYPES)
PLANE = next(n for n in NAMES if SUBTYPES[n][0] == "aeroplane")
CAR = next(n for n in NAMES if SUBTYPES[n][0] == "car")


def _det(shape: str, dist: float, u: float = 160.0, v: float = 120.0) -> Detection:
    return Detection(u=u, v=v, score=0.9, subtype_logp=onehot(len(NAMES), NAMES.index(shape)),
                     color_logp=onehot(len(COLOR_NAMES), 0), alpha=0.3, dist=dist, height=2.0)


def _constant_net(log_correction: float) -> PlaneDistanceNet:
    net = PlaneDistanceNet()
    last = net.mlp[-1]
    torch.nn.init.zeros_(last.weight)
    torch.nn.init.constant_(last.bias, log_correction / SCALE)
    return net.eval()


def test_the_crop_is_centred_on_the_detection_and_scaled_to_its_half_side():
    frame = np.zeros((240, 320, 3), np.uint8)
    frame[70:90, 90:110] = 255                      # a 20-pixel square centred on (100, 80)
    out = crop(frame, 100.0, 80.0, 20.0)            # 40 pixels across -> 64: the square is 32 across, centred
    rows, cols = np.nonzero(out[..., 0] > 127)
    assert out.shape == (CROP, CROP, 3)
    assert (rows.min(), rows.max(), cols.min(), cols.max()) == (16, 47, 16, 47)
    # beyond the frame's edge it is black, not the edge's pixels repeated
    assert crop(np.full((240, 320, 3), 200, np.uint8), 0.0, 0.0, 20.0)[:20, :20].max() == 0


def test_a_plane_twice_as_far_gets_a_crop_half_as_wide():
    near, far = half_side(CAMERA, _det(PLANE, 8.0)), half_side(CAMERA, _det(PLANE, 16.0))
    assert near == pytest.approx(2 * far)
    assert near == pytest.approx(MARGIN * CAMERA.fx * SUBTYPES[PLANE][1][0] / 2 / 8.0)


def test_only_the_planes_distances_are_read_again():
    frames = np.random.default_rng(0).integers(0, 255, (2, 240, 320, 3), dtype=np.uint8)
    dets = [[_det(PLANE, 10.0), _det(CAR, 9.0, u=60.0)], [_det(CAR, 12.0)]]
    out = refine(_constant_net(math.log(1.1)), frames, dets, CAMERA)
    assert out[0][0].dist == pytest.approx(11.0, rel=1e-5)
    assert out[0][1] == dets[0][1] and out[1][0] == dets[1][0]
    assert dets[0][0].dist == 10.0                  # the input is left as it was
    assert refine(_constant_net(0.5), frames, [[_det(CAR, 5.0)]], CAMERA)[0][0].dist == 5.0


def test_an_augmented_crop_tells_the_same_true_distance():
    rng = np.random.default_rng(1)
    x = rng.integers(0, 255, (16, CROP, CROP, 3), dtype=np.uint8)
    f = rng.normal(size=(16, PlaneDistanceNet().mlp[0].in_features - 128 * 16)).astype(np.float32)
    f[:, 1] = 0.4
    y = rng.normal(0, 0.03, 16).astype(np.float32)
    crops, f2, y2 = augment(x, f, y, torch.Generator().manual_seed(0))
    assert crops.shape == (16, 3, CROP, CROP)
    # the head's log distance plus the correction is the true log distance, whatever the zoom drew
    np.testing.assert_allclose((f2[:, 0] + y2).numpy(), f[:, 0] + y, atol=1e-5)
    # and the crop's size scales with the distance the head is taken to have read
    np.testing.assert_allclose((f2[:, 1] * torch.exp(f2[:, 0])).numpy(), f[:, 1] * np.exp(f[:, 0]), rtol=1e-5)
    assert not np.allclose(y2.numpy(), y)


def test_weights_missing_or_not_their_manifests_are_one_clear_line(tmp_path):
    with pytest.raises(PlaneDistanceWeightsError, match="plane distance weights missing .*plane_distance = false"):
        load_plane_distance(tmp_path)
    assert plane_distance_digest(tmp_path) == "missing"
    torch.save({"net": PlaneDistanceNet().state_dict()}, tmp_path / "plane_distance.pt")
    (tmp_path / "manifest.json").write_text(json.dumps({"weights_sha256": "0" * 64}))
    with pytest.raises(PlaneDistanceWeightsError, match="does not match its manifest"):
        load_plane_distance(tmp_path)


def test_a_tiny_training_run_records_its_curves_and_resumes(tmp_path):
    from dynclevr.config import Config, ConfigError
    from dynclevr.perception.plane_distance_train import train_plane_distance

    settings = ("[parser]\nplane_distance_first_shard = 0\nplane_distance_shards = 3\n"
                "plane_distance_heldout_shards = 1\ndetector_scenes_per_shard = 2\ndetector_frames_per_video = 3\n"
                "plane_distance_batch = 2\n")
    (tmp_path / "tiny.toml").write_text(settings + "plane_distance_epochs = 1\n")
    said = []
    first = train_plane_distance(Config.load(tmp_path / "tiny.toml"), tmp_path / "data", tmp_path / "out",
                                 echo=said.append)
    assert first["crops_train"] >= 2 and first["crops_heldout"] >= 1
    assert [c["epoch"] for c in first["heldout_curve"]] == [1]
    assert {"head_median", "refined_median", "refined_bias"} <= set(first["metrics_heldout"])
    with pytest.raises(ConfigError, match="trained 1 epochs already"):
        train_plane_distance(Config.load(tmp_path / "tiny.toml"), tmp_path / "data", tmp_path / "out", resume=True)
    (tmp_path / "tiny.toml").write_text(settings + "plane_distance_epochs = 2\n")
    again = train_plane_distance(Config.load(tmp_path / "tiny.toml"), tmp_path / "data", tmp_path / "out",
                                 resume=True, echo=said.append)
    assert [c["epoch"] for c in again["loss_curve"]] == [1, 2]
    assert any("resuming after epoch 1" in line for line in said)
    load_plane_distance(tmp_path / "out")           # the weights match their manifest


def test_bad_refiner_settings_are_one_clear_line(tmp_path):
    from dynclevr.config import Config, ConfigError
    from dynclevr.perception.plane_distance_train import shard_numbers

    for text, message in (("plane_distance_heldout_shards = 0", "must be a positive integer"),
                          ("plane_distance_first_shard = 838", "leaves no training shard"),
                          ("plane_distance_shards = 100000", "raise 'splits.parser-train.scenes'")):
        (tmp_path / "bad.toml").write_text(f"[parser]\n{text}\n")
        with pytest.raises(ConfigError, match=message):
            shard_numbers(Config.load(tmp_path / "bad.toml"))
