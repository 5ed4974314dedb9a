"""How well collision events can be told from states sampled at the video's frame rate at all (issue 11's
collision-event F1, frame within 3): the truth's own poses and velocities at each frame, hull gaps from the
catalogue's collision shapes (the engine's, as parse-scene uses them), and simple event rules, scored against the
truth's merged events as eval-parser scores the parse. The truth's events come from the engine's contacts between
frames (several physics steps each), with impacts too gentle to count left out as grazes; a frame-rate view sees
the pair's gap and velocities only at the frames.

- touch: the first frame the pair's hulls are within EPS after they were apart for more than the merge window;
- touch and turn: the same, counting only frames where the pair's relative velocity changes by DV or more between
  two frames within 2 of it (a graze changes it little).

    .venv/bin/python docs/analysis/collision_bound.py --split full-test --data-dir D

An analysis (it reads the truth; no model is involved); it reads `dynclevr run`'s sim/.
"""

import collections
from pathlib import Path

import numpy as np

from dynclevr.config import Config
from dynclevr.perception.evaluate import STRICT_EVENT_TOLERANCE
from dynclevr.physics import Body, PhysicsParams, World
from dynclevr.questions.labels import merge_events
from dynclevr.scene import Scene4D

from split_args import split_args

EPS = (0.005, 0.01, 0.02, 0.05)   # metres
DV = (0.25, 0.5)                   # m/s

args = split_args().parse_args()
cfg = Config.load()
params = PhysicsParams.from_config(cfg)
merge = cfg["labels"]["collision_merge_frames"]
counts = collections.defaultdict(lambda: np.zeros(3, int))   # rule -> true positives, estimated, true


def events(hits: np.ndarray) -> list[tuple[int, int, int]]:
    """[T, N, N] booleans -> one event per pair where it starts, merged as the truth merges contacts."""
    out, last = [], {}
    for t, i, j in zip(*np.nonzero(hits)):
        if j <= i:
            continue
        if (i, j) not in last or t - last[(i, j)] > merge:
            out.append((int(t), int(i), int(j)))
        last[(i, j)] = t
    return out


def true_positives(est: list, true: list) -> int:
    used = set()
    for t, i, j in est:
        k = next((k for k, g in enumerate(true) if k not in used and g[1:] == (i, j)
                  and abs(g[0] - t) <= STRICT_EVENT_TOLERANCE), None)
        if k is not None:
            used.add(k)
    return len(used)


for path in sorted((Path(args.data_dir) / args.split / "sim").glob("*.mcap")):
    s = Scene4D.read(path)
    T, N = s.position.shape[:2]
    column = {o.id: i for i, o in enumerate(s.objects)}
    true = [(e.frame, *sorted((column[e.a], column[e.b]))) for e in merge_events(s.collisions, merge)]
    bodies = [Body(o.shape, tuple(s.position[0, i]), tuple(s.orientation[0, i]), (0, 0, 0), (0, 0, 0), False, False,
                   o.mass) for i, o in enumerate(s.objects)]
    gap = np.ones((T, N, N))
    with World(bodies, params) as world:
        for t in range(T):
            world.set_state(s.position[t], s.orientation[t], s.velocity[t])
            for (i, j), g in world.gaps(0.5).items():
                gap[t, i, j] = g
    rel = s.velocity[:, :, None] - s.velocity[:, None, :]                 # [T, N, N, 3]
    step = np.linalg.norm(np.diff(rel, axis=0), axis=-1)                   # [T-1, N, N]: change from t to t+1
    turn = np.zeros((T, N, N))
    for t in range(T):
        lo, hi = max(t - 2, 0), min(t + 2, T - 1)
        if hi > lo:
            turn[t] = step[lo:hi].max(0)
    for eps in EPS:
        rules = {f"touch within {eps} m": gap <= eps}
        rules.update({f"touch within {eps} m and turn by {dv} m/s": (gap <= eps) & (turn >= dv) for dv in DV})
        for name, hits in rules.items():
            est = events(hits)
            counts[name] += (true_positives(est, true), len(est), len(true))

print(f"# Collision events from the truth's own states at the frame rate ({args.split}, frame within "
      f"{STRICT_EVENT_TOLERANCE})\n\n| rule | precision | recall | F1 |\n|---|---|---|---|")
for name, (tp, n_est, n_true) in counts.items():
    p, r = tp / max(n_est, 1), tp / max(n_true, 1)
    print(f"| {name} | {p:.3f} | {r:.3f} | {2 * p * r / max(p + r, 1e-9):.3f} |")
