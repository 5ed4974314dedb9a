"""The render stage: geometry of masks and depth against the recorded calibration, appearance, determinism, cache."""

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from dynclevr.artifacts import Store
from dynclevr.camera import Camera
from dynclevr.colors import COLOR_NAMES
from dynclevr.config import Config
from dynclevr.pipeline import Runner
from dynclevr.render import environments
from dynclevr.render.appearance import VARIANTS, body_material, nearest_color
from dynclevr.scene import Scene4D, SceneObject
from dynclevr.stages.render import appearance, render_scene
from dynclevr.video import Video


@pytest.fixture(scope="module")
def spread_scene() -> Scene4D:
    """Three vehicles far apart in the image, turning and driving, so none occludes another."""
    T = 12
    objs = [SceneObject(0, "sedan", "car", "red", (3.0, 1.3, 1.0), 10.0, False, False, "slow"),
            SceneObject(1, "school_bus", "bus", "yellow", (3.8, 1.3, 1.6), 20.0, False, False, "static"),
            SceneObject(2, "suv", "car", "blue", (2.8, 1.4, 1.3), 12.0, True, False, "fast")]
    start = np.array([[1.0, -3.0, 0.5], [-4.0, 3.0, 0.8], [2.0, 4.0, 0.65]])
    vel = np.array([[3.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, -6.0, 0.0]])
    t = np.arange(T)[:, None, None] / 60
    pos = start[None] + vel[None] * t
    yaw = np.array([0.3, 2.0, -1.6])[None, :] + np.arange(T)[:, None] * np.array([0.02, 0.0, -0.03])
    quat = Rotation.from_euler("z", yaw.reshape(-1, 1)).as_quat().reshape(T, 3, 4)
    cam = Camera((8.3, -6.8, 3.4), (0.0, 0.0, 1.3), 35.0, 32.0, 320, 240)
    z = np.zeros((T, 3, 3))
    return Scene4D("000000", 60, cam, objs, pos, quat, np.broadcast_to(vel, (T, 3, 3)).copy(), z, z,
                   np.zeros((T, 3), bool), np.zeros((T, 3), bool), np.ones((T, 3), bool), observed_frames=4)


@pytest.fixture(scope="module")
def rendered(spread_scene, tmp_path_factory) -> Video:
    path = tmp_path_factory.mktemp("video") / "000000.mcap"
    render_scene(spread_scene, 11, Config.load(), path)
    return Video.read(path)


def _box_corners(scene: Scene4D, t: int, i: int) -> np.ndarray:
    half = np.array(scene.objects[i].size) / 2
    corners = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)]) * half
    R = Rotation.from_quat(scene.orientation[t, i]).as_matrix()
    return corners @ R.T + scene.position[t, i]


def test_video_reader_api(rendered, spread_scene):
    assert rendered.num_frames == spread_scene.num_frames
    assert rendered.camera == spread_scene.camera.with_resolution(320, 240)
    frames, masks, depth = rendered.frames(), rendered.masks(), rendered.depth()
    assert frames.shape == (12, 240, 320, 3) and frames.dtype == np.uint8
    assert masks.shape == (12, 240, 320) and masks.dtype == np.int16
    assert depth.shape == (12, 240, 320) and depth.dtype == np.float32
    assert set(np.unique(masks)) == {-1, 0, 1, 2}
    assert np.isinf(depth[masks < 0]).any() and np.isfinite(depth[masks >= 0]).all()   # sky has no depth
    assert rendered.frames(slice(3, 5)).shape[0] == 2


def test_centre_projects_into_own_mask_and_depth_matches(rendered, spread_scene):
    """The recorded calibration projects each object's true centre inside its own mask; the depth there lies
    between the object's front surface and its centre; the mask stays inside the projected bounding box."""
    cam, masks, depth = rendered.camera, rendered.masks(), rendered.depth()
    for t in range(0, spread_scene.num_frames, 3):
        for i, o in enumerate(spread_scene.objects):
            (u, v), z = cam.project(spread_scene.position[t, i])
            assert masks[t, int(v), int(u)] == o.id, (t, o.id)
            d = depth[t, int(v), int(u)]
            assert z - np.linalg.norm(o.size) / 2 <= d <= z + 0.05, (t, o.id, d, z)
            uv, _ = cam.project(_box_corners(spread_scene, t, i))
            ys, xs = np.nonzero(masks[t] == o.id)
            assert xs.min() >= uv[:, 0].min() - 1.5 and xs.max() <= uv[:, 0].max() + 1.5
            assert ys.min() >= uv[:, 1].min() - 1.5 and ys.max() <= uv[:, 1].max() + 1.5
            # and fills it: a wrong orientation or scale would leave a much smaller silhouette
            assert xs.max() - xs.min() > 0.6 * np.ptp(uv[:, 0])


