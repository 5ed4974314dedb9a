"""The question parser's list of real English words (dynclevr/language/english.py, english.txt): a common word the
parser does not know is never fixed as a typo of a known one, a typo still is, and the shipped file is what
wordfreq's list and the parser's own typo fixing give."""

from copy import copy

import pytest

from dynclevr import DynclevrError
from dynclevr.language.english import ENGLISH_FILE, HEADER, build, real_words
from dynclevr.language.parse import QuestionParser


@pytest.fixture(scope="module")
def parser():
    return QuestionParser.load()


def test_a_real_word_is_not_fixed_as_a_typo_and_a_typo_still_is(parser):
    # (and a word that begins with a known one is no form of it: 'card' was read as 'car', 'busy' as 'bus')
    assert {"hall", "boys", "tuck", "small", "fellow", "card", "busy", "driver"} <= parser.real_words
    assert [parser.typo_fixed(w) for w in ("feast", "hall", "tuck", "small")] == ["feast", "hall", "tuck", "small"]
    assert [parser.typo_fixed(w) for w in ("fsat", "slolwy", "acelerating", "stationery")] == [
        "fast", "slowly", "accelerating", "stationary"]
    # a question that says a real word the parser does not know stays unread, never read as another question
    feast = parser.analyse_batch(["Does the red sedan feast on the blue bus at the start?"])[0]
    assert feast.program is None and ("feast", "fast") not in feast.read_as
    # ... and its other words are read as before ('Feast your eyes:' had been read as 'fast')
    assert parser.parse("Feast your eyes: is the red car moving slowly at the start?") == [
        "Objects", "filter_attributes[red]", "filter_attributes[car]", "unique", "start", "is_moving_velocity[slow]"]


def test_every_listed_word_is_unknown_and_the_list_is_not_of_forms_of_known_words(parser):
    words = real_words()
    assert len(words) > 200 and not words & parser.readable
    assert not {"buses", "comin", "blu", "grey", "airplanes"} & words   # forms and spellings of words it reads


def test_an_unreadable_list_is_one_clear_error(tmp_path):
    with pytest.raises(DynclevrError, match="english.txt.*restore it"):
        real_words(tmp_path / "english.txt")


def test_shipped_file_is_what_wordfreq_and_the_parser_give(parser):
    pytest.importorskip("wordfreq", reason="wordfreq (`pip install -e '.[lexicon]'`) makes the file")
    unlisted = copy(parser)   # as it fixes typos without the list; the module's fixture stays as shipped
    unlisted.real_words = frozenset()
    assert ENGLISH_FILE.read_text() == HEADER + "".join(w + "\n" for w in build(unlisted))
