"""Questions for the question parser, drawn from the phrasing grammar with random objects: no scene is needed to
learn how a question maps to its program, so the data is unlimited and any split of phrasings can be held out.

`synthesize(n, seed, pool)`: n questions, families uniform, references and slot values at random; pool 'train' for
training (seen and taught phrasings, no held-out structure or phrase: dynclevr/questions/phrasing.py), 'heldout' to
measure generalisation.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from dynclevr.assets.catalogue import CATEGORIES, SUBTYPES
from dynclevr.colors import COLOR_NAMES
from dynclevr.questions.generate import REFERENCES, phrase, reference, templates

VALUES = {"color": tuple(COLOR_NAMES), "shape": tuple(SUBTYPES), "category": tuple(CATEGORIES)}
# Ways people open or close a question that change nothing (training only: they teach the parser to look past them).
OPENINGS = ("", "", "", "", "", "", "Question: ", "Tell me: ", "Please answer: ", "Can you tell me: ", "Quick one: ")


@dataclass(frozen=True)
class Example:
    family: str
    text: str
    program: str


def random_values(rng: np.random.Generator) -> tuple[str, ...]:
    """A random object reference (its attribute values), with generate.REFERENCES' weights."""
    w = np.array([wt for _, wt in REFERENCES])
    attrs = REFERENCES[rng.choice(len(REFERENCES), p=w / w.sum())][0]
    return tuple(VALUES[a][rng.integers(len(VALUES[a]))] for a in attrs)


def example(fam: dict, rng: np.random.Generator, pool: str) -> Example:
    values: dict[str, dict] = {}
    used: set[tuple] = set()
    for name in fam["objects"]:
        while (v := random_values(rng)) in used:
            pass
        used.add(v)
        text, program = reference(v, rng)
        values[name] = {"text": text, "program": program}
    slot_keys = {s: list(templates()["slots"][s])[rng.integers(len(templates()["slots"][s]))]
                 for s in fam.get("slots", [])}
    text, program = phrase(fam, values, slot_keys, rng, pool)
    return Example(fam["name"], text, program)


def augment(text: str, rng: np.random.Generator) -> str:
    """Casual writing: an opening, no closing mark, all lower case."""
    opening = OPENINGS[rng.integers(len(OPENINGS))]
    if opening:
        text = opening + text[0].lower() + text[1:]
    if rng.random() < 0.2:
        text = text.rstrip("?.")
    return text.lower() if rng.random() < 0.2 else text


def synthesize(n: int, seed: int, pool: str = "train", augmented: bool = False) -> list[Example]:
    rng = np.random.default_rng(np.random.SeedSequence([seed, 0x9A5]))
    fams = templates()["families"]
    out = []
    for _ in range(n):
        e = example(fams[rng.integers(len(fams))], rng, pool)
        out.append(Example(e.family, augment(e.text, rng), e.program) if augmented else e)
    return out
