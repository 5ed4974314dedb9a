"""`QuestionParser`: question text -> program tokens (postfix), or unparsed with a one-line reason, never a crash.

A question is unparsed (counted wrong) rather than given a confident wrong program when
- it is empty, or has more unknown words than `max_unknown_words` (a word one typo away from exactly one vocabulary
  word counts as that word, so a misspelt colour such as 'gren' reads as 'green');
- decoding gives no well-formed program: no <eos> within `max_decode_len`, a special token, an operation sequence no
  training program has, or not a valid postfix program of dynclevr/questions/programs.py's operations;
- the decoding's probability is below `min_confidence` (a wording unlike any the parser learnt);
- the program's object words disagree with the question's: every colour, sub-type and category the question names
  must be a `filter_attributes` argument of the program and the reverse (a pointer check: the sequence model may
  generalise a sentence, never invent or drop an object).
"""

from __future__ import annotations

import io
import json
import pickle
from collections import Counter
from dataclasses import dataclass
from pathlib import Path

import torch

from dynclevr import WEIGHTS_DIR, DynclevrError
from dynclevr.artifacts import ArtifactError, atomic_path, write_json_atomic
from dynclevr.language.params import QParserParams
from dynclevr.language.seq2seq import Dims, Seq2Seq, one_thread, pad_batch
from dynclevr.language.tokenize import tokenize
from dynclevr.language.vocab import SPECIALS, UNK_ID, Vocab
from dynclevr.questions.programs import ATTRIBUTE_VALUES, OPS, ProgramError
from dynclevr.questions.programs import parse as parse_program

QUESTION_VOCAB = "question_vocab.json"
PROGRAM_VOCAB = "program_vocab.json"
SETTINGS = "parser.json"   # model dims, params and the training programs' shapes: what `load` rebuilds from
MODEL = "model.pt"
MAX_WORDS = 200      # far beyond any template question; bounds the cost of a pasted essay
BATCH = 256


def operation(token: str) -> str:
    """'filter_attributes[red]' -> 'filter_attributes': a program token without its argument."""
    return token.split("[", 1)[0]


def program_shape(tokens: list[str]) -> str:
    return " ".join(operation(t) for t in tokens)


# Attribute values as words: 'school_bus' is said 'school bus'; longest first, so 'school bus' is not read as 'bus'.
_NAMES = sorted(((tuple(v.split("_")), v) for v in ATTRIBUTE_VALUES), key=lambda kv: -len(kv[0]))


def mentions(words: list[str]) -> Counter:
    """The attribute values a question names: ['the', 'school', 'bus', ...] -> Counter({'school_bus': 1})."""
    out, i = Counter(), 0
    while i < len(words):
        for name, value in _NAMES:
            if tuple(words[i:i + len(name)]) == name:
                out[value] += 1
                i += len(name)
                break
        else:
            i += 1
    return out


def program_mentions(tokens: list[str]) -> Counter:
    return Counter(t[len("filter_attributes["):-1] for t in tokens if t.startswith("filter_attributes["))


@dataclass(frozen=True)
class Parse:
    """A question's program (None: unparsed), why it is unparsed, and the decoding's probability."""
    program: list[str] | None
    reason: str = ""
    confidence: float = 0.0


