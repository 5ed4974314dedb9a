"""eval-parser's scoring: objects matched to the truth, and collision events counted per pair and frame."""

from dataclasses import replace

import numpy as np

from dynclevr.config import Config
from dynclevr.perception.evaluate import scene_stats, summarise
from test_programs import known_scene


def test_collision_events_count_by_pair_and_frame_tolerance():
    truth = known_scene()       # events: (0, 1) at frame 20 (and 22: the same event), (1, 4) at 45
    # the estimate names its objects otherwise, finds (0, 1) 5 frames late, (1, 4) in time, and a pair that never
    # collided
    rename = {o.id: o.id + 10 for o in truth.objects}
    est = replace(truth, objects=[replace(o, id=rename[o.id]) for o in truth.objects], collisions=[
        replace(truth.collisions[0], frame=25, a=10, b=11), replace(truth.collisions[2], a=11, b=14),
        replace(truth.collisions[2], frame=30, a=12, b=15)])
    s = summarise([scene_stats(truth, est, Config.load()["labels"])])
    assert s["detection_precision"] == 1.0 and s["detection_recall"] == 1.0
    assert (s["collision_precision"], s["collision_recall"]) == (2 / 3, 1.0)    # within 6 frames
    assert abs(s["collision_f1"] - 0.8) < 1e-9
    assert abs(s["collision_f1_strict"] - 2 * (1 / 3) * 0.5 / (1 / 3 + 0.5)) < 1e-9   # within 3: only (1, 4)


def test_the_cut_state_is_scored_for_the_objects_the_observed_frames_show():
    truth = known_scene()
    cut = truth.observed_frames - 1
    state = {k: np.array(v, copy=True) for k, v in truth.state_at(cut).items()}
    state["velocity"][[1, 2, 3], 0] += 1.0       # 1 m/s off for three objects
    state["engine"][4] = True                     # a wrong engine
    state["velocity"][5, 0] += 9.0                # first seen after the cut: not scored
    visible = truth.visible.copy()
    visible[:cut + 1, 5] = False
    est = replace(truth, cut_state=state, visible=visible)
    s = summarise([scene_stats(truth, est, Config.load()["labels"])])
    assert s["cut_speed_err_median"] == 1.0
    assert s["cut_engine_acc"] == 0.8
