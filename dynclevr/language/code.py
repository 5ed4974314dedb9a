"""Questions typed as code: engineers ask the way they write it ('speed(red_sedan, t=0)?', 'collides(yellow sedan,
purple mountain bike) -> bool?', 'blueJet.is_fast at start?', "SELECT color FROM vehicles WHERE speed = 'static' AND
t = start"). `code_as_said` says such a text as the English the grammar says, before the words are read; a text with
no mark of code is left as it is. Names are the vehicles' (snake_case and camelCase read apart, 'the' before them),
calls and members the properties the questions ask (speed, direction, colour, type, collisions, a comparison), and
't=0' the start; what it does not know stays as typed, for the parser to refuse.
"""

from __future__ import annotations

import re

from dynclevr.colors import COLOR_NAMES
from dynclevr.language.references import EVERYDAY_NAMES, OBJECT_WORDS

_CODE = re.compile(r"[a-z][A-Z]|[A-Za-z0-9]_[A-Za-z0-9]|==|->|=>|\u2192|\u21d2|[a-z]\(|\bSELECT\b|\bt\s*=\s*\w|"
                   r"^\s*(//|#)|[a-z]{2}\.[a-z_]{2,}|\b(?:vel|velocity|speed)\s*[<>]")
_COLOURS = "|".join(COLOR_NAMES)
NAME_WORDS = OBJECT_WORDS | {name.split()[0] for name in EVERYDAY_NAMES}   # a vehicle's name starts so
SPEED_NAMES = ("speed", "velocity", "vel", "v")
DIRECTION_NAMES = ("direction", "heading", "dir")
COLLIDE_NAMES = ("collides", "collide", "collision", "collided", "crash", "crashes", "hits")
COLOUR_NAMES = ("color_of", "colour_of", "color", "colour")
TYPE_NAMES = ("type_of", "shape_of", "kind_of", "vehicle_type", "type", "shape")
IF_NAMES = ("what_if", "whatif", "counterfactual", "if", "suppose", "hypothetical", "intervene", "intervention")
# a member that says what a vehicle is ('blueJet.is_fast'), or what it has ('red_sedan.speed')
STATES = {"is_fast": "fast", "fast": "fast", "is_slow": "slow", "slow": "slow", "is_static": "static",
          "static": "static", "is_moving": "moving", "is_floating": "floating", "floating": "floating",
          "is_accelerating": "accelerating", "accelerating": "accelerating"}
HAS = {**dict.fromkeys(SPEED_NAMES, "speed"), "v0": "speed at the start", **dict.fromkeys(DIRECTION_NAMES, "direction"),
       "color": "colour", "colour": "colour", "type": "type"}
MAX_CHARS = 1000
_TIME = r"(?:\s*(?:@|[Aa][Tt])?\s*t\s*=\s*(?:0|zero|start)\b|\s*@\s*start\b|\s+at\s+start\b)"
_VEHICLE = r"(?:the )?((?:" + _COLOURS + r") [a-z ]*?)"   # a vehicle's name, as `_names` leaves it
_PAIR = r"the (?:" + _COLOURS + r") [^,:?.=>]+? and the (?:" + _COLOURS + r") [^,:?.=>]+? collide\b"   # `_calls`'
_KEYWORD = re.compile(r"(?:t|at|time|when)\s*=\s*[^=]+|at the start")


def _times(text: str) -> str:
    text = re.sub(r"\bfrom\s+(?:t\s*=\s*(?:0|zero|start)|start)\b", "from the start", text)
    return re.sub(_TIME, " at the start", text)


def _names(text: str) -> str:
    """'red_sedan' -> 'the red sedan', 'yellowDoubleDecker' -> 'the yellow double decker'."""
    def name(m: re.Match) -> str:
        words = re.sub(r"(?<=[a-z])(?=[A-Z])", " ", m.group(0)).replace("_", " ").lower()
        return ("the " if words.split()[0] in COLOR_NAMES else "") + words
    text = re.sub(r"\b(?:" + "|".join(COLOR_NAMES) + r")(?:_[a-z]+|[A-Z][a-z]+)+\b",
                  name, text, flags=re.IGNORECASE)
    text = re.sub(r"\b(?:" + _COLOURS + r")[A-Z][a-z]+(?:[A-Z][a-z]+)*\b", name, text)
    return re.sub(r"\b(?<!the )(?<!a )(" + _COLOURS + r") (?=(\w+))",
                  lambda m: f"the {m.group(1)} " if m.group(2) in NAME_WORDS else m.group(0), text)