class QuestionParser:
    def __init__(self, model: Seq2Seq, words: Vocab, programs: Vocab, params: QParserParams, shapes: set[str]):
        self.model = model.eval()
        self.words, self.programs, self.params = words, programs, params
        # The operation sequences of the training programs: a decoded program must have one of them (as well as
        # pass `well_formed`), so a decoding that wanders off every template is unparsed, not executed.
        self.shapes = shapes

    @classmethod
    def load(cls, dir: Path = WEIGHTS_DIR / "qparser") -> "QuestionParser":
        dir = Path(dir)
        hint = f"run `dynclevr train qparser --out {dir}`"
        try:
            settings = json.loads((dir / SETTINGS).read_text())
            params = QParserParams.from_dict(settings["params"])
            words, programs = Vocab.load(dir / QUESTION_VOCAB), Vocab.load(dir / PROGRAM_VOCAB)
            model = Seq2Seq(Dims(**settings["model"]))
            model.load_state_dict(torch.load(dir / MODEL, map_location="cpu", weights_only=True))
            shapes = set(settings["shapes"])
        except FileNotFoundError as e:
            raise ArtifactError(f"question parser weights incomplete ({e.filename} is missing): {hint}") from None
        except ArtifactError:
            raise
        except (ValueError, KeyError, TypeError, RuntimeError, pickle.UnpicklingError, DynclevrError) as e:
            raise ArtifactError(f"question parser weights in {dir} are unreadable ({e}): {hint}") from None
        return cls(model, words, programs, params, shapes)

    def save(self, dir: Path) -> None:
        dir = Path(dir)
        dir.mkdir(parents=True, exist_ok=True)
        # Through a buffer: torch.save names the archive's root folder after the file, here a random temporary
        # name, which would make the same weights differ byte for byte.
        buf = io.BytesIO()
        torch.save(self.model.state_dict(), buf)
        with atomic_path(dir / MODEL) as tmp:
            tmp.write_bytes(buf.getvalue())
        self.words.save(dir / QUESTION_VOCAB)
        self.programs.save(dir / PROGRAM_VOCAB)
        write_json_atomic(dir / SETTINGS, {"model": self.model.dims.to_dict(), "params": self.params.to_dict(),
                                           "shapes": sorted(self.shapes)})

    def parse(self, text: str) -> list[str] | None:
        return self.parse_batch([text])[0]

    def parse_batch(self, texts: list[str]) -> list[list[str] | None]:
        return [p.program for p in self.analyse_batch(texts)]

    def analyse_batch(self, texts: list[str]) -> list[Parse]:
        out: list[Parse | None] = [None] * len(texts)
        todo = []
        for i, t in enumerate(texts):
            words, why = self._words(t)
            if why:
                out[i] = Parse(None, why)
            else:
                todo.append((i, words))
        for start in range(0, len(todo), BATCH):
            chunk = todo[start:start + BATCH]
            src, lens = pad_batch([[self.words.stoi.get(w, UNK_ID) for w in words] for _, words in chunk])
            with torch.inference_mode(), one_thread():
                decoded = self.model.greedy(src, lens, self.params.max_decode_len)
            for (i, words), (ids, p) in zip(chunk, decoded):
                out[i] = self._check(words, ids, p)
        return out

    def _words(self, text) -> tuple[list[str], str]:
        """The question's words, typos fixed; or a reason it cannot be parsed."""
        if not isinstance(text, str) or not text.strip():
            return [], "empty question"
        words = tokenize(text)
        if not words:
            return [], "empty question"
        if len(words) > MAX_WORDS:
            return [], f"too long ({len(words)} words, at most {MAX_WORDS})"
        words = [w if w in self.words else (self.words.closest(w) or w) for w in words]
        unknown = [w for w in words if w not in self.words]
        if len(unknown) > self.params.max_unknown_words:
            return [], "unknown words: " + ", ".join(f"'{w}'" for w in dict.fromkeys(unknown))
        return words, ""

    def _check(self, words: list[str], ids: list[int] | None, p: float) -> Parse:
        if not ids:
            return Parse(None, "no program came out of the decoder", p)
        tokens = self.programs.decode(ids)
        if any(t in SPECIALS for t in tokens) or program_shape(tokens) not in self.shapes or not well_formed(tokens):
            return Parse(None, "the question matches no known question family", p)
        if p < self.params.min_confidence:
            return Parse(None, f"not a question the parser knows how to read (confidence {p:.2f})", p)
        # As sets: a program names an object once per use ('when X collides with Y' uses X twice), a question once
        # per mention ('when X and Y collide, is X ...').
        said, used = set(mentions(words)), set(program_mentions(tokens))
        if said != used:
            extra, missing = sorted(used - said), sorted(said - used)
            why = (f"the program would refer to {', '.join(extra)}, which the question does not name" if extra else
                   f"the question names {', '.join(w.replace('_', ' ') for w in missing)}, which no question family "
                   "here can use")
            return Parse(None, why, p)
        return Parse(tokens, "", p)


def well_formed(tokens: list[str]) -> bool:
    """Every token an operation with an argument it accepts, and a postfix stack that ends with one value."""
    try:
        ops = parse_program(tokens)
    except ProgramError:
        return False
    depth = 0
    for name, _ in ops:
        n = len(OPS[name].inputs)
        if depth < n:
            return False
        depth += 1 - n
    return depth == 1
