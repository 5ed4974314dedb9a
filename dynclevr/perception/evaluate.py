"""The scene parser's estimate (`parsed/`, `parsed-noprior/`) against the truth (`sim/`): an evaluation, so it reads
the truth; nothing here feeds back into the model.

Objects are matched one-to-one (Hungarian) by their mean distance over the frames where both are visible;
a pair further apart than MATCH_RADIUS is no match. The language labels (velocity class, accelerating, floating)
are computed by the same function the dataset uses (dynclevr.questions.labels) on both scenes and compared
where the truth's label is unambiguous, i.e. where a question could be asked. The state at the last observed frame,
from which the predictive questions start (an estimate's cut state), is scored for the matched objects that the
observed frames show: its horizontal speed error, the share of gross errors (over CUT_GROSS: a parked body read
as moving, a start speed picked wrong) and whether its engine is right. With `future`, the predicted future collisions
(simulate-future's, from the cut state) are scored by pair among the matched objects that the observed frames show:
a steadier yardstick for prediction than the few predictive questions, where a pair's yes flips with small changes.
Recall is also given for what a viewer can see (the rendered masks: an object with `labels.min_visible_pixels` in
MIN_VISIBLE frames, a collision with both vehicles in sight at its frame), beside the recall of everything inside
the camera's view, which counts vehicles hidden behind a bus for the whole video. Recall per category is by the true
object's category, precision per category by the category the estimate reports (issue 10 asks both of every category).
`cut_attribution` re-predicts that future with parts of the matched objects' cut state taken from the truth, one
part at a time: how much of the prediction's error each part of the estimated state carries.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np
from scipy.optimize import linear_sum_assignment

from dynclevr.assets.catalogue import CATEGORIES, SUBTYPES
from dynclevr.perception.detector_data import yaw_of
from dynclevr.questions.labels import compute_labels, future_events, merge_events
from dynclevr.scene import CUT_FIELDS, Scene4D
from dynclevr.uncertainty import interval, resample_weights

MATCH_RADIUS = 1.5      # metres
DUPLICATE_RADIUS = 1.5  # metres: an unmatched estimate this close to a matched true object is a duplicate of it
FLIP = np.deg2rad(135)  # a heading further off than this is a front/back flip
MIN_VISIBLE = 5         # frames a true object must be in view to count as one to detect
EVENT_TOLERANCE = 6     # frames between an estimated and a true collision of the same pair
STRICT_EVENT_TOLERANCE = 3   # ... and issue 11's stricter bar
CUT_GROSS = 1.5         # m/s: a cut speed this far off is a wrong motion, not noise (the line fit's is ~0.6 at worst)
# the cut state's parts that cut_attribution takes from the truth, one at a time, then all together
ATTRIBUTION = (("the estimate", ()), ("velocity from the truth", ("velocity",)),
               ("position from the truth", ("position",)),
               ("heading and spin from the truth", ("orientation", "angular_velocity")),
               ("engine and floating from the truth", ("engine", "floating")),
               ("all of the state from the truth", CUT_FIELDS))


def match(truth: Scene4D, est: Scene4D) -> list[tuple[int, int]]:
    """(truth index, estimate index) pairs."""
    if not est.objects or not truth.objects:
        return []
    cost = np.full((len(truth.objects), len(est.objects)), 1e6)
    for i in range(len(truth.objects)):
        for j in range(len(est.objects)):
            both = truth.visible[:, i] & est.visible[:, j]
            if both.any():
                cost[i, j] = np.linalg.norm(truth.position[both, i] - est.position[both, j], axis=1).mean()
    rows, cols = linear_sum_assignment(cost)
    return [(int(i), int(j)) for i, j in zip(rows, cols) if cost[i, j] <= MATCH_RADIUS]


def scene_stats(truth: Scene4D, est: Scene4D, labels_cfg: dict, future: bool = False,
                pixels: np.ndarray | None = None) -> dict:
    """`future`: est carries its simulated future (simulate_future.attach), to be scored by pair. `pixels` [T, N]:
    each true object's pixels in each rendered frame (questions.evidence.pixel_counts), for the recalls of what a
    viewer can see: an object in view but hidden behind others (or a collision out of sight) is no error of the
    parser's there (issue 10: "an object hidden in every frame is the only excuse")."""
    pairs = match(truth, est)
    lt, le = compute_labels(truth, labels_cfg), compute_labels(est, labels_cfg)
    counted = truth.visible.sum(0) >= MIN_VISIBLE
    sighted = truth.visible if pixels is None else truth.visible & (pixels >= labels_cfg["min_visible_pixels"])
    shown = sighted.sum(0) >= MIN_VISIBLE
    s = {"true_objects": int(counted.sum()), "est_objects": len(est.objects),
         "matched": len(pairs), "subtype": [], "color": [], "pos_err": [], "velocity": [], "accelerating": [],
         "floating": [], "depth_err": [], "yaw_err": [], "confusion": [], "cut_speed_err": [], "cut_engine": [],
         "cut_engine_moving": [],
         "pos_err_by_category": {c: [] for c in CATEGORIES},
         "true_by_category": {c: 0 for c in CATEGORIES}, "found_by_category": {c: 0 for c in CATEGORIES},
         "shown_by_category": {c: 0 for c in CATEGORIES}, "shown_found_by_category": {c: 0 for c in CATEGORIES},
         "est_by_category": {c: 0 for c in CATEGORIES}, "est_matched_by_category": {c: 0 for c in CATEGORIES}}
    for i, o in enumerate(truth.objects):
        if counted[i]:
            s["true_by_category"][o.category] += 1
        if shown[i]:
            s["shown_by_category"][o.category] += 1
    eye = np.asarray(truth.camera.position, float)
    matched_est = {j for _, j in pairs}
    # precision per category by the estimate's category: of the objects it reports as aeroplanes, the share that are real
    for j, o in enumerate(est.objects):
        s["est_by_category"][o.category] += 1
        s["est_matched_by_category"][o.category] += int(j in matched_est)
    # the state the predictive questions start from, of the objects the observed frames show
    cut = est.observed_frames - 1
    cut_true, cut_est = truth.state_at(cut), est.state_at(cut)
    struck = {x for c in truth.collisions if c.frame <= cut for x in (c.a, c.b)}
    for i, j in pairs:
        s["found_by_category"][truth.objects[i].category] += int(counted[i])
        s["shown_found_by_category"][truth.objects[i].category] += int(shown[i])
        s["subtype"].append(truth.objects[i].shape == est.objects[j].shape)
        s["confusion"].append((truth.objects[i].shape, est.objects[j].shape))
        s["color"].append(truth.objects[i].color == est.objects[j].color)
        if 0 <= cut < truth.num_frames and est.visible[:cut + 1, j].any():
            s["cut_speed_err"].append(float(np.linalg.norm(cut_est["velocity"][j, :2] - cut_true["velocity"][i, :2])))
            s["cut_engine"].append(bool(cut_est["engine"][j]) == bool(cut_true["engine"][i]))
            # where the engine is a question at all: a body on its way, no impact yet (most bodies are parked)
            if truth.objects[i].id not in struck and \
                    np.linalg.norm(cut_true["velocity"][i, :2]) >= labels_cfg["slow_above"]:
                s["cut_engine_moving"].append(s["cut_engine"][-1])
        both = truth.visible[:, i] & est.visible[:, j]
        err = np.linalg.norm(truth.position[both, i] - est.position[both, j], axis=1).tolist()
        s["pos_err"] += err
        s["pos_err_by_category"][truth.objects[i].category] += err
        ray = truth.position[both, i] - eye
        ray /= np.linalg.norm(ray, axis=1, keepdims=True)
        s["depth_err"] += ((est.position[both, j] - truth.position[both, i]) * ray).sum(1).tolist()
        dyaw = yaw_of(est.orientation[both, j]) - yaw_of(truth.orientation[both, i])
        s["yaw_err"] += np.abs(np.arctan2(np.sin(dyaw), np.cos(dyaw))).tolist()
        for key, amb in (("velocity", "velocity_ambiguous"), ("accelerating", "accelerating_ambiguous"),
                         ("floating", "floating_ambiguous")):
            ok = both & ~getattr(lt, amb)[:, i]
            s[key] += (getattr(lt, key)[ok, i] == getattr(le, key)[ok, j]).tolist()
    s["duplicates"] = 0
    for j in set(range(len(est.objects))) - matched_est:
        for i, jj in pairs:
            both = truth.visible[:, i] & est.visible[:, j]
            if both.any() and np.linalg.norm(truth.position[both, i] - est.position[both, j], axis=1).mean() \
                    < DUPLICATE_RADIUS:
                s["duplicates"] += 1
                break
    # collision events: estimated pairs renamed to the true ids they matched
    to_truth, seen = _to_truth_and_seen(truth, est, pairs)
    merge = labels_cfg["collision_merge_frames"]
    true_events = merge_events(truth.collisions, merge)
    est_events = [e for e in merge_events(est.collisions, merge) if e.a in to_truth and e.b in to_truth]
    column = {o.id: i for i, o in enumerate(truth.objects)}
    # the events a viewer sees: both vehicles in sight at the event's frame (the dataset asks only about these)
    in_sight = {k for k, g in enumerate(true_events)
                if sighted[g.frame, column[g.a]] and sighted[g.frame, column[g.b]]}
    for key, tolerance in (("events_tp", EVENT_TOLERANCE), ("events_tp_strict", STRICT_EVENT_TOLERANCE)):
        used, tp = set(), 0
        for e in est_events:
            pair = frozenset((to_truth[e.a], to_truth[e.b]))
            for k, g in enumerate(true_events):
                if k not in used and g.pair() == pair and abs(g.frame - e.frame) <= tolerance:
                    used.add(k)
                    tp += 1
                    break
        s[key] = tp
        s[key + "_in_sight"] = len(used & in_sight)
    s.update(events_true=len(true_events), events_est=len(merge_events(est.collisions, merge)),
             events_in_sight=len(in_sight))
    # who hits whom, at any frame: what the factual collision questions read (an unmatched estimate's pair is false)
    true_pairs = {e.pair() for e in true_events}
    est_pairs = {frozenset((to_truth.get(e.a, ("est", e.a)), to_truth.get(e.b, ("est", e.b)))) for e in est.collisions}
    s.update(pairs_tp=len(true_pairs & est_pairs), pairs_est=len(est_pairs), pairs_true=len(true_pairs))
    if future:
        true_pairs = {e.pair() for e in future_events(truth, merge) if {e.a, e.b} <= seen}
        est_pairs = _future_pairs(est, to_truth, seen, merge)
        s.update(future_tp=len(true_pairs & est_pairs), future_fp=len(est_pairs - true_pairs),
                 future_fn=len(true_pairs - est_pairs))
    return s