def _the(arg: str) -> str:
    arg = arg.strip().strip("'\"")
    return arg if arg.split()[:1] in (["the"], ["a"], ["it"], ["they"]) else "the " + arg


def _calls(text: str) -> str:
    def at(keyword: str | None) -> str:
        if not keyword:
            return ""
        value = keyword.split("=", 1)[-1].strip().strip("'\"")
        return " at the start" if value in ("0", "zero", "start", "at the start") else \
            " when they collide" if re.search(r"collision|collide|impact|crash", value) else f" at {value}"

    def call(m: re.Match) -> str:
        name, args = m.group(1).lower(), [a.strip() for a in m.group(2).split(",") if a.strip()]
        keyword = next((a for a in args if _KEYWORD.fullmatch(a)), None)
        args = [a for a in args if not _KEYWORD.fullmatch(a)]
        when = at(keyword)
        if name in SPEED_NAMES and len(args) == 1:
            return f"the speed of {_the(args[0])}{when}"
        if name in DIRECTION_NAMES and len(args) == 1:
            return f"the direction of {_the(args[0])}{when}"
        if name in COLLIDE_NAMES and len(args) == 2:
            return f"{_the(args[0])} and {_the(args[1])} collide"
        if name in ("slower", "faster") and len(args) == 2:
            return f"is {_the(args[0])} {name} than {_the(args[1])}{when}"
        if name in COLOUR_NAMES + TYPE_NAMES and len(args) == 1:
            said = "colour" if name in COLOUR_NAMES else "type"
            vehicle = re.sub(r"^(?:the )?vehicle where (\w+) ==? true", r"the vehicle that is \1", args[0],
                             flags=re.IGNORECASE)
            return f"the {said} of {_the(vehicle)}"
        if name in IF_NAMES and len(args) == 1:
            return f"if {args[0]}"
        return m.group(0)
    before = None
    while before != text:
        before, text = text, re.sub(r"\b([A-Za-z_]+)\(\s*([^()]*)\)", call, text)
    return text


def _members(text: str) -> str:
    text = re.sub(_VEHICLE + r"\.collides_with\(\s*\??\s*\)\.(colou?r|type)\b",
                  lambda m: f"what {'type' if m.group(2) == 'type' else 'colour'} is the vehicle the {m.group(1)} "
                            "collides with", text)

    def state(m: re.Match) -> str:
        member, value = m.group(2), m.group(3)
        if member not in STATES and member not in HAS:
            return m.group(0)
        return f"the {m.group(1)} is {STATES.get(member, value) if value.lower() == 'true' else value}"
    text = re.sub(_VEHICLE + r"\.(\w+)\s*(?:==|=)\s*'?(\w+)'?", state, text)
    text = re.sub(r"\.(\w+)\b", lambda m: f" is {STATES[m.group(1)]}" if m.group(1) in STATES else
                  f"'s {HAS[m.group(1)]}" if m.group(1) in HAS else m.group(0), text)
    return text


def _compared(text: str) -> str:
    """'the speed of A at the start > the speed of B at the start' -> 'is A faster than B at the start'."""
    # (and a note's 'green motorbike vel > red airliner vel', its vehicles named by colour)
    term = (r"(?:the speed of (?P<{0}>the [a-z ]+?)|(?P<{0}2>the [a-z ]+?)'s speed|(?P<{0}3>(?:the )?(?:" + _COLOURS
            + r") [a-z]+(?: [a-z]+)?) (?:vel|velocity|speed))(?P<{0}t> at the start)?")
    m = re.search(term.format("a") + r"\s*(?P<op>[<>])\s*" + term.format("b") + r"(?=\s*[?.,:]|\s*$|\s+when\b)", text)
    if not m:
        return text
    a, b = (m.group(k) or m.group(k + "2") or _the(m.group(k + "3")) for k in ("a", "b"))
    when = m.group("at") or m.group("bt") or ""
    return text[:m.start()] + f"is {a} {'faster' if m.group('op') == '>' else 'slower'} than {b}{when}" + \
        text[m.end():]


