"""Table 1's baselines (issue 15): the per-frame 3D model (PO3D-VQA style) and the CNN+LSTM. Each reads only what
its model may: the video's RGB frames and calibration, and of a question its text (and type); never the truth."""

import shutil

import numpy as np
import pyarrow as pa
import pytest

from dynclevr.artifacts import ArtifactError, read_parquet, write_parquet
from dynclevr.baselines import cnnlstm, perframe
from dynclevr.camera import Camera
from dynclevr.colors import COLOR_NAMES
from dynclevr.config import Config
from dynclevr.perception.detector import Detection
from dynclevr.perception.detector_data import azimuth
from dynclevr.perception.place import SUBTYPE_NAMES, resting_height
from dynclevr.pipeline import Runner, SceneJob
from dynclevr.stages import answer, answer_cnnlstm
from dynclevr.stages.annotate import QUESTIONS_SCHEMA, QUESTIONS_VERSION
from dynclevr.video import Video

from conftest import onehot, strip_video

CAMERA = Camera((8.0, -7.0, 3.2), (0.0, 0.0, 1.3), 35.0, 32.0, 320, 240)
FPS, T = 60, 120


def _detections(tracks, rng, pixel_noise=0.3):
    """Per frame, one detection per object: tracks = [(positions [T, 3], yaw, shape, colour index)]."""
    out = []
    for t in range(len(tracks[0][0])):
        frame = []
        for positions, yaw, shape, colour in tracks:
            pos = positions[t]
            (u, v), _ = CAMERA.project(pos)
            dist = float(np.linalg.norm(pos - np.asarray(CAMERA.position)))
            frame.append(Detection(float(u + rng.normal(0, pixel_noise)), float(v + rng.normal(0, pixel_noise)), 0.9,
                                   onehot(len(SUBTYPE_NAMES), SUBTYPE_NAMES.index(shape)),
                                   onehot(len(COLOR_NAMES), colour), yaw - float(azimuth(CAMERA.position, pos)),
                                   dist, float(pos[2])))
        out.append(frame)
    return out


def _per_frame_cfg() -> Config:
    cfg = Config.load()
    cfg.data["parser"].update(filter="none", physics_prior=False)
    return cfg


def _head_on(speed=4.0, frames=T):
    """A parked sedan at x = 2 and a truck driving at `speed` along +x from x = -6 (kinematic, as the baseline
    sees the world): the frame their boxes first touch."""
    parked = np.tile([2.0, 0.0, resting_height("sedan")], (frames, 1))
    moving = np.stack([-6.0 + speed * np.arange(frames) / FPS, np.zeros(frames),
                       np.full(frames, resting_height("truck"))], 1)
    return parked, moving


def test_per_frame_speeds_and_collision_by_finite_differences_and_distance():
    cfg = _per_frame_cfg()
    parked, moving = _head_on()
    dets = _detections([(parked, 0.0, "sedan", 1), (moving, 0.0, "truck", 3)], np.random.default_rng(0))
    est = perframe.parse(np.zeros((T, 1, 1, 3), np.uint8), CAMERA, None, cfg, "syn", dets)
    assert sorted(o.shape for o in est.objects) == ["sedan", "truck"]
    car, truck = (next(i for i, o in enumerate(est.objects) if o.shape == s) for s in ("sedan", "truck"))
    gaps = perframe.box_gap(parked, np.tile([0, 0, 0, 1.0], (T, 1)), est.objects[car].size, moving,
                            np.tile([0, 0, 0, 1.0], (T, 1)), est.objects[truck].size)
    touch = int(np.argmax(gaps < cfg["perframe"]["contact_gap"]))
    assert touch > cfg["video"]["observed_frames"] + 10        # (so that the prediction below is a prediction)
    # until they meet (the kinematic truck then drives through the car, which no video shows)
    speed = np.linalg.norm(est.velocity[:, truck, :2], axis=1)
    assert abs(float(np.median(speed[10:touch])) - 4.0) < 0.5
    # under static_speed mostly 0: five frames of centimetres of jitter make a metre per second now and then
    assert (np.abs(est.velocity[10:touch, car]).max(1) == 0.0).mean() > 0.9
    assert [c.frame for c in est.collisions][:1] and abs(est.collisions[0].frame - touch) <= 3
    assert est.cut_collisions == []   # the observed frames show no contact: a predictive question must predict it