def _to_truth_and_seen(truth: Scene4D, est: Scene4D, pairs: list[tuple[int, int]]) -> tuple[dict, set]:
    """Estimated ids renamed to the true ids they matched, and the true ids of those the observed frames show."""
    to_truth = {est.objects[j].id: truth.objects[i].id for i, j in pairs}
    cut = est.observed_frames - 1
    return to_truth, {to_truth[est.objects[j].id] for _, j in pairs if est.visible[:cut + 1, j].any()}


def _future_pairs(est: Scene4D, to_truth: dict, seen: set, merge: int) -> set:
    return {frozenset((to_truth[e.a], to_truth[e.b])) for e in future_events(est, merge)
            if e.a in to_truth and e.b in to_truth and {to_truth[e.a], to_truth[e.b]} <= seen}


def cut_attribution(truth: Scene4D, est: Scene4D, labels_cfg: dict, params, ensemble=None
                    ) -> dict[str, tuple[int, int, int]]:
    """Per ATTRIBUTION row, the predicted future collision pairs' (true positives, false positives, false
    negatives), scored as `scene_stats` scores them, when the future is simulated (simulate_future.predict_future,
    physics.PhysicsParams `params`, simulate_future.Ensemble `ensemble`, by default the single run; every row with
    the stage's draws) from est's cut state with those parts of every matched object's state put in from the truth.
    Missed and spurious objects stay as the estimate has them, so the last row is what perfect states of the
    objects found would give."""
    from dynclevr.stages.simulate_future import Ensemble, future_rng, predict_future

    merge = labels_cfg["collision_merge_frames"]
    pairs = match(truth, est)
    to_truth, seen = _to_truth_and_seen(truth, est, pairs)
    true_pairs = {e.pair() for e in future_events(truth, merge) if {e.a, e.b} <= seen}
    cut = est.observed_frames - 1
    out = {}
    for name, fields in ATTRIBUTION:
        state = {k: np.array(v, copy=True) for k, v in est.state_at(cut).items()}
        for i, j in pairs:
            for f in fields:
                state[f][j] = truth.state_at(cut)[f][i]
        scene = replace(est, cut_state=state)
        scene.future_collisions = predict_future(scene, params, ensemble or Ensemble(), future_rng(est.name))
        est_pairs = _future_pairs(scene, to_truth, seen, merge)
        out[name] = (len(true_pairs & est_pairs), len(est_pairs - true_pairs), len(true_pairs - est_pairs))
    return out


