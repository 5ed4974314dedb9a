"""Question generation (paper section 3.4), as CLEVR's engine does it: templates are data, programs are data.

Per scene, from its truth: every family of templates.json is instantiated for every binding of its objects and
slots; the program runs on the truth in strict mode, so a binding whose reference is not unique, or that touches
an ambiguous label or an object out of view, is dropped, and the answer is the executor's own. Objects are named by
colour and shape, or by fewer words where those already pick one object (CLEVR's variety), or by colour and category.

"Out of view" is what the rendered masks show (annotate passes `seen`); strict mode also refuses collisions that
graze, happen out of view or start right after the observed frames (programs.py); every refusal is counted per
reason.

Across the split (`select`): per scene and family a few questions with the answers taken in turn, then per family
no answer above `max_answer_share` and, for counterfactuals, at most `max_copy_share` answered by copying the
video's own outcome, where the data allows. Every draw comes from a seeded generator. The wording of each
question is drawn from the phrasing grammar (phrasing.py): only its seen phrasings, or all (`annotate.phrasings`).
"""

from __future__ import annotations

import json
import math
from collections import Counter
from functools import lru_cache
from itertools import permutations
from pathlib import Path

import numpy as np

from dynclevr.colors import COLOR_NAMES
from dynclevr.config import ConfigError
from dynclevr.questions.phrasing import grammar
from dynclevr.questions.programs import AmbiguousLabel, Executor, ProgramError
from dynclevr.scene import INTERVENTIONS, Scene4D, SceneObject

TEMPLATES_PATH = Path(__file__).with_name("templates.json")
TYPES = ("factual", "predictive", "counterfactual")
SUBTYPES_Q = ("velocity", "acceleration", "collision")
CONDITIONS = ("visible_start", "observed", "aeroplane_X", "changes_X")

# (attributes named, weight): colour + shape is the default reference; the shorter ones add variety.
REFERENCES = ((("color", "shape"), 3.0), (("shape",), 1.0), (("color",), 1.0), (("color", "category"), 1.0),
              (("category",), 1.0))
COLOR_NOUNS = ("object", "vehicle")


@lru_cache(maxsize=1)
def templates() -> dict:
    data = json.loads(TEMPLATES_PATH.read_text())
    for fam in data["families"]:
        bad = [c for c in fam["where"] if c not in CONDITIONS]
        if bad or fam["type"] not in TYPES or fam["subtype"] not in SUBTYPES_Q:
            raise ConfigError(f"templates.json family '{fam['name']}': unknown type, subtype or condition {bad}")
        if "intervention" in fam and fam["intervention"] not in INTERVENTIONS:
            raise ConfigError(f"templates.json family '{fam['name']}': unknown intervention {fam['intervention']}")
    return data


def family_names() -> list[str]:
    return [f["name"] for f in templates()["families"]]


def words(value: str) -> str:
    """A sub-type key as the text says it: 'school_bus' -> 'school bus'."""
    return value.replace("_", " ")


def references(scene: Scene4D, obj: SceneObject) -> list[tuple[tuple[str, ...], float]]:
    """The attribute sets that pick exactly this object out of the scene's objects."""
    out = []
    for attrs, weight in REFERENCES:
        key = tuple(getattr(obj, a) for a in attrs)
        if sum(tuple(getattr(o, a) for a in attrs) == key for o in scene.objects) == 1:
            out.append((attrs, weight))
    return out


def describe(obj: SceneObject, attrs: tuple[str, ...], rng: np.random.Generator) -> tuple[str, str]:
    """-> (text, program fragment) for one object reference."""
    return reference(tuple(getattr(obj, a) for a in attrs), rng)


def reference(values: tuple[str, ...], rng: np.random.Generator) -> tuple[str, str]:
    """Attribute values ('red', 'sedan') -> ('the red sedan', 'Objects filter_attributes[red] ... unique'). A
    colour alone gets a noun ('the red vehicle')."""
    program = "Objects " + " ".join(f"filter_attributes[{v}]" for v in values) + " unique"
    named = [words(v) for v in values]
    if len(values) == 1 and values[0] in COLOR_NAMES:
        named.append(COLOR_NOUNS[rng.integers(len(COLOR_NOUNS))])
    return "the " + " ".join(named), program


def phrase(fam: dict, values: dict[str, dict], slot_keys: dict[str, str], rng: np.random.Generator,
           pool: str = "all") -> tuple[str, str]:
    """One question of a family -> (text, program): `values` the objects' {text, program}, `slot_keys` the slots'
    value keys; the wording drawn from the phrasing grammar's pool (phrasing.py)."""
    slots = {name: templates()["slots"][name][key] for name, key in slot_keys.items()}
    objects = {name: v for name, v in values.items() if name not in slots}
    text = _fill(grammar().sample(fam["name"], rng, pool, slots), objects, "text")
    program = _fill(fam["program"], {**objects, **slots}, "program")
    return _sentence(text), program


