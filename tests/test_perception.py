"""The scene parser: render-and-compare gradients, contrastive training, causality and honesty."""

import math
import shutil

import numpy as np
import pytest
import torch

from dynclevr.artifacts import ArtifactError
from dynclevr.camera import Camera
from dynclevr.config import Config
from dynclevr.perception.features import FeatureNet
from dynclevr.perception.collisions import CollisionModel
from dynclevr.perception.detector_train import load_detector
from dynclevr.perception.model import DEFAULT_DIR, ParserModel
from dynclevr.perception.neural_mesh import NeuralMeshes
from dynclevr.perception.pose import Evidence, fit, score
from dynclevr.perception.render import GridCamera, transform, visible
from dynclevr.perception.tracker import parse_video
from dynclevr.perception.train import contrastive_step, neighbours
from dynclevr.pipeline import Runner
from dynclevr.scene import CUT_FIELDS, Scene4D
from dynclevr.video import Video

from conftest import strip_video

CAMERA = Camera((8.0, -7.0, 3.2), (0.0, 0.0, 1.3), 35.0, 32.0, 320, 240)


def _splat(meshes: NeuralMeshes, pose: torch.Tensor, cam: GridCamera) -> torch.Tensor:
    """A feature map in which the mesh at `pose` shows its vertex features and the rest is clutter."""
    D = meshes.features.shape[-1]
    fmap = meshes.clutter[0][:, None].repeat(1, cam.H * cam.W)
    world = transform(meshes.points[[0]], pose[None])
    uv, depth = cam.project(world)
    vis = visible(uv, depth, cam.W, cam.H, joint=True)[0]
    cell = (uv[0, :, 1].round().long() * cam.W + uv[0, :, 0].round().long())[vis]
    acc = torch.zeros(D, cam.H * cam.W).index_add_(1, cell, meshes.features[0][vis].T)
    hit = acc.norm(dim=0) > 0
    fmap[:, hit] = torch.nn.functional.normalize(acc[:, hit], dim=0)
    return fmap.view(D, cam.H, cam.W)


def _smooth_meshes(vertices: int, dim: int) -> NeuralMeshes:
    """A sedan whose neural texture varies smoothly over the surface (as a trained one does), clutter apart."""
    meshes = NeuralMeshes.build(["sedan"], vertices, dim, 4, seed=0)
    g = torch.Generator().manual_seed(0)
    w, b = torch.randn(3, dim - 1, generator=g) * 1.2, torch.rand(dim - 1, generator=g) * 6.3
    feats = torch.cat([torch.cos(meshes.points[0] @ w + b), torch.ones(vertices, 1)], 1)
    meshes.features[0] = torch.nn.functional.normalize(feats, dim=1)
    meshes.clutter[:] = torch.nn.functional.normalize(torch.cat([torch.zeros(4, dim - 1), -torch.ones(4, 1)], 1), dim=1)
    return meshes


def test_render_and_compare_gradients_move_the_pose_to_the_truth():
    meshes = _smooth_meshes(128, 16)
    cam = GridCamera(CAMERA)
    truth = torch.tensor([0.5, 0.2, 0.5, 0.4, 0.0, 0.0])
    ev = Evidence.compute(_splat(meshes, truth, cam), meshes, [0], kappa=1.0)
    start = truth + torch.tensor([0.35, -0.3, 0.0, 0.15, 0.0, 0.0])
    mesh_idx = torch.tensor([0])
    before, _ = score(start[None], mesh_idx, ev, meshes, cam, joint=True)
    pose, after, _ = fit(start[None], mesh_idx, ev, meshes, cam, iterations=60, lr=0.05, joint=True)
    assert float(after) > float(before)
    err0 = float((start[:2] - truth[:2]).norm())
    err1 = float((pose[0, :2] - truth[:2]).norm())
    assert err1 < 0.4 * err0, (err0, err1)
    assert abs(float(pose[0, 3] - truth[3])) < 0.15   # started 0.15 off


def test_physics_prior_pulls_towards_its_mean_where_the_image_says_nothing():
    meshes = NeuralMeshes.build(["sedan"], 64, 16, 4, seed=0)
    cam = GridCamera(CAMERA)
    ev = Evidence(torch.zeros(64, cam.H * cam.W), torch.tensor([0]), cam.W, cam.H)   # no evidence at all
    mu = torch.tensor([[1.0, 0.0, 0.5, 0.0, 0.0, 0.0]])
    pose, _, _ = fit(torch.zeros(1, 6), torch.tensor([0]), ev, meshes, cam, 40, 0.05, True, prior_mean=mu,
                     sigma2=3.0)
    assert float(pose[0, 0]) > 0.5


def _frame_sample(rng):
    """A frame with one flat-coloured square object whose cells belong to 4 vertices, the rest background."""
    rgb = np.full((240, 320, 3), 90, np.uint8)
    rgb[80:160, 120:200] = [200, 40, 40]
    rgb[80:120, 120:160] = [40, 200, 40]
    uv = np.array([[r, c] for r in range(10, 20) for c in range(15, 25)], np.float32)[:, ::-1].copy()
    vert = ((uv[:, 1] >= 15).astype(int) * 2 + (uv[:, 0] >= 20).astype(int))
    bg = np.ones((30, 40), bool)
    bg[10:20, 15:25] = False
    heat = np.zeros((30, 40), np.float32)
    heat[15, 20] = 1
    return {"rgb": rgb, "mesh": np.zeros(len(uv), np.int64), "vert": vert.astype(np.int64), "uv": uv, "bg": bg,
            "heat": heat, "centres": [(20.0, 15.0, math.log(10.0), 1.0)], "colors": []}