def attribution_markdown(rows: list[dict[str, tuple[int, int, int]]]) -> str:
    """cut_attribution's counts over scenes as a table of precision, recall and F1."""
    lines = ["| future simulated from the cut state with | precision | recall | F1 |", "|---|---|---|---|"]
    for name, _ in ATTRIBUTION:
        tp, fp, fn = (sum(r[name][k] for r in rows) for k in range(3))
        lines.append(f"| {name} | {tp / max(tp + fp, 1):.3f} | {tp / max(tp + fn, 1):.3f} | "
                     f"{2 * tp / max(2 * tp + fp + fn, 1):.3f} |")
    return "\n".join(lines) + "\n"


def summarise(stats: list[dict]) -> dict:
    def total(k):
        return sum(s[k] for s in stats)

    def mean(k):
        v = [x for s in stats for x in s[k]]
        return float(np.mean(v)) if v else float("nan")

    err = np.array([x for s in stats for x in s["pos_err"]])
    depth = np.array([x for s in stats for x in s["depth_err"]])
    yaw = np.array([x for s in stats for x in s["yaw_err"]])
    cut_speed = np.array([x for s in stats for x in s["cut_speed_err"]])
    per_cat = {}
    for c in CATEGORIES:
        n = sum(s["est_by_category"][c] for s in stats)
        per_cat[f"precision_{c}"] = sum(s["est_matched_by_category"][c] for s in stats) / n if n else float("nan")
        n = sum(s["true_by_category"][c] for s in stats)
        per_cat[f"recall_{c}"] = sum(s["found_by_category"][c] for s in stats) / n if n else float("nan")
        n = sum(s["shown_by_category"][c] for s in stats)
        per_cat[f"shown_recall_{c}"] = sum(s["shown_found_by_category"][c] for s in stats) / n if n else float("nan")
        e = [x for s in stats for x in s["pos_err_by_category"][c]]
        per_cat[f"position_err_median_{c}"] = float(np.median(e)) if e else float("nan")
        per_cat[f"position_err_p90_{c}"] = float(np.percentile(e, 90)) if e else float("nan")
    shown = sum(sum(s["shown_by_category"].values()) for s in stats)
    per_cat["shown_recall"] = sum(sum(s["shown_found_by_category"].values()) for s in stats) / max(shown, 1)
    p = total("matched") / max(total("est_objects"), 1)
    r = total("matched") / max(total("true_objects"), 1)
    ep = total("events_tp") / max(total("events_est"), 1)
    er = total("events_tp") / max(total("events_true"), 1)
    sp = total("events_tp_strict") / max(total("events_est"), 1)
    sr = total("events_tp_strict") / max(total("events_true"), 1)
    pp, pr = total("pairs_tp") / max(total("pairs_est"), 1), total("pairs_tp") / max(total("pairs_true"), 1)
    if all("future_tp" in s for s in stats):
        tp, fp, fn = total("future_tp"), total("future_fp"), total("future_fn")
        fut = {"future_pair_precision": tp / max(tp + fp, 1), "future_pair_recall": tp / max(tp + fn, 1),
               "future_pair_f1": 2 * tp / max(2 * tp + fp + fn, 1)}
    else:
        fut = {k: float("nan") for k in ("future_pair_precision", "future_pair_recall", "future_pair_f1")}
    return {
        "scenes": len(stats),
        "detection_precision": p, "detection_recall": r, **per_cat,
        "duplicate_rate": total("duplicates") / max(total("est_objects"), 1),
        "subtype_acc": mean("subtype"), "color_acc": mean("color"),
        "position_err_median_m": float(np.median(err)) if len(err) else float("nan"),
        "position_err_p90_m": float(np.percentile(err, 90)) if len(err) else float("nan"),
        "depth_bias_m": float(depth.mean()) if len(depth) else float("nan"),
        "yaw_err_median_deg": float(np.degrees(np.median(yaw))) if len(yaw) else float("nan"),
        "yaw_flip_rate": float((yaw > FLIP).mean()) if len(yaw) else float("nan"),
        "velocity_class_acc": mean("velocity"), "accelerating_acc": mean("accelerating"),
        "floating_acc": mean("floating"),
        "cut_speed_err_median": float(np.median(cut_speed)) if len(cut_speed) else float("nan"),
        "cut_speed_gross_rate": float((cut_speed > CUT_GROSS).mean()) if len(cut_speed) else float("nan"),
        "cut_engine_acc": mean("cut_engine"), "cut_engine_moving_acc": mean("cut_engine_moving"), **fut,
        "collision_precision": ep, "collision_recall": er,
        "collision_f1": 2 * ep * er / (ep + er) if ep + er else 0.0,
        "collision_f1_strict": 2 * sp * sr / (sp + sr) if sp + sr else 0.0,
        "collision_recall_in_sight": total("events_tp_in_sight") / max(total("events_in_sight"), 1),
        "collision_recall_in_sight_strict": total("events_tp_strict_in_sight") / max(total("events_in_sight"), 1),
        "collision_pair_precision": pp, "collision_pair_recall": pr,
        "collision_pair_f1": 2 * pp * pr / (pp + pr) if pp + pr else 0.0,
    }


