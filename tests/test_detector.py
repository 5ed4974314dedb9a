"""The detection head's targets and decoding, and 3D placement from the camera geometry."""

import json
import math

import numpy as np
import pytest
import torch

from dynclevr.assets.catalogue import SUBTYPES
from dynclevr.camera import Camera
from dynclevr.colors import COLOR_NAMES
from dynclevr.perception.detector import CHANNELS, OUT, STRIDE, Detection, DetectNet, decode, mirror, run
from dynclevr.perception.detector_data import LABEL_COLUMNS, azimuth
from dynclevr.perception.detector_train import COL, DetectorWeightsError, losses, targets
from dynclevr.perception.place import place, resting_height

from conftest import onehot

CAMERA = Camera((8.0, -7.0, 3.2), (0.0, 0.0, 1.3), 35.0, 32.0, 320, 240)
NAMES = list(SUBTYPES)


def _detection(pos, yaw, shape) -> Detection:
    (u, v), _ = CAMERA.project(np.asarray(pos))
    dist = float(np.linalg.norm(np.asarray(pos) - np.asarray(CAMERA.position)))
    return Detection(u=float(u), v=float(v), score=0.9, subtype_logp=onehot(len(NAMES), NAMES.index(shape)),
                     color_logp=onehot(len(COLOR_NAMES), 0), alpha=yaw - float(azimuth(CAMERA.position, pos)),
                     dist=dist, height=float(pos[2]))


def test_a_ground_vehicle_is_placed_on_the_ground_plane():
    pos = np.array([1.0, 2.0, resting_height("sedan")])
    det = _detection(pos, 0.7, "sedan")
    det.dist *= 1.3                      # the head's distance is off: the ground plane still pins the centre
    m = place(CAMERA, det)
    np.testing.assert_allclose(m.position, pos, atol=1e-6)
    assert not m.flying
    assert abs(m.yaw - 0.7) < 1e-6


def test_an_aeroplane_is_placed_at_the_heads_distance_in_the_air():
    pos = np.array([-2.0, 1.0, 2.7])
    m = place(CAMERA, _detection(pos, -2.5, "jet"))
    np.testing.assert_allclose(m.position, pos, atol=1e-6)
    assert m.flying and abs(m.yaw + 2.5) < 1e-6


def test_a_knocked_over_two_wheeler_is_placed_at_its_own_height():
    pos = np.array([1.5, -1.0, 0.26])    # a dirt bike on its side: its centre well under its resting height
    det = _detection(pos, 0.3, "dirtbike")
    standing = place(CAMERA, det, "dirtbike")
    lying = place(CAMERA, det, "dirtbike", height=0.26)
    np.testing.assert_allclose(lying.position, pos, atol=1e-6)
    assert lying.lying and not standing.lying
    # placed at the resting height, the ray meets that plane too far from the camera
    assert np.linalg.norm(standing.position - pos) > 0.5


def test_a_landed_aeroplane_is_pinned_by_the_ground_not_its_distance():
    pos = np.array([-1.0, 2.5, resting_height("biplane")])
    det = _detection(pos, 1.1, "biplane")
    det.dist *= 0.9                      # a tenth too near: a metre along the ray, above the floor
    flying, landed = place(CAMERA, det, "biplane"), place(CAMERA, det, "biplane", height=resting_height("biplane"))
    assert np.linalg.norm(flying.position - pos) > 0.5 and not flying.landed
    np.testing.assert_allclose(landed.position, pos, atol=1e-6)
    assert landed.landed and landed.flying and not landed.lying


def test_an_aeroplane_is_never_placed_under_the_floor():
    pos = np.array([0.5, 1.0, resting_height("jet") + 0.05])
    det = _detection(pos, 0.0, "jet")
    det.dist *= 1.3                      # the camera looks down: that far along the ray is under the floor
    m = place(CAMERA, det, "jet")
    assert abs(m.position[2] - resting_height("jet")) < 1e-6 and m.landed
    assert np.linalg.norm(m.position - pos) < 0.5


