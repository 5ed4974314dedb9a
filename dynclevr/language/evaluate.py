"""`dynclevr eval-qparser`: how the question parser does on a split's questions, in wordings it saw in training and
in wordings it never saw, scored by program exact match and by the answer its program gives on the truth scene.

Every question of the split is said again from its program: its family's objects and slot values are read back out
of the program (`bindings`), then put into one phrasing from the grammar's seen pool and one from its held-out pool
(phrasing.py). The split's own texts (drawn as `annotate.phrasings` says) are scored as they are. Questions outside
what the parser can answer (OUT_OF_SCOPE_FILE: gibberish, objects no catalogue has, questions of no family) must
come back unparsed; their share is reported too. Last, questions written by hand, not from the grammar
(HANDWRITTEN_FILE), are scored by program exact match: the grammar's held-out phrasings are still its own phrases.
"""

from __future__ import annotations

import re
from collections import Counter, defaultdict
from pathlib import Path

import numpy as np

from dynclevr import DynclevrError
from dynclevr.language.parse import QuestionParser
from dynclevr.language.tokenize import tokenize
from dynclevr.language.vocab import NEIGHBOURS
from dynclevr.questions.generate import phrase, reference, templates
from dynclevr.questions.programs import Executor

OUT_OF_SCOPE_FILE = Path(__file__).with_name("out_of_scope.txt")
HANDWRITTEN_FILE = Path(__file__).with_name("handwritten.txt")
_CHAIN = r"Objects(?: filter_attributes\[[a-z_]+\])+ unique"


def out_of_scope() -> list[str]:
    return [line for line in OUT_OF_SCOPE_FILE.read_text().splitlines() if line and not line.startswith("#")]


def handwritten() -> list[tuple[str, str]]:
    """(text, program) of every question in HANDWRITTEN_FILE ('family | X | Y | slots | text')."""
    fams = {f["name"]: f for f in templates()["families"]}
    out = []
    try:
        text = HANDWRITTEN_FILE.read_text()
    except (OSError, UnicodeDecodeError) as e:
        raise DynclevrError(f"{HANDWRITTEN_FILE} is unreadable ({e}): restore it "
                            "(`git checkout -- dynclevr/language/handwritten.txt`) or reinstall dynclevr") from None
    for n, line in enumerate(text.splitlines(), 1):
        if not line.strip() or line.startswith("#"):
            continue
        try:
            family, x, y, slots, text = (part.strip() for part in line.split("|"))
            objects = {name: {"program": "Objects " + " ".join(f"filter_attributes[{v}]" for v in words.split())
                              + " unique"} for name, words in (("X", x), ("Y", y)) if words}
            values = {name: templates()["slots"][name][key]
                      for name, key in (kv.split("=") for kv in slots.split(",") if kv)}
            program = fams[family]["program"]
            for name, v in {**objects, **values}.items():
                program = program.replace(f"<{name}>", v["program"])
            out.append((text, " ".join(program.split())))
        except (ValueError, KeyError) as e:
            raise DynclevrError(f"{HANDWRITTEN_FILE}:{n}: expected 'family | X | Y | slots | text' naming a "
                                f"family, attribute values and slots of templates.json ({e})") from None
    return out


def _pattern(fam: dict) -> re.Pattern:
    """The family's program template as a regex whose groups are its objects and slots."""
    seen: set[str] = set()
    out = []
    for tok in fam["program"].split():
        m = re.fullmatch(r"<([A-Z]+)>", tok)
        if m and m.group(1) in fam["objects"]:
            name = m.group(1)
            out.append(f"(?P={name})" if name in seen else f"(?P<{name}>{_CHAIN})")
            seen.add(name)
        else:
            def slot(m):
                name = m.group(1)
                options = "|".join(re.escape(v["program"]) for v in templates()["slots"][name].values())
                if name in seen:
                    return f"(?P={name})"
                seen.add(name)
                return f"(?P<{name}>{options})"
            out.append(re.sub(r"<([A-Z]+)>", slot, re.escape(tok).replace(r"\<", "<").replace(r"\>", ">")))
    return re.compile(" ".join(out))


