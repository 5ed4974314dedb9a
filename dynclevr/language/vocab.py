"""Token <-> id maps for the question words and the program tokens, saved as JSON."""

from __future__ import annotations

import itertools
import json
import re
from collections import Counter
from difflib import SequenceMatcher
from pathlib import Path
from typing import Iterable

from dynclevr.artifacts import ArtifactError, write_json_atomic

PAD, SOS, EOS, UNK = "<pad>", "<sos>", "<eos>", "<unk>"
SPECIALS = (PAD, SOS, EOS, UNK)
PAD_ID, SOS_ID, EOS_ID, UNK_ID = range(4)


class Vocab:
    def __init__(self, tokens: Iterable[str]):
        self.itos = list(SPECIALS) + [t for t in tokens if t not in SPECIALS]
        self.stoi = {t: i for i, t in enumerate(self.itos)}
        if len(self.stoi) != len(self.itos):
            raise ValueError("vocabulary tokens must be unique")

    @classmethod
    def build(cls, sequences: Iterable[list[str]]) -> "Vocab":
        # Sorted by (-count, token): the same data gives the same ids whatever the row order.
        counts = Counter(t for seq in sequences for t in seq)
        return cls(t for t, _ in sorted(counts.items(), key=lambda kv: (-kv[1], kv[0])))

    def __len__(self) -> int:
        return len(self.itos)

    def __contains__(self, token: str) -> bool:
        return token in self.stoi and token not in SPECIALS

    def encode(self, tokens: list[str]) -> list[int]:
        return [self.stoi.get(t, UNK_ID) for t in tokens]

    def decode(self, ids: Iterable[int]) -> list[str]:
        return [self.itos[i] for i in ids]

    def closest(self, word: str) -> str | None:
        """The one vocabulary word one edit (insert, delete, substitute, swap) from `word`, for words of 4+ letters;
        None when there is none or more than one (a typo is fixed only when the fix is unambiguous)."""
        if len(word) < 4:
            return None
        hits = [t for t in self.itos[len(SPECIALS):] if abs(len(t) - len(word)) <= 1 and _one_edit(word, t)]
        return hits[0] if len(hits) == 1 else None

    def save(self, path: Path) -> None:
        write_json_atomic(path, {"tokens": self.itos})

    @classmethod
    def load(cls, path: Path) -> "Vocab":
        try:
            tokens = json.loads(Path(path).read_text())["tokens"]
        except FileNotFoundError:
            raise ArtifactError(f"{path} is missing: run `dynclevr train qparser`") from None
        except (ValueError, KeyError, TypeError) as e:
            raise ArtifactError(f"{path} is not a vocabulary file ({e}): run `dynclevr train qparser`") from None
        if list(tokens[:len(SPECIALS)]) != list(SPECIALS):
            raise ArtifactError(f"{path} does not start with {SPECIALS}: run `dynclevr train qparser`")
        return cls(tokens)


def _one_edit(a: str, b: str) -> bool:
    """Damerau-Levenshtein distance exactly 1 (optimal string alignment)."""
    if a == b:
        return False
    if len(a) == len(b):
        diff = [i for i in range(len(a)) if a[i] != b[i]]
        return len(diff) == 1 or (len(diff) == 2 and diff[1] == diff[0] + 1
                                  and a[diff[0]] == b[diff[1]] and a[diff[1]] == b[diff[0]])
    short, long_ = (a, b) if len(a) < len(b) else (b, a)
    i = next((k for k in range(len(short)) if short[k] != long_[k]), len(short))
    return short[i:] == long_[i + 1:]


# Each letter's neighbours on a QWERTY keyboard: a finger that lands one key off types one of them
_ROWS = ("qwertyuiop", "asdfghjkl", "zxcvbnm")
NEIGHBOURS = {c: {row[j] for j in (k - 1, k + 1) if 0 <= j < len(row)}
              | {other[j] for other in (_ROWS[r - 1] if r else "", _ROWS[r + 1] if r + 1 < len(_ROWS) else "")
                 for j in (k - 1, k, k + 1) if 0 <= j < len(other)}
              for r, row in enumerate(_ROWS) for k, c in enumerate(row)}
