"""The shipped question parser on the two corpora written by hand: questions of every family in wordings no template
has (`handwritten.txt`), and questions no family asks (`out_of_scope.txt`), which it must leave unparsed. Apart from
test_qparser.py so that CI's two workers share the parser's tests evenly (`--dist loadfile`)."""

import pytest

from dynclevr import DynclevrError
from dynclevr.language import evaluate as qeval
from dynclevr.language.evaluate import handwritten, out_of_scope
from dynclevr.language.parse import QuestionParser, well_formed


def test_handwritten_questions_are_read_into_their_families_programs(tmp_path, monkeypatch):
    """The hand-written questions' gold programs come out of their family's template, well formed; the shipped
    parser gets most of them (85.5% when the file was written; every line is scored by eval-qparser and
    docs/analysis/blind_questions.py, so the test reads every tenth, a few minutes less of CI)."""
    hand = handwritten()
    assert len(hand) >= 70 and all(well_formed(program.split()) for _, program in hand)
    assert ("Does the gray dirtbike collide with the brown truck?",
            "Events Objects filter_attributes[gray] filter_attributes[dirtbike] unique filter_collision "
            "Objects filter_attributes[brown] filter_attributes[truck] unique filter_collision exist") in hand
    sample = hand[::10]
    got = QuestionParser.load().parse_batch([t for t, _ in sample])
    assert sum(g == p.split() for g, (_, p) in zip(got, sample)) >= 0.9 * len(sample)
    bad = tmp_path / "hand.txt"
    bad.write_text("# comment\ncollide_sideways | red sedan |  |  | Does the red sedan slide?\n")
    monkeypatch.setattr(qeval, "HANDWRITTEN_FILE", bad)
    with pytest.raises(DynclevrError, match="hand.txt:2: expected 'family"):
        handwritten()
    monkeypatch.setattr(qeval, "HANDWRITTEN_FILE", tmp_path / "gone.txt")
    with pytest.raises(DynclevrError, match="gone.txt is unreadable"):
        handwritten()


def test_shipped_weights_leave_most_out_of_scope_questions_unparsed():
    parses = QuestionParser.load().analyse_batch(out_of_scope())
    assert all(p.reason for p in parses if p.program is None)
    assert sum(p.program is None for p in parses) >= 0.75 * len(parses)
