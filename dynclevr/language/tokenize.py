"""Question text -> word tokens: lower-case, words and punctuation apart, a few spellings unified."""

from __future__ import annotations

import re
import unicodedata

_TOKEN = re.compile(r"[a-z0-9]+|[^\sa-z0-9]")
# One spelling per word, so that the vocabulary (built from generated questions) covers common variants.
_SPELLINGS = {"grey": "gray", "colour": "color", "colours": "colors", "airplane": "aeroplane",
              "airplanes": "aeroplanes", "motorcycle": "motorbike", "motorcycles": "motorbikes"}
_QUOTES = str.maketrans({"\u2018": "'", "\u2019": "'", "\u201c": '"', "\u201d": '"', "\u2013": "-", "\u2014": "-"})


def tokenize(text: str) -> list[str]:
    """'Is the grey SUV moving?' -> ['is', 'the', 'gray', 'suv', 'moving', '?']. Never raises on a str."""
    text = unicodedata.normalize("NFKC", text).translate(_QUOTES).lower()
    return [_SPELLINGS.get(t, t) for t in _TOKEN.findall(text)]