_LETTERS = "abcdefghijklmnopqrstuvwxyz"
SLIP_LETTERS = 30   # longer than any word read; bounds the candidates a pasted string of letters would make


def slips(word: str, words: set[str], spellings: dict[str, str] | None = None) -> list[str]:
    """The words of `words` that `word` (4+ letters) is a slip of the fingers away from: two neighbouring letters
    swapped ('slolwy'), a key next to the right one hit instead ('shaoe') or as well ('sopeed'), a letter left out
    ('oject') or doubled ('speeed'); `spellings` unifies a variant first ('cloour' -> 'colour' -> 'color')."""
    if not 4 <= len(word) <= SLIP_LETTERS:
        return []
    n = len(word)
    swaps = {word[:k] + word[k + 1] + word[k] + word[k + 2:] for k in range(n - 1)}
    wrong = {word[:k] + c + word[k + 1:] for k in range(n) for c in NEIGHBOURS.get(word[k], ())}
    extra = {word[:k] + word[k + 1:] for k in range(n)
             if word[k] in {*NEIGHBOURS.get(word[k - 1] if k else "", ()), *NEIGHBOURS.get(word[k + 1:k + 2], ()),
                            word[k - 1:k], word[k + 1:k + 2]} - {""}}
    left_out = {word[:k] + c + word[k:] for k in range(n + 1) for c in _LETTERS}
    spellings = spellings or {}
    return sorted({spellings.get(t, t) for t in (swaps | wrong | extra | left_out) - {word}} & words)


def slipped(word: str, words: set[str], spellings: dict[str, str] | None = None) -> str | None:
    """The one word of `words` that `word` is a slip of the fingers away from (`slips`); None when there is none or
    more than one. Slips are rarer between real words than any one edit, so short words are fixed too ('oclor'),
    where `Vocab.closest` would make 'black' 'back'."""
    hits = slips(word, words, spellings)
    return hits[0] if len(hits) == 1 else None


def stretched(word: str, words: set[str]) -> str | None:
    """'sloooow' -> 'slow', 'seeeen' -> 'seen': a word with a letter held three times or more, as chat stretches it,
    read with each held letter twice or once (twice first), where a reading is of `words`; else None."""
    runs = re.split(r"((\w)\2{2,})", word)
    if len(runs) == 1:
        return None
    parts = [[p] for p in runs[::3]]   # between the held letters, and each held letter as two or one
    options = [parts[0]]
    for k, held in enumerate(runs[1::3]):
        options += [[held[0] * 2, held[0]], parts[k + 1]]
    return next((w for w in map("".join, itertools.product(*options)) if w in words), None)


# Words said with their g dropped and no apostrophe, which the refusals read in full ('slowin down')
DROPPED_G_WORDS = {"slowing", "nothing", "losing", "braking", "stopping", "landing", "turning"}


def dropped_g(word: str, words: set[str]) -> str | None:
    """'movin' -> 'moving', 'somethin' -> 'something', 'slowin' -> 'slowing': a word ending in 'in' that is one of
    `words` (or `DROPPED_G_WORDS`) with its g; else None. (Said first: 'slowin' was read as 'slow in'.)"""
    full = word + "g"
    return full if len(word) >= 5 and word.endswith("in") and (full in words or full in DROPPED_G_WORDS) else None


# Printed letters a scanner (OCR) takes for others, read either way: 'rnotorbike', 'bicyde', 's1ower', 'int0'.
SCANNED = (("rn", "m"), ("cl", "d"), ("li", "h"), ("vv", "w"), ("1", "l"), ("1", "i"), ("l", "i"), ("0", "o"),
           ("5", "s"))


def scanned(word: str, words: set[str], spellings: dict[str, str] | None = None) -> str | None:
    """The one word of `words` that `word` (3+ characters) reads as with one of a scanner's confusions of printed
    letters (`SCANNED`) undone, or two in a word with a digit ('c0l1ide'); None when there is none or more than
    one ('stll' is no misread 'sth')."""
    if len(word) < 3:
        return None
    spellings = spellings or {}
    pairs = [p for pair in SCANNED for p in (pair, pair[::-1])]

    def undone(w: str) -> set[str]:
        return {w[:k] + b + w[k + len(a):] for a, b in pairs for k in range(len(w)) if w.startswith(a, k)}

    once = undone(word)
    hits = {spellings.get(w, w) for w in once} & words
    if not hits and any(c.isdigit() for c in word):   # two only where a digit shows the print was misread
        hits = {spellings.get(w, w) for w in set().union(*map(undone, once))} & words
    return hits.pop() if len(hits) == 1 else None


