"""eval-parser's scoring: objects matched to the truth, and collision events counted per pair and frame."""

from dataclasses import replace

import numpy as np

from dynclevr.config import Config
from dynclevr.perception.evaluate import intervals, markdown, scene_stats, summarise
from dynclevr.scene import Collision
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
    # who hits whom, at any frame: both true pairs found, one pair that never collided
    assert (s["collision_pair_precision"], s["collision_pair_recall"]) == (2 / 3, 1.0)


def test_recall_of_what_a_viewer_can_see_leaves_out_the_hidden():
    truth = known_scene()       # events: (0, 1) at frame 20 (and 22), (1, 4) at 45
    labels = Config.load()["labels"]
    # the estimate misses object 5, which is hidden behind others in all but 3 frames, and object 4, in sight
    keep = [i for i, o in enumerate(truth.objects) if o.id not in (4, 5)]
    est = replace(truth, objects=[truth.objects[i] for i in keep], position=truth.position[:, keep],
                  orientation=truth.orientation[:, keep], velocity=truth.velocity[:, keep],
                  angular_velocity=truth.angular_velocity[:, keep], acceleration=truth.acceleration[:, keep],
                  engine=truth.engine[:, keep], floating=truth.floating[:, keep], visible=truth.visible[:, keep],
                  collisions=[truth.collisions[0]], cut_state=None)
    pixels = np.full(truth.visible.shape, 1000)
    pixels[3:, truth.index(5)] = 20
    pixels[45, truth.index(1)] = 0           # at (1, 4)'s collision, object 1 is out of sight
    s = summarise([scene_stats(truth, est, labels, pixels=pixels)])
    assert s["detection_recall"] == 4 / 6 and s["shown_recall"] == 4 / 5
    assert s["shown_recall_" + truth.objects[truth.index(4)].category] < 1.0
    assert (s["collision_recall"], s["collision_recall_in_sight"]) == (0.5, 1.0)
    # without the masks, in sight is in view
    s = summarise([scene_stats(truth, est, labels)])
    assert s["shown_recall"] == s["detection_recall"] and s["collision_recall_in_sight"] == 0.5


def test_precision_per_category_counts_the_estimate_s_false_objects_by_their_category():
    truth = known_scene()
    # the estimate adds a phantom: object 0's kind, 30 m from anything
    fields = ("position", "orientation", "velocity", "angular_velocity", "acceleration", "engine", "floating",
              "visible")
    extra = {f: np.concatenate([getattr(truth, f), getattr(truth, f)[:, :1]], 1) for f in fields}
    extra["position"][:, -1] += 30.0
    est = replace(truth, objects=truth.objects + [replace(truth.objects[0], id=99)], cut_state=None, **extra)
    s = summarise([scene_stats(truth, est, Config.load()["labels"])])
    phantom = truth.objects[0].category
    same = sum(o.category == phantom for o in truth.objects)
    assert s["detection_recall"] == 1.0 and s["detection_precision"] == len(truth.objects) / (len(truth.objects) + 1)
    assert s["precision_" + phantom] == same / (same + 1)
    assert all(s["precision_" + o.category] == 1.0 for o in truth.objects if o.category != phantom)


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
    assert s["cut_engine_moving_acc"] == 0.5      # objects 2 and 4 (1 is struck at frame 20, 0 and 3 parked)


def test_predicted_future_collisions_are_scored_by_pair_among_the_objects_seen_by_the_cut():
    truth = known_scene()       # after the cut (frame 29): (1, 4) at 45; before it: (0, 1) at 20
    cut = truth.observed_frames - 1
    labels = Config.load()["labels"]
    known = [e for e in truth.collisions if e.frame <= cut]
    # the estimate knows (0, 1) from the observed frames, misses (1, 4), and predicts (2, 3), which never happens
    est = replace(truth, cut_collisions=known, future_collisions=[Collision(60, 2, 3)])
    s = summarise([scene_stats(truth, est, labels, future=True)])
    assert (s["future_pair_precision"], s["future_pair_recall"], s["future_pair_f1"]) == (0.0, 0.0, 0.0)
    # a contact that the observed frames show going on (0, 1 touching at frame 28) is no future collision
    est = replace(est, cut_collisions=known + [Collision(28, 0, 1)],
                  future_collisions=[Collision(46, 1, 4), Collision(31, 0, 1)])
    s = summarise([scene_stats(truth, est, labels, future=True)])
    assert (s["future_pair_precision"], s["future_pair_recall"]) == (1.0, 1.0)
    # an object first seen after the cut takes no part: its pairs are neither predicted nor missed
    visible = truth.visible.copy()
    visible[:cut + 1, 4] = False
    s = summarise([scene_stats(truth, replace(est, visible=visible, future_collisions=[]), labels, future=True)])
    assert s["future_pair_recall"] == 0.0 and s["future_pair_f1"] == 0.0
    assert np.isnan(summarise([scene_stats(truth, est, labels)])["future_pair_f1"])   # not simulated: no score