def test_per_frame_contacts_within_the_observed_frames_are_known_at_the_cut():
    """A truck at 12 m/s reaches the parked car before the cut: the parse of the observed frames alone shows the
    contact, with the objects named as in the whole video's parse."""
    cfg = _per_frame_cfg()
    parked, moving = _head_on(speed=12.0)
    dets = _detections([(parked, 0.0, "sedan", 1), (moving, 0.0, "truck", 3)], np.random.default_rng(0))
    est = perframe.parse(np.zeros((T, 1, 1, 3), np.uint8), CAMERA, None, cfg, "syn", dets)
    assert est.collisions and est.collisions[0].frame < cfg["video"]["observed_frames"]
    assert est.cut_collisions == [e for e in est.collisions if e.frame < cfg["video"]["observed_frames"]]


def test_per_frame_future_and_counterfactuals_at_constant_velocity_from_the_observed_frames():
    cfg = _per_frame_cfg()
    parked, moving = _head_on()
    rng = np.random.default_rng(1)
    dets = _detections([(parked, 0.0, "sedan", 1), (moving, 0.0, "truck", 3)], rng)
    est = perframe.parse(np.zeros((T, 1, 1, 3), np.uint8), CAMERA, None, cfg, "syn", dets)
    future, outcomes = perframe.imagine(est, cfg)
    assert len(future) == 1 and abs(future[0].frame - est.collisions[0].frame) <= 4
    truck = next(o.id for o in est.objects if o.shape == "truck")
    car = next(o.id for o in est.objects if o.shape == "sedan")
    assert outcomes[(truck, "static")] == []                                   # it never reaches the car
    assert outcomes[(truck, "fast")][0].frame < outcomes[(truck, "slow")][0].frame   # 6 m/s before 3 m/s
    assert outcomes[(car, "floating")] == est.collisions                       # a car cannot float: as seen
    # what follows the observed frames does not change the prediction: the truck stops at frame 31 here
    stopped = moving.copy()
    stopped[31:] = stopped[30]
    later = _detections([(parked, 0.0, "sedan", 1), (stopped, 0.0, "truck", 3)], np.random.default_rng(1))
    alt = perframe.parse(np.zeros((T, 1, 1, 3), np.uint8), CAMERA, None, cfg, "syn", dets[:31] + later[31:])
    assert alt.collisions == [] and perframe.imagine(alt, cfg)[0] == future


# ---- on one rendered scene, with the shipped weights ------------------------------------------------------------

@pytest.fixture(scope="module")
def rendered(tmp_path_factory):
    """One rendered, annotated scene: data dir, config, runner."""
    root = tmp_path_factory.mktemp("baselines")
    user = root / "bl.toml"
    user.write_text("[splits.bl]\nseed = 7\nscenes = 1\n[video]\nframes = 60\n")   # half the paper's 2 s: half the parse
    cfg = Config.load(user)
    data = root / "full"
    r = Runner(cfg, cfg.split("bl"), data, echo=lambda *a: None)
    for stage in ("simulate", "render", "annotate"):
        r.run(stage, [0])
    return data, cfg, r


def _video_only(src_data, dst_data):
    """A data directory holding only video/, its files stripped to the RGB frames and the camera."""
    src, dst = src_data / "bl" / "video", dst_data / "bl" / "video"
    dst.mkdir(parents=True)
    strip_video(src / "000000.mcap", dst / "000000.mcap")
    with pytest.raises(ArtifactError):
        Video.read(dst / "000000.mcap").masks()
    # the manifests of video/ (whichever layout keeps them), so that the stage finds its input recorded
    for manifest in [src / "manifest.json", src_data / "bl" / "manifests" / "video.json"]:
        if manifest.exists():
            target = dst_data / manifest.relative_to(src_data)
            target.parent.mkdir(parents=True, exist_ok=True)
            shutil.copy(manifest, target)


def test_per_frame_parse_reads_only_the_video(rendered, tmp_path):
    data, cfg, _ = rendered
    pf = _per_frame_cfg()
    pf.data["splits"], pf.data["video"] = cfg.data["splits"], cfg.data["video"]
    Runner(pf, pf.split("bl"), data, echo=lambda *a: None).run("parse-scene", [0])
    expected = (data / "bl" / "parsed-perframe" / "000000.mcap").read_bytes()
    alone = tmp_path / "alone"
    _video_only(data, alone)
    Runner(pf, pf.split("bl"), alone, echo=lambda *a: None).run("parse-scene", [0])
    assert (alone / "bl" / "parsed-perframe" / "000000.mcap").read_bytes() == expected
    assert not (alone / "bl" / "sim").exists() and not (alone / "bl" / "labels").exists()


