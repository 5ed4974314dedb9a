"""Which part of the parse the counterfactual answers depend on: the split's counterfactual questions answered with
their gold programs on the parse (parsed/ and future/ of `dynclevr run`), then with parts of every matched object's
estimate put in from the truth and the counterfactual runs imagined again (simulate_future.predict, the replay of
perception/imagine.py). Missed and spurious objects stay as the parse has them; the parse's visibility stays too
(where it starts, the replay starts an object; `--truth-visibility` puts in the truth's as well).

    .venv/bin/python docs/analysis/counterfactual_attribution.py --split full-val --data-dir D

Rows: the observed collisions (the replay keeps those the intervention does not reach), each object's state at
the first frame the parse shows it (where the replay starts the intervened object), its trajectory after that
frame (what the replay carries the others along), and parts of the whole trajectory. An analysis (it reads the
truth), not part of the model.
"""

from dataclasses import replace
from pathlib import Path

import numpy as np

from dynclevr.config import Config
from dynclevr.perception.evaluate import match
from dynclevr.physics import PhysicsParams
from dynclevr.scene import Collision, Scene4D
from dynclevr.stages.simulate_future import attach, predict

from gold_answers import right, table
from split_args import split_args

STATE = ("position", "orientation", "velocity", "angular_velocity", "engine", "floating")
PARTS = {"position and heading": ("position", "orientation"), "velocity and spin": ("velocity", "angular_velocity"),
         "engine and floating": ("engine", "floating")}

ap = split_args()
ap.add_argument("--truth-visibility", action="store_true",
                help="also give the matched objects the truth's visibility (where the truth's video shows them)")
args = ap.parse_args()
root = Path(args.data_dir) / args.split
cfg = Config.load()
params = PhysicsParams.from_config(cfg)
replay = cfg["imagine"]["counterfactuals"] == "replay"


def with_truth(est: Scene4D, truth: Scene4D, pairs, fields, frames) -> Scene4D:
    """The estimate with `fields` of each matched object put in from the truth at `frames(j)` (a slice)."""
    out = replace(est)
    for f in fields:
        arr = np.array(getattr(est, f), copy=True)
        for i, j in pairs:
            arr[frames(j), j] = getattr(truth, f)[frames(j), i]
        setattr(out, f, arr)
    if args.truth_visibility:
        vis = np.array(est.visible, copy=True)
        for i, j in pairs:
            vis[:, j] |= truth.visible[:, i]
        out.visible = vis
    return out


def scene(job):
    name, questions = job
    truth = Scene4D.read(root / "sim" / f"{name}.mcap")
    est = attach(Scene4D.read(root / "parsed" / f"{name}.mcap"), root / "future" / f"{name}.parquet")
    pairs = match(truth, est)
    to_est = {truth.objects[i].id: est.objects[j].id for i, j in pairs}
    first = {j: int(np.argmax(est.visible[:, j])) for _, j in pairs}
    whole = lambda j: slice(None)   # noqa: E731
    variants = {
        "observed collisions from the truth": replace(est, collisions=[
            Collision(c.frame, *sorted((to_est[c.a], to_est[c.b])), c.point, c.impulse)
            for c in truth.collisions if c.a in to_est and c.b in to_est]),
        "the state at the first frame shown from the truth": with_truth(
            est, truth, pairs, STATE, lambda j: slice(first[j], first[j] + 1)),
        "the trajectory after the first frame shown from the truth": with_truth(
            est, truth, pairs, STATE, lambda j: slice(first[j] + 1, None)),
        **{f"{label} from the truth": with_truth(est, truth, pairs, fields, whole) for label, fields in PARTS.items()},
        "all of the trajectory from the truth": with_truth(est, truth, pairs, STATE, whole)}
    for s in variants.values():
        s.counterfactuals = predict(s, params, replay)[1]
    return right({"the parse": est, **variants}, questions, cfg["labels"])


if __name__ == "__main__":
    table(root, args.split, "counterfactual", scene)