def _fill(template: str, values: dict[str, dict], field: str) -> str:
    for name, v in values.items():
        template = template.replace(f"<{name}>", v[field])
    return template


def _sentence(text: str) -> str:
    return text[0].upper() + text[1:]


def _changes(obj: SceneObject, intervention: str) -> bool:
    if intervention in ("static", "slow", "fast"):
        return obj.speed_class != intervention
    if intervention == "accelerating":
        return not obj.engine_on
    return obj.category == "aeroplane" and not obj.floating


def _applies(fam: dict, objs: dict[str, SceneObject]) -> bool:
    x = objs.get("X")
    if "aeroplane_X" in fam["where"] and x.category != "aeroplane":
        return False
    return "changes_X" not in fam["where"] or _changes(x, fam["intervention"])


def _seen_enough(fam: dict, scene: Scene4D, objs: dict[str, SceneObject], start: int, seen: np.ndarray) -> bool:
    """Every object is seen in the frames the question is about: at the start for start questions, within the
    observed frames for predictive and counterfactual ones, at some frame otherwise."""
    idx = {o.id: i for i, o in enumerate(scene.objects)}
    frames = scene.observed_frames if "observed" in fam["where"] else scene.num_frames
    for o in objs.values():
        if not seen[:frames, idx[o.id]].any():
            return False
        if "visible_start" in fam["where"] and not seen[start, idx[o.id]]:
            return False
    return True


def _bindings(fam: dict, scene: Scene4D):
    """Objects (dicts name -> SceneObject) x slot values (dicts name -> value key), in a fixed order."""
    names = fam["objects"]
    if fam.get("unordered"):
        tuples = [(a, b) for a, b in permutations(scene.objects, len(names)) if a.id < b.id]
    else:
        tuples = list(permutations(scene.objects, len(names)))
    slot_values = [[]]
    for s in fam.get("slots", []):
        slot_values = [prev + [(s, v)] for prev in slot_values for v in templates()["slots"][s]]
    for objs in tuples:
        for slots in slot_values:
            yield dict(zip(names, objs)), dict(slots)


def scene_candidates(scene: Scene4D, labels_cfg: dict, seed: int, seen: np.ndarray | None = None,
                     phrasings: str = "seen") -> tuple[list[dict], Counter]:
    """Every answerable question of one scene, its answer from the truth by the executor in strict mode, and the
    bindings dropped per (family, reason). `seen` [T, N]: the objects a viewer sees (default: centres in view).

    A counterfactual question also records the answer of copying the video's own outcome ("factual"), against
    which `select` balances."""
    seen = scene.visible if seen is None else seen
    rng = np.random.default_rng(seed)
    ex = Executor(scene, labels_cfg, strict=True, seen=seen)
    copy = Executor(scene, labels_cfg, copy_factual=True)
    refs = {o.id: references(scene, o) for o in scene.objects}
    out, dropped = [], Counter()
    start = labels_cfg["start_frame"]
    for fam in templates()["families"]:
        for objs, slot_keys in _bindings(fam, scene):
            if any(not refs[o.id] for o in objs.values()) or not _applies(fam, objs):
                continue
            if not _seen_enough(fam, scene, objs, start, seen):
                dropped[(fam["name"], "not visible")] += 1
                continue
            if fam.get("unordered") and rng.random() < 0.5:
                objs = dict(zip(objs, reversed(list(objs.values()))))
            values = {}
            for name, o in objs.items():
                options = refs[o.id]
                w = np.array([wt for _, wt in options])
                text, program = describe(o, options[rng.choice(len(options), p=w / w.sum())][0], rng)
                values[name] = {"text": text, "program": program}
            text, program = phrase(fam, values, slot_keys, rng, phrasings)
            try:
                answer = ex.run(program)
            except AmbiguousLabel as e:
                dropped[(fam["name"], e.reason)] += 1
                continue
            except ProgramError:
                continue
            factual = copy.run(program) if fam["type"] == "counterfactual" else None
            out.append({"id": None, "scene": scene.name, "type": fam["type"], "subtype": fam["subtype"],
                        "family": fam["name"], "text": text, "program": program, "answer": answer,
                        "factual": factual})
    return out, dropped


# ---- split-level selection --------------------------------------------------------------------------------------

def check_annotate_cfg(cfg: dict) -> dict:
    for k in ("max_per_family", "max_per_family_predictive", "max_per_family_counterfactual"):
        v = cfg.get(k)
        if not isinstance(v, int) or isinstance(v, bool) or v < 1:
            raise ConfigError(f"'annotate.{k}' = {v!r} must be a positive integer")
    for k in ("max_answer_share", "max_copy_share"):
        if not 0.5 <= cfg.get(k, 0) <= 1:
            raise ConfigError(f"'annotate.{k}' = {cfg.get(k)!r} must lie in [0.5, 1]")
    if cfg.get("phrasings") not in ("seen", "all"):
        raise ConfigError(f"'annotate.phrasings' = {cfg.get('phrasings')!r} must be \"seen\" or \"all\"")
    return cfg


