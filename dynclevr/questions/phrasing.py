"""The phrasing grammar: how people word each question family (templates.json `lexicon` and each family's texts).

A text is a small grammar expression:
- `{a|b|c}` one of the alternatives, `[words]` the words or nothing,
- `@NAME` one phrase of the lexicon entry NAME (its `seen` phrases, or its `heldout` ones),
- `<X>`, `<Y>` (object descriptions) and `<A>`, `<A:key>` (slot values), filled in after expansion.

Each family lists `texts` and `heldout_texts` (sentence structures), each lexicon entry `seen` and `heldout` phrases.
A phrasing is *held out* when it uses a held-out structure or a held-out phrase. The question parser trains only on
phrasings that are not held out, so `dynclevr eval-qparser` can measure how it does on wordings it never saw; the
dataset's own questions draw from every phrasing, as CLEVR's do.

`taught.json` adds structures and phrases that only the question parser's training draws (pool 'train': seen and
taught, never held out): sentence forms people use that the dataset's texts need not hold (passives, a fronted
reference, a possessive), so adding to them changes no dataset question.
"""

from __future__ import annotations

import itertools
import json
import re
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

import numpy as np

from dynclevr.config import ConfigError

POOLS = ("all", "seen", "heldout", "train")
TAUGHT_PATH = Path(__file__).with_name("taught.json")
_LEX = re.compile(r"@([A-Z_]+)")


@dataclass(frozen=True)
class Node:
    """kind: 'text' (value: str), 'seq' (parts), 'alt' (options), 'opt' (one part), 'lex' (value: the name)."""
    kind: str
    value: object = None
    parts: tuple = ()


def parse(expr: str) -> Node:
    """A grammar expression -> its tree; ConfigError naming the expression if the brackets do not balance."""
    pos = 0

    def seq(stop: str) -> Node:
        nonlocal pos
        parts, text = [], ""
        while pos < len(expr) and expr[pos] not in stop:
            c = expr[pos]
            if c in "{[":
                if text:
                    parts.append(Node("text", text))
                    text = ""
                pos += 1
                if c == "{":
                    options = [seq("|}")]
                    while pos < len(expr) and expr[pos] == "|":
                        pos += 1
                        options.append(seq("|}"))
                    close = "}"
                    node = Node("alt", parts=tuple(options))
                else:
                    node = Node("opt", parts=(seq("]"),))
                    close = "]"
                if pos >= len(expr) or expr[pos] != close:
                    raise ConfigError(f"templates.json: unbalanced '{c}' in {expr!r}")
                pos += 1
                parts.append(node)
            elif c == "@":
                m = _LEX.match(expr, pos)
                if not m:
                    raise ConfigError(f"templates.json: '@' without an upper-case lexicon name in {expr!r}")
                if text:
                    parts.append(Node("text", text))
                    text = ""
                parts.append(Node("lex", m.group(1)))
                pos = m.end()
            else:
                text += c
                pos += 1
        if text:
            parts.append(Node("text", text))
        return Node("seq", parts=tuple(parts))

    tree = seq("")
    if pos != len(expr):
        raise ConfigError(f"templates.json: unexpected '{expr[pos]}' in {expr!r}")
    return tree


def _tidy(text: str) -> str:
    text = re.sub(r"\s+", " ", text).strip()
    return re.sub(r"\s+([?,;:.])", r"\1", text)


def fill_slots(expr: str, slots: dict[str, dict]) -> str:
    """Put the slot values' grammar texts in: '<VQ>' -> '@STATIC', '<VF:adj>' -> '@STATIC_ADJ'."""
    for name, value in slots.items():
        for key, text in value.items():
            if key != "program":
                expr = expr.replace(f"<{name}:{key}>", text)
        expr = expr.replace(f"<{name}>", value["text"])
    return expr


_parse = lru_cache(maxsize=4096)(parse)