def bindings(fam: dict, program: str, rng: np.random.Generator) -> tuple[dict, dict] | None:
    """A family's program -> (objects {name: {text, program}}, slot keys {name: key}); None if it is not one."""
    m = _pattern(fam).fullmatch(program)
    if not m:
        return None
    values, slot_keys = {}, {}
    for name in fam["objects"]:
        attrs = tuple(re.findall(r"filter_attributes\[([a-z_]+)\]", m.group(name)))
        text, chain = reference(attrs, rng)
        values[name] = {"text": text, "program": chain}
    for name in fam.get("slots", []):
        slot_keys[name] = next(k for k, v in templates()["slots"][name].items() if v["program"] == m.group(name))
    return values, slot_keys


def rephrase(question: dict, pool: str, rng: np.random.Generator) -> str:
    fam = next(f for f in templates()["families"] if f["name"] == question["family"])
    bound = bindings(fam, question["program"], rng)
    if bound is None:
        raise DynclevrError(f"question {question['id']}: its program is not one of family {fam['name']}'s: "
                            "annotate the split again (`dynclevr annotate --split S --force`)")
    text, program = phrase(fam, *bound, rng, pool)
    assert program == question["program"], (program, question["program"])
    return text


SLIPS = ("swap", "wrong key", "left out", "extra key")


def typed_with_a_slip(text: str, rng: np.random.Generator) -> str:
    """The text as typed with one slip of the fingers in one of its words of 5+ letters (two neighbouring letters
    swapped, a neighbouring key hit instead or as well, a letter left out; never the first letter, which people get
    right): what people type, and what the parser's slip reading (vocab.slipped) is for."""
    words = text.split(" ")
    long_words = [i for i, w in enumerate(words) if sum(c.isalpha() for c in w) >= 5 and w.isascii()]
    if not long_words:
        return text
    i = long_words[rng.integers(len(long_words))]
    w = words[i]
    k = int(rng.integers(1, len(w) - 1))
    if not (w[k].isalpha() and w[k + 1].isalpha()):
        return text
    kind, c = SLIPS[rng.integers(len(SLIPS))], w[k].lower()
    near = sorted(NEIGHBOURS.get(c, {c}))
    key = near[rng.integers(len(near))]
    words[i] = {"swap": w[:k] + w[k + 1] + w[k] + w[k + 2:], "wrong key": w[:k] + key + w[k + 1:],
                "left out": w[:k] + w[k + 1:], "extra key": w[:k] + key + w[k:]}[kind]
    return " ".join(words)


def score(parser: QuestionParser, questions: list[dict], texts: list[str], executors: dict[str, Executor]) -> dict:
    parses = parser.analyse_batch(texts)
    exact = answered = unparsed = 0
    by_family: dict[str, list[bool]] = defaultdict(list)
    for q, p in zip(questions, parses):
        ok = p.program is not None and " ".join(p.program) == q["program"]
        exact += ok
        by_family[q["family"]].append(ok)
        unparsed += p.program is None
        if p.program is not None:
            try:
                answered += executors[q["scene"]].run(p.program) == q["answer"]
            except DynclevrError:
                pass
    n = max(1, len(questions))
    return {"questions": len(questions), "exact_match": exact / n, "answer_accuracy": answered / n,
            "unparsed": unparsed / n, "by_family": {f: float(np.mean(v)) for f, v in sorted(by_family.items())}}


