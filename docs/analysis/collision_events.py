"""Where the truth's collision events are lost (issue 11's collision-event F1): every true event (merged as the
questions merge them) sorted by what the parse shows of its pair around it, and every estimated event by what it
hit, within 3 frames (evaluate.STRICT_EVENT_TOLERANCE):

- an object of the pair unmatched (evaluate.match);
- no rows: the engine never put the pair's hulls within collisions.FAR near the event;
- hulls apart: rows, but the estimated hulls never within collisions.CONTACT_GAP near it;
- touching nearby: they touch, but the pair's candidate (collisions.contacts) is further than 3 frames away;
- touching throughout: a later contact of the pair while the estimated hulls have touched since its last event,
  where the candidate rule (a new candidate only after a gap) cannot put one.

The classifier's rows are not stored, so each video is parsed again from its cached detections (the same parse:
parse-scene's output is checked against the stored one).

    .venv/bin/python docs/analysis/collision_events.py --split full-val --data-dir D

An analysis (it reads the truth), not part of the model; it reads `dynclevr run`'s render/, sim/ and parsed/, and
the detection cache (`<data>/.cache/<split>/detections/`, filled by parse-scene).
"""

import collections
from pathlib import Path

import torch

from dynclevr.artifacts import Store
from dynclevr.config import Config
from dynclevr.perception import collisions
from dynclevr.perception.evaluate import STRICT_EVENT_TOLERANCE, _to_truth_and_seen, match
from dynclevr.perception.tracker import SceneParser
from dynclevr.questions.labels import merge_events
from dynclevr.scene import Scene4D
from dynclevr.stages import parse_scene
from dynclevr.video import Video

from split_args import split_args

ap = split_args()
args = ap.parse_args()
torch.set_num_threads(1)
cfg = Config.load()
store = Store(Path(args.data_dir), args.split)
root = Path(args.data_dir) / args.split
merge, tol = cfg["labels"]["collision_merge_frames"], STRICT_EVENT_TOLERANCE
gap_col, engine_col = collisions.FEATURES.index("gap"), collisions.FEATURES.index("engine_dv")
true_kinds, est_kinds, found = collections.Counter(), collections.Counter(), collections.Counter()

for path in sorted((root / "sim").glob("*.mcap")):
    scene = path.stem
    truth, stored = Scene4D.read(path), Scene4D.read(root / "parsed" / path.name)
    video = Video.read(store.path("render", scene, ".mcap"))
    frames = video.frames()
    parser = SceneParser(*parse_scene._model(), video.camera, cfg, parse_scene._collision_model())
    est = parser.parse(frames, scene, parse_scene.scene_detections(store, scene, frames, cfg))
    if [(c.frame, c.a, c.b) for c in est.collisions] != [(c.frame, c.a, c.b) for c in stored.collisions]:
        raise SystemExit(f"{scene}: the parse differs from parsed/{scene}.mcap: rerun `dynclevr run` first")
    to_truth, _ = _to_truth_and_seen(truth, est, match(truth, est))
    to_est = {v: k for k, v in to_truth.items()}
    rows = collections.defaultdict(dict)
    for pair, t, x in parser.rows:
        rows[pair][t] = x
    candidates = collections.defaultdict(list)
    for pair, t, _ in collisions.contacts(parser.rows, merge):
        candidates[pair].append(t)
    true_events = merge_events(truth.collisions, merge)

    used = set()
    for e in merge_events(est.collisions, merge):
        if e.a not in to_truth or e.b not in to_truth:
            est_kinds["an object no true one matches"] += 1
            continue
        pair = frozenset((to_truth[e.a], to_truth[e.b]))
        near = sorted((abs(g.frame - e.frame), k) for k, g in enumerate(true_events) if g.pair() == pair)
        if not near:
            est_kinds["a pair that never collided"] += 1
        elif near[0][0] <= tol and near[0][1] not in used:
            used.add(near[0][1])
            est_kinds[f"within {tol} frames of a true event"] += 1
        elif near[0][0] <= 10:
            est_kinds[f"the pair's true event {tol + 1}-10 frames off (or already taken)"] += 1
        else:
            est_kinds["the pair, at another time"] += 1

    last = {}
    for k, g in enumerate(true_events):
        order = "a later contact of the pair" if g.pair() in last else "first of its pair"
        since = last.get(g.pair())
        last[g.pair()] = g.frame
        found[order] += k in used
        if g.a not in to_est or g.b not in to_est:
            true_kinds[(order, "an object of the pair unmatched")] += 1
            continue
        pair = tuple(sorted((to_est[g.a], to_est[g.b])))
        fr = rows.get(pair, {})
        near = [u for u in range(g.frame - tol, g.frame + tol + 1) if u in fr]
        touch = [u for u in fr if fr[u][gap_col] < collisions.CONTACT_GAP or fr[u][engine_col] > 0]
        if not near:
            kind = "no rows near it"
        elif any(abs(c - g.frame) <= tol for c in candidates[pair]):
            kind = f"a candidate within {tol} frames"
        elif since is not None and sum(since <= u <= g.frame for u in touch) >= 0.8 * (g.frame - since + 1):
            kind = "hulls touching throughout since the pair's last event"
        elif any(fr[u][gap_col] < collisions.CONTACT_GAP for u in near):
            kind = f"hulls touching nearby, the candidate further than {tol} frames"
        else:
            kind = "rows, hulls apart"
        true_kinds[(order, kind)] += 1

print(f"true events ({sum(true_kinds.values())}), by what the parse shows around them:")
for (order, kind), n in sorted(true_kinds.items()):
    print(f"  {order:28s} {kind:55s} {n}")
print(f"  found within {tol} frames: " + ", ".join(f"{k} {v}" for k, v in sorted(found.items())))
print(f"estimated events ({sum(est_kinds.values())}):")
for kind, n in est_kinds.most_common():
    print(f"  {kind:60s} {n}")
