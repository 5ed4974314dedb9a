"""The phrasing grammar: how people word each question family (templates.json `lexicon` and each family's texts).

A text is a small grammar expression:
- `{a|b|c}` one of the alternatives, `[words]` the words or nothing,
- `@NAME` one phrase of the lexicon entry NAME (its `seen` phrases, or its `heldout` ones),
- `<X>`, `<Y>` (object descriptions) and `<A>`, `<A:key>` (slot values), filled in after expansion.

Each family lists `texts` and `heldout_texts` (sentence structures), each lexicon entry `seen` and `heldout` phrases.
A phrasing is *held out* when it uses a held-out structure or a held-out phrase. The question parser trains only on
phrasings that are not held out, so `dynclevr eval-qparser` can measure how it does on wordings it never saw; the
dataset's own questions draw from every phrasing, as CLEVR's do.
"""

from __future__ import annotations

import itertools
import re
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from dynclevr.config import ConfigError

POOLS = ("all", "seen", "heldout")
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

    def __init__(self, data: dict):
        self.lexicon = {name: {pool: [parse(t) for t in entry.get(pool, [])] for pool in ("seen", "heldout")}
                        for name, entry in data.get("lexicon", {}).items()}
        self.structures = {f["name"]: {"seen": list(f["texts"]), "heldout": list(f.get("heldout_texts", []))}
                           for f in data["families"]}
        self.slots = data.get("slots", {})
        for fam in data["families"]:
            if not fam["texts"]:
                raise ConfigError(f"templates.json family '{fam['name']}' has no texts")
            for combo in self.slot_combinations(fam):
                for text in fam["texts"] + fam.get("heldout_texts", []):
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
        if pool == "seen":
            node = _parse(fill_slots(s["seen"][rng.integers(len(s["seen"]))], slots))
            return _tidy(self._expand(node, rng, False)[0])
        everything = s["seen"] + s["heldout"]
        for _ in range(1000):
            k = int(rng.integers(len(everything)))
            text, held = self._expand(_parse(fill_slots(everything[k], slots)), rng, True)
            if pool == "all" or held or k >= len(s["seen"]):
                return _tidy(text)
        raise ConfigError(f"templates.json family '{family}' has no held-out phrasing")

    def _expand(self, node: Node, rng: np.random.Generator, any_pool: bool) -> tuple[str, bool]:
        """-> (text, whether a held-out phrase was used)."""
        if node.kind == "text":
            return node.value, False
        if node.kind == "seq":
            out = [self._expand(p, rng, any_pool) for p in node.parts]
            return "".join(t for t, _ in out), any(h for _, h in out)
        if node.kind == "alt":
            return self._expand(node.parts[rng.integers(len(node.parts))], rng, any_pool)
        if node.kind == "opt":
            return self._expand(node.parts[0], rng, any_pool) if rng.random() < 0.5 else ("", False)
        entry = self.lexicon[node.value]
        options = [(n, False) for n in entry["seen"]] + ([(n, True) for n in entry["heldout"]] if any_pool else [])
        choice, held = options[rng.integers(len(options))]
        text, inner = self._expand(choice, rng, any_pool)
        return text, held or inner

    # ---- enumeration (for counting phrasings and testing that held-out ones are absent from training) -------------

    def phrasings(self, family: str, pool: str, slots: dict | None = None, limit: int = 200_000) -> set[str]:
        """Every distinct phrasing of the family in the pool with these slot values (up to `limit`)."""
        s, out = self.structures[family], set()
        for text, held_structure in [(t, False) for t in s["seen"]] + [(t, True) for t in s["heldout"]]:
            for phrase, held in self._all(_parse(fill_slots(text, slots or {})), pool != "seen"):
                if pool == "all" or (pool == "seen" and not (held or held_structure)) or (
                        pool == "heldout" and (held or held_structure)):
                    out.add(_tidy(phrase))
                    if len(out) >= limit:
                        return out
        return out

    def _all(self, node: Node, any_pool: bool):
        if node.kind == "text":
            yield node.value, False
        elif node.kind == "seq":
            for combo in itertools.product(*[list(self._all(p, any_pool)) for p in node.parts]):
                yield "".join(t for t, _ in combo), any(h for _, h in combo)
        elif node.kind == "alt":
            for p in node.parts:
                yield from self._all(p, any_pool)
        elif node.kind == "opt":
            yield "", False
            yield from self._all(node.parts[0], any_pool)
        else:
            entry = self.lexicon[node.value]
            for pool, held in (("seen", False), ("heldout", True)):
                if held and not any_pool:
                    continue
                for n in entry[pool]:
                    for text, inner in self._all(n, any_pool):
                        yield text, held or inner


@lru_cache(maxsize=1)
def grammar() -> Grammar:
    from dynclevr.questions.generate import templates

    return Grammar(templates())