def balanced_counts(counts: dict[str, int], max_share: float) -> dict[str, int]:
    """How many of each answer to keep: the most questions with no answer above max_share of them."""
    for n in range(sum(counts.values()), 0, -1):
        cap = math.floor(max_share * n + 1e-9)
        keep = {a: min(c, cap) for a, c in counts.items()}
        excess = sum(keep.values()) - n
        if excess < 0:
            continue
        for a in sorted(keep, key=lambda a: (-keep[a], a)):   # trim the most frequent answers first
            cut = min(excess, keep[a])
            keep[a] -= cut
            excess -= cut
        return keep
    return {a: 0 for a in counts}


def _kind(r: dict) -> str:
    """What per-scene picking spreads over: the answer, and for counterfactuals whether it differs from the video's."""
    return r["answer"] + ("|same" if r.get("factual") == r["answer"] else "|differs" if r.get("factual") else "")


def _round_robin(rows: list[dict], cap: int, rng: np.random.Generator) -> list[dict]:
    by_answer: dict[str, list[dict]] = {}
    for r in rows:
        by_answer.setdefault(_kind(r), []).append(r)
    queues = [[group[i] for i in rng.permutation(len(group))] for _, group in sorted(by_answer.items())]
    queues = [queues[i] for i in rng.permutation(len(queues))]
    out = []
    while len(out) < cap and any(queues):
        for q in queues:
            if q and len(out) < cap:
                out.append(q.pop(0))
    return out


def _balance(rows: list[tuple], max_share: float, max_copy: float, rng: np.random.Generator) -> list[tuple]:
    """The rows (scene, index, question) of one family to keep: no answer above max_share of them and, for
    counterfactuals, no more than max_copy of them answered by copying the video's own outcome. Each pass only
    drops rows (at random within a group), so alternating the two caps converges."""
    while True:
        counts: dict[str, int] = {}
        for _, _, r in rows:
            counts[r["answer"]] = counts.get(r["answer"], 0) + 1
        quota = balanced_counts(counts, max_share)
        kept = []
        for answer in sorted(quota):
            group = [row for row in rows if row[2]["answer"] == answer]
            kept += [group[j] for j in sorted(rng.permutation(len(group))[:quota[answer]])]
        same = [row for row in kept if row[2].get("factual") == row[2]["answer"]]
        differ = sum(1 for row in kept if row[2].get("factual") not in ("", None, row[2]["answer"]))
        allowed = math.floor(max_copy / (1 - max_copy) * differ + 1e-9) if max_copy < 1 else len(same)
        if len(same) > allowed:
            drop = {id(same[j]) for j in rng.permutation(len(same))[:len(same) - allowed]}
            kept = [row for row in kept if id(row) not in drop]
        if len(kept) == len(rows):
            return sorted(kept, key=lambda row: (row[0], row[1]))
        rows = sorted(kept, key=lambda row: (row[0], row[1]))


def select(candidates: dict[str, list[dict]], cfg: dict, seed: int) -> list[dict]:
    """Per-scene caps, then per-family answer balance across the split; ids '<scene>-<k>'. Deterministic."""
    c = check_annotate_cfg(cfg)
    caps = {"factual": c["max_per_family"], "predictive": c["max_per_family_predictive"],
            "counterfactual": c["max_per_family_counterfactual"]}
    rng = np.random.default_rng(np.random.SeedSequence([seed, 0xA11]))
    order = {f: i for i, f in enumerate(family_names())}
    picked: list[tuple[str, int, dict]] = []
    for scene in sorted(candidates):
        rows = candidates[scene]
        pos = {id(r): i for i, r in enumerate(rows)}
        for fam in sorted({r["family"] for r in rows}, key=order.__getitem__):
            group = [r for r in rows if r["family"] == fam]
            picked += [(scene, pos[id(r)], r) for r in _round_robin(group, caps[group[0]["type"]], rng)]
    keep: set[tuple[str, int]] = set()
    for fam in family_names():
        rows = [(s, i, r) for s, i, r in picked if r["family"] == fam]
        keep.update((s, i) for s, i, _ in _balance(rows, c["max_answer_share"], c["max_copy_share"], rng))
    out, k = [], {}
    for s, i, r in sorted(picked, key=lambda p: (p[0], p[1])):
        if (s, i) in keep:
            k[s] = k.get(s, 0) + 1
            out.append({**r, "id": f"{s}-{k[s] - 1}"})
    return out