def test_contrastive_training_step_lowers_the_loss():
    torch.manual_seed(0)
    rng = np.random.default_rng(0)
    meshes = NeuralMeshes.build(["sedan", "suv"], 16, 16, 4, seed=0)
    net = FeatureNet(16, 16)
    opt = torch.optim.Adam(net.parameters(), lr=3e-3)
    p = {"temperature": 0.1, "momentum": 0.9, "heatmap_weight": 1.0, "train_crop": [160, 120]}
    batch = [_frame_sample(rng)]
    neigh = neighbours(meshes, 0.01)
    first = contrastive_step(net, meshes, batch, neigh, p, rng)
    for _ in range(25):
        contrastive_step(net, meshes, batch, neigh, p, rng, opt)
    last = contrastive_step(net, meshes, batch, neigh, p, rng)
    assert last["loss_fg"] < first["loss_fg"] - 0.2
    assert last["loss_bg"] < first["loss_bg"]


# ---- on a tiny rendered split, with the shipped weights -----------------------------------------------------------

@pytest.fixture(scope="module")
def tiny(tmp_path_factory):
    """One short rendered scene: data dir, config."""
    root = tmp_path_factory.mktemp("tiny")
    user = root / "tiny.toml"
    user.write_text("[splits.ptiny]\nseed = 11\nscenes = 1\n\n[video]\nframes = 36\n")
    cfg = Config.load(user)
    data = root / "full"
    r = Runner(cfg, cfg.split("ptiny"), data)
    for stage in ("simulate", "render", "parse-scene"):
        r.run(stage, [0])
    return data, cfg, r


def _only_video(src_data, dst_data, strip: bool):
    """A data directory holding nothing but video/ (optionally without the mask and depth channels)."""
    src, dst = src_data / "ptiny" / "video", dst_data / "ptiny" / "video"
    dst.mkdir(parents=True)
    (dst_data / "ptiny" / "manifests").mkdir()
    shutil.copy(src_data / "ptiny" / "manifests" / "video.json", dst_data / "ptiny" / "manifests" / "video.json")
    if not strip:
        shutil.copy(src / "000000.mcap", dst / "000000.mcap")
        return
    strip_video(src / "000000.mcap", dst / "000000.mcap")


@pytest.mark.parametrize("strip", [False, True], ids=["video-only", "rgb-and-camera-only"])
def test_parse_scene_reads_only_the_video(tiny, tmp_path, strip):
    data, cfg, r = tiny
    expected = r.store.path("parse-scene", "000000", ".mcap").read_bytes()
    alone = tmp_path / "alone"
    _only_video(data, alone, strip)
    if strip:
        v = Video.read(alone / "ptiny" / "video" / "000000.mcap")
        with pytest.raises(ArtifactError):
            v.masks()
    Runner(cfg, cfg.split("ptiny"), alone).run("parse-scene", [0])
    # (beside the split's lock file, which holds no data)
    assert sorted(p.name for p in (alone / "ptiny").iterdir() if p.name != ".lock") == ["manifests", "parsed", "video"]
    assert sorted(p.name for p in (alone / "ptiny" / "manifests").iterdir()) == ["parsed.json", "video.json"]
    assert (alone / "ptiny" / "parsed" / "000000.mcap").read_bytes() == expected


def test_estimates_up_to_frame_30_ignore_later_frames(tiny):
    data, cfg, r = tiny
    video = Video.read(r.store.path("render", "000000", ".mcap"))
    frames = video.frames()
    model, detector = ParserModel.load(DEFAULT_DIR), load_detector()
    est = parse_video(frames, video.camera, model, detector, cfg, "000000", CollisionModel.load())
    altered = frames.copy()
    altered[31:] = altered[31:][::-1] // 2 + 60          # later frames: another story entirely
    alt = parse_video(altered, video.camera, model, detector, cfg, "000000", CollisionModel.load())
    assert est.objects, "the parser found nothing to compare"
    early = [i for i, o in enumerate(est.objects) if est.visible[:31, i].any()]
    assert [est.objects[i].shape for i in early] == [alt.objects[i].shape for i in early]
    assert [est.objects[i].color for i in early] == [alt.objects[i].color for i in early]
    assert [est.objects[i].engine_on for i in early] == [alt.objects[i].engine_on for i in early]
    for key in ("orientation", "acceleration", "floating", "visible"):
        np.testing.assert_array_equal(getattr(est, key)[:31, early], getattr(alt, key)[:31, early], err_msg=key)
    # The predictive questions start from the cut state, the filter's at the last observed frame; the factual
    # position, velocity and engine arrays are smoothed over the whole video (a factual question sees it all).
    for key in CUT_FIELDS:
        np.testing.assert_array_equal(est.cut_state[key][early], alt.cut_state[key][early], err_msg=key)
    # an event merges the contacts of the next merge_frames frames: the ones complete by frame 30 are fixed
    merge = cfg["labels"]["collision_merge_frames"]
    assert [c for c in est.collisions if c.frame + merge <= 30] == [c for c in alt.collisions if c.frame + merge <= 30]
    assert est.cut_collisions == alt.cut_collisions   # what the predictive questions know of the observed frames
    assert est.objects[0].confidence == alt.objects[0].confidence
    assert not np.array_equal(est.position[31:, early], alt.position[31:, early])
    assert isinstance(est, Scene4D)
