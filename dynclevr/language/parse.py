"""`QuestionParser`: question text -> program tokens (postfix), or None ("unparsed", counted wrong), never a crash.

A question is unparsed when it has more unknown words than `max_unknown_words` (a word one typo away from exactly
one vocabulary word counts as that word, so a misspelt colour such as 'gren' reads as 'green'), or when decoding
gives no well-formed program: no <eos> within `max_decode_len`, a special token, an operation sequence no training
program has, or one that is not a valid postfix program of dynclevr/questions/programs.py's operations.
"""

from __future__ import annotations

import io
import json
import pickle
from pathlib import Path

import torch

from dynclevr import WEIGHTS_DIR, DynclevrError
from dynclevr.artifacts import ArtifactError, atomic_path, write_json_atomic
from dynclevr.language.params import QParserParams
from dynclevr.language.seq2seq import Dims, Seq2Seq, one_thread, pad_batch
from dynclevr.language.tokenize import tokenize
from dynclevr.language.vocab import SPECIALS, UNK_ID, Vocab
from dynclevr.questions.programs import OPS, ProgramError
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
        out: list[list[str] | None] = [None] * len(texts)
        todo = [(i, ids) for i, t in enumerate(texts) if (ids := self._encode(t)) is not None]
        for start in range(0, len(todo), BATCH):
            chunk = todo[start:start + BATCH]
            src, lens = pad_batch([ids for _, ids in chunk])
            with torch.inference_mode(), one_thread():
                decoded = self.model.greedy(src, lens, self.params.max_decode_len)
            for (i, _), ids in zip(chunk, decoded):
                out[i] = self._program(ids)
        return out

    def _encode(self, text) -> list[int] | None:
        if not isinstance(text, str):
            return None
        words = tokenize(text)
        if not words or len(words) > MAX_WORDS:
            return None
        ids = [self.words.stoi[w] if w in self.words else self.words.stoi.get(self.words.closest(w), UNK_ID)
               for w in words]
        return ids if ids.count(UNK_ID) <= self.params.max_unknown_words else None

    def _program(self, ids: list[int] | None) -> list[str] | None:
        if not ids:
            return None
        tokens = self.programs.decode(ids)
        if any(t in SPECIALS for t in tokens) or program_shape(tokens) not in self.shapes:
            return None
        return tokens if well_formed(tokens) else None


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