def _selected(text: str) -> str:
    """"SELECT color FROM vehicles WHERE speed = 'static' AND t = start" -> 'what colour is the vehicle that is
    static at the start'."""
    m = re.match(r"\s*select\s+(.+?)(?:\s+from\s+\w+)?\s+where\s+(.+?)\s*([?.]?)\s*$", text, flags=re.IGNORECASE)
    if not m:
        return text
    what, conditions = m.group(1).strip(), re.split(r"\s+and\s+", m.group(2), flags=re.IGNORECASE)
    when = " at the start" if any(re.fullmatch(r"t\s*=\s*(0|start|zero)|at the start", c.strip()) for c in conditions) \
        else ""
    states = []
    for c in conditions:
        c = c.strip()
        if re.fullmatch(r"t\s*=\s*(0|start|zero)|at the start", c):
            continue
        k = re.fullmatch(r"(\w+)\s*==?\s*'?(\w+)'?", c)
        if not k:
            return text
        states.append(k.group(1) if k.group(2).lower() == "true" else k.group(2))
    if what.lower() in COLOUR_NAMES + TYPE_NAMES and len(states) == 1:
        said = "colour" if what.lower() in COLOUR_NAMES else "type"
        return f"what {said} is the vehicle that is {states[0]}{when} ?"
    return f"{what}{when} ?" if not states else text


def code_as_said(text: str) -> tuple[str, tuple[tuple[str, str], ...]]:
    """A question typed as code said as the grammar says it, with what was read so; the text as it is and () where
    it shows no mark of code."""
    # (a text longer than any question is left to the parser's own bound on words: these patterns are not linear)
    if not isinstance(text, str) or len(text) > MAX_CHARS or not _CODE.search(text):
        return text, ()
    said = re.sub(r"\s+", " ", text).replace("\u2192", "->").replace("\u21d2", "=>")   # a typeset arrow
    said = re.sub(r"^\s*(?://+|#+)\s*", "", said)                                  # a comment's mark before it
    said = re.sub(r"(?<=[?.!])\s*(?://|#).*$|\s+(?://|#)\s*[a-z ]*$", "", said)    # ... and a comment after it
    said = re.sub(r"(?:->|=>)\s*(?:bool|boolean)\b\s*\??", "?", said)
    said = re.sub(r"(?:->|=>)\s*\{\s*(\w+)\s*,\s*(\w+)\s*,\s*(\w+)\s*\}", r": \1, \2 or \3", said)
    said = re.sub(r"^\s*assert\s+", "is it true that ", said)
    said = _names(said)
    said = _times(said)
    said = _selected(said)
    said = re.sub(r"\s+\((?:i\.e\.|ie|e\.g\.)[^()]*\)|\s+\([^()]*[=<>/][^()]*\)", "", said)   # a gloss
    said = _members(said)
    said = _calls(said)
    said = _compared(said)
    said = re.sub(r"\bset (?=the )", "suppose ", said)
    # a collision as a time ('speed(bus) @ collision(bus, car)'), as a question, said first
    said = re.sub(r"(?:@|\bat t\s*=|\bon|\bat)\s+(" + _PAIR + ")", r"when \1", said)
    said = re.sub(r"(^|[:,.]\s*)(" + _PAIR + ")", r"\1do \2", said)
    said = re.sub(r"^(the (?:" + _COLOURS + r") [a-z ]+?) is (\w+)", r"is \1 \2", said)
    said = re.sub(r"\s*=\s*\?\s*$", " ?", said)
    said = re.sub(r"^if ([^:]+?)\s*:\s*", r"if \1 , ", said)
    # what follows a condition's arrow is what it asks: a sentence of its own, as the parser reads a condition
    imagined = re.match(r"\s*(?:counterfactual|cf|hypothetical|intervention|what if|what-if|whatif|suppose|if)\b", said)
    said = re.sub(r"\s*(?:->|=>)\s*", " . " if imagined else " , ", said)
    said = re.sub(r"(^|[:,.]\s*)(" + _PAIR + ")", r"\1do \2", said)
    said = re.sub(r"\s*@\s*(?=when|the)", " ", said)
    said = re.sub(r"\s+", " ", said).strip()
    return said, ((text.strip(), said),) if said != text.strip() else ()