def rejoined(words: list[str], readable: set[str], spellings: dict[str, str] | None = None) -> list[str]:
    """A word a printed line's break or a stray space split ('col lides', 'col - lide', 'yel low') made whole, where
    a part is no word of `readable` and the whole is."""
    spellings = spellings or {}
    out: list[str] = []
    k = 0
    while k < len(words):
        a = words[k]
        for gap in (1, 2):
            b = words[k + gap] if k + gap < len(words) else ""
            whole = spellings.get(a + b, a + b)
            if b.isalpha() and (gap == 1 or words[k + 1] == "-") and a.isalpha() and whole in readable \
                    and (a not in readable or b not in readable):
                out.append(whole)
                k += gap + 1
                break
        else:
            out.append(a)
            k += 1
    return out


def run_together(word: str, words: set[str]) -> str | None:
    """'fastmoving' -> 'fast moving': two words of `words` (of 2+ letters each) that `word` is, typed without the
    space or hyphen between them, where it splits so one way only; else None."""
    splits = [f"{word[:k]} {word[k:]}" for k in range(2, len(word) - 1) if word[:k] in words and word[k:] in words]
    return splits[0] if len(splits) == 1 else None


# How English letters are said, as a speller by ear writes them ('fiter' for 'fighter', 'privit' for 'private',
# 'culler' for 'colour', 'enjin' for 'engine'): rewrites applied in order ('%' is the sound of 'sh'), then vowels after
# the first letter dropped and doubled letters made one.
SOUNDS = ((r"x", "ks"), (r"ough", "o"), (r"ould", "ud"), (r"igh", "i"), (r"gh", ""), (r"ph", "f"), (r"wh", "w"),
          (r"sch", "sk"), (r"[ts]ion", "%n"), (r"sh", "%"), (r"ch", "%"), (r"ck", "k"), (r"c(?=[eiy])", "s"),
          (r"c", "k"), (r"q", "k"), (r"z", "s"), (r"g(?=[eiy])", "j"), (r"kn", "n"), (r"wr", "r"), (r"y", "i"),
          (r"our$", "or"))


def sound_key(word: str) -> str:
    """A key that words said alike share: 'fighter' and 'fiter' -> 'ftr', 'school' and 'skool' -> 'skl'."""
    for pattern, said in SOUNDS:
        word = re.sub(pattern, said, word)
    head, rest = ("a" if word[:1] in "aeiou" else word[:1]), re.sub(r"[aeiou]", "", word[1:])
    return re.sub(r"(.)\1+", r"\1", head + rest)


def sound_index(words: Iterable[str]) -> dict[str, list[str]]:
    """`words` of 3+ letters by their `sound_key`."""
    index: dict[str, list[str]] = {}
    for w in sorted(words):
        if len(w) >= 3 and w.isalpha():
            index.setdefault(sound_key(w), []).append(w)
    return index


def sounded(word: str, index: dict[str, list[str]]) -> str | None:
    """The word of `index` that `word` (3+ letters) sounds like as its letters are said and is spelt somewhat like:
    the only one of its key, or of several the one spelt most like it, where it is clearly so ('fiter': 'fighter',
    not 'future'); else None."""
    if len(word) < 3 or not word.isalpha():
        return None
    ranked = sorted(((SequenceMatcher(None, word, w).ratio(), w) for w in index.get(sound_key(word), [])),
                    reverse=True)
    # spelt somewhat alike as well ('scale' is no 'school')
    if not ranked or ranked[0][0] < 0.55 or len(ranked) > 1 and (ranked[0][0] < 0.6
                                                                  or ranked[0][0] - ranked[1][0] < 0.1):
        return None
    return ranked[0][1]