def test_measurement_covariance_is_loose_along_the_ray_only():
    m = place(CAMERA, _detection(np.array([0.0, 0.0, resting_height("suv")]), 0.0, "suv"))
    C = m.covariance(0.04, 0.25)
    along = m.ray @ C @ m.ray
    side = np.cross(m.ray, [0, 0, 1.0])
    side /= np.linalg.norm(side)
    assert along > 10 * (side @ C @ side)
    assert abs(side @ C @ side - 0.04 ** 2) < 1e-9


def _labels(rows):
    lab = np.zeros((len(rows), len(LABEL_COLUMNS)), np.float32)
    for i, r in enumerate(rows):
        for k, v in r.items():
            lab[i, COL[k]] = v
    return lab


def test_targets_decode_back_to_the_labels():
    lab = _labels([
        dict(u=101.3, v=77.9, pixels=900, subtype=5, color=2, alpha=1.0, logdist=math.log(9.0), height=0.6, radius=30),
        dict(u=250.6, v=160.2, pixels=400, subtype=17, color=7, alpha=-2.0, logdist=math.log(14.0), height=2.4,
             radius=20),
        dict(u=40.0, v=40.0, pixels=10, subtype=1, color=1, alpha=0.0, logdist=2.0, height=0.5, radius=15)])
    h, w = 240 // STRIDE, 320 // STRIDE
    tg = targets(lab, h, w)
    assert len(tg["cells"]) == 2                       # the third is hidden (10 pixels): neither positive ...
    assert tg["ignore"][round(40 / STRIDE - 0.5), round(40 / STRIDE - 0.5)]   # ... nor negative
    maps = _maps(tg, h, w)
    dets = sorted(decode(maps, 0.5), key=lambda d: d.u)
    assert len(dets) == 2
    for d, row in zip(dets, lab[:2]):
        assert abs(d.u - row[COL["u"]]) < 1e-4 and abs(d.v - row[COL["v"]]) < 1e-4
        assert int(np.argmax(d.subtype_logp)) == int(row[COL["subtype"]])
        assert int(np.argmax(d.color_logp)) == int(row[COL["color"]])
        assert abs(d.alpha - row[COL["alpha"]]) < 1e-5
        assert abs(math.log(d.dist) - row[COL["logdist"]]) < 1e-5 and abs(d.height - row[COL["height"]]) < 1e-5


def test_a_heads_pixel_offset_moves_every_decoded_centre():
    """A head trained on frames whose vehicles lay off their labels carries the offset in its manifest, and the
    decoded centres move by it (nothing else does)."""
    lab = _labels([dict(u=101.3, v=77.9, pixels=900, subtype=5, color=2, alpha=1.0, logdist=math.log(9.0),
                        height=0.6, radius=30)])
    h, w = 240 // STRIDE, 320 // STRIDE
    maps = _maps(targets(lab, h, w), h, w)
    (plain,), (moved,) = decode(maps, 0.5), decode(maps, 0.5, offset=(0.25, -0.44))
    assert moved.u == pytest.approx(plain.u + 0.25) and moved.v == pytest.approx(plain.v - 0.44)
    assert (moved.score, moved.alpha, moved.dist, moved.height) == (plain.score, plain.alpha, plain.dist, plain.height)


def _maps(tg: dict, h: int, w: int) -> torch.Tensor:
    """The maps [OUT, h, w] a perfect head would give for `targets`' output."""
    maps = torch.full((OUT, h, w), 0.0)
    maps[0] = torch.logit(torch.from_numpy(tg["heat"]).clamp(1e-4, 1 - 1e-4) * 0.999)
    for (r, c), g in zip(tg["cells"], tg["regs"]):
        maps[CHANNELS["offset"], r, c] = torch.tensor(g[:2])
        maps[CHANNELS["subtype"].start + int(g[2]), r, c] = 20.0
        maps[CHANNELS["color"].start + int(g[3]), r, c] = 20.0
        maps[CHANNELS["alpha"], r, c] = torch.tensor(g[4:6])
        maps[CHANNELS["logdist"], r, c] = float(g[6])
        maps[CHANNELS["height"], r, c] = float(g[7])
    return maps