def evaluate(parser: QuestionParser, questions: list[dict], truth: dict, labels_cfg: dict, seed: int = 0) -> dict:
    """-> {'seen': ..., 'heldout': ..., 'dataset': ..., 'dataset_slips': ..., 'handwritten': ..., 'out_of_scope':
    ...}; `truth` maps scene name -> Scene4D."""
    executors = {name: Executor(scene, labels_cfg) for name, scene in truth.items()}
    rng = np.random.default_rng(np.random.SeedSequence([seed, 0xE7A1]))
    texts = {pool: [rephrase(q, pool, rng) for q in questions] for pool in ("seen", "heldout")}
    out = {pool: score(parser, questions, texts[pool], executors) for pool in ("seen", "heldout")}
    # Held-out phrasings split by whether every word was in training: a new combination or sentence structure of
    # known words (generalisation a sequence model can learn) or a synonym never seen (a guess from the context).
    known = [all(w in parser.known for w in tokenize(t)) for t in texts["heldout"]]
    for key, keep in (("heldout_known_words", True), ("heldout_new_words", False)):
        pick = [i for i, k in enumerate(known) if k == keep]
        out[key] = score(parser, [questions[i] for i in pick], [texts["heldout"][i] for i in pick], executors)
    out["dataset"] = score(parser, questions, [q["text"] for q in questions], executors)
    out["dataset_slips"] = score(parser, questions, [typed_with_a_slip(q["text"], rng) for q in questions], executors)
    hand = handwritten()
    parses = parser.analyse_batch([t for t, _ in hand])
    right = [p.program is not None and " ".join(p.program) == program for (_, program), p in zip(hand, parses)]
    out["handwritten"] = {"questions": len(hand), "exact_match": float(np.mean(right)) if hand else 0.0,
                          "unparsed": float(np.mean([p.program is None for p in parses])) if hand else 0.0,
                          "missed": [t for (t, _), ok in zip(hand, right) if not ok]}
    oos = out_of_scope()
    parses = parser.analyse_batch(oos)
    out["out_of_scope"] = {"questions": len(oos), "unparsed": sum(p.program is None for p in parses) / len(oos),
                           "answered": [t for t, p in zip(oos, parses) if p.program is not None],
                           "reasons": dict(Counter(p.reason.split(":")[0].split(" (")[0] for p in parses))}
    return out


def markdown(result: dict) -> str:
    rows = [("phrasings seen in training", "seen"), ("held-out phrasings (never in training)", "heldout"),
            ("- of them, all words known (new combinations and sentences)", "heldout_known_words"),
            ("- of them, with a word never seen in training", "heldout_new_words"),
            ("the split's own texts", "dataset"),
            ("- of them, typed with one slip of the fingers (swap, wrong key, letter left out or added)",
             "dataset_slips")]
    lines = ["| questions | n | program exact match | answer accuracy (truth) | unparsed |", "|---|---|---|---|---|"]
    for label, key in rows:
        r = result[key]
        lines.append(f"| {label} | {r['questions']} | {100 * r['exact_match']:.2f}% | "
                     f"{100 * r['answer_accuracy']:.2f}% | {100 * r['unparsed']:.2f}% |")
    h = result["handwritten"]
    lines.append(f"| questions written by hand, not from the grammar | {h['questions']} | "
                 f"{100 * h['exact_match']:.2f}% | - | {100 * h['unparsed']:.2f}% |")
    o = result["out_of_scope"]
    lines.append(f"| out of scope (must be unparsed) | {o['questions']} | - | - | {100 * o['unparsed']:.2f}% |")
    worst = sorted(result["heldout"]["by_family"].items(), key=lambda kv: kv[1])[:5]
    lines += ["", "Held-out phrasings, lowest exact match by family: "
              + ", ".join(f"{f} {100 * v:.1f}%" for f, v in worst)]
    if h["missed"]:
        lines += ["", "Questions written by hand that the parser misses: " + "; ".join(f"'{t}'" for t in h["missed"])]
    if o["answered"]:
        lines += ["", "Out-of-scope questions given a program: " + "; ".join(f"'{t}'" for t in o["answered"])]
    return "\n".join(lines) + "\n"