def test_gross_cut_speed_errors_are_counted_apart():
    truth = known_scene()
    state = {k: np.array(v, copy=True) for k, v in truth.state_at(truth.observed_frames - 1).items()}
    state["velocity"][0, 0] += 0.5               # noise
    state["velocity"][1, 1] += 2.0               # a wrong motion
    s = summarise([scene_stats(truth, replace(truth, cut_state=state), Config.load()["labels"])])
    assert s["cut_speed_gross_rate"] == 1 / 6 and s["cut_speed_err_median"] == 0.0


def test_cut_attribution_puts_the_truths_parts_into_the_estimate():
    """An estimate whose cut state is the truth's but for the velocities (all read as parked, which predicts a
    collision that does not come): putting the true velocities in gives what putting the whole true state in
    gives, which is what the truth's own cut state predicts; the other parts leave its future as the estimate's
    own."""
    from dynclevr.perception.evaluate import ATTRIBUTION, attribution_markdown, cut_attribution
    from dynclevr.physics import PhysicsParams

    cfg = Config.load()
    truth = known_scene()
    cut = truth.observed_frames - 1
    state = {k: np.array(v, copy=True) for k, v in truth.state_at(cut).items()}
    state["velocity"][:] = 0.0                   # every body read as parked
    rows = cut_attribution(truth, replace(truth, cut_state=state), cfg["labels"], PhysicsParams.from_config(cfg))
    clean = cut_attribution(truth, truth, cfg["labels"], PhysicsParams.from_config(cfg))
    assert set(rows) == {name for name, _ in ATTRIBUTION}
    assert len(set(clean.values())) == 1
    assert rows["velocity from the truth"] == rows["all of the state from the truth"] == clean["the estimate"]
    assert rows["position from the truth"] == rows["the estimate"] != clean["the estimate"]
    assert attribution_markdown([rows, clean]).count("\n") == len(ATTRIBUTION) + 2


def test_the_position_error_is_reported_per_category():
    truth = known_scene()
    est = replace(truth, position=truth.position.copy())
    planes = [i for i, o in enumerate(truth.objects) if o.category == "aeroplane"]
    others = sorted({o.category for o in truth.objects} - {"aeroplane"})
    assert planes and others
    est.position[:, planes, 0] += 0.5            # only the aeroplanes are off, half a metre
    s = summarise([scene_stats(truth, est, Config.load()["labels"])])
    assert abs(s["position_err_median_aeroplane"] - 0.5) < 1e-9 and abs(s["position_err_p90_aeroplane"] - 0.5) < 1e-9
    assert all(s[f"position_err_p90_{c}"] == 0.0 for c in others)


def test_intervals_resample_whole_scenes_and_hold_the_figures_of_the_split():
    """Two scenes, one parsed perfectly and one missing an object: the recall's interval spans the two scenes'
    own recalls and holds the split's; a figure the same in every scene has no width."""
    truth = known_scene()
    labels = Config.load()["labels"]
    keep = list(range(1, len(truth.objects)))
    missing = replace(truth, objects=[truth.objects[i] for i in keep], position=truth.position[:, keep],
                      orientation=truth.orientation[:, keep], velocity=truth.velocity[:, keep],
                      angular_velocity=truth.angular_velocity[:, keep], acceleration=truth.acceleration[:, keep],
                      engine=truth.engine[:, keep], floating=truth.floating[:, keep], visible=truth.visible[:, keep],
                      collisions=[], cut_state=None)
    stats = [scene_stats(truth, truth, labels), scene_stats(truth, missing, labels)]
    spans = intervals(stats, resamples=200, seed=0)
    recall = summarise(stats)["detection_recall"]
    lo, hi = spans["detection_recall"]
    assert lo <= recall <= hi and lo >= summarise(stats[1:])["detection_recall"] and hi <= 1.0 and hi > lo
    assert spans["detection_precision"] == (1.0, 1.0)
    again = intervals(stats, resamples=200, seed=0)
    assert np.array_equal(np.array(list(again.values())), np.array(list(spans.values())), equal_nan=True)
    assert "95% interval" in markdown({"ours": summarise(stats)}, spans)