ROWS = [("detection_precision", "detection precision"),
        *[(f"precision_{c}", f"precision, {c}") for c in CATEGORIES], ("detection_recall", "detection recall"),
        *[(f"recall_{c}", f"recall, {c}") for c in CATEGORIES],
        ("shown_recall", "recall of the objects a viewer can see (150 px in 5+ frames)"),
        *[(f"shown_recall_{c}", f"... {c}") for c in CATEGORIES], ("duplicate_rate", "duplicates per estimate"),
        ("subtype_acc", "sub-type accuracy"), ("color_acc", "colour accuracy"),
        ("position_err_median_m", "position error, median (m)"), ("position_err_p90_m", "position error, 90th pct (m)"),
        # the tail by category: an aeroplane's distance is the head's alone (no ground plane pins it)
        *[(f"position_err_{q}_{c}", f"... {c}, {w}") for c in CATEGORIES for q, w in (("median", "median"),
                                                                                      ("p90", "90th pct"))],
        ("depth_bias_m", "depth bias along the ray (m)"), ("yaw_err_median_deg", "yaw error, median (deg)"),
        ("yaw_flip_rate", "yaw flips (> 135 deg)"),
        ("velocity_class_acc", "velocity-class accuracy"), ("accelerating_acc", "accelerating accuracy"),
        ("floating_acc", "floating accuracy"),
        ("cut_speed_err_median", "speed error at the cut, median (m/s)"),
        ("cut_speed_gross_rate", f"speed at the cut over {CUT_GROSS} m/s off"), ("cut_engine_acc", "engine at the cut"),
        ("cut_engine_moving_acc", "engine at the cut, moving bodies not yet struck"),
        ("future_pair_precision", "predicted future collision pairs: precision"),
        ("future_pair_recall", "predicted future collision pairs: recall"),
        ("future_pair_f1", "predicted future collision pairs: F1"),
        ("collision_precision", f"collision-event precision (frame within {EVENT_TOLERANCE})"),
        ("collision_recall", "collision-event recall"), ("collision_f1", "collision-event F1"),
        ("collision_f1_strict", f"collision-event F1, frame within {STRICT_EVENT_TOLERANCE}"),
        ("collision_recall_in_sight", f"collision-event recall, both vehicles in sight (within {EVENT_TOLERANCE})"),
        ("collision_recall_in_sight_strict", f"... within {STRICT_EVENT_TOLERANCE}"),
        ("collision_pair_precision", "colliding pairs, any frame (who hits whom): precision"),
        ("collision_pair_recall", "colliding pairs: recall"), ("collision_pair_f1", "colliding pairs: F1")]