def _coverage_centroid(coverage: np.ndarray) -> np.ndarray:
    """(u, v) of an image's coverage-weighted centre, pixel centres at half-integers as the calibration has them."""
    v, u = np.mgrid[0:coverage.shape[0], 0:coverage.shape[1]] + 0.5
    return np.array([(coverage * u).sum(), (coverage * v).sum()]) / coverage.sum()


@pytest.mark.parametrize("supersample", [1, 2])
def test_vehicles_are_drawn_where_the_calibration_projects_them(supersample):
    """A sphere rasterised through the fast backend's view and projection (at its supersampling, area-averaged as
    the backend averages) is centred where the recorded calibration projects its centre, to a tenth of a pixel
    (TinyRenderer samples pixel corners: without the half-pixel terms of gl_projection it lands 0.5 px off)."""
    from dynclevr.physics import p
    from dynclevr.render.tiny import gl_projection, gl_view

    cam = Camera((0.0, -10.0, 3.0), (0.0, 0.0, 0.5), 35.0, 36.0, 160, 120)
    hi = cam.with_resolution(cam.width * supersample, cam.height * supersample)
    client = p.connect(p.DIRECT)
    try:
        for centre in ((0.0, 0.0, 0.5), (2.0, 1.0, 0.5), (-3.0, 2.0, 1.0)):
            body = p.createMultiBody(0, -1, p.createVisualShape(p.GEOM_SPHERE, radius=0.4, physicsClientId=client),
                                     basePosition=centre, physicsClientId=client)
            seg = p.getCameraImage(hi.width, hi.height, gl_view(hi), gl_projection(hi),
                                   renderer=p.ER_TINY_RENDERER, physicsClientId=client)[4]
            inside = (np.asarray(seg).reshape(hi.height, hi.width) == body).astype(float)
            coverage = inside.reshape(cam.height, supersample, cam.width, supersample).mean((1, 3))
            uv, _ = cam.project(np.array(centre))
            assert np.abs(_coverage_centroid(coverage) - uv).max() < 0.1, (centre, _coverage_centroid(coverage), uv)
            p.removeBody(body, physicsClientId=client)
    finally:
        p.disconnect(client)


def test_shadows_are_drawn_where_the_calibration_projects_them(spread_scene):
    """A square on the ground, drawn as the fast backend draws shadows (cv2, pixel centres at integers), is centred
    where the calibration projects its centre, to a tenth of a pixel."""
    from dynclevr.render.tiny import TinyRenderer

    cam = spread_scene.camera
    with TinyRenderer(spread_scene, cam, environments.environment(0), [0, 0, 0]) as r:
        img = np.zeros((cam.height, cam.width), np.uint8)
        square = np.array([[sx, sy, 0.0] for sx, sy in ((-0.2, -0.2), (0.2, -0.2), (0.2, 0.2), (-0.2, 0.2))])
        r._fill(img, square, 16)
    uv, _ = cam.project(np.zeros(3))
    assert np.abs(_coverage_centroid(img.astype(float)) - uv).max() < 0.1


def test_mask_depth_agrees_with_camera_distance(rendered, spread_scene):
    """Every mask pixel, lifted to 3D with its depth through the recorded calibration, lies on its own object: inside
    its bounding box (in the object's frame), and within the box's reach of the centre's camera distance."""
    cam, masks, depth = rendered.camera, rendered.masks(), rendered.depth()
    R_cw = cam.world_to_camera[:3, :3].T
    for t in (0, spread_scene.num_frames - 1):
        for i, o in enumerate(spread_scene.objects):
            v, u = np.nonzero(masks[t] == o.id)
            d = depth[t, v, u]
            _, z = cam.project(spread_scene.position[t, i])
            assert (np.abs(d - z) <= np.linalg.norm(o.size) / 2 + 0.01).all()
            rays = np.stack([(u + 0.5 - cam.width / 2) / cam.fx, (v + 0.5 - cam.height / 2) / cam.fx,
                             np.ones_like(d)], 1)
            world = np.asarray(cam.position) + (rays * d[:, None]) @ R_cw.T
            R = Rotation.from_quat(spread_scene.orientation[t, i]).as_matrix()
            local = (world - spread_scene.position[t, i]) @ R
            assert (np.abs(local) <= np.array(o.size) / 2 + 0.03).all(), (t, o.id, np.abs(local).max(0))


def test_ground_depth_is_the_plane(rendered):
    """Background pixels below the horizon are the ground plane z = 0."""
    cam, masks, depth = rendered.camera, rendered.masks(), rendered.depth()
    v, u = 230, 10
    assert masks[0, v, u] == -1
    d_cam = np.array([(u + 0.5 - cam.width / 2) / cam.fx, (v + 0.5 - cam.height / 2) / cam.fx, 1.0])
    R = cam.world_to_camera[:3, :3]
    point = np.asarray(cam.position) + R.T @ d_cam * depth[0, v, u]
    assert abs(point[2]) < 0.01