def test_the_maps_of_a_mirrored_frame_mirror_back_to_the_frames_objects():
    lab = _labels([
        dict(u=101.3, v=77.9, pixels=900, subtype=5, color=2, alpha=1.0, logdist=math.log(9.0), height=0.6, radius=30),
        dict(u=250.6, v=160.2, pixels=400, subtype=17, color=7, alpha=-2.0, logdist=math.log(14.0), height=2.4,
             radius=20)])
    h, w = 240 // STRIDE, 320 // STRIDE
    seen = lab.copy()                      # the mirrored frame's labels, as detector_train.augment mirrors them
    seen[:, COL["u"]] = 320 - seen[:, COL["u"]]
    seen[:, COL["alpha"]] = -seen[:, COL["alpha"]]
    dets = sorted(decode(mirror(_maps(targets(seen, h, w), h, w)[None])[0], 0.5), key=lambda d: d.u)
    assert len(dets) == 2
    for d, row in zip(dets, lab):
        assert abs(d.u - row[COL["u"]]) < 1e-4 and abs(d.v - row[COL["v"]]) < 1e-4
        assert abs(d.alpha - row[COL["alpha"]]) < 1e-5
        assert int(np.argmax(d.subtype_logp)) == int(row[COL["subtype"]])


def test_the_head_read_both_ways_is_mirror_symmetric():
    torch.manual_seed(0)
    net = DetectNet(width=8)
    frames = np.random.default_rng(0).integers(0, 256, (3, 48, 64, 3), dtype=np.uint8)
    maps = run(net, frames, flip=True)
    assert torch.allclose(run(net, frames[:, :, ::-1], flip=True), mirror(maps), atol=1e-5)
    assert not torch.allclose(run(net, frames[:, :, ::-1]), mirror(run(net, frames)), atol=1e-3)


def test_an_out_of_view_centre_is_reached_through_the_offset():
    lab = _labels([dict(u=-12.0, v=100.0, pixels=300, subtype=0, color=0, alpha=0, logdist=2, height=2, radius=40)])
    tg = targets(lab, 60, 80)
    (r, c), g = tg["cells"][0], tg["regs"][0]
    assert c == 0 and (c + 0.5 + g[0]) * STRIDE == -12.0


def test_the_losses_train_the_net_and_fall_on_one_batch():
    torch.manual_seed(0)
    net = DetectNet(16)
    img = torch.rand(2, 3, 96, 128)
    lab = _labels([dict(u=50, v=40, pixels=500, subtype=3, color=4, alpha=0.5, logdist=2.3, height=0.7, radius=20)])
    opt = torch.optim.Adam(net.parameters(), 3e-3)
    first = None
    for _ in range(30):
        maps = net(img)
        parts = losses(maps, [targets(lab, maps.shape[2], maps.shape[3])] * 2)
        loss = sum(parts.values())
        first = first if first is not None else float(loss.detach())
        opt.zero_grad()
        loss.backward()
        opt.step()
    assert float(loss.detach()) < 0.5 * first


def _checkpoint(tmp_path, net: DetectNet, step: int = 100):
    from dynclevr.perception.detector_train import _save

    opt = torch.optim.AdamW(net.parameters())
    _save(net, opt, step, tmp_path, {"params": {}, "loss_curve": [], "heldout_curve": []})
    return tmp_path


def test_a_grown_head_computes_what_it_grew_from_and_then_learns_in_its_new_blocks(tmp_path):
    from dynclevr.perception.detector_train import _grown, load_detector

    torch.manual_seed(0)
    small = DetectNet(16)
    with torch.no_grad():          # BatchNorm statistics other than the defaults, as after training
        for m in small.modules():
            if isinstance(m, torch.nn.BatchNorm2d):
                m.running_mean.uniform_(-0.5, 0.5)
                m.running_var.uniform_(0.5, 2.0)
    big, step = _grown(_checkpoint(tmp_path, small.eval()), 16, 2, 1)
    img = torch.rand(2, 3, 96, 128)
    assert step == 100 and big.blocks == 2 and big.fine_blocks == 1
    assert torch.equal(small.eval()(img), big.eval()(img))
    big.train()
    big(img).square().mean().backward()
    assert big.s16[-1].b[1].weight.grad.abs().sum() > 0      # the zero scale is where learning starts
    assert big.fine[0].b[1].weight.grad.abs().sum() > 0
    # the grown head saves and loads as what it is
    _checkpoint(tmp_path, big, step)
    loaded = load_detector(tmp_path)
    assert (loaded.blocks, loaded.fine_blocks) == (2, 1)