class Grammar:
    """The lexicon and every family's structures (parsed on first use)."""

    def __init__(self, data: dict, taught: dict | None = None):
        taught = taught or {"lexicon": {}, "families": {}}
        unknown = (set(taught["lexicon"]) - set(data.get("lexicon", {}))) | (
            set(taught["families"]) - {f["name"] for f in data["families"]})
        if unknown:
            raise ConfigError(f"taught.json names {sorted(unknown)}, which templates.json lacks")
        self.lexicon = {name: {**{pool: [parse(t) for t in entry.get(pool, [])] for pool in ("seen", "heldout")},
                               "taught": [parse(t) for t in taught["lexicon"].get(name, [])]}
                        for name, entry in data.get("lexicon", {}).items()}
        self.structures = {f["name"]: {"seen": list(f["texts"]), "heldout": list(f.get("heldout_texts", [])),
                                       "taught": list(taught["families"].get(f["name"], []))}
                           for f in data["families"]}
        self.slots = data.get("slots", {})
        for fam in data["families"]:
            if not fam["texts"]:
                raise ConfigError(f"templates.json family '{fam['name']}' has no texts")
            for combo in self.slot_combinations(fam):
                for text in [t for pool in self.structures[fam["name"]].values() for t in pool]:
                    self._check(_parse(fill_slots(text, combo)), fam["name"])
        for entry in self.lexicon.values():
            for nodes in entry.values():
                for node in nodes:
                    self._check(node, "lexicon")

    def slot_combinations(self, fam: dict) -> list[dict[str, dict]]:
        combos: list[dict] = [{}]
        for s in fam.get("slots", []):
            combos = [{**c, s: v} for c in combos for v in self.slots[s].values()]
        return combos

    def _check(self, node: Node, where: str) -> None:
        if node.kind == "lex" and node.value not in self.lexicon:
            raise ConfigError(f"templates.json ({where}): unknown lexicon entry @{node.value}")
        for p in node.parts:
            self._check(p, where)

    # ---- sampling -------------------------------------------------------------------------------------------------

    def sample(self, family: str, rng: np.random.Generator, pool: str = "all", slots: dict | None = None) -> str:
        """One phrasing of the family (objects still as <X>, <Y>) with the slot values `slots` (name -> the
        templates.json slot value), drawn from the pool: 'all', 'seen' (no held-out structure or phrase) or
        'heldout' (at least one of them). Every choice is uniform."""
        if pool not in POOLS:
            raise ValueError(f"pool must be one of {POOLS}")
        s, slots = self.structures[family], slots or {}
        if pool in ("seen", "train"):
            pools = ("seen",) if pool == "seen" else ("seen", "taught")
            texts = [t for p in pools for t in s[p]]
            node = _parse(fill_slots(texts[rng.integers(len(texts))], slots))
            return _tidy(self._expand(node, rng, pools)[0])
        everything = s["seen"] + s["heldout"]
        for _ in range(1000):
            k = int(rng.integers(len(everything)))
            text, held = self._expand(_parse(fill_slots(everything[k], slots)), rng, ("seen", "heldout"))
            if pool == "all" or held or k >= len(s["seen"]):
                return _tidy(text)
        raise ConfigError(f"templates.json family '{family}' has no held-out phrasing")

    def _expand(self, node: Node, rng: np.random.Generator, pools: tuple[str, ...]) -> tuple[str, bool]:
        """-> (text, whether a held-out phrase was used); lexicon phrases drawn from `pools`."""
        if node.kind == "text":
            return node.value, False
        if node.kind == "seq":
            out = [self._expand(p, rng, pools) for p in node.parts]
            return "".join(t for t, _ in out), any(h for _, h in out)
        if node.kind == "alt":
            return self._expand(node.parts[rng.integers(len(node.parts))], rng, pools)
        if node.kind == "opt":
            return self._expand(node.parts[0], rng, pools) if rng.random() < 0.5 else ("", False)
        entry = self.lexicon[node.value]
        options = [(n, pool == "heldout") for pool in pools for n in entry[pool]]
        choice, held = options[rng.integers(len(options))]
        text, inner = self._expand(choice, rng, pools)
        return text, held or inner

    # ---- enumeration (for counting phrasings and testing that held-out ones are absent from training) -------------

    def phrasings(self, family: str, pool: str, slots: dict | None = None, limit: int = 200_000) -> set[str]:
        """Every distinct phrasing of the family in the pool with these slot values (up to `limit`)."""
        s, out = self.structures[family], set()
        pools = {"seen": ("seen",), "train": ("seen", "taught")}.get(pool, ("seen", "heldout"))
        for structure in pools:
            for text in s[structure]:
                for phrase, held in self._all(_parse(fill_slots(text, slots or {})), pools):
                    held = held or structure == "heldout"
                    if held if pool == "heldout" else pool == "all" or not held:
                        out.add(_tidy(phrase))
                        if len(out) >= limit:
                            return out
        return out

    def _all(self, node: Node, pools: tuple[str, ...]):
        if node.kind == "text":
            yield node.value, False
        elif node.kind == "seq":
            for combo in itertools.product(*[list(self._all(p, pools)) for p in node.parts]):
                yield "".join(t for t, _ in combo), any(h for _, h in combo)
        elif node.kind == "alt":
            for p in node.parts:
                yield from self._all(p, pools)
        elif node.kind == "opt":
            yield "", False
            yield from self._all(node.parts[0], pools)
        else:
            for pool in pools:
                for n in self.lexicon[node.value][pool]:
                    for text, inner in self._all(n, pools):
                        yield text, pool == "heldout" or inner


def taught() -> dict:
    """taught.json: {"lexicon": {NAME: [phrases]}, "families": {family: [structures]}}; a missing file is none."""
    if not TAUGHT_PATH.exists():
        return {"lexicon": {}, "families": {}}
    try:
        data = json.loads(TAUGHT_PATH.read_text())
        return {"lexicon": dict(data.get("lexicon", {})), "families": dict(data.get("families", {}))}
    except (json.JSONDecodeError, AttributeError, TypeError) as e:
        raise ConfigError(f"{TAUGHT_PATH} is not a JSON object of 'lexicon' and 'families' ({e}): restore it from "
                          "the repository") from None


@lru_cache(maxsize=1)
def grammar() -> Grammar:
    from dynclevr.questions.generate import templates

    return Grammar(templates(), taught())
