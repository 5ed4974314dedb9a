"""Which parts of the cut state the predictive answers depend on: the split's predictive questions answered with
their gold programs on the parse (parsed/ and future/ of `dynclevr run`), then with parts of every matched object's
state at the last observed frame put in from the truth and the future re-simulated from there
(simulate_future.predict_future) as the stage simulates it: the configured vote over perturbed runs, with the scene's
own draws (`--single`: one unperturbed run instead, as this analysis did before 2026-11-29; it undercounts a part
put in alone, since the other parts then lose the vote). Missed and spurious objects stay as the parse has them.

    .venv/bin/python docs/analysis/predictive_attribution.py --split full-val

Also `--margin`: the parse's own future again, with pairs whose hulls come within these many metres counted as
colliding (are the predictions' misses near misses?). And `--streams K [--samples N ...]`: the parse's future
drawn again from K other random streams with N runs each (by default the configured number), for the noise the
vote's draws alone put into the predictive answers. An analysis (it reads the truth), not part of the model.
"""

import zlib
from dataclasses import replace
from pathlib import Path

import numpy as np

from dynclevr.config import Config
from dynclevr.perception.evaluate import match
from dynclevr.physics import ContactEvents, PhysicsParams, World
from dynclevr.scene import Collision, Scene4D
from dynclevr.stages.simulate_future import ENSEMBLE_STREAM, Ensemble, _bodies, _events, attach, predict_future

from gold_answers import right, table
from split_args import split_args

PARTS = {"velocity": ("velocity",), "position": ("position",), "heading and spin": ("orientation", "angular_velocity"),
         "engine and floating": ("engine", "floating"), "velocity, position": ("velocity", "position"),
         "velocity, position, heading": ("velocity", "position", "orientation"),
         "velocity, position, heading, spin": ("velocity", "position", "orientation", "angular_velocity"),
         "all of it": ("position", "orientation", "velocity", "angular_velocity", "engine", "floating")}

ap = split_args()
ap.add_argument("--margin", type=float, nargs="*", default=[])
ap.add_argument("--streams", type=int, default=0)
ap.add_argument("--samples", type=int, nargs="*", default=[])
ap.add_argument("--single", action="store_true", help="the variants' futures as one unperturbed run each")
args = ap.parse_args()
root = Path(args.data_dir) / args.split
cfg = Config.load()
params = PhysicsParams.from_config(cfg)


def near_misses(est: Scene4D, margin: float) -> list[Collision]:
    """The parse's future with pairs whose hulls come within `margin` counted as colliding, at the first such frame."""
    last = est.observed_frames - 1
    ids = [o.id for o in est.objects if est.visible[: last + 1, est.index(o.id)].any()]
    if not ids:
        return []
    near = {}
    with World(_bodies(est, np.full(len(ids), last), ids), params) as w:
        contacts = ContactEvents(params.merge_frames, w.masses, params.min_impact_speed)
        for t in range(1, est.num_frames - last):
            contacts.add(t, w.step_frame())
            for (a, b), gap in w.gaps(margin).items():
                near.setdefault((min(ids[a], ids[b]), max(ids[a], ids[b])), t + last)
        hits = _events(contacts.done()[0], ids, offset=last)
    return [e for e in hits if e.frame >= est.observed_frames] + [
        Collision(f, a, b, (0.0, 0.0, 0.0), 0.0) for (a, b), f in near.items() if f >= est.observed_frames]


def scene(job):
    name, questions = job
    truth = Scene4D.read(root / "sim" / f"{name}.mcap")
    est = attach(Scene4D.read(root / "parsed" / f"{name}.mcap"), root / "future" / f"{name}.parquet")
    cut = est.observed_frames - 1
    pairs = match(truth, est)
    variants = {"the parse": est}
    ensemble = Ensemble.from_config(cfg)
    for label, fields in PARTS.items():
        state = {k: np.array(v, copy=True) for k, v in est.state_at(cut).items()}
        for i, j in pairs:
            for f in fields:
                state[f][j] = truth.state_at(cut)[f][i]
        variants[f"{label} from the truth"] = s = replace(est, cut_state=state)
        s.future_collisions = predict_future(s, params, Ensemble() if args.single else ensemble)
    for n in args.samples or [ensemble.samples]:
        for k in range(1, args.streams + 1):
            variants[f"the parse, its future from stream {k} ({n} runs)"] = s = replace(est)
            s.future_collisions = predict_future(s, params, replace(ensemble, samples=n),
                                                 np.random.default_rng([ENSEMBLE_STREAM, zlib.crc32(name.encode()), k]))
    for m in args.margin:
        variants[f"the parse, hulls within {m} m collide"] = s = replace(est)
        s.future_collisions = near_misses(est, m)
    return right(variants, questions, cfg["labels"])


if __name__ == "__main__":
    table(root, args.split, "predictive", scene)