def test_a_widened_head_computes_what_it_grew_from_and_its_copies_learn_apart(tmp_path):
    from dynclevr.perception.detector import widened
    from dynclevr.perception.detector_train import _grown, load_detector

    torch.manual_seed(0)
    small = DetectNet(16, blocks=1, fine_blocks=1)
    with torch.no_grad():          # trained-looking BatchNorms: the copies must carry their statistics too
        for m in small.modules():
            if isinstance(m, torch.nn.BatchNorm2d):
                m.running_mean.uniform_(-0.5, 0.5)
                m.running_var.uniform_(0.5, 2.0)
                m.weight.uniform_(0.5, 1.5)
    small.eval()
    img = torch.rand(2, 3, 96, 128)
    exact = widened(small, 24, torch.Generator().manual_seed(1), noise=0.0).eval()
    assert exact.width == 24 and sum(p.numel() for p in exact.parameters()) > sum(p.numel() for p in small.parameters())
    assert torch.allclose(small(img), exact(img), atol=1e-4)
    # through --grow-from: wider and deeper at once, near the old function (the copies' noise), then its own head
    big, step = _grown(_checkpoint(tmp_path, small), 24, 2, 1)
    assert (big.width, big.blocks, big.fine_blocks, step) == (24, 2, 1, 100)
    out, ref = big.eval()(img), small(img)
    assert (out - ref).abs().max() < 0.05 * ref.abs().max()
    # a new channel copies an old one; the noise touches the copies only, so they can learn apart
    noisy = widened(small, 24, torch.Generator().manual_seed(1)).s4[0][0].weight
    plain = exact.s4[0][0].weight
    assert any(torch.equal(plain[16], plain[j]) for j in range(16))
    assert torch.equal(noisy[:16], plain[:16]) and not torch.equal(noisy[16:], plain[16:])
    _checkpoint(tmp_path, big, step)
    assert load_detector(tmp_path).width == 24


def test_the_checkpoint_keeps_adams_moments_small_and_resumes_them_as_float32(tmp_path):
    from dynclevr.perception.detector_train import WEIGHTS_FILE, _save

    torch.manual_seed(0)
    net = DetectNet(8)
    opt = torch.optim.AdamW(net.parameters())
    for _ in range(2):
        net(torch.rand(2, 3, 32, 32)).square().mean().backward()
        opt.step()
    _save(net, opt, 2, tmp_path, {"params": {}, "loss_curve": [], "heldout_curve": []})
    saved = torch.load(tmp_path / WEIGHTS_FILE, weights_only=True)
    assert {v["exp_avg"].dtype for v in saved["opt"]["state"].values()} == {torch.bfloat16}
    again = torch.optim.AdamW(net.parameters())
    again.load_state_dict(saved["opt"])
    for k, state in again.state_dict()["state"].items():
        for key in ("exp_avg", "exp_avg_sq"):
            assert state[key].dtype == torch.float32
            assert torch.allclose(state[key], opt.state_dict()["state"][k][key], rtol=1e-2, atol=1e-12)


def test_growing_a_head_narrower_is_one_clear_line(tmp_path):
    from dynclevr.config import ConfigError
    from dynclevr.perception.detector_train import _grown

    path = _checkpoint(tmp_path, DetectNet(16))
    with pytest.raises(ConfigError, match="an even number of at least 16"):
        _grown(path, 8, 2, 0)
    with pytest.raises(ConfigError, match="an even number of at least 16"):
        _grown(path, 17, 0, 0)
    _checkpoint(tmp_path, DetectNet(16, fine_blocks=1))
    with pytest.raises(ConfigError, match="detector_fine_blocks at least 1"):
        _grown(path, 16, 0, 0)


def test_bad_growth_settings_are_one_clear_line_before_any_data_is_made(tmp_path):
    from dynclevr.config import Config, ConfigError
    from dynclevr.perception.detector_train import train_detector

    for key in ("detector_blocks", "detector_fine_blocks"):
        (tmp_path / "user.toml").write_text(f"[parser]\n{key} = -1\n")
        with pytest.raises(ConfigError, match=f"'parser.{key}' = -1 must be a non-negative integer"):
            train_detector(Config.load(tmp_path / "user.toml"), tmp_path / "data", tmp_path / "out")
    with pytest.raises(ConfigError, match="--resume and --grow-from exclude each other"):
        train_detector(Config.load(), tmp_path / "data", tmp_path / "out", resume=True, grow_from=tmp_path)
    assert not (tmp_path / "data").exists()