def test_cnnlstm_reads_only_the_video_and_the_question_text(rendered, tmp_path):
    """The stage's predictions, made in a data dir holding the stripped video and questions.parquet cut to
    answer.MODEL_COLUMNS, equal those made beside the truth and the full questions."""
    data, cfg, r = rendered
    full = read_parquet(data / "bl" / "questions.parquet", QUESTIONS_SCHEMA, QUESTIONS_VERSION)
    assert full.num_rows > 0

    def predict(root):
        out = tmp_path / f"{root.name}.parquet"
        answer_cnnlstm.run_scene(SceneJob("bl", "000000", 0, 0, cfg.data, root,
                                          {"render": [root / "bl" / "video" / "000000.mcap"]}, [out]))
        return read_parquet(out, answer.PREDICTIONS_SCHEMA, answer.PREDICTIONS_VERSION).to_pylist()

    expected = predict(data)
    alone = tmp_path / "alone"
    _video_only(data, alone)
    write_parquet(full.select(answer.MODEL_COLUMNS), alone / "bl" / "questions.parquet", QUESTIONS_SCHEMA,
                  QUESTIONS_VERSION)
    got = predict(alone)
    assert got == expected and len(got) == full.num_rows
    answers = set(cnnlstm.CnnLstmModel.load().answers)
    assert all(p["predicted_answer"] in answers for p in got)


def test_cnnlstm_predictive_questions_see_only_the_observed_frames():
    whole, seen = cnnlstm.clip_indices(120, 30, 15)
    assert seen.max() == 29 and whole.max() == 119
    model = cnnlstm.CnnLstmModel.load()
    p = model.p
    rng = np.random.default_rng(0)
    clips = rng.integers(0, 255, (2, p["frames"], p["height"], p["width"], 3), dtype=np.uint8)
    other = clips.copy()
    other[0] = 255 - other[0]                       # the whole video differs, the observed frames do not
    qs = [{"text": "Will the red sedan collide with the blue bus?", "type": "predictive"},
          {"text": "What will happen next: will the cyan jet hit the truck?", "type": "predictive"}]
    assert model.answer(clips, qs) == model.answer(other, qs)


def test_cnnlstm_trains_resumes_and_refuses_a_measured_split(tmp_path, monkeypatch):
    """Two training scenes and one held out, random clips: an epoch, then --resume to a second; the manifest logs
    both, and the weights load."""
    rng = np.random.default_rng(0)
    cfg = Config.load()
    cfg.data["splits"]["syn"] = {"seed": 1, "scenes": 3}
    p = cfg.data["cnnlstm"]
    p.update(heldout_scenes=1, frames=3, height=32, width=48, videos_per_batch=2)
    monkeypatch.setattr(cnnlstm, "video_clips", lambda path, p, observed: rng.integers(
        0, 255, (2, p["frames"], p["height"], p["width"], 3), dtype=np.uint8))
    from dynclevr.questions.tables import QUESTION_FIELDS

    rows = [{"id": f"{s:06d}-{k}", "scene": f"{s:06d}", "type": ["factual", "predictive", "counterfactual"][k % 3],
             "subtype": "velocity", "family": "f", "text": f"Is the red sedan moving {['fast', 'slow'][k % 2]}?",
             "program": "x", "answer": ["true", "false"][k % 2], "factual": None} for s in range(3) for k in range(6)]
    table = pa.Table.from_pylist(rows, schema=pa.schema(QUESTION_FIELDS))
    write_parquet(table, tmp_path / "data" / "syn" / "questions.parquet", QUESTIONS_SCHEMA, QUESTIONS_VERSION)
    out = tmp_path / "w"
    m = cnnlstm.train_cnnlstm(cfg, tmp_path / "data", "syn", out, epochs=1, echo=lambda *a: None)
    assert [c["epoch"] for c in m["curve"]] == [1] and m["heldout_scenes"] == ["000002"]
    m = cnnlstm.train_cnnlstm(cfg, tmp_path / "data", "syn", out, resume=True, epochs=2, echo=lambda *a: None)
    assert [c["epoch"] for c in m["curve"]] == [1, 2] and m["epochs_done"] == 2 and len(m["runs"]) == 2
    model = cnnlstm.CnnLstmModel.load(out)
    assert set(model.answers) == {"true", "false"}
    with pytest.raises(Exception, match="training split"):
        cnnlstm.train_cnnlstm(cfg, tmp_path / "data", "full-test", out, epochs=1, echo=lambda *a: None)