def test_every_colour_variant_stays_in_its_category():
    for colour in COLOR_NAMES:
        for v in range(len(VARIANTS)):
            assert nearest_color(body_material(colour, v).mean_rgb) == colour, (colour, VARIANTS[v])


def test_body_takes_colour_other_parts_fixed(rendered, spread_scene):
    """The red sedan's pixels are mostly red-ish; the parts' materials do not depend on the object's colour."""
    from dynclevr.render.appearance import part_material

    for part in ("wheels", "windows", "lights"):
        assert part_material(part, "red", 0) is part_material(part, "cyan", 3)
    frame, mask = rendered.frames(slice(0, 1))[0], rendered.masks(slice(0, 1))[0]
    px = frame[mask == 0].astype(float)
    assert (px[:, 0] > px[:, 1] + 30).mean() > 0.4


def test_at_least_50_distinct_environments():
    assert environments.NUM_ENVIRONMENTS >= 50
    names = {environments.GROUNDS[i % len(environments.GROUNDS)] + "/" +
             environments.SKIES[i // len(environments.GROUNDS)] for i in range(environments.NUM_ENVIRONMENTS)}
    assert len(names) == environments.NUM_ENVIRONMENTS
    seeds = [appearance(s, 3)[0] for s in range(400)]
    assert len(set(seeds)) > 45                             # the per-scene draw reaches (nearly) all of them
    assert appearance(123, 3) == appearance(123, 3)


def test_same_seed_same_bytes(spread_scene, rendered, tmp_path):
    path = tmp_path / "again.mcap"
    render_scene(spread_scene, 11, Config.load(), path)
    assert path.read_bytes() == rendered.path.read_bytes()
    render_scene(spread_scene, 12, Config.load(), tmp_path / "other.mcap")
    assert not np.array_equal(Video.read(tmp_path / "other.mcap").frames(slice(0, 1)), rendered.frames(slice(0, 1)))


def test_cache_skips_unchanged_and_resolution_change_reruns(spread_scene, tmp_path):
    data = Config.load().data
    data["splits"]["one"] = {"seed": 5, "scenes": 1}
    cfg = Config(data)
    store = Store(tmp_path, "one")
    sim = store.path("simulate", "000000", ".mcap")
    spread_scene.write(sim, kind="truth")
    manifest = store.manifest("simulate")
    manifest.record("000000", "hand-built", [sim])
    manifest.save()
    runner = Runner(cfg, cfg.split("one"), tmp_path, echo=lambda *a: None)
    assert runner.run("render", [0]).items() >= {"ran": 1, "cached": 0}.items()
    assert runner.run("render", [0]).items() >= {"ran": 0, "cached": 1}.items()
    data["render"]["width"], data["render"]["height"] = 160, 120
    runner = Runner(Config(data), cfg.split("one"), tmp_path, echo=lambda *a: None)
    assert runner.run("render", [0]).items() >= {"ran": 1, "cached": 0}.items()
    video = Video.read(store.path("render", "000000", ".mcap"))
    assert video.frames(slice(0, 1)).shape == (1, 120, 160, 3)
    assert video.camera.K[0, 0] == pytest.approx(spread_scene.camera.fx / 2)


def test_realistic_backend_missing_is_one_clear_error(monkeypatch):
    import sys

    from dynclevr.render import RenderError
    from dynclevr.render.mitsuba import require_mitsuba

    monkeypatch.setitem(sys.modules, "mitsuba", None)   # as if not installed
    with pytest.raises(RenderError, match="make realistic"):
        require_mitsuba()


def test_realistic_backend_same_schema_and_truth(spread_scene, rendered, tmp_path):
    """Mitsuba frames come with the very masks and depth of the fast backend (one geometry, one artifact schema),
    and are deterministic too."""
    from dynclevr.render.mitsuba import mitsuba_available

    if not mitsuba_available():
        pytest.skip("the realistic backend (Mitsuba 3) is not installed: `make realistic`")
    short = Scene4D(**{**spread_scene.__dict__, **{k: getattr(spread_scene, k)[:2] for k in (
        "position", "orientation", "velocity", "angular_velocity", "acceleration", "engine", "floating", "visible")}})
    data = Config.load().data
    data["render"].update(backend="mitsuba", mitsuba_spp=4)
    render_scene(short, 11, Config(data), tmp_path / "m.mcap")
    render_scene(short, 11, Config(data), tmp_path / "again.mcap")
    assert (tmp_path / "m.mcap").read_bytes() == (tmp_path / "again.mcap").read_bytes()
    video = Video.read(tmp_path / "m.mcap")
    assert video.meta["backend"] == "mitsuba" and video.num_frames == 2
    assert np.array_equal(video.masks(), rendered.masks()[:2])
    assert np.array_equal(video.depth(), rendered.depth()[:2])
    frame = video.frames(slice(0, 1))[0].astype(float)
    sedan = frame[video.masks()[0] == 0]
    assert (sedan[:, 0] > sedan[:, 1] + 20).mean() > 0.4          # the red car is red here too
