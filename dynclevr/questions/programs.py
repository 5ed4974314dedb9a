"""The paper's program operations (appendix, "Program execution", table "All operations") and the executor.

A program is a list of tokens in postfix (reverse Polish) order, stored as one space-separated string. A token is
an operation name, optionally with one bracketed argument and no spaces: `filter_attributes[red]`,
`query_attributes[color]`. Each operation pops its typed inputs (the first input was pushed first) and pushes its
typed output; the answer is the single value left: "true"/"false", a colour, a sub-type key ("school_bus"), a
velocity label or a direction word.

    Objects filter_attributes[red] filter_attributes[sedan] unique start query_moving_velocity
      -> how fast is the red sedan moving at the start?

The operations keep the paper's names. Added (and only these):
- `start`: None -> FrameID, "the start of the video": frame `labels.start_frame` (1/6 s in), because a velocity is
  a change over frames: no one, model or person, reads a speed or direction from frame 0 alone.
- `unique` and `exist` also take a CollisionEventSet (-> CollisionEvent / Bool), so that "when X collides with Y"
  is `... filter_collision unique get_frame`.
- `filter_moving_velocity[slow|fast]` keeps objects of that velocity class; without an argument, every moving
  (not static) object. `is_moving_velocity[slow|fast]`: Object, FrameID -> Bool, the yes/no form the paper asks
  ("Is the red mountain bike moving fast at the beginning?") beside its `is_static`.
- `come_in_frame` is the object's first frame in view plus the same offset as `start`, for the same reason: the
  state "when X comes into view" is read once it has moved in view.

A program that cannot run (a reference that matches no object or several, an input of the wrong type, a missing
counterfactual run, a frame outside the scene) raises ProgramError: the answer stage counts these, never crashes.
In strict mode (question generation on the truth) a label that is ambiguous, asked of an object out of view, or at
the start but different at frame 0, and a collision question touching an unclear contact (a graze, a collision out
of view, a predicted one right after the observed frames), raise AmbiguousLabel with its reason, so no question is
ever asked about them. Counterfactual programs can also run with every run replaced by the video's own collisions
(`copy_factual`): the answer of a model that ignores the intervention.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Callable

import numpy as np

from dynclevr import DynclevrError
from dynclevr.assets.catalogue import CATEGORIES, SUBTYPES
from dynclevr.colors import COLOR_NAMES
from dynclevr.questions.labels import DIRECTIONS, VELOCITIES, Labels, compute_labels, future_events, merge_events
from dynclevr.scene import Collision, Scene4D


class ProgramError(DynclevrError):
    """The program cannot run on this scene."""


class AmbiguousLabel(ProgramError):
    """Strict execution touched a label no question may be asked about; `reason` says which kind (REASONS)."""

    def __init__(self, message: str, reason: str):
        super().__init__(message)
        self.reason = reason


# Why question generation drops a binding (`dynclevr stats` counts them).
REASONS = ("not visible", "ambiguous label", "start differs from frame 0", "similar speeds", "graze",
           "collision out of view", "collision at the cut")


# ---- types ------------------------------------------------------------------------------------------------------

class Object(int):
    """An object id."""


class FrameID(int):
    pass


class ObjectSet(tuple):
    """Object ids, ascending.

    `misses` remembers, for every object the set was narrowed from, how far it is from the description so far (the
    filters it failed; a sub-type of the right category fails by half; a later collision partner by a thousandth per
    place, get_all_col_partners). `unique` uses it to resolve a reference that an estimated scene matches with no
    object or several: perception is uncertain, and the object closest to the description is the most likely
    referent. On the truth, generated references match exactly one object, so the resolution never acts there, and
    strict mode (question generation) keeps it off."""

    misses: dict

    def __new__(cls, ids=(), misses: dict | None = None):
        s = super().__new__(cls, ids)
        s.misses = {i: 0.0 for i in s} if misses is None else misses
        return s


class CollisionEventSet(tuple):
    """Collisions, by frame. `about` names the objects it was filtered by, so that `unique` can resolve "the
    moment X collides with Y" in an estimate that missed the contact: the moment they come closest.

    `unclear` holds (reason, contact) for the contacts a viewer could not call either way (strict mode only):
    grazes (they touch, but too gently to be a collision), collisions hidden from view, and predicted collisions so
    soon after the observed frames that the pair already touches there. A question touching one is not asked."""

    about: tuple
    unclear: tuple

    def __new__(cls, events=(), about: tuple = (), unclear: tuple = ()):
        s = super().__new__(cls, events)
        s.about, s.unclear = about, tuple(unclear)
        return s


# A CollisionEvent is a scene.Collision, a Bool a bool, a Value (colour, sub-type, velocity label or direction) a str.
TYPE_NAMES = {Object: "Object", FrameID: "FrameID", ObjectSet: "ObjectSet", CollisionEventSet: "CollisionEventSet",
              Collision: "CollisionEvent", bool: "Bool", str: "Value"}

ATTRIBUTE_VALUES = frozenset(COLOR_NAMES) | frozenset(SUBTYPES) | frozenset(CATEGORIES)
ATTRIBUTES = frozenset({"color", "shape"})
MOVING = frozenset({"slow", "fast"})


@dataclass(frozen=True)
class Op:
    name: str
    inputs: tuple          # per input: a type or a tuple of accepted types
    output: type | tuple
    fn: Callable
    args: frozenset | None = None   # accepted bracket arguments; None: takes none
    arg_required: bool = True


OPS: dict[str, Op] = {}


def op(name: str, *inputs, returns, args: frozenset | None = None, arg_required: bool = True):
    def register(fn):
        OPS[name] = Op(name, inputs, returns, fn, args, arg_required)
        return fn
    return register


# ---- the scene as the operations see it ---------------------------------------------------------------------------

class World:
    """A Scene4D with its labels; truth and estimate alike."""

    def __init__(self, scene: Scene4D, labels_cfg: dict, strict: bool = False, seen: np.ndarray | None = None,
                 copy_factual: bool = False):
        """`seen` [T, N]: what strict mode may ask about (default: the scene's visibility); annotate passes what
        the rendered masks show. `copy_factual`: every counterfactual run is replaced by the video's own
        collisions (the answer of a model that ignores the intervention; annotate balances against it)."""
        self.scene, self.strict, self.copy_factual = scene, strict, copy_factual
        self.labels: Labels = compute_labels(scene, labels_cfg)
        self.seen = scene.visible if seen is None else seen
        self.margin = labels_cfg["compare_margin"]
        self.start_frame = min(labels_cfg["start_frame"], scene.num_frames - 1)
        merge = labels_cfg["collision_merge_frames"]
        self._index = {o.id: i for i, o in enumerate(scene.objects)}
        events = merge_events(scene.collisions, merge)
        future = future_events(scene, merge)
        runs = {k: merge_events(v, merge) for k, v in scene.counterfactuals.items()}
        if not strict:
            self.events, self.future_events = CollisionEventSet(events), CollisionEventSet(future)
            self.counterfactuals = {k: CollisionEventSet(v) for k, v in runs.items()}
            return
        def why(reason, events):
            return [(reason, e) for e in events]

        grazes = merge_events(scene.grazes, merge)
        hidden = [e for e in events if not self._both_seen(e)]
        self.events = CollisionEventSet([e for e in events if e not in hidden],
                                        unclear=why("collision out of view", hidden) + why("graze", grazes))
        # A predicted collision within predict_margin frames of the cut is all but seen: its pair touches already.
        soon = scene.observed_frames + labels_cfg["predict_margin"]
        self.future_events = CollisionEventSet(
            [e for e in future if e.frame >= soon],
            unclear=why("collision at the cut", [e for e in future if e.frame < soon])
            + why("graze", [e for e in grazes if e.frame >= scene.observed_frames]))
        self.counterfactuals = {
            k: CollisionEventSet(v, unclear=why("graze", merge_events(scene.counterfactual_grazes.get(k, []), merge)))
            for k, v in runs.items()}

    def _both_seen(self, e: Collision) -> bool:
        return all(oid in self._index and self.seen[e.frame, self._index[oid]] for oid in (e.a, e.b))

    def closest(self, a: int, b: int) -> tuple[int, float]:
        """(frame, distance) of the closest approach of two objects' centres while both are in view."""
        ia, ib = self._index[a], self._index[b]
        both = self.scene.visible[:, ia] & self.scene.visible[:, ib]
        if not both.any():
            return 0, float("inf")
        d = np.linalg.norm(self.scene.position[:, ia] - self.scene.position[:, ib], axis=1)
        d[~both] = np.inf
        t = int(np.argmin(d))
        return t, float(d[t])

    def obj(self, oid: int):
        return self.scene.objects[self._index[oid]]

    def _cell(self, oid: int, t: int, what: str) -> tuple[int, int]:
        if not 0 <= t < self.scene.num_frames:
            raise ProgramError(f"frame {t} is outside the scene's {self.scene.num_frames} frames")
        i = self._index[oid]
        if self.strict and not self.seen[t, i]:
            raise AmbiguousLabel(f"object {oid} is out of view at frame {t} ({what})", "not visible")
        return t, i

    def _label(self, values, ambiguous, oid: int, t: int, what: str):
        cell = self._cell(oid, t, what)
        if self.strict and ambiguous[cell]:
            raise AmbiguousLabel(f"{what} of object {oid} at frame {t} is ambiguous", "ambiguous label")
        if self.strict and t == self.start_frame and np.any(values[:t + 1, cell[1]] != values[cell]):
            # "At the start" must agree with the first frame (a plane spawned at rest and falling is "static" at
            # frame 0 and "slow" at the start frame).
            raise AmbiguousLabel(f"{what} of object {oid} changes between frame 0 and the start",
                                 "start differs from frame 0")
        return values[cell]

    def velocity(self, oid: int, t: int) -> str:
        return VELOCITIES[int(self._label(self.labels.velocity, self.labels.velocity_ambiguous, oid, t, "velocity"))]

    def direction(self, oid: int, t: int) -> str:
        return DIRECTIONS[int(self._label(self.labels.direction, self.labels.direction_ambiguous, oid, t,
                                          "direction"))]

    def accelerating(self, oid: int, t: int) -> bool:
        return bool(self._label(self.labels.accelerating, self.labels.accelerating_ambiguous, oid, t,
                                "accelerating"))

    def floating(self, oid: int, t: int) -> bool:
        return bool(self._label(self.labels.floating, self.labels.floating_ambiguous, oid, t, "floating"))

    def speed_difference(self, a: int, b: int, t: int) -> float:
        speed = self.labels.speed
        d = float(speed[self._cell(a, t, "speed")] - speed[self._cell(b, t, "speed")])
        if self.strict and abs(d) < self.margin:
            raise AmbiguousLabel(f"objects {a} and {b} move at similar speeds at frame {t}", "similar speeds")
        if self.strict and t == self.start_frame and np.any(
                (speed[:t + 1, self._index[a]] - speed[:t + 1, self._index[b]]) * d <= 0):
            raise AmbiguousLabel(f"objects {a} and {b} change order of speed between frame 0 and the start",
                                 "start differs from frame 0")
        return d


# ---- input operations -------------------------------------------------------------------------------------------

@op("Objects", returns=ObjectSet)
def Objects(w: World) -> ObjectSet:
    return ObjectSet(sorted(o.id for o in w.scene.objects))


@op("Events", returns=CollisionEventSet)
def Events(w: World) -> CollisionEventSet:
    return w.events


@op("futureEvents", returns=CollisionEventSet)
def futureEvents(w: World) -> CollisionEventSet:
    return w.future_events


@op("start", returns=FrameID)
def start(w: World) -> FrameID:
    return FrameID(w.start_frame)


# ---- event operations -------------------------------------------------------------------------------------------

@op("filter_collision", CollisionEventSet, Object, returns=CollisionEventSet)
def filter_collision(w: World, events: CollisionEventSet, obj: Object) -> CollisionEventSet:
    return CollisionEventSet((e for e in events if obj in (e.a, e.b)), events.about + (int(obj),),
                             (u for u in events.unclear if obj in (u[1].a, u[1].b)))


def _clear(w: World, events: CollisionEventSet) -> None:
    if w.strict and events.unclear:
        reason, e = events.unclear[0]
        raise AmbiguousLabel(f"objects {e.a} and {e.b} touch at frame {e.frame}: {reason}", reason)


@op("get_all_col_partners", CollisionEventSet, Object, returns=ObjectSet)
def get_all_col_partners(w: World, events: CollisionEventSet, obj: Object) -> ObjectSet:
    _clear(w, CollisionEventSet(unclear=[u for u in events.unclear if obj in (u[1].a, u[1].b)]))
    first: dict[int, int] = {}   # each partner's first collision with obj
    for e in sorted(events, key=lambda e: e.frame):
        if obj in (e.a, e.b):
            first.setdefault(e.b if e.a == obj else e.a, e.frame)
    # Several partners in an estimate: the one obj collided with first is the likeliest meant (a question asks "the"
    # partner only of an object with one), so each later one misses by a little. An estimate's later contacts are
    # its weakest: they come after the bodies' motion changed, often while the estimated hulls still touch.
    # Non-partners miss by more than any filter can, nearest first: an estimate that missed the contact still
    # names the object that came closest.
    order = {p: k for k, p in enumerate(sorted(first, key=lambda p: (first[p], p)))}
    misses = {o.id: 1e-3 * order[o.id] if o.id in first else 2.0 + w.closest(int(obj), o.id)[1] / 100
              for o in w.scene.objects if o.id != obj}
    return ObjectSet(sorted(first), misses)


@op("get_frame", Collision, returns=FrameID)
def get_frame(w: World, event: Collision) -> FrameID:
    return FrameID(event.frame)


@op("come_in_frame", Object, returns=FrameID)
def come_in_frame(w: World, obj: Object) -> FrameID:
    # The scene's own visibility (truth: the centre in the image; estimate: the track), in strict mode too, so that
    # the truth gives the same frame to the generator and to the oracle; strict mode then refuses a frame where
    # the rendered masks do not show the object.
    seen = w.scene.visible[:, w._index[obj]].nonzero()[0]
    if len(seen) == 0:
        raise ProgramError(f"object {obj} never comes into view")
    return FrameID(min(int(seen[0]) + w.start_frame, w.scene.num_frames - 1))


# ---- object filters ---------------------------------------------------------------------------------------------

def _narrow(w: World, objs: ObjectSet, miss: Callable[[int], float]) -> ObjectSet:
    """The members with miss 0, remembering every candidate's accumulated miss (see ObjectSet)."""
    if w.strict:
        return ObjectSet([i for i in objs if miss(i) == 0])
    misses = {}
    for i, m in objs.misses.items():
        try:
            misses[i] = m + miss(i)
        except ProgramError:  # a candidate outside the set whose label cannot be read is simply far
            misses[i] = m + 1.0
    return ObjectSet([i for i in objs if misses[i] == objs.misses[i]], misses)


@op("filter_attributes", ObjectSet, returns=ObjectSet, args=ATTRIBUTE_VALUES)
def filter_attributes(w: World, objs: ObjectSet, value: str) -> ObjectSet:
    def miss(i: int) -> float:
        o = w.obj(i)
        if value in (o.color, o.shape, o.category):
            return 0.0
        return 0.5 if value in SUBTYPES and SUBTYPES[value][0] == o.category else 1.0
    return _narrow(w, objs, miss)


@op("filter_static", ObjectSet, FrameID, returns=ObjectSet)
def filter_static(w: World, objs: ObjectSet, t: FrameID) -> ObjectSet:
    return _narrow(w, objs, lambda i: float(w.velocity(i, t) != "static"))


@op("filter_moving_velocity", ObjectSet, FrameID, returns=ObjectSet, args=MOVING, arg_required=False)
def filter_moving_velocity(w: World, objs: ObjectSet, t: FrameID, velocity: str | None = None) -> ObjectSet:
    keep = {velocity} if velocity else MOVING
    return _narrow(w, objs, lambda i: float(w.velocity(i, t) not in keep))


@op("filter_accelerating", ObjectSet, FrameID, returns=ObjectSet)
def filter_accelerating(w: World, objs: ObjectSet, t: FrameID) -> ObjectSet:
    return _narrow(w, objs, lambda i: float(not w.accelerating(i, t)))


@op("filter_floating", ObjectSet, FrameID, returns=ObjectSet)
def filter_floating(w: World, objs: ObjectSet, t: FrameID) -> ObjectSet:
    return _narrow(w, objs, lambda i: float(not w.floating(i, t)))


# ---- object queries ---------------------------------------------------------------------------------------------

@op("query_attributes", Object, returns=str, args=ATTRIBUTES)
def query_attributes(w: World, obj: Object, attribute: str) -> str:
    return w.obj(obj).color if attribute == "color" else w.obj(obj).shape


@op("is_static", Object, FrameID, returns=bool)
def is_static(w: World, obj: Object, t: FrameID) -> bool:
    return w.velocity(obj, t) == "static"


@op("is_moving_velocity", Object, FrameID, returns=bool, args=MOVING)
def is_moving_velocity(w: World, obj: Object, t: FrameID, velocity: str) -> bool:
    return w.velocity(obj, t) == velocity


@op("query_moving_velocity", Object, FrameID, returns=str)
def query_moving_velocity(w: World, obj: Object, t: FrameID) -> str:
    return w.velocity(obj, t)


@op("query_moving_direction", Object, FrameID, returns=str)
def query_moving_direction(w: World, obj: Object, t: FrameID) -> str:
    return w.direction(obj, t)


@op("is_accelerating", Object, FrameID, returns=bool)
def is_accelerating(w: World, obj: Object, t: FrameID) -> bool:
    return w.accelerating(obj, t)


@op("is_floating", Object, FrameID, returns=bool)
def is_floating(w: World, obj: Object, t: FrameID) -> bool:
    return w.floating(obj, t)


# ---- comparison -------------------------------------------------------------------------------------------------

@op("faster_velocity", Object, Object, FrameID, returns=bool)
def faster_velocity(w: World, a: Object, b: Object, t: FrameID) -> bool:
    return w.speed_difference(a, b, t) > 0


@op("slower_velocity", Object, Object, FrameID, returns=bool)
def slower_velocity(w: World, a: Object, b: Object, t: FrameID) -> bool:
    return w.speed_difference(a, b, t) < 0


# ---- counterfactual ---------------------------------------------------------------------------------------------

def _counterfactual(intervention: str):
    def run(w: World, obj: Object) -> CollisionEventSet:
        events = w.counterfactuals.get((int(obj), intervention))
        if events is None:
            raise ProgramError(f"no counterfactual run of object {obj} with '{intervention}'")
        return w.events if w.copy_factual else events
    return run


for _name, _iv in [("Counterfactual_static", "static"), ("Counterfactual_moving_slow", "slow"),
                   ("Counterfactual_moving_fast", "fast"), ("Counterfactual_accelerating", "accelerating"),
                   ("Counterfactual_floating", "floating")]:
    op(_name, Object, returns=CollisionEventSet)(_counterfactual(_iv))

COUNTERFACTUAL_OPS = {"static": "Counterfactual_static", "slow": "Counterfactual_moving_slow",
                      "fast": "Counterfactual_moving_fast", "accelerating": "Counterfactual_accelerating",
                      "floating": "Counterfactual_floating"}


# ---- others -----------------------------------------------------------------------------------------------------

@op("unique", (ObjectSet, CollisionEventSet), returns=(Object, Collision))
def unique(w: World, items: tuple):
    if isinstance(items, CollisionEventSet):
        _clear(w, items)
    if len(items) != 1 and not w.strict:
        if isinstance(items, ObjectSet) and items.misses:
            pool = items if items else items.misses
            return Object(min(pool, key=lambda i: (items.misses[i], -w.obj(i).confidence, i)))
        if isinstance(items, CollisionEventSet) and items:
            return items[0]  # several contacts of the pair: the first is the moment they collide
        if isinstance(items, CollisionEventSet) and len(items.about) == 2:
            a, b = items.about
            return Collision(w.closest(a, b)[0], min(a, b), max(a, b))
    if len(items) != 1:
        kind = "objects" if isinstance(items, ObjectSet) else "collisions"
        raise ProgramError(f"unique: {len(items)} {kind} match, expected exactly one")
    return Object(items[0]) if isinstance(items, ObjectSet) else items[0]


@op("exist", (ObjectSet, CollisionEventSet), returns=bool)
def exist(w: World, items: tuple) -> bool:
    if isinstance(items, CollisionEventSet):
        _clear(w, items)
    return len(items) > 0


# ---- the executor -----------------------------------------------------------------------------------------------

_TOKEN = re.compile(r"^([A-Za-z_]+)(?:\[([a-z_]+)\])?$")


def parse(program: str | list[str]) -> list[tuple[str, str | None]]:
    """'Objects filter_attributes[red]' or a token list -> [(operation, argument or None)], checked against OPS."""
    tokens = program.split() if isinstance(program, str) else list(program)
    if not tokens:
        raise ProgramError("empty program")
    out = []
    for tok in tokens:
        m = _TOKEN.match(tok)
        if not m or m.group(1) not in OPS:
            raise ProgramError(f"unknown token '{tok}'")
        name, arg = m.groups()
        o = OPS[name]
        if arg is None and o.args is not None and o.arg_required:
            raise ProgramError(f"{name} needs an argument, e.g. {name}[{sorted(o.args)[0]}]")
        if arg is not None and (o.args is None or arg not in o.args):
            raise ProgramError(f"'{tok}': {name} takes {'no argument' if o.args is None else 'another argument'}")
        out.append((name, arg))
    return out


def _type_name(t) -> str:
    return " or ".join(TYPE_NAMES[x] for x in t) if isinstance(t, tuple) else TYPE_NAMES[t]


def _accepts(t, value) -> bool:
    # bool is an int in Python, and Object / FrameID are both ints: check the exact kinds.
    kinds = t if isinstance(t, tuple) else (t,)
    return any(type(value) is k or (k is Collision and isinstance(value, Collision)) for k in kinds)


def answer_word(value) -> str:
    if type(value) is bool:
        return "true" if value else "false"
    if type(value) is str:
        return value
    raise ProgramError(f"the program ends in a {TYPE_NAMES.get(type(value), type(value).__name__)}, not an answer")


class Executor:
    """Runs many programs on one scene (its labels are computed once)."""

    def __init__(self, scene: Scene4D, labels_cfg: dict, strict: bool = False, seen: np.ndarray | None = None,
                 copy_factual: bool = False):
        self.world = World(scene, labels_cfg, strict, seen, copy_factual)

    def run(self, program: str | list[str], trace: list | None = None) -> str:
        """The program's answer word; `trace` (a list) receives (token, inputs, output) of every step."""
        stack: list = []
        for name, arg in parse(program):
            o = OPS[name]
            n = len(o.inputs)
            if len(stack) < n:
                raise ProgramError(f"{name} needs {n} inputs, the stack holds {len(stack)}")
            args = stack[len(stack) - n:] if n else []
            del stack[len(stack) - n:]
            for i, (t, v) in enumerate(zip(o.inputs, args)):
                if not _accepts(t, v):
                    raise ProgramError(f"{name}: input {i + 1} must be a {_type_name(t)}, got "
                                       f"{TYPE_NAMES.get(type(v), type(v).__name__)}")
            stack.append(o.fn(self.world, *args, arg) if arg is not None else o.fn(self.world, *args))
            if trace is not None:
                trace.append((f"{name}[{arg}]" if arg is not None else name, args, stack[-1]))
        if len(stack) != 1:
            raise ProgramError(f"the program leaves {len(stack)} values, expected one answer")
        return answer_word(stack[0])


def execute(program: str | list[str], scene: Scene4D, labels_cfg: dict, strict: bool = False) -> str:
    """Run one postfix program on a scene (truth or estimate) -> its answer word; ProgramError if it cannot run."""
    return Executor(scene, labels_cfg, strict).run(program)