def test_a_run_reads_its_shards_from_the_first_one_and_holds_out_the_last():
    from dynclevr.config import Config, ConfigError
    from dynclevr.perception.detector_train import shards

    cfg = Config.load()
    cfg["parser"].update(detector_shards=10, detector_heldout_shards=2, detector_first_shard=3)
    assert shards(cfg) == [3, 4, 5, 6, 7, 8, 9]     # 3-7 train, 8 and 9 held out
    for first in (8, -1, 2.5, True):
        cfg["parser"]["detector_first_shard"] = first
        with pytest.raises(ConfigError, match=r"'parser.detector_first_shard' = .* must be an integer from 0 to 7"):
            shards(cfg)
    cfg["parser"].update(detector_first_shard=0, detector_heldout_shards=0)
    with pytest.raises(ConfigError, match="'parser.detector_heldout_shards' = 0 must be positive"):
        shards(cfg)
    # a shard past the split's last scene would be empty: one line, not a run on fewer frames than asked for
    cfg["parser"].update(detector_heldout_shards=2, detector_scenes_per_shard=50)
    cfg.data["splits"]["parser-train"]["scenes"] = 480
    with pytest.raises(ConfigError, match="needs 500 scenes, but split 'parser-train' has 480: raise "
                                          "'splits.parser-train.scenes'"):
        shards(cfg)


def test_a_shard_drawn_by_another_render_version_is_drawn_again(tmp_path):
    """Render version 1 drew vehicles half a pixel off their labels: its shards are not reused."""
    from dynclevr.perception.detector_data import _made_by

    old, new = tmp_path / "old.npz", tmp_path / "new.npz"
    np.savez(old, jpeg=np.zeros(1, np.uint8))
    np.savez(new, jpeg=np.zeros(1, np.uint8), render_version=2)
    assert not _made_by(old, 2) and _made_by(old, 1) and _made_by(new, 2) and not _made_by(tmp_path / "no.npz", 2)
    (tmp_path / "torn.npz").write_bytes(new.read_bytes()[:40])     # a damaged shard is drawn again, not read
    assert not _made_by(tmp_path / "torn.npz", 2)


def test_every_nth_shard_is_path_traced_and_kept_apart():
    from dynclevr.config import Config, ConfigError
    from dynclevr.perception.detector_data import shard_backend, shard_path

    cfg = Config.load()
    assert [shard_backend(cfg, s) for s in range(9)] == ["tiny"] * 9      # off by default
    cfg["parser"]["detector_realistic_every"] = 4
    assert [shard_backend(cfg, s) for s in range(9)] == ["tiny"] * 3 + ["mitsuba"] + ["tiny"] * 3 + ["mitsuba", "tiny"]
    split = cfg.split("parser-train")
    # the same scenes drawn by another backend never overwrite (or pass for) a TinyRenderer shard
    assert shard_path("d", split, 3, "mitsuba").parent.name == "detector-mitsuba"
    assert shard_path("d", split, 3, "tiny").parent.name == "detector"
    for bad in (-1, 2.5, True):
        cfg["parser"]["detector_realistic_every"] = bad
        with pytest.raises(ConfigError, match="'parser.detector_realistic_every' = .* must be a non-negative integer"):
            shard_backend(cfg, 0)


def _shard(path, frames: int = 3):
    import cv2

    rng = np.random.default_rng(0)
    jpegs = [cv2.imencode(".jpg", rng.integers(0, 255, (48, 64, 3), dtype=np.uint8))[1].tobytes()
             for _ in range(frames)]
    labels = [[k, 20.0 + k, 30.0, 400, 1, 2, 0.3, np.log(9.0), 0.5, 6.0] for k in range(frames)]
    with open(path, "wb") as f:
        np.savez(f, jpeg=np.frombuffer(b"".join(jpegs), np.uint8), offsets=np.cumsum([0] + [len(j) for j in jpegs]),
                 labels=np.array(labels, np.float32))
    return path