def intervals(stats: list[dict], resamples: int, seed: int) -> dict[str, tuple[float, float]]:
    """Each of `summarise`'s figures as a 95% interval: the scenes resampled with replacement (whole videos, as
    dynclevr/uncertainty.py resamples them for the accuracy table), `summarise` over each resample."""
    w = resample_weights(len(stats), resamples, seed).astype(int)
    draws = [summarise([s for s, n in zip(stats, row) for _ in range(n)]) for row in w]
    lo, hi = interval(np.array([[d[key] for key, _ in ROWS] for d in draws], float))
    return {key: (float(a), float(b)) for (key, _), a, b in zip(ROWS, lo, hi)}


def markdown(results: dict[str, dict], spans: dict[str, tuple[float, float]] | None = None) -> str:
    """results: variant name -> summarise() output; `spans`: the first variant's `intervals`, as a last column."""
    names = list(results)
    extra = [f"{names[0]}: 95% interval (videos resampled)"] if spans else []
    lines = ["| metric | " + " | ".join(names + extra) + " |", "|---|" + "---|" * (len(names) + len(extra))]
    for key, label in ROWS:
        cells = [f"{results[n][key]:.3f}" for n in names]
        if spans:
            cells.append(f"{spans[key][0]:.3f} to {spans[key][1]:.3f}")
        lines.append(f"| {label} | " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def confusion_png(stats: list[dict], path) -> None:
    """Sub-type confusion of matched objects (rows: truth, columns: estimate), row-normalised."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from dynclevr.artifacts import atomic_path

    names = list(SUBTYPES)
    m = np.zeros((len(names), len(names)))
    for s in stats:
        for a, b in s["confusion"]:
            m[names.index(a), names.index(b)] += 1
    m = m / np.maximum(m.sum(1, keepdims=True), 1)
    fig, ax = plt.subplots(figsize=(7, 6))
    ax.imshow(m, cmap="Blues", vmin=0, vmax=1)
    ax.set_xticks(range(len(names)), names, rotation=90, fontsize=7)
    ax.set_yticks(range(len(names)), names, fontsize=7)
    ax.set(xlabel="estimated sub-type", ylabel="true sub-type", title="sub-type confusion (matched objects)")
    fig.tight_layout()
    with atomic_path(path) as tmp:
        fig.savefig(tmp, format="png", dpi=90)
    plt.close(fig)
