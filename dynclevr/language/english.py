"""Real English words the question parser does not know, which its typo fixing would otherwise read as a known word
('feast' as 'fast', 'hall' as 'shall', 'tuck' as 'truck', 'boys' as 'bus'): an unknown word is read as a slip of a
known one only where it is no common English word itself, so a writer's own word is never turned into another
(the question is then unread, not read as something it does not say). `python -m dynclevr.language.english` writes
english.txt from wordfreq's English word list (install `.[lexicon]`) and the parser's own typo fixing; parsing needs
neither wordfreq nor the list's making: the file is the whole of it.

A word is listed where English text uses it at least ZIPF (wordfreq's Zipf scale: 3.5 is about once in 300,000
words), the parser neither knows it nor reads it by a synonym, stem, WordNet, a spelling ('grey') or a catalogue's
name ('airplanes'), and its typo fixing (or its reading of a word spelt as it sounds) would change it into another
word, not another form of it ('buses' stays the 'bus' it is, 'comin' 'coming'). The threshold keeps the words that
writers misspell into fixable ('stationery', 3.3, is mostly 'stationary' misspelt; 'recieve' 2.8).
"""

from __future__ import annotations

import sys
from pathlib import Path

from dynclevr import DynclevrError

ZIPF = 3.5
INFLECTIONS = {"s", "es", "ed", "ing", "er", "ers", "est", "ly", "n"}
ENGLISH_FILE = Path(__file__).with_name("english.txt")
HEADER = ("# Made by `python -m dynclevr.language.english` from wordfreq's English list and the question parser's typo "
          "fixing\n# (dynclevr/language/english.py says how); do not edit.\n")


def real_words(path: Path = ENGLISH_FILE) -> frozenset[str]:
    """The listed words."""
    try:
        text = path.read_text()
    except (OSError, UnicodeDecodeError) as e:
        raise DynclevrError(f"the question parser's word list {path} is unreadable ({e}): restore it "
                            f"(`git checkout -- dynclevr/language/{path.name}`) or reinstall dynclevr") from None
    return frozenset(line.strip() for line in text.splitlines() if line.strip().isalpha())


def build(parser) -> list[str]:
    """The common English words `parser` would fix as typos."""
    from wordfreq import top_n_list, zipf_frequency   # only here: parsing never needs wordfreq itself

    from dynclevr.language.parse import STEMMER
    from dynclevr.language.references import catalogue_names
    from dynclevr.language.tokenize import tokenize
    from dynclevr.language.vocab import sounded

    def changed(w: str) -> str | None:
        fixed = parser.typo_fixed(w)
        return fixed if fixed != w else sounded(w, parser.sounds)

    def same_word(w: str, fixed: str) -> bool:
        """Whether the fix is the word itself in another form ('buses' -> 'bus', 'comin' -> 'coming', 'blu' ->
        'blue', 'alot' -> 'a lot'), which the writer meant."""
        rest = w[len(fixed):] if w.startswith(fixed) else None   # 'buses', but not 'card' ('car') or 'bust'
        return STEMMER.stemWord(w) == STEMMER.stemWord(fixed) or fixed.startswith(w) or \
            rest in INFLECTIONS or rest == "d" and fixed.endswith("e") or fixed.replace(" ", "") == w

    return sorted(w for w in top_n_list("en", 100_000)
                  if w.isascii() and w.isalpha() and len(w) >= 3 and zipf_frequency(w, "en") >= ZIPF
                  and w not in parser.readable and parser._stand_in(w) == [w] and tokenize(w) == [w]
                  and catalogue_names([w])[0] == [w]
                  and (fixed := changed(w)) and not same_word(w, fixed))


def main(path: Path = ENGLISH_FILE) -> None:
    from dynclevr.language.parse import QuestionParser

    parser = QuestionParser.load()
    parser.real_words = frozenset()   # its typo fixing without the list
    words = build(parser)
    path.write_text(HEADER + "".join(w + "\n" for w in words))
    print(f"{len(words)} words written to {path}", file=sys.stderr)


if __name__ == "__main__":
    main()