def test_the_batches_are_the_same_whatever_the_number_of_loader_processes(tmp_path):
    from dynclevr.perception.detector_train import Frames, Samples, _batches

    samples = Samples(Frames([_shard(tmp_path / "s.npz")]), seed=3, h=12, w=16)
    here = list(_batches(samples, 2, 4, batch=2, workers=0))
    loaders = list(_batches(samples, 2, 4, batch=2, workers=2))
    assert len(here) == len(loaders) == 2
    for (x, tg), (y, tg2) in zip(here, loaders):
        assert x.dtype == torch.uint8 and x.shape == (2, 48, 64, 3)
        assert torch.equal(x, y)
        for a, b in zip(tg, tg2):
            np.testing.assert_array_equal(a["heat"], b["heat"])
            np.testing.assert_array_equal(a["regs"], b["regs"])
    # a later step draws other samples
    assert not torch.equal(here[0][0], here[1][0])


def test_a_device_that_is_not_here_is_one_clear_line(tmp_path):
    from dynclevr.config import Config, ConfigError
    from dynclevr.perception.detector_train import train_detector

    if torch.cuda.is_available():
        pytest.skip("this machine has a GPU")
    with pytest.raises(ConfigError, match="--device cuda: no such device here; use cpu"):
        train_detector(Config.load(), tmp_path / "data", tmp_path / "out", device="cuda")
    with pytest.raises(ConfigError, match="--loader-workers -1"):
        train_detector(Config.load(), tmp_path / "data", tmp_path / "out", loader_workers=-1)
    assert not (tmp_path / "data").exists()


def test_a_tiny_training_run_records_how_often_it_drew_each_frame_and_resumes(tmp_path):
    from dynclevr.config import Config
    from dynclevr.perception.detector_train import load_detector, train_detector

    (tmp_path / "tiny.toml").write_text("[parser]\ndetector_shards = 2\ndetector_heldout_shards = 1\n"
                                        "detector_scenes_per_shard = 1\ndetector_frames_per_video = 2\n"
                                        "detector_width = 8\ndetector_batch = 2\n")
    cfg, said = Config.load(tmp_path / "tiny.toml"), []
    first = train_detector(cfg, tmp_path / "data", tmp_path / "out", steps=3, echo=said.append)
    assert first["runs"][-1]["draws_per_frame"] == 3.0        # 3 steps x 2 draws over 2 frames
    assert any("more shards would make the draws fresh frames" in line for line in said)
    again = train_detector(cfg, tmp_path / "data", tmp_path / "out", resume=True, steps=4, echo=said.append)
    assert [(r["from_step"], r["to_step"], r["draws_per_frame"]) for r in again["runs"]] == [(0, 3, 3.0), (3, 4, 1.0)]
    assert load_detector(tmp_path / "out").width == 8
    # a manifest's pixel offset is read with the weights, and training on (frames on their labels) drops it
    manifest = json.loads((tmp_path / "out" / "manifest.json").read_text())
    (tmp_path / "out" / "manifest.json").write_text(json.dumps({**manifest, "pixel_offset": [0.0, -0.44]}))
    assert load_detector(tmp_path / "out").pixel_offset == (0.0, -0.44)
    (tmp_path / "out" / "manifest.json").write_text(json.dumps({**manifest, "pixel_offset": "up"}))
    with pytest.raises(DetectorWeightsError, match="'pixel_offset' = 'up' must be two numbers"):
        load_detector(tmp_path / "out")
    (tmp_path / "out" / "manifest.json").write_text(json.dumps({**manifest, "pixel_offset": [0.0, -0.44]}))
    train_detector(cfg, tmp_path / "data", tmp_path / "out", resume=True, steps=5, echo=said.append)
    assert load_detector(tmp_path / "out").pixel_offset == (0.0, 0.0)
    # a head kept without its optimiser (checkpoints/) is grown from, not resumed: one clear line
    s = torch.load(tmp_path / "out" / "detector.pt", weights_only=True)
    del s["opt"]
    torch.save(s, tmp_path / "out" / "detector.pt")
    with pytest.raises(DetectorWeightsError, match="holds no optimiser state to resume: .*--grow-from"):
        train_detector(cfg, tmp_path / "data", tmp_path / "out", resume=True, steps=6, echo=said.append)
