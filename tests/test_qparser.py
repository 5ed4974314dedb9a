"""The question parser: tokenizer and vocabulary, training on synthetic template questions, robustness to bad
text, held-out phrasings that training never sees, the reasons a question is unparsed, and the shipped weights on
questions of scenes and wordings they never saw."""

import copy
import dataclasses
import json
import random
import re

import numpy as np
import pytest
import torch

from dynclevr import WEIGHTS_DIR, DynclevrError
from dynclevr.artifacts import ArtifactError
from dynclevr.config import Config, ConfigError
from dynclevr.assets.catalogue import SUBTYPES
from dynclevr.colors import COLOR_NAMES
from dynclevr.language.corpus import synthesize
from dynclevr.language.evaluate import typed_with_a_slip
from dynclevr.language.params import qparser_params
from dynclevr.language.asides import (_courtesy, _remarked_after, addressed_as_named, asides_dropped,
                                      corrections_dropped, dashed_aside_dropped, description_dropped,
                                      digressions_dropped, dislocated_as_asked, distractors_dropped,
                                      examination_as_asked, framing_dropped, heading_dropped, headlines_dropped,
                                      hedges_dropped, hypothesis_as_asked, in_verse, interjections_dropped,
                                      log_stamp_dropped, preamble_dropped, prompt_dropped, proof_as_asked,
                                      radio_as_asked, reference_dropped, remark_after_dropped, requested_as_asked,
                                      riddles_dropped, script_cues_dropped, simile_closing_dropped,
                                      speaker_clauses_dropped, ticket_fields_read, wagers_read)
from dynclevr.language.checks import (anything_unasked, clock_unasked, collision_at_start, collision_unread,
                                      comparison_imagined, condition_subject, condition_subject_first,
                                      direction_unasked, floating_unsaid, form_unasked, form_unmatched, future_unread,
                                      impact_unsaid, motion_unfiltered, named_attribute, reversed_reading,
                                      speed_unsaid, time_unasked)
from dynclevr.language.context import (afterthoughts_read, check_ins_stated, context_as_question,
                                       impact_said_first, told_otherwise_as_imagined, transcript_as_asked)
from dynclevr.language.parse import (Parse, QuestionParser, _chosen, clause_time, program_shape, synonyms,
                                     time_clause_last, well_formed)
from dynclevr.language.refusals import (chained, checked_attribute, imagined_otherwise, ordered, otherwise_compared,
                                        premised, properties_joined, quantified, questions_joined, ranking,
                                        reversed_as_said, several_asked, speed_measure, speed_measured, speeds_alike,
                                        times_joined)
from dynclevr.language.surface import (archaic_as_said, code_switched_as_said, corrections_starred, creole_as_said,
                                       emoji_as_said, glosses_read, homophones_as_said, lettered_options,
                                       quoted_question, she_as_it, shorthand_as_said, spelt_by_ear, telegram_as_said,
                                       worksheet_as_said)
from dynclevr.language.times import first_frames_as_said, inserted_time_last, video_end_as_said
from dynclevr.language.wordings import (alternatives_as_asked, attention_as_subject, attributes_offered_dropped,
                                        class_as_asked, inverted_as_asked, comparative_as_said, floating_plane_as_vehicle,
                                        heading_as_direction, height_as_aloft, idioms_as_said, imperative_as_stated,
                                        negative_question_as_asked, noun_phrase_as_question, request_as_imperative,
                                        speed_as_subject, tail_as_question, type_as_said, type_of_category_as_vehicle)
from dynclevr.language.words import impact_like
from dynclevr.language.code import code_as_said
from dynclevr.language.references import (COLOUR_SHADES, EVERYDAY_NAMES, abstract_program, attributes_as_named,
                                          catalogue_names, concrete_program, corefer, delexicalise,
                                          described_as_named, description_as_said, heard_as_said)
from dynclevr.language.seq2seq import Ensemble, pad_batch
from dynclevr.language.tokenize import SPELLINGS, tokenize
from dynclevr.language.train import blind_baseline, fit, train_qparser
from dynclevr.language.vocab import (EOS_ID, UNK_ID, Vocab, dropped_g, rejoined, run_together, scanned, slipped, slips,
                                     sound_index, sound_key, sounded, stretched)
from dynclevr.pipeline import Runner
from dynclevr.questions.generate import templates
from dynclevr.questions import phrasing
from dynclevr.questions.phrasing import Grammar, grammar
from dynclevr.questions.tables import CANDIDATES_OUT, read_questions, write_questions

COLORS = ["gray", "red", "blue", "green", "brown", "purple", "cyan", "yellow"]
SHAPES = ["airliner", "fighter", "jet", "mountain bike", "tandem bike", "utility bike", "articulated bus",
          "double bus", "school bus", "minivan", "sedan", "suv", "truck", "wagon", "chopper", "cruiser", "scooter"]


def _object(rng: random.Random) -> tuple[str, list[str]]:
    color, shape = rng.choice(COLORS + [""]), rng.choice(SHAPES)
    prog = ["Objects"] + ([f"filter_attributes[{color}]"] if color else [])
    return f"{color} {shape}".strip(), prog + [f"filter_attributes[{shape.replace(' ', '_')}]", "unique"]


def synthetic(n: int, seed: int, scenes: int = 20) -> tuple[list[str], list[list[str]], list[str]]:
    """Template questions shaped like DynSuperCLEVR's (objects by colour and shape, nested in several families)."""
    rng = random.Random(seed)
    texts, programs = [], []
    for _ in range(n):
        (a, pa), (b, pb) = _object(rng), _object(rng)
        text, prog = rng.choice([
            (f"What is the moving velocity of the {a} at the beginning?", pa + ["start", "query_moving_velocity"]),
            (f"Is the {a} floating at the start?", pa + ["start", "is_floating"]),
            (f"Is the {a} faster than the {b} at the start?", pa + pb + ["start", "faster_velocity"]),
            (f"Will the {a} collide with the {b}?",
             ["futureEvents"] + pa + ["filter_collision"] + pb + ["filter_collision", "exist"]),
            (f"What color is the object that collides with the {a}?",
             ["Events"] + pa + ["get_all_col_partners", "unique", "query_attributes[color]"]),
        ])
        texts.append(text)
        programs.append(prog)
    return texts, programs, [f"{i % scenes:06d}" for i in range(n)]


def small_params(**changes):
    p = qparser_params(Config.load())
    return dataclasses.replace(p, **{"embedding": 32, "hidden": 64, "lr": 0.01, "batch_size": 32, "epochs_max": 8,
                                       "patience": 2, "max_unknown_words": 0, "min_confidence": 0.0, **changes})


def pairs(n: int, seed: int):
    texts, programs, _ = synthetic(n, seed)
    return list(zip(texts, programs))


@pytest.fixture(scope="module")
def synthetic_fit():
    return fit(lambda k: pairs(1500, seed=10 + k), pairs(150, seed=0), small_params(), echo=lambda *_: None)


def assert_refused(parser: QuestionParser, texts: list[str] | dict[str, str]) -> None:
    """Each text is unparsed, with a reason (that says the text's value, where `texts` maps each to one)."""
    for text, parse in zip(texts, parser.analyse_batch(list(texts))):
        assert parse.program is None and parse.reason, text
        assert not isinstance(texts, dict) or texts[text] in parse.reason, (text, parse.reason)


def test_tokenize_splits_words_and_punctuation_and_unifies_spellings():
    assert tokenize("Is the grey SUV moving?") == ["is", "the", "gray", "suv", "moving", "?"]
    assert tokenize("What\u2019s  the colour,\tthen") == ["what", "'", "s", "the", "color", ",", "then"]
    assert tokenize("") == [] and tokenize("   ") == []
    # short negations are said in full, as the grammar says them; a possessive "'s" is left alone
    assert tokenize("Isn\u2019t it moving? It won't; it can't") == ["is", "not", "it", "moving", "?", "it", "will",
                                                                     "not", ";", "it", "can", "not"]
    # typed without the apostrophe, too; other words ending in "nt" are left alone
    assert tokenize("it isnt moving, didnt hit, wont") == ["it", "is", "not", "moving", ",", "did", "not", "hit", ",",
                                                           "will", "not"]
    assert tokenize("want cantilever isnt") == ["want", "cantilever", "is", "not"]


def test_vocab_round_trip_and_typo_fix(tmp_path):
    v = Vocab.build([["the", "red", "car"], ["the", "green", "bus"]])
    assert v.itos[4] == "the"                         # most frequent first, then alphabetical
    ids = v.encode(["the", "red", "plane"])
    assert ids[-1] == UNK_ID and v.decode(ids[:2]) == ["the", "red"]
    v.save(tmp_path / "v.json")
    assert Vocab.load(tmp_path / "v.json").itos == v.itos
    assert v.closest("gren") == "green" and v.closest("rde") is None      # short words are never guessed
    assert v.closest("graen") == "green" and v.closest("bsu") is None
    assert Vocab(["cats", "cars"]).closest("cabs") is None                # ambiguous: no guess


def test_bad_config_is_one_clear_error(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text("[qparser]\nhidden = 0\n")
    with pytest.raises(ConfigError, match="qparser.hidden"):
        qparser_params(Config.load(bad))
    bad.write_text("[qparser]\nlr = 5.0\n")
    with pytest.raises(ConfigError, match="qparser.lr"):
        qparser_params(Config.load(bad))
    bad.write_text("[qparser]\nmembers = 0\n")
    with pytest.raises(ConfigError, match="qparser.members"):
        qparser_params(Config.load(bad))


def _templates_of(text: str, program: str) -> str:
    """A generated question with its object descriptions put back as <X>, <Y> (the phrasing it was drawn from)."""
    chains = re.findall(r"Objects((?: filter_attributes\[[a-z_]+\])+) unique", program)
    text = text.lower()
    for name, chain in zip(("<X>", "<Y>"), dict.fromkeys(chains)):
        words = " ".join(w.replace("_", " ") for w in re.findall(r"\[([a-z_]+)\]", chain))
        for noun in ("", " object", " vehicle"):
            text = re.sub(rf"\bthe {words}{noun}\b(?! (object|vehicle)\b)", name.lower(), text)
    return text


def test_held_out_phrasings_never_reach_training():
    """The pools are disjoint phrase for phrase, and every training question is a phrasing of the training pool (the
    seen and taught phrasings)."""
    g = grammar()
    fams = {f["name"]: f for f in templates()["families"]}
    lower, lower_held = {}, {}
    for name, fam in fams.items():
        lower[name] = {t.lower() for c in g.slot_combinations(fam) for t in g.phrasings(name, "train", c)}
        lower_held[name] = {t.lower() for c in g.slot_combinations(fam) for t in g.phrasings(name, "heldout", c)}
        assert lower[name] and lower_held[name] and not lower[name] & lower_held[name], name
        assert len(lower[name] | lower_held[name]) >= 20, name        # many phrasings per family
    training = synthesize(600, seed=3, pool="train")
    found = 0
    for e in training:
        t = _templates_of(e.text, e.program)
        assert t not in lower_held[e.family], (e.text, t)
        found += t in lower[e.family]
    assert found >= 0.95 * len(training)      # (the rest: a description that is also a word of the sentence)
    assert all(_templates_of(e.text, e.program) not in lower[e.family]
               for e in synthesize(300, seed=4, pool="heldout"))


def test_taught_phrasings_are_checked(tmp_path, monkeypatch):
    """taught.json naming a lexicon entry or family the grammar lacks, or not a JSON object, is one clear line."""
    with pytest.raises(ConfigError, match=r"taught.json names \['NOPE'\]"):
        Grammar(templates(), {"lexicon": {"NOPE": ["x"]}, "families": {}})
    with pytest.raises(ConfigError, match="unknown lexicon entry @MISSING"):
        Grammar(templates(), {"lexicon": {}, "families": {"collide_any": ["Does <X> @MISSING?"]}})
    bad = tmp_path / "taught.json"
    bad.write_text("[1, 2")
    monkeypatch.setattr(phrasing, "TAUGHT_PATH", bad)
    with pytest.raises(ConfigError, match="is not a JSON object of 'lexicon' and 'families'"):
        phrasing.taught()


def test_every_phrasing_names_its_objects():
    """Every phrasing of every pool (training's seen and taught ones, the held-out ones) names each object its
    family's program reads."""
    g = grammar()
    for fam in templates()["families"]:
        for pool in ("train", "heldout"):
            for name in fam["objects"]:
                assert all(f"<{name}>" in t for c in g.slot_combinations(fam)
                           for t in g.phrasings(fam["name"], pool, c)), (fam["name"], pool, name)


def test_copy_path_for_object_words():
    """Runs of attribute words become placeholders (multi-word sub-types first) and come back as filter chains."""
    words, refs = delexicalise(tokenize("When the school bus hits the red bus, is the school bus fast?"))
    assert refs == [("school_bus",), ("red", "bus")]
    assert words == ["when", "the", "<obj1>", "hits", "the", "<obj2>", ",", "is", "the", "<obj1>", "fast", "?"]
    program = "Objects filter_attributes[school_bus] unique Events Objects filter_attributes[school_bus] unique " \
              "filter_collision Objects filter_attributes[red] filter_attributes[bus] unique filter_collision " \
              "unique get_frame is_moving_velocity[fast]"
    abstract = abstract_program(program.split(), refs)
    assert abstract[:3] == ["<obj1>", "Events", "<obj1>"] and "filter_attributes[red]" not in abstract
    assert concrete_program(abstract, refs) == program.split()
    assert concrete_program(["<obj3>", "start", "is_static"], refs) is None
    with pytest.raises(ValueError):
        abstract_program("Objects filter_attributes[cyan] unique start is_static".split(), refs)
    # A lone 'bike' is a bicycle; in a sub-type's name it is that sub-type.
    assert delexicalise(tokenize("Did the red bike hit the road bike?"))[1] == [("red", "bicycle"), ("road_bike",)]


def test_the_names_people_give_the_vehicles_are_read_as_the_catalogues():
    """A vehicle named as people name it, or a sub-type's name hyphenated, run together or said with its category,
    is read as the catalogue's name before anything else reads the words; no other words change."""
    cases = {"the cyan double-decker bus": ("the cyan double bus", "double-decker bus"),
             "the dirt bike": ("the dirtbike", "dirt bike"), "the red fighter jet": ("the red fighter", "fighter jet"),
             "the red fighter plane": ("the red fighter", "fighter plane"), "a station wagon": ("a wagon", None),
             "the tandem": ("the tandem bike", "tandem"), "the tandem bicycle": ("the tandem bike", None),
             "the school-bus": ("the school bus", "school-bus"), "the mountainbike": ("the mountain bike", None),
             "the gray cruiser motorcycle": ("the gray cruiser", "cruiser motorbike"),
             "the pick-up truck": ("the truck", "pick-up truck")}
    for said, (read, name) in cases.items():
        words, names = catalogue_names(tokenize(said))
        assert words == read.split() and len(names) == 1, said
        assert names[0][0] == name or name is None, said
    for said in ("is the tandem bike moving up in the air ?", "does the red sedan hit the bus - or the car ?",
                 "the jet , a car , and the bike"):
        assert catalogue_names(tokenize(said)) == (tokenize(said), ()), said
    # an everyday noun is its catalogue name ('plane', as the synonym lexicon reads it too)
    assert catalogue_names(tokenize("a plane"))[0] == ["a", "aeroplane"]
    # a shade that is one catalogue colour reads as it; one that is not stays ('navy' is as near purple as blue)
    for said, read in {"the crimson sedan": "the red sedan", "the forest green bus": "the green bus",
                       "the dark blue jet": "the blue jet", "the gray-ish truck": "the gray truck",
                       "the navy bus": "the navy bus", "the light blue jet": "the light blue jet"}.items():
        assert catalogue_names(tokenize(said))[0] == read.split(), said
    for shade, colour in COLOUR_SHADES.items():
        assert colour in COLOR_NAMES and shade not in COLOR_NAMES, shade
    # every everyday name is one sub-type of the catalogue's, or one category ('plane', 'automobile')
    categories = {category for category, *_ in SUBTYPES.values()}
    for name in EVERYDAY_NAMES:
        refs = delexicalise(catalogue_names(tokenize(name))[0])[1]
        assert len(refs) == 1 and len(refs[0]) == 1 and refs[0][0] in SUBTYPES.keys() | categories, name


def test_a_shorter_second_mention_is_the_same_object():
    """'the bus' after 'the yellow double bus' can only be that bus (each reference picks out one object); a
    description that says something the first did not, or fits two earlier ones, stays its own object."""
    words, refs = corefer(*delexicalise(tokenize(
        "When the cyan mountain bike hits the yellow double bus, is it slower than the bus?")))
    assert refs == [("cyan", "mountain_bike"), ("yellow", "double_bus")]
    assert words[-3:] == ["the", "<obj2>", "?"]
    assert corefer(*delexicalise(tokenize("Is the gray dirtbike faster than the red car when the dirtbike hits it?"))
                   )[1] == [("gray", "dirtbike"), ("red", "car")]
    for text in ("When the school bus hits the red bus, is the school bus fast?",   # 'red' is new
                 "Does the red sedan hit the red suv before the red one stops?"):  # fits both
        assert corefer(*delexicalise(tokenize(text))) == delexicalise(tokenize(text)), text
    # Said before its fuller mention, as a clause of time put last says it: numbered again in order of mention.
    words, refs = corefer(*delexicalise(tokenize(
        "Is the airliner fast when the blue airliner and the green scooter collide?")))
    assert refs == [("blue", "airliner"), ("green", "scooter")]
    assert [w for w in words if w.startswith("<")] == ["<obj1>", "<obj1>", "<obj2>"]
    # Joined by 'and' or 'or', the question itself tells them apart: the bus is not the school bus.
    for text in ("Does the red sedan hit the bus and the sedan, and the school bus?",
                 "Does the red sedan hit the bus or the school bus?"):
        assert {("bus",), ("school_bus",)} <= set(corefer(*delexicalise(tokenize(text)))[1]), text
    assert QuestionParser.load().parse("Does the red sedan hit the bus and the school bus?") is None


def test_a_clause_of_time_said_first_is_also_read_last():
    """People front a clause of time; the grammar mostly says it last, where a pronoun in it follows its object. A
    counterfactual's condition is not a time and stays where it is, and so does a question without the clause."""
    assert time_clause_last(tokenize("When it hits the blue bus, is the red sedan parked?")) == tokenize(
        "Is the red sedan parked when it hits the blue bus?")
    assert time_clause_last(tokenize("At the moment of impact with the bus, how fast is the red car going")) == \
        tokenize("how fast is the red car going at the moment of impact with the bus")
    for text in ("In case the red sedan had stopped, would it hit the blue bus?",
                 "In a world where the red sedan had been still, would it hit the blue bus?",
                 "Is the red sedan parked when it hits the blue bus?", "Suppose it stops, is it slow?",
                 "At the start,", "at the start"):
        assert time_clause_last(tokenize(text)) is None, text
    # An object named in the clause and 'it' in the question change places, so that the pronoun follows it again;
    # not where the question names an object of its own before its 'it'.
    assert time_clause_last(tokenize("Once the cyan tandem bike shows up, how fast is it moving?")) == tokenize(
        "how fast is the cyan tandem bike moving once it shows up?")
    assert time_clause_last(tokenize("When the bus hits the red car, is the car faster than it?")) == tokenize(
        "is the car faster than it when the bus hits the red car?")


def test_the_time_a_fronted_clause_names_chooses_between_the_readings():
    """'At impact, ...' read as said asks at the start, surely; put last, at the collision, less surely: the clause
    says which. Without a time in the clause, or where both or neither reading asks at it, the surer reading wins."""
    assert clause_time(tokenize("at impact")) == "get_frame"
    assert clause_time(tokenize("once it first appears")) == "come_in_frame"
    assert clause_time(tokenize("right at the start")) == "start"
    assert clause_time(tokenize("in the video")) is None
    start = Parse("<obj1> <obj2> start slower_velocity".split(), confidence=0.9)
    impact = Parse("<obj1> <obj2> Events <obj1> filter_collision <obj2> filter_collision unique get_frame "
                   "slower_velocity".split(), confidence=0.6)
    assert _chosen([start, impact], "get_frame") is impact
    assert _chosen([start, impact], None) is start and _chosen([start, impact], "come_in_frame") is start
    assert _chosen([start, Parse(None, "no program")], "get_frame") is start
    # a main question that names its own subject: the clause put last, whose first object is that subject
    assert _chosen([start, impact], None, True) is impact and _chosen([start, Parse(None, "x")], None, True) is start


def test_questions_in_broken_english_read_as_the_grammar_says_them():
    """A comparative with 'more', the asking said last ('..., yes or no?', '... is what?')."""
    assert comparative_as_said(tokenize("is the red car more fast than the bus?"))[0] == \
        tokenize("is the red car faster than the bus?")
    assert comparative_as_said(tokenize("is the red car less fast than the bus?"))[0][4] == "slower"
    assert comparative_as_said(tokenize("is the red car moving more slowly?"))[1] == ()
    assert tail_as_question(tokenize("green bus is not moving at start, yes or no?"))[0] == \
        tokenize("green bus is not moving at start?")
    assert tail_as_question(tokenize("red sedan speed at beginning is what?"))[0] == \
        tokenize("what is red sedan speed at beginning?")
    for text in ("what is the speed of the red car?", "how fast is the red car, is it what?", "yes or no?"):
        assert tail_as_question(tokenize(text)) == (tokenize(text), ()), text
    # a first sentence that points at an object, or says nothing but pointing at it: the question about it
    for text, asked in (("Watch the yellow bus. Does it hit anything?", "does the yellow bus hit anything?"),
                        ("look at the red car: is its speed low?", "is the red car's speed low?"),
                        ("How about the blue bus, is it fast at the start?", "is the blue bus fast at the start?"),
                        ("As for the brown truck - does it hit anything?", "does the brown truck hit anything?"),
                        ("look at the red car and the bus, do they collide?", "do the red car and the bus collide?"),
                        ("This is about the red sedan. Does it hit the blue bus?",
                         "does the red sedan hit the blue bus?"),
                        ("There is a red sedan in the video. Is it fast?", "is the red sedan fast?"),
                        ("I have a question about the red car and the bus. Do they collide?",
                         "do the red car and the bus collide?")):
        assert attention_as_subject(tokenize(text))[0] == tokenize(asked), text
    for text in ("watch the video. does the bus hit the car?", "look at the red car and the video, do they collide?",
                 "how about the red car and the bus, does it collide?", "the red car is parked. does it hit the bus?",
                 "the gray cruiser shows up at some point. how fast is it moving then?",
                 "this is about the red car. does the bus hit the jet?", "the red car, is the bus fast?"):
        assert attention_as_subject(tokenize(text)) == (tokenize(text), ()), text
    # a preamble that frames the question and names no object is no part of it
    for text in ("thinking about the whole clip, does the red car hit the bus?", "not sure, but does the red car hit "
                 "the bus?", "looking at the video, does the red car hit the bus?"):
        assert framing_dropped(tokenize(text))[0] == tokenize("does the red car hit the bus?"), text
    for text in ("watching the red car, is it fast?", "thinking about it, had the red car been parked, would it hit "
                 "the bus?", "when the red car hits the bus, is it fast?"):
        assert framing_dropped(tokenize(text)) == (tokenize(text), ()), text


def test_a_colour_after_its_vehicle_alternatives_and_the_videos_end_read_as_the_grammar_says_them():
    """'the bus that is yellow' -> 'the yellow bus'; 'fast or slow' offers the classes; 'once the video is over'
    is 'after the video ends' in a question about collisions."""
    for text in ("does the bus that is yellow hit the red car?", "does the bus which is yellow hit the red car?",
                 "does the bus painted yellow hit the red car?", "does the bus in yellow hit the red car?",
                 "does the bus, the yellow one, hit the red car?", "does the bus (the yellow one) hit the red car?",
                 "does the yellow-coloured bus hit the red car?", "does the bus in yellow colour hit the red car?"):
        assert description_as_said(tokenize(text))[0] == tokenize("does the yellow bus hit the red car?"), text
    assert description_as_said(catalogue_names(tokenize("is the double decker that's cyan fast?"))[0])[0] == \
        tokenize("is the cyan double bus fast?")
    for text in ("does the red bus that is yellow hit the car?", "does the bus that is moving hit the car?",
                 "is the bus in front of the car?", "does the bus, the red car and the blue jet collide?"):
        assert description_as_said(tokenize(text)) == (tokenize(text), ()), text
    for text in ("is the red car fast or slow at the start?", "is the red car moving slowly or quickly?",
                 "is the red car fast, slow, or stationary?"):
        words, read = alternatives_as_asked(tokenize(text))
        assert " static , slow or fast" in " ".join(words) and read, text
    for text in ("is the red car moving left or right?", "is the plane going up or down when it hits the bus?",
                 "is the red car going towards the camera or away from it?",
                 "is it moving forwards, backwards or left?"):
        words, read = alternatives_as_asked(tokenize(text))
        assert " front , back , left , right , up or down" in " ".join(words) and read, text
    for text in ("is the red car still fast?", "is the red car static or moving?", "how fast or slow is the red car?",
                 "is the red car fast and slow?", "is the red car to the left or right of the bus?",
                 "is the red car on the left or on the right?"):
        assert alternatives_as_asked(tokenize(text)) == (tokenize(text), ()), text
    # a direction or a place that a reading asking no direction would pass over
    fast = "Objects filter_attributes[red] filter_attributes[car] unique start is_moving_velocity[fast]".split()
    which = "Objects filter_attributes[red] filter_attributes[car] unique start query_moving_direction".split()
    for text, said in (("is the red car moving left at the start?", "left"), ("is the red car moving to the right at "
                       "the start?", "right"), ("is it heading away from us?", "away from us"),
                       ("is it driving towards the camera?", "towards the camera")):
        assert direction_unasked(tokenize(text), fast).startswith(f"the question turns on '{said}'"), text
    assert direction_unasked(tokenize("which way is the red car moving, left or right?"), which) == ""
    come_in = "Objects filter_attributes[red] filter_attributes[car] unique come_in_frame query_moving_velocity".split()
    for text in ("when the red car appears, which way is it going?", "what direction does it move in when it enters?"):
        assert direction_unasked(tokenize(text), come_in).startswith("the question asks 'w"), text
    assert direction_unasked(tokenize("which way is the red car moving at the start?"), which) == ""
    # a yes/no question read as a query, unless it offers the answers; 'which is faster, X or Y?' is yes or no
    for text in ("does the red car change direction?", "at the start, is the red car accelerating?"):
        assert form_unmatched(tokenize(text), which).startswith("the question asks yes or no"), text
    for text in ("is the red car going left or right?", "which way is the red car moving?"):
        assert form_unmatched(tokenize(text), which) == "", text
    assert form_unmatched(tokenize("which is faster, the red car or the bus?"), fast) == ""
    assert form_unasked(tokenize("who hits the red car?"), fast).startswith("the question asks who"), "who"
    # a motion read at the start, of a question that says another time and no word of the start
    for text, said in (("in the middle of the video, is the red car fast?", "middle"), ("is the red car fast after "
                       "two seconds?", "two seconds"), ("at frame 50, is the red car fast?", "frame 50"),
                       ("is the red car ever fast?", "ever")):
        assert time_unasked(tokenize(text), fast).startswith(f"the question asks at a time other than the start "
                                                             f"('{said}')"), text
    for text in ("is the red car fast at the start?", "in the first frames, is the red car fast?", "at frame 1, is "
                 "the red car fast?", "is the red car fast?", "is the red car fast initially?"):
        assert time_unasked(tokenize(text), fast) == "", text
    for text in ("right at the start, is the red car fast?", "is the red car fast right when it appears?"):
        assert direction_unasked(tokenize(text), fast) == "", text
    for text in ("once the video is over, does the red car hit the bus?", "when the clip is done, does the red car "
                 "hit the bus?", "as soon as the video has ended, does the red car hit the bus?"):
        assert video_end_as_said(tokenize(text))[0] == tokenize("after the video ends, does the red car hit the bus?")
    assert video_end_as_said(tokenize("will the red car run into the bus once the video ends?"))[0][-5:] == \
        tokenize("after the video ends?")
    for text in ("when the video ends, is the red car fast?", "after the video ends, does the red car hit the bus?",
                 "when the red car comes into view, is it fast?"):
        assert video_end_as_said(tokenize(text)) == (tokenize(text), ()), text


def test_a_question_asked_as_a_request_is_read_as_tell_me():
    """'Could you tell me ...', 'I'd like to know ...', 'I wonder ...': the grammar words requests as 'Tell me ...'.
    A request said later, or words that only look like one, stay as they are."""
    for text in ("Could you tell me the speed of the red sedan at the start?", "I'd like to know the speed of the "
                 "red sedan at the start?", "Please, can you please tell me the speed of the red sedan at the start?",
                 "do you happen to know the speed of the red sedan at the start?"):
        words, read_as = request_as_imperative(tokenize(text))
        assert words == tokenize("tell me the speed of the red sedan at the start?"), text
        assert "' " not in read_as[0][0], read_as       # said as written: "i'd like to know"
        assert read_as[0][1] == "tell me" and tokenize(text)[:len(tokenize(read_as[0][0]))] == tokenize(read_as[0][0])
    assert request_as_imperative(tokenize("I wonder whether the red sedan hits the bus."))[0] == tokenize(
        "tell me whether the red sedan hits the bus.")
    assert negative_question_as_asked(tokenize("the bus accelerates at the start, or nah?"))[0] == \
        tokenize("the bus accelerates at the start?")
    assert request_as_imperative(tokenize("I would be most grateful to know whether the bus hits the car."))[0] == \
        tokenize("tell me whether the bus hits the car.")
    assert tokenize("can u tell me") == tokenize("can you tell me")
    for text in ("Would you kindly tell me the speed of the bus?", "I should like to know the speed of the bus?"):
        assert request_as_imperative(tokenize(text))[0] == tokenize("tell me the speed of the bus?"), text
    for text in ("Tell me the speed of the red sedan at the start.", "Would you say the red sedan is fast at first?",
                 "Do you expect the red sedan to hit the bus?", "Is the red sedan, could you tell me, fast?"):
        assert request_as_imperative(tokenize(text)) == (tokenize(text), ()), text


def test_a_reading_of_another_kind_than_the_question_asks_is_refused():
    """A collision the question never says, yes or no for what or which, the video's collisions for a question
    about the time after it: each reading answers another question. The grammar's own forms stay read: 'run into',
    'which is faster, X or Y?', 'which one is faster, is it X?', 'what will happen next: will ...?'."""
    partner = "Events Objects filter_attributes[car] unique get_all_col_partners unique query_attributes[color]".split()
    assert impact_unsaid(tokenize("what colour is the parked car?"), partner).startswith("the question says nothing")
    for text in ("what colour is the thing the car runs into?", "what colour is the thing the car hits?"):
        assert impact_unsaid(tokenize(text), partner) == "", text
    static = "Objects filter_attributes[bus] unique start is_static".split()
    accel = "Objects filter_attributes[car] unique start is_accelerating".split()
    faster = "Objects filter_attributes[red] unique Objects filter_attributes[bus] unique start faster_velocity".split()
    future = "futureEvents Objects filter_attributes[car] unique filter_collision exist".split()
    for text, program in (("which bus is parked at the start?", static), ("what's the type of the car that's "
                          "speeding up?", accel), ("what will the car hit after the video?", future)):
        assert form_unasked(tokenize(text), program).startswith("the question asks"), text
    for text, program in (("which is faster, the red one or the bus?", faster), ("which one is faster, is it the "
                          "red one?", faster), ("what will happen next: will the car hit anything?", future),
                          ("is the bus parked at the start?", static)):
        assert form_unasked(tokenize(text), program) == "", text
    assert form_unasked(tokenize("what colour is the parked car?"), partner) == ""
    assert future_unread(tokenize("what colour is the thing the car hits after the video?"), partner) \
        .startswith("the question asks about the time after the video ('after the video')")
    for text in ("what colour is the thing the car hits?", "after the collision, what colour is it?"):
        assert future_unread(tokenize(text), partner) == "", text


def test_idioms_of_speed_time_and_the_engine_read_as_the_grammar_says_them():
    """Read word by word 'flat out' was floating (a typo fix), 'tearing along' slow, 'sitting tight' fast and 'right
    off the bat' a direction; whole, each is what it means. The longest idiom at a place wins; words that only hold
    an idiom's words stay as they are."""
    cases = {"Is the red car going flat out right off the bat?": "is the red car going fast at the start?",
             "Is the bus tearing along from the get-go?": "is the bus moving fast at the start?",
             "Is the bus sitting tight when things kick off?": "is the bus staying still at the start?",
             "Is the car barely moving out of the gate?": "is the car moving slowly at the start?",
             "Does the car have its foot on the gas?": "does the car accelerate?",
             "Is the car on the gas?": "is the car accelerating?",
             "Had the truck floored it, would it have hit the bus?": "had the truck accelerated, would it have hit the "
                                                                     "bus?",
             "Does the car rear-end the bus?": "does the car hit the bus?",
             "Does the car end up hitting the bus?": "does the car hit the bus?",
             "Has the car hit anything by the end of the clip?": "has the car hit anything during the video?",
             "Picture the car moving slowly. Would it hit the bus?": "imagine the car moving slowly. would it hit the "
                                                                     "bus?",
             "Is the quick car gathering speed?": "is the fast car accelerating?",
             "How much fast is the car?": "how fast is the car?",
             "Which colour is the slower-moving car, and the non-moving one?": "which colour is the slow-moving car, "
                                                                               "and the stationary one?"}
    for text, said in cases.items():
        words, read_as = idioms_as_said(tokenize(text))
        assert words == tokenize(said), text
        assert all(" ".join(tokenize(idiom)) in " ".join(tokenize(text)) for idiom, _ in read_as), read_as
    for text in ("Is the jet flying at the start?", "Does the car hit the bus right at the start?",
                 "Is the bus going out of view?", "Is the gas truck fast?", "How fast is the car when it enters the "
                 "picture?", "Does the car stop at the end?"):
        assert idioms_as_said(tokenize(text)) == (tokenize(text), ()), text


def test_a_notes_shorthand_reads_as_the_grammar_says_it():
    """An answer's form after the question, 'w/', '+' and choices split by slashes, as the grammar says them."""
    cases = {"green wagon slow at collision w/ red road bike? y/n": "green wagon slow at collision with red road bike?",
             "does the bus hit anything (yes/no)?": "does the bus hit anything?",
             "bus + car collide after end?": "bus and car collide after end?",
             "red car vs. blue bus: do they collide?": "red car and blue bus: do they collide?",
             "speed of biplane at start (static/slow/fast)": "speed of biplane at start: static, slow or fast"}
    for text, said in cases.items():
        assert shorthand_as_said(tokenize(text))[0] == tokenize(said), text
    for text in ("Is the bus slow or fast?", "Does the bus hit the car?"):
        assert shorthand_as_said(tokenize(text)) == (tokenize(text), ()), text
    # 'km/h' is a unit, not a choice; an answer's form alone asks nothing (and never raises)
    assert shorthand_as_said(tokenize("in km/h"))[0] == tokenize("in km/h")
    assert shorthand_as_said(tokenize("y/n"))[0] == []
    parser = QuestionParser.load()
    speed, cause, end, wrap, over = parser.analyse_batch([
        "speed of biplane at start (static/slow/fast)", "What made the green bus change direction?",
        "Is the dirtbike stopped when video is finish?", "Which way is the scooter heading as the clip wraps up?",
        "Once the clip's over, are the gray truck and the brown airliner headed for a collision?"])
    assert speed.program == "Objects filter_attributes[biplane] unique start query_moving_velocity".split()
    assert "asks nothing" in parser.analyse_batch(["y/n"])[0].reason
    assert "why" in cause.reason and "video's end" in end.reason and "video's end" in wrap.reason
    assert over.program[0] == "futureEvents"
    # a label's noun phrase; a heading before a colon that says nothing; a request is never yes or no; a unit
    label, heading, identify, unit, very = parser.analyse_batch([
        "blue scooter speed at the start?", "Cycling coach here: is the red sedan fast at the start?",
        "identify the colour of the aircraft floating aloft at the start",
        "What is the speed in km/h of the green scooter?", "How fast is the red sedan at the very end of the video?"])
    assert label.program == "Objects filter_attributes[blue] filter_attributes[scooter] unique start " \
        "query_moving_velocity".split()
    assert heading.program == f"{'Objects filter_attributes[red] filter_attributes[sedan] unique'} start " \
        "is_moving_velocity[fast]".split()
    assert "asks for something" in identify.reason and "in km/h" in unit.reason and "video's end" in very.reason
    # a heading that says when stays
    assert asides_dropped(tokenize("after the video ends: do they collide?"))[0] == \
        tokenize("after the video ends: do they collide?")


def test_a_request_closed_by_a_question_mark_reads_as_the_grammar_closes_it():
    assert imperative_as_stated(tokenize("Describe the speed of the bus?")) == (
        tokenize("describe the speed of the bus."), (("?", "."),))
    for text in ("Is the bus fast?", "Describe the speed of the bus.", "What is the speed of the bus?"):
        assert imperative_as_stated(tokenize(text)) == (tokenize(text), ()), text


def test_a_speed_class_the_question_never_says_is_refused():
    """'Is the bus driving at the start?' asks whether it moves, which no family asks; the decoder read it as slow.
    A reading of slow or fast needs a word that says a pace (the grammar's, or English's: 'at a snail's pace', 'at
    full speed', 'the slower-moving')."""
    slow = "Objects filter_attributes[bus] unique start is_moving_velocity[slow]".split()
    for text in ("is the bus driving at the start?", "is the bus going along at the start?"):
        assert speed_unsaid(tokenize(text), slow).startswith("the question says no speed"), text
    for text in ("is the bus driving slowly at the start?", "is the bus crawling at the start?", "is the bus moving "
                 "at a snail's pace?", "which colour is the slower-moving one?", "is the bus moving at full speed?"):
        assert speed_unsaid(tokenize(text), slow) == "", text
    static = "Objects filter_attributes[bus] unique start is_static".split()
    assert speed_unsaid(tokenize("is the bus parked at the start?"), static) == ""


def test_two_objects_and_anything_else_at_once_are_no_question_here():
    """'Does either X or Y hit anything?' read as the pair's collision answers another question: refused where the
    reading names two objects and the question an indefinite one; 'at any point' is no object."""
    program = ("Events Objects filter_attributes[red] filter_attributes[car] unique filter_collision Objects "
               "filter_attributes[blue] filter_attributes[bus] unique filter_collision exist").split()
    for text in ("Does either the red car or the blue bus hit anything?", "Do both the red car and the blue bus "
                 "collide with some other vehicle?", "Does the red car hit anything other than the blue bus?"):
        assert anything_unasked(tokenize(text), program).startswith("the question asks about two objects"), text
    for text in ("Does the red car hit the blue bus at any point?", "Do the red car and the blue bus collide?"):
        assert anything_unasked(tokenize(text), program) == "", text
    single = "Events Objects filter_attributes[red] filter_attributes[car] unique filter_collision exist".split()
    assert anything_unasked(tokenize("Does the red car hit anything?"), single) == ""


def test_a_negated_auxiliary_or_a_tag_asks_what_the_question_without_it_asks():
    """English answers 'Isn't X fast?' and 'X is fast, isn't it?' as 'Is X fast?': the negation on an auxiliary said
    before its subject (first, or after a clause said first) and a tag after a statement deny nothing. A negation
    inside the clause does, and a tag after a statement that denies is left to the rules that read negations."""
    cases = {"Isn't the red car fast at the start?": "is the red car fast at the start?",
             "Doesn't the red car hit the bus?": "does the red car hit the bus?",
             "When they collide, isn't the sedan faster than the bus?": "when they collide, is the sedan faster than "
                                                                         "the bus?",
             "If it had been fast, wouldn't the bike have hit the bus?": "if it had been fast, would the bike have hit "
                                                                         "the bus?",
             "The red car is fast at the start, isn't it?": "the red car is fast at the start?",
             "The car and the bus collide, don't they?": "the car and the bus collide?",
             "Had the jet been floating, it would have hit the bus, wouldn't it?": "had the jet been floating, it "
                                                                                    "would have hit the bus?",
             "The jet floats at the start, right?": "the jet floats at the start?"}
    for text, said in cases.items():
        words, read_as = negative_question_as_asked(tokenize(text))
        assert words == tokenize(said), text
        assert read_as and read_as[0][0] in " ".join(tokenize(text)), read_as
    for text in ("Is the red car not moving at the start?", "Does the red car not hit the bus?",
                 "The red car isn't moving at the start, is it?", "Is the car going left, right?",
                 "Isn't it?"):
        assert negative_question_as_asked(tokenize(text)) == (tokenize(text), ()), text


def test_a_question_said_as_a_noun_phrase_or_a_height_reads_as_the_grammar_says_it():
    """'speed of the red car at the start?' asks what the speed is; 'high above the ground' is up in the air, not the
    'high' of 'at high speed'; 'the heading of' is the direction; 'is the red car's speed low?' asks whether it is
    slow."""
    words, read_as = noun_phrase_as_question(tokenize("speed of red sedan at start?"))
    assert words == tokenize("what is the speed of red sedan at start?") and read_as == (("speed of",
                                                                                          "what is the speed of"),)
    assert noun_phrase_as_question(tokenize("the colour of the thing that floats?"))[0][:4] == ["what", "is", "the",
                                                                                               "color"]
    # 'tell me' with a motion's noun phrase, which the grammar never says ('tell me how fast ...' it does), or with
    # a colour's or a kind's, which the decoder read as yes or no before a clause ('... of the plane that floats')
    for text in ("tell me the speed of the red car at first", "tell me the red car's speed at first",
                 "Tell me the color of the thing that floats."):
        assert noun_phrase_as_question(tokenize(text))[0][:2] == ["what", "is"], text
    for text in ("What is the speed of the red car?", "Is the speed of the red car high?",
                 "Tell me the speed at which the red car is moving."):
        assert noun_phrase_as_question(tokenize(text)) == (tokenize(text), ()), text
    assert height_as_aloft(tokenize("is the jet high above the ground?"))[0] == tokenize("is the jet up above the "
                                                                                         "ground?")
    assert height_as_aloft(tokenize("is the jet high up at first?"))[0] == tokenize("is the jet up at first?")
    for text in ("is the jet moving at high speed?", "is the jet flying high?", "how high up is the jet?"):
        assert height_as_aloft(tokenize(text)) == (tokenize(text), ()), text
    # 'heading' as a noun is the direction; as a verb it stays the grammar's word of motion
    for text in ("what is the heading of the red car?", "what is the red car's heading?", "what is its heading?"):
        assert "direction" in heading_as_direction(tokenize(text))[0] and "heading" not in \
            heading_as_direction(tokenize(text))[0], text
    assert heading_as_direction(tokenize("where is the red car heading?")) == (tokenize("where is the red car "
                                                                                         "heading?"), ())
    # a speed said as the subject of a yes/no question: the object is, as the grammar says it
    for text, read in (("is the red car's speed low?", "is the red car slow ?"),
                       ("is the red car's initial speed high?", "is the red car fast at the start ?"),
                       ("is the speed of the red car zero at the start?", "is the red car static at the start ?"),
                       ("is the initial speed of the blue bus slow?", "is the blue bus slow at the start ?")):
        assert speed_as_subject(tokenize(text))[0] == read.split(), text
    # a time said by its clock or frame is the start; the first frame that shows an object is its coming into view
    assert first_frames_as_said(tokenize("at t = 0, how fast is the red car?"))[0] == tokenize(
        "at the start, how fast is the red car?")
    assert first_frames_as_said(tokenize("how fast is the red car in the first frame in which it is visible?"))[0] == \
        tokenize("how fast is the red car when it first appears?")
    for text in ("is the red car fast at the first frame?", "is the red car fast at time 2?"):
        assert first_frames_as_said(tokenize(text)) == (tokenize(text), ()), text
    for text in ("is the red car's speed higher than the bus's?", "what is the speed of the red car?",
                 "is the red car slow?", "is the speed of it low?"):
        assert speed_as_subject(tokenize(text)) == (tokenize(text), ()), text


def test_slowing_down_however_said_is_refused():
    """The lexicon would read 'slowing down' as the speed 'slow' and 'losing speed' or 'getting slower' as
    accelerating: each asks what no question here asks. Slowness and comparisons stay in scope, and no wording of
    the grammar is refused."""
    for text in ("Is the bus slowing down?", "Is the bus slowing at first?", "Does the car slow down at the start?",
                 "Is the red car losing speed?", "Is the car reducing its speed?", "Does the car's speed drop?",
                 "Is its speed going down?", "Is the truck getting slower at the start?",
                 "Is the red car coming to a stop?", "Is the car decelerating?"):
        assert reversed_as_said(tokenize(text)).startswith("the question asks whether an object slows down"), text
    for text in ("Is the car moving at a constant speed?", "Is the bus going at the same speed throughout?",
                 "Does the car keep a steady speed?", "Is the jet's speed unchanged at the start?"):
        assert reversed_as_said(tokenize(text)).startswith("the question asks whether an object keeps its speed"), text
    for text in ("Is the bus moving slowly at the start?", "Is the bus slower than the car?",
                 "Is the jet dropping at high speed?", "Had the car come to a stop, would it hit the bus?",
                 "Is the bus getting slower than the car?"):
        assert not reversed_as_said(tokenize(text)), text
    for e in synthesize(3000, 12, "all", augmented=True):
        assert not reversed_as_said(tokenize(e.text)), e.text


def test_a_reading_that_asks_the_opposite_of_the_question_is_refused():
    """No operation negates, so 'is it moving?' read as is_static, 'is it not accelerating?' as is_accelerating or
    'does it miss the bus?' as a collision would answer the opposite: each is unparsed. Rest said as rest or as
    negated motion, a negated fall and 'or not' stay in scope, and no wording of the grammar is refused."""
    static, floating = "<obj1> start is_static".split(), "<obj1> start is_floating".split()
    collide, accel = "Events <obj1> filter_collision <obj2> filter_collision exist".split(), \
        "<obj1> start is_accelerating".split()
    refused = [("is <obj1> moving at the start ?", static), ("is <obj1> in motion at the start ?", static),
               ("is <obj1> not accelerating at the start ?", accel), ("is the engine of <obj1> off at first ?", accel),
               ("does <obj1> never hit <obj2> ?", collide), ("does <obj1> miss <obj2> ?", collide),
               ("is <obj1> on the ground at the start ?", floating), ("is <obj1> grounded at first ?", floating),
               ("is <obj1> falling at the start ?", floating), ("is <obj1> descending at first ?", floating)]
    for text, program in refused:
        assert reversed_reading(tokenize(text), program), text
    kept = [("is <obj1> not moving at the start ?", static), ("is <obj1> standing still ?", static),
            ("is <obj1> non-moving at first ?", static), ("is <obj1> not in motion ?", static),
            ("without <obj1> moving at the start , would it hit <obj2> ?", static),
            ("is <obj1> accelerating or not at the start ?", accel), ("does <obj1> stay off the ground ?", floating),
            ("if <obj1> had not fallen , would it hit <obj2> ?", floating),
            ("is <obj1> hovering or falling ?", floating),
            ("is <obj1> up in the air or on the ground ?", floating),
            ("is <obj1> moving fast at the start ?", "<obj1> start is_moving_velocity[fast]".split())]
    for text, program in kept:
        assert not reversed_reading(tokenize(text), program), text
    for e in synthesize(3000, 11, "all", augmented=True):
        assert not reversed_reading(tokenize(e.text), e.program.split()), e.text


def test_an_attribute_of_an_object_the_question_names_is_refused():
    """'What is the color of the red sedan?' asks what no family asks (the decoder's nearest reading is its collision
    partner's colour); the attribute of an object described by what it does stays in scope, and so does every
    wording of the grammar."""
    partner = "Events <obj1> get_all_col_partners unique query_attributes[color]".split()
    for text in ("What is the color of the red sedan?", "What shape is the blue bus?", "what color is the sedan"):
        assert named_attribute(delexicalise(tokenize(text))[0], partner), text
    for text in ("What is the color of the thing the red sedan hits?", "What color is the object that hits the bus?"):
        assert not named_attribute(delexicalise(tokenize(text))[0], partner), text
    for e in synthesize(3000, 14, "all", augmented=True):
        said, refs = delexicalise(tokenize(e.text))
        assert not named_attribute(said, abstract_program(e.program.split(), refs)), e.text


def test_a_plane_as_the_noun_of_what_floats_is_no_object_left_out():
    """Only aeroplanes float, so 'plane' there is the object's noun; where the category would narrow the answer (a
    speed, a collision) no program can say it and the question stays unparsed."""
    parser = QuestionParser.load()
    ok, narrowed = parser.analyse_batch(["What type of plane is floating in the air at the start?",
                                         "What type of plane is moving fast at the start?"])
    assert ok.program == "Objects start filter_floating unique query_attributes[shape]".split()
    assert narrowed.program is None and narrowed.reason


def test_interjections_a_question_opens_with_are_left_out():
    for text in ("So, um, does the red car hit the bus?", "Hmm... does the red car hit the bus?",
                 "Okay, right, does the red car hit the bus?", "uh does the red car hit the bus?"):
        assert interjections_dropped(tokenize(text))[0] == tokenize("does the red car hit the bus?"), text
    # 'right' opens a time without a comma; an interjection with no question after it stays
    for text in ("Right at the start, is the red car fast?", "So the red car hits the bus?", "Well."):
        assert interjections_dropped(tokenize(text)) == (tokenize(text), ()), text


def test_a_vehicles_kind_or_sort_is_its_type():
    assert type_as_said(tokenize("What kind of plane is floating?"))[0] == tokenize("What type of plane is floating?")
    assert type_as_said(tokenize("which sort of bike is parked?"))[0] == tokenize("which type of bike is parked?")
    for text in ("Is the red car kind of slow?", "What kind of red is the car?"):
        assert type_as_said(tokenize(text)) == (tokenize(text), ()), text


def test_the_other_answer_offered_in_a_clause_of_its_own_is_left_out():
    for text, asked in (("Did the bus hit the bike, or did it miss it?", "Did the bus hit the bike?"),
                        ("is the jet hovering at the start or is it on the ground",
                         "is the jet hovering at the start?"),
                        ("Is the car parked at the start, or isn't it?", "Is the car parked at the start?")):
        assert tail_as_question(tokenize(text))[0] == tokenize(asked), text
    # a shared time, another object, or an alternative that is no opposite stays for the rules after
    for text in ("Is the jet floating or falling at the start?", "Does the car hit the bus or does it hit the jet?",
                 "Is the car fast at the start, or is it slow?"):
        assert tail_as_question(tokenize(text)) == (tokenize(text), ()), text


def test_an_asking_said_in_place_is_said_first():
    assert tail_as_question(tokenize("The red sedan is moving at what speed at the start?"))[0] == \
        tokenize("at what speed is the red sedan moving at the start?")
    assert tail_as_question(tokenize("right at the start, the jet was going at what speed?"))[0] == \
        tokenize("right at the start, at what speed was the jet going?")
    for text in ("At what speed is the red sedan moving?", "How fast is it, at what speed?"):
        assert tail_as_question(tokenize(text)) == (tokenize(text), ()), text
    # the object alone, set off by a comma, is what the question's 'they' stands for
    assert attention_as_subject(tokenize("The blue bus and the red car, do they crash?"))[0] == \
        tokenize("do the blue bus and the red car crash?")


def test_a_counterfactual_that_compares_a_vehicle_with_itself_is_refused():
    imagined = "Objects unique Counterfactual_moving_fast Objects unique filter_collision exist".split()
    for text in ("if it had been slower at the start, would it hit the bus?", "had it moved more slowly, would it "
                 "hit the bus?", "if it had gone faster, would it hit the bus?"):
        assert comparison_imagined(tokenize(text), imagined), text
    accelerating = "Objects unique Counterfactual_accelerating Objects unique filter_collision exist".split()
    for text in ("if it had been getting faster from the start, would it hit the bus?", "if it had been going "
                 "faster and faster, would it hit the bus?"):
        assert not comparison_imagined(tokenize(text), accelerating), text
    compared = "Objects unique faster_velocity".split()
    assert not comparison_imagined(tokenize("is the car faster than the bus?"), compared)


def test_counts_places_relative_directions_and_a_vehicle_read_as_its_motion_are_refused():
    parser = QuestionParser.load()
    texts = ["Does the blue scooter collide with two other vehicles?", "Is the red car heading towards the bus?",
             "Is the jet flying away from the red bus at the start?", "Which vehicle hits the blue bus first?",
             "Is the gray jet higher than the blue bus at the start?"]
    assert_refused(parser, texts)
    assert "counts" in parser.analyse_batch(texts[:1])[0].reason
    # ... but a higher speed is a speed
    assert parser.analyse_batch(["Is the red car moving at a higher speed than the bus at the start?"])[0].program
    assert form_unmatched(tokenize("which vehicle hits the bus first?"),
                          "Objects filter_attributes[bus] unique start query_moving_direction".split())


def test_a_partner_in_turn_or_by_its_motion_a_height_and_another_property_are_refused():
    parser = QuestionParser.load()
    texts = ["What type of vehicle does the green truck hit third?", "Is the cyan airliner moving upwards?",
             "Is the jet going up at the start?", "Does the brown minivan crash into a stationary vehicle?",
             "Is the gray sedan hit by a floating plane?", "What is the speed of the vehicle that hits the truck?",
             "What direction is the vehicle that hits the red jet moving in?"]
    assert_refused(parser, texts)
    # ... but a speed going up, what floats up in the air and a partner's colour are read
    kept = ["Is the blue truck's speed going up at the start?", "Is the red biplane floating up in the air?",
            "What colour is the vehicle that the purple sedan crashes into?"]
    for text, parse in zip(kept, parser.analyse_batch(kept)):
        assert parse.program, text


def test_a_pose_a_spin_and_a_landing_are_refused():
    parser = QuestionParser.load()
    texts = ["Is the purple motorbike standing upright at the start?", "Is the blue fighter rotating at the start?",
             "Does the red biplane hit the ground?", "Does the gray airliner touch down at some point?"]
    assert_refused(parser, texts)
    assert parser.analyse_batch(["Is the red fighter off the ground when the video begins?"])[0].program


def test_a_speed_as_a_number_and_a_time_window_are_refused():
    for text, said in (("is it going 3.5 m/s at the start?", "3.5 m/s"), ("is it doing 20mph?", "20mph"),
                       ("is it over five metres per second?", "five metres per second"), ("at 5m/s?", "5m/s")):
        assert speed_measured(tokenize(text)) == said, text
    for text in ("is it fast at the start?", "does it hit the bus in 5 minutes?", "is the m bus fast?"):
        assert speed_measured(tokenize(text)) == "", text
    collision = "Events Objects filter_attributes[red] unique filter_collision exist".split()
    for text in ("does it hit anything within 2 seconds?", "does it hit anything in the first second?"):
        assert clock_unasked(tokenize(text), collision), text
    assert not clock_unasked(tokenize("does it hit anything?"), collision)
    # at the start, and in a counterfactual's condition, 'the first second' and 'the first frames' are the start
    assert not clock_unasked(tokenize("is it fast in the first second?"), "Objects unique start is_static".split())
    imagined = "Objects unique Counterfactual_static Objects unique filter_collision exist".split()
    assert not clock_unasked(tokenize("had it been parked in the first frames, would it hit the bus?"), imagined)
    assert clock_unasked(tokenize("had it been parked, would it hit the bus within 2 seconds?"), imagined)


def test_a_ranking_alike_speeds_a_manner_and_an_amount_of_acceleration_are_refused():
    for text, said in (("is the red sedan the fastest at the start?", "fastest"), ("which one moves the most?",
                       "the most"), ("is the wagon the first vehicle to collide?", "the first vehicle"),
                       ("is it the only one that floats?", "the only one")):
        assert said in ranking(tokenize(text)), text
    # the first partner is a partner's question
    assert not ranking(tokenize("what colour is the first vehicle to hit the red sedan?"))
    assert speeds_alike(tokenize("is the van as quick as the gray jet?")) == "as quick as"
    assert speeds_alike(tokenize("are the van and the jet equally fast?")) == "equally fast"
    for text in ("would you describe the plane as slow as the video starts?", "is it going as fast as it can?",
                 "is it as still as a rock?"):
        assert not speeds_alike(tokenize(text)), text
    parser = QuestionParser.load()
    texts = ["How hard does the red sedan hit the blue bus?", "What is the acceleration of the brown wagon?",
             "How quickly is the yellow scooter speeding up at the start?", "Is the red sedan the fastest vehicle?",
             "Is the cyan minivan as fast as the gray airliner at the start?"]
    assert_refused(parser, texts)
    kept = ["How swiftly is the red sedan moving at the start?", "How fsat is the red sedan at the start?"]
    for text, parse in zip(kept, parser.analyse_batch(kept)):
        assert parse.program and parse.program[-1] == "query_moving_velocity", text


def test_two_things_at_once_several_vehicles_a_path_and_a_take_off_are_refused():
    assert properties_joined(tokenize("is it moving fast and accelerating?"))
    assert properties_joined(tokenize("is it floating and not moving fast?"))
    for text in ("is it going fast and not slowly?", "do the sedan and the bus collide?", "faster and faster?"):
        assert not properties_joined(tokenize(text)), text
    assert several_asked(tokenize("what colours are the floating planes?"))
    assert not several_asked(tokenize("compare the speeds of the sedan and the cruiser: is the sedan faster?"))
    assert questions_joined(tokenize("is it fast at the start, and does it hit the bus?"))
    assert not questions_joined(tokenize("does it hit anything, and if so, is it in the video?"))
    parser = QuestionParser.load()
    texts = ["Does the purple biplane fly in a straight line?", "Does the gray jet take off at some point?",
             "If the red sedan had been static, how fast would the blue bus be when it hits it?",
             "What is the speed of the red sedan when the blue bus comes into view?"]
    assert_refused(parser, texts)
    # the other answer denied after 'and' is the question's own
    fast, aloft = parser.analyse_batch(["Is the yellow truck going fast and not slowly at the start?",
                                        "Is the brown biplane up in the air and not on the ground at the start?"])
    assert fast.program[-1] == "is_moving_velocity[fast]" and aloft.program[-1] == "is_floating"


def test_a_near_miss_a_chase_a_size_an_ought_and_a_collision_at_the_start_are_refused():
    parser = QuestionParser.load()
    texts = ["Does the red sedan nearly hit the blue bus?", "Does the cyan truck come close to hitting the red jet?",
             "Is the yellow minivan chasing the red bike?", "Does the red bus pass the green sedan?",
             "Does the metal bus hit the rubber car?", "Should the gray truck have stopped?",
             "Are the green jet and the red bus touching at the start?", "Does the red sedan lose control?",
             "Does the cyan truck knock the green bike over?"]
    assert_refused(parser, texts)
    # ... but 'the frames that follow' is the future, and a start said of a motion is the motion's
    kept = ["Will the gray car slam into the brown bicycle in the frames that follow?",
            "In the frames that follow the video, will the red jet hit the cyan truck?"]
    for text, parse in zip(kept, parser.analyse_batch(kept)):
        assert parse.program and "filter_collision" in parse.program, text
    # it was read as had the bus been parked: no condition is said (`condition_unsaid`), so it is not imagined
    parked = parser.parse("Does the purple bus, parked at the start, get hit by the red sedan?")
    assert parked is None or not any(t.startswith("Counterfactual") for t in parked)
    assert collision_at_start(tokenize("do they touch at the start?"), "Events X filter_collision exist".split())
    assert not collision_at_start(tokenize("is it parked at the start?"), "Events X filter_collision exist".split())


def test_staying_still_speeding_and_coming_down_on_read_and_floating_unsaid_refused():
    parser = QuestionParser.load()
    still, put, speeding, down = parser.analyse_batch([
        "If the red bus had stayed still, would the green truck have hit it?",
        "What if the purple cruiser had stayed put - would it still have hit the yellow sedan?",
        "Is the red car speeding at the start?", "Does the purple airliner come down on the cyan wagon?"])
    assert "Counterfactual_static" in still.program and "Counterfactual_static" in put.program
    assert speeding.program[-1] == "is_moving_velocity[fast]"
    assert down.program[-1] == "exist" and "filter_collision" in down.program
    assert parser.analyse_batch(["Is the red car speeding up at the start?"])[0].program[-1] == "is_accelerating"
    # a reading of floating needs a word of it; a reading of rest, no speed said
    assert floating_unsaid(tokenize("had the bus stayed still, would it hit the truck?"),
                           "Objects unique Counterfactual_floating X".split())
    assert not floating_unsaid(tokenize("had the jet stayed aloft, would it hit the truck?"),
                               "Objects unique Counterfactual_floating X".split())
    assert parser.analyse_batch(["Does the gray jet come down on the ground?"])[0].program is None
    # a condition said in the simple past after 'imagine' is the grammar's 'had been'
    imagined = parser.analyse_batch(["Imagine the blue double bus was parked the whole time. Would the red utility "
                                     "bike still crash into it?"])[0]
    assert imagined.program and "Counterfactual_static" in imagined.program


def test_all_vehicles_a_premise_a_chain_an_order_of_appearing_and_visibility_are_refused():
    assert quantified(tokenize("do all the cars collide?")) and quantified(tokenize("which vehicles are parked?"))
    assert not quantified(tokenize("of all the vehicles, which one is slow?"))
    assert not quantified(tokenize("do they collide with each other?"))
    assert premised(tokenize("given that the bus is parked, does the sedan hit it?"))
    assert not premised(tokenize("assuming the bus had been parked, would the sedan hit it?"))
    assert chained(tokenize("what colour is the vehicle hit by the vehicle that hits the bus?"))
    assert not chained(tokenize("what colour is the vehicle that the red sedan hits?"))
    assert not chained(tokenize("which model is the thing that the gray vehicle struck?"))   # the grammar's
    parser = QuestionParser.load()
    texts = ["Does the red sedan appear before the blue bus?", "Is the red sedan visible at the start?"]
    assert_refused(parser, texts)
    seen = parser.analyse_batch(["How fast is the yellow fighter moving when it becomes visible?"])[0]
    assert seen.program and "come_in_frame" in seen.program


def test_a_measure_of_speed_a_colour_checked_a_count_and_scenery_are_refused():
    for text in ("what is the top speed of the red sedan?", "how does the speed of the sedan change?",
                 "what speed does the sedan reach?", "is the sedan much faster than the bus?"):
        assert speed_measure(tokenize(text)), text
    for text in ("is the car going at top speed?", "what would happen if it had been gaining speed: would it hit "
                 "the bus?", "what is the speed of the sedan at the start?"):
        assert not speed_measure(tokenize(text)), text
    assert checked_attribute(tokenize("is the accelerating vehicle blue?"))
    assert not checked_attribute(tokenize("what colour is the accelerating vehicle?"))
    parser = QuestionParser.load()
    texts = ["Count the planes in the video.", "Does the green jet hit the wall?", "Is the accelerating vehicle blue?"]
    assert_refused(parser, texts)


def test_a_label_an_aside_a_closing_word_and_an_inverted_condition_are_read():
    assert asides_dropped(tokenize("Q1: how fast is the red sedan (the car) moving?"))[0] == \
        tokenize("how fast is the red sedan moving?")
    assert asides_dropped(tokenize("quick question: is it fast?"))[0] == tokenize("is it fast?")
    # an aside that says more stays ('the blue one' is a colour), and so does a first sentence that is no label
    assert asides_dropped(tokenize("is the bus (the blue one) fast?"))[0] == tokenize("is the bus (the blue one) fast?")
    assert asides_dropped(tokenize("the bus is parked. is it red?"))[0] == tokenize("the bus is parked. is it red?")
    assert interjections_dropped(tokenize("does it hit anything lol?"))[0] == tokenize("does it hit anything")
    # a speaker's fillers within the question, with their commas
    assert interjections_dropped(tokenize("is the um green sedan, uh, fast?"))[0] == tokenize("is the green sedan fast?")
    # more said between commas about a vehicle already named by colour and type is no part of the question
    assert asides_dropped(tokenize("is the red sedan, which later hits the bus, fast?"))[0] == \
        tokenize("is the red sedan fast?")
    for kept in ("is the sedan, the red one, fast?", "when the red sedan hits the blue bus, is it fast, or slow?",
                 "when the red sedan hits the bus, the sedan it is going slow, yes or no?"):   # the question itself
        assert asides_dropped(tokenize(kept))[0] == tokenize(kept), kept
    # a remark that names no vehicle, motion or collision goes; one that says what is asked stays
    assert asides_dropped(tokenize("there are many vehicles here. is this red bus fast?"))[0] == \
        tokenize("is the red bus fast?")
    assert asides_dropped(tokenize("one vehicle is floating. what colour is it?"))[0] == \
        tokenize("one vehicle is floating. what colour is it?")
    parser = QuestionParser.load()
    red = "Objects filter_attributes[red] filter_attributes[sedan] unique"
    label, chat, inverted, landed = parser.analyse_batch([
        "Q1: how fast is the red sedan (the car) moving at the start?", "does the red sedan hit anything lol",
        "Had the cyan biplane stayed still, would the cyan biplane have collided with the red sedan?",
        "If the gray jet had never landed, would it have hit the red sedan?"])
    assert label.program == f"{red} start query_moving_velocity".split()
    assert chat.program == f"Events {red} filter_collision exist".split()
    assert "Counterfactual_static" in inverted.program and "Counterfactual_floating" in landed.program


def test_a_person_the_picture_an_intent_a_pose_a_landing_and_motions_compared_are_refused():
    assert motion_unfiltered(tokenize("is the parked blue bus faster than the sedan?"),
                             "Objects X unique Objects Y unique start faster_velocity".split())
    assert not motion_unfiltered(tokenize("what colour is the parked vehicle?"),
                                 "Objects start filter_static unique query_attributes[color]".split())
    assert not motion_unfiltered(tokenize("is the bus the faster one?"), "X Y start faster_velocity".split())
    parser = QuestionParser.load()
    texts = ["Is the gray scooter ridden by anyone?", "Does the blue jet cast a shadow on the ground?",
             "Does the red sedan hit the blue bus on purpose?", "Is the red sedan trying to reach the blue bus?",
             "Does the brown scooter flip over when it hits the red sedan?", "Is the yellow airliner about to land?",
             "Does the green minivan change lanes?", "Does the cyan biplane lose height during the video?",
             "Is the red sedan accelerating faster than the blue bus?", "Is the moving bus faster than the red sedan?",
             "Is the red sedan still accelerating when it hits the blue bus?", "Does the blue bus complete a lap?",
             "Are the red sedan and the blue bus in a queue?", "Is the red sedan breaking the speed limit?",
             "Does the cyan jet stall?"]
    assert_refused(parser, texts)
    assert_refused(parser, ["Would you recommend the blue bus?", "What physics engine made this video?",
                            "Is gravity acting on the gray jet?", "Does the yellow bus absorb the impact?",
                            "Was the collision between the red sedan and the blue bus avoidable?",
                            "Track the blue bus through the video.", "Explain why the red sedan hits the blue bus.",
                            "Does the red sedan stop moving?", "How fast is the red sedan now?",
                            "Can you see the red sedan?", "Are you sure about the blue bus?",
                            "Does the red sedan cut off the blue bus?", "Does the blue bus tailgate the red sedan?",
                            "Is the red sedan drifting at the start?", "Does the red sedan hit the blue bus at an angle?",
                            "Does the red sedan cross the path of the blue bus?"])
    drifting = parser.analyse_batch(["Is the gray jet drifting in the air at the start?"])[0]
    assert drifting.program and drifting.program[-1] == "is_floating"
    stops, request = parser.analyse_batch([
        "After the video stops, are the yellow jet and the green sedan going to crash into each other?",
        "Can you see whether the yellow tandem bike is accelerating at the start?"])
    assert stops.program[0] == "futureEvents" and request.program[-1] == "is_accelerating"
    who = parser.analyse_batch(["Who is faster at the start: the purple sedan or the gray jet?"])[0]
    assert who.program and who.program[-1] == "faster_velocity"
    # two vehicles side by side with nothing that compares them ask about each, not whether one is faster
    assert_refused(parser, {"Is the red car or the blue bus moving at the start?": "side by side",
                            "Are the red car and the blue bus speeding up at the start?": "compares nothing"})
    cut = parser.analyse_batch(["After the video cuts off, will the yellow suv hit anything?"])[0]
    assert cut.program and cut.program[0] == "futureEvents"   # the video cuts off; no vehicle cuts another off


def test_a_hedge_is_a_preamble_but_a_preamble_that_says_when_stays():
    assert framing_dropped(tokenize("if you had to guess, do the bus and the truck collide?"))[0] == \
        tokenize("do the bus and the truck collide?")
    assert framing_dropped(tokenize("considering the video, and looking closely, is the bus fast?"))[0] == \
        tokenize("is the bus fast?")
    assert framing_dropped(tokenize("thinking about the moment they collide, is the bus faster?"))[1] == ()
    assert framing_dropped(tokenize("if the bus had been parked, would it hit the truck?"))[1] == ()
    assert framing_dropped(tokenize("if it isn't too much trouble, could you tell me whether the bus is fast?"))[0] == \
        tokenize("could you tell me whether the bus is fast?")
    parser = QuestionParser.load()
    guess, when = parser.analyse_batch([
        "If you had to guess, do the blue bus and the green truck collide at any point in the video?",
        "Thinking only about the moment they collide, is the yellow bus faster than the brown sedan?"])
    assert guess.program[0] == "Events" and when.program[-3:] == ["unique", "get_frame", "faster_velocity"]


def test_two_changes_the_video_otherwise_and_other_comparisons_are_refused_not_the_grammars():
    for text in ("if the sedan had been fast and the blue bus parked, would they collide?",
                 "would the sedan hit the bus if the video were longer?"):
        assert imagined_otherwise(tokenize(text), tokenize(text)), text
    for text in ("if the video kept going, would the bus hit the sedan?", "do you know if the sedan and the bus "
                 "will collide?", "if the sedan had been parked, would it and the bus collide?"):
        assert not imagined_otherwise(tokenize(text), tokenize(text)), text
    for text in ("is the collision violent?", "does the sedan move more than the bus?", "is the truck faster than it "
                 "was at the start?", "is the truck carrying anything?", "is either the sedan or the bus fast?"):
        assert otherwise_compared(tokenize(text), tokenize(text)), text
    for text in ("is the bike moving more slowly than the bus?", "when it hits the bus, is it slower than it?",
                 "is the bike going less quickly than the bus?"):
        assert not otherwise_compared(tokenize(text), tokenize(text)), text


def test_the_viewer_how_it_heads_and_the_faster_of_two_read_by_the_shipped_parser():
    parser = QuestionParser.load()
    camera, heading, two = parser.analyse_batch([
        "Initially, where is the green double bus going: left, right, towards the camera or away from it?",
        "At the start, how is the red sedan heading?", "Is the brown scooter the faster of the two at the start, "
        "compared with the cyan jet?"])
    assert camera.program[-1] == heading.program[-1] == "query_moving_direction"
    assert two.program and two.program[-1] == "faster_velocity"
    # towards another vehicle is still no direction asked here
    assert parser.analyse_batch(["Is the red sedan heading towards the blue bus?"])[0].program is None


def test_kinds_interjections_and_offered_opposites_read_by_the_shipped_parser():
    parser = QuestionParser.load()
    kind, um, ground, which = parser.analyse_batch([
        "What kind of plane is floating at the beginning?", "So, um, does the gray chopper crash into anything?",
        "Is the purple jet flying at the beginning, or is it sitting on the ground?",
        "Which kind of plane is moving fast at the start?"])
    assert kind.program == "Objects start filter_floating unique query_attributes[shape]".split()
    assert um.program == ("Events Objects filter_attributes[gray] filter_attributes[chopper] unique filter_collision "
                          "exist").split()
    assert ground.program == "Objects filter_attributes[purple] filter_attributes[jet] unique start is_floating".split()
    assert which.program is None and which.reason     # 'which kind' asked as yes or no was read as 'is it floating'


def test_tiny_model_learns_template_programs(synthetic_fit):
    assert synthetic_fit.val_exact_match >= 0.98
    texts, programs, _ = synthetic(400, seed=1)     # new questions, new object combinations
    got = synthetic_fit.parser.parse_batch(texts)
    assert sum(g == p for g, p in zip(got, programs)) / len(texts) >= 0.98


def test_bad_text_is_unparsed_never_a_crash(synthetic_fit):
    p = synthetic_fit.parser
    assert p.parse("florp zzk blarg?") is None
    assert p.parse_batch(["", "   ", None, "Is the red sedan floating at the start?" * 100]) == [None] * 4
    # Known words in no template's order: a program of a training shape, or unparsed; never an exception.
    text = "floating collide sedan the the red velocity with?"
    salad = p.parse(text)
    assert salad is None or program_shape(abstract_program(salad, delexicalise(tokenize(text))[1])) in p.shapes
    # Every opening of a question, down to one word, reads without an exception (a rule once read a third word
    # that 'Is the?' does not have).
    question = tokenize("Is the vehicle that hits the red car a bus, and what colour and type is it?")
    p.analyse_batch([" ".join(question[:k]) for k in range(1, len(question) + 1)])


def test_one_unknown_word(synthetic_fit):
    """Documented behaviour: a typo one edit from a unique vocabulary word is read as that word (best effort);
    a word with no such neighbour is unknown, and with `max_unknown_words` = 0 the question is unparsed."""
    p = synthetic_fit.parser
    good = ["Objects", "filter_attributes[green]", "filter_attributes[sedan]", "unique", "start", "is_floating"]
    assert p.parse("Is the green sedan floating at the start?") == good
    assert p.parse("Is the gren sedan floating at the start?") == good
    assert p.parse("Is the magenta sedan floating at the start?") is None
    assert p.analyse_batch(["Is the magenta sedan floating at the start?"])[0].reason == "unknown words: 'magenta'"


def test_unparsed_questions_say_why(synthetic_fit):
    p = dataclasses.replace(synthetic_fit.parser.params, max_unknown_words=1)
    parser = QuestionParser(synthetic_fit.parser.model, synthetic_fit.parser.words, synthetic_fit.parser.programs,
                            p, synthetic_fit.parser.shapes)
    empty, tractor = parser.analyse_batch(["  ", "Is the green tractor floating at the start?"])
    assert empty.program is None and empty.reason == "empty question"
    # One unknown word is allowed, but not as the name of an object.
    assert tractor.program is None and tractor.reason == ("the question names the green tractor: no vehicle here is "
                                                          "called 'tractor'")


def test_a_word_after_a_whole_description_is_the_sentences(synthetic_fit):
    """An unknown word after a colour alone is the object's noun (a vehicle the catalogue lacks); after a sub-type
    the description is whole and the word belongs to the sentence, unless 'than' follows (a comparison of what no
    question asks)."""
    p = dataclasses.replace(synthetic_fit.parser.params, max_unknown_words=1)
    parser = QuestionParser(synthetic_fit.parser.model, synthetic_fit.parser.words, synthetic_fit.parser.programs,
                            p, synthetic_fit.parser.shapes)
    still, bigger, tractor = parser.analyse_batch(["Is the green sedan still floating at the start?",
                                                   "Is the red sedan bigger than the blue bus at the start?",
                                                   "Is the green tractor floating at the start?"])
    assert still.program == ["Objects", "filter_attributes[green]", "filter_attributes[sedan]", "unique", "start",
                             "is_floating"], still.reason
    assert bigger.program is None and bigger.reason == ("the question compares the red sedan by 'bigger', which no "
                                                         "question here asks about")
    assert tractor.program is None and "called 'tractor'" in tractor.reason


def test_a_count_is_no_question_here(synthetic_fit):
    """No program counts or explains, so 'how many' and 'why' are out of scope whatever the rest of the question
    reads like."""
    count = synthetic_fit.parser.analyse_batch(["How many wheels does the green sedan have at the start?"])[0]
    assert count.program is None and count.reason.startswith("the question asks for a count")
    # nor does any explain: 'why' reads like the collision it asks the cause of
    for text in ("Why did the green sedan hit the red bus?", "How come the green sedan hit the red bus?"):
        why = synthetic_fit.parser.analyse_batch([text])[0]
        assert why.program is None and why.reason == "the question asks why, which no question here answers", text


def test_a_property_no_question_asks_is_no_question_here(synthetic_fit):
    """An unknown word where the question says what it asks ('the mass of', 'how heavy', 'what size') is the property
    asked, 'where is it' without a word of motion asks a place and 'is there a red sedan' whether it is there: out of
    scope; 'where is it heading' and a known word there are read."""
    parser = synthetic_fit.parser
    for text, asked in (("What is the mass of the green sedan?", "the 'mass'"), ("How heavy is the red bus?",
                        "how 'heavy'"), ("At the start, what size is the green sedan?", "the 'size'"),
                        ("Tell me the weight of the red bus.", "the 'weight'")):
        parse = parser.analyse_batch([text])[0]
        assert parse.program is None and parse.reason.startswith(f"the question asks {asked}, "), text
    owned = parser.analyse_batch(["Does the green sedan have its headlights on?", "Are the red bus's tyres flat?"])
    assert [p.reason.split(",")[0] for p in owned] == ["the question asks about its 'headlights'",
                                                      "the question asks about its 'tyres'"]
    unknown = parser.analyse_batch(["What is the temperature of the green sedan?"])[0]
    assert unknown.reason.startswith("the question asks the 'temperature', a word the parser does not know")
    # a place, a size or a time, however the lexicon would read the word ('far' as 'right', 'high' as the speed,
    # 'behind' as 'down'); how often, the time around a collision, one of several in turn, a turn
    for text, asked in (("How far is the green sedan from the red bus?", "how 'far', which no question here asks"),
                        ("What is the distance between the green sedan and the red bus?", "the 'distance', which"),
                        ("How high up is the red bus?", "how 'high', which"),
                        ("What is the green sedan's height at the start?", "the 'height', which"),
                        ("When does the green sedan stop?", "when something happens"),
                        ("At which frame does the green sedan hit the red bus?", "when something happens"),
                        ("Where is the green sedan at the end of the video?", "where an object is"),
                        ("Is there a green sedan in the video?", "whether an object is there"),
                        ("Is the red car behind the blue bus?", "where a vehicle is ('behind')"),
                        ("Is the red car next to the bus?", "where a vehicle is ('next to')"),
                        ("Is the red car closer to the camera than the bus?", "where a vehicle is ('closer')"),
                        ("Does the red car hit the bus twice?", "how often ('twice')"),
                        ("Does the red car hit the bus three times?", "how often ('three times')"),
                        ("Is the red car fast after it hits the bus?", "about the time after a collision"),
                        ("Is the red car moving before the crash?", "about the time before a collision"),
                        ("What colour is the second vehicle the red car hits?", "for one of several in turn"),
                        ("Does the red car turn at the start?", "whether a vehicle turns ('turn')")):
        parse = parser.analyse_batch([text])[0]
        assert parse.program is None and parse.reason.startswith(f"the question asks {asked}"), text
    # the video's end, asked of anything but collisions (the decoder read 'at the end' as the start)
    for text in ("At the end of the video, is the green sedan moving fast?", "Is the green sedan static when the "
                 "clip is over?", "In the last frame, what colour is the moving vehicle?"):
        parse = parser.analyse_batch([text])[0]
        assert parse.program is None and parse.reason.startswith("the question asks about the video's end"), text
    # a comparison offered as a choice asks which, which no family answers; one comparison asked is read
    for text in ("Is the green sedan faster or slower than the red bus at the start?", "At the start, is the red "
                 "bus slower or quicker than the green sedan?"):
        parse = parser.analyse_batch([text])[0]
        assert parse.program is None and parse.reason.startswith("the question offers '"), text
    assert not parser.analyse_batch(["Is the green sedan faster than the red bus or the blue bus?"])[0] \
        .reason.startswith("the question offers")
    for text in ("Where is the green sedan heading at the start?", "What is the moving velocity of the green sedan "
                 "at the beginning?", "What is the green sedan's moving velocity at the beginning?",
                 "When the green sedan hits the red bus, is it fast?", "By the end of the video, has the green sedan "
                 "hit the red bus?", "Once the video is over, will the green sedan run into the red bus?",
                 "Is the engine of the green sedan turned on at the start?", "Is the green sedan fast right after the "
                 "video starts?", "Will the green sedan hit the red bus after the video ends?"):
        assert not parser.analyse_batch([text])[0].reason.startswith("the question asks"), text


def test_blind_baseline_majority_per_family():
    b = blind_baseline(["f1", "f1", "f1", "f2", "f2"], ["true", "false", "true", "red", "blue"])
    assert b == {"majority": {"f1": "true", "f2": "blue"}, "overall": "true"}


def test_save_load_round_trip(synthetic_fit, tmp_path):
    synthetic_fit.parser.save(tmp_path / "qp")
    loaded = QuestionParser.load(tmp_path / "qp")
    texts, _, _ = synthetic(50, seed=2)
    assert loaded.parse_batch(texts) == synthetic_fit.parser.parse_batch(texts)
    assert [loaded.parse(t) for t in texts[:5]] == loaded.parse_batch(texts[:5])


def test_an_ensemble_decodes_by_its_members_mean_probability(synthetic_fit):
    """Alike members decode as one; a member that is sure of another first token outvotes a hesitant one."""
    model = synthetic_fit.parser.model.members[0]
    texts, _, _ = synthetic(30, seed=3)
    src, lens = pad_batch([synthetic_fit.parser.words.encode(delexicalise(tokenize(t))[0]) for t in texts])
    one, two = Ensemble([model]).greedy(src, lens, 48), Ensemble([model, model]).greedy(src, lens, 48)
    assert [i for i, _, _ in one] == [i for i, _, _ in two]
    assert np.allclose([p for _, p, _ in one], [p for _, p, _ in two], rtol=1e-5)
    assert np.allclose([a for _, _, a in one][0], [a for _, _, a in two][0], atol=1e-6)
    sure = copy.deepcopy(model)
    with torch.no_grad():                  # the first step's readout: one token, far above every other
        sure.out.weight.zero_()
        sure.out.bias.fill_(-50.0)
        sure.out.bias[EOS_ID] = 50.0
    mixed = Ensemble([model, sure]).greedy(src, lens, 48)
    assert all(ids == [] and 0.4 < p < 0.6 for ids, p, _ in mixed)   # <eos> first: mean of ~0 and ~1


def test_missing_or_broken_weights_are_one_clear_error(synthetic_fit, tmp_path):
    with pytest.raises(ArtifactError, match="dynclevr train qparser"):
        QuestionParser.load(tmp_path / "nowhere")
    synthetic_fit.parser.save(tmp_path / "qp")
    (tmp_path / "qp" / "model.pt").write_bytes(b"not a model")
    with pytest.raises(ArtifactError, match="unreadable"):
        QuestionParser.load(tmp_path / "qp")


def test_training_is_deterministic(tmp_path):
    params = small_params(epochs_max=2)
    for run in ("a", "b"):
        fit(lambda k: pairs(200, seed=3 + k), pairs(20, seed=9), params, echo=lambda *_: None).parser.save(
            tmp_path / run)
    for name in ("model.pt", "question_vocab.json", "program_vocab.json", "parser.json"):
        assert (tmp_path / "a" / name).read_bytes() == (tmp_path / "b" / name).read_bytes()


def test_well_formed_checks_arguments_and_stack():
    assert well_formed("Objects filter_attributes[red] unique start is_floating".split())
    assert not well_formed("Objects filter_attributes[red] unique is_floating".split())          # one input short
    assert not well_formed("Objects filter_attributes[red] unique start".split())                # two values left
    assert not well_formed("Objects filter_attributes[fast] unique start is_floating".split())   # bad argument
    assert not well_formed(["Objects", "florp"])


def test_train_command_writes_loadable_weights_and_manifest(tmp_path):
    config = tmp_path / "qp.toml"
    config.write_text("[splits.qp-synthetic]\nseed = 5\nscenes = 10\n"
                      "[qparser]\nembedding = 16\nhidden = 32\nepochs_max = 1\nexamples_per_epoch = 300\n"
                      "val_examples = 40\nmembers = 2\n")
    cfg = Config.load(config)
    texts, programs, scenes = synthetic(300, seed=4, scenes=10)
    families = [p[-1] for p in programs]
    write_questions([{"id": f"{s}-{i}", "scene": s, "type": "factual", "subtype": "velocity", "family": f,
                      "text": t, "program": " ".join(p), "answer": "true" if i % 3 else "false"}
                     for i, (t, p, s, f) in enumerate(zip(texts, programs, scenes, families))],
                    tmp_path / "data" / "qp-synthetic" / "questions.parquet")
    manifest = train_qparser(cfg, tmp_path / "data", cfg.split("qp-synthetic"), tmp_path / "out",
                             echo=lambda *_: None)
    on_disk = json.loads((tmp_path / "out" / "manifest.json").read_text())
    assert on_disk == manifest and manifest["blind_questions"] == 300 and manifest["examples_per_epoch"] == 300
    assert manifest["blind_split"] == "qp-synthetic" and manifest["params"]["hidden"] == 32
    assert {"questions_digest", "templates_digest", "val_exact_match", "heldout_phrasings_exact_match", "members",
            "train_seconds", "torch"} <= set(manifest)
    assert [m["seed"] for m in manifest["members"]] == [0, 1] and all(m["curve"] for m in manifest["members"])
    blind = json.loads((tmp_path / "out" / "blind.json").read_text())
    assert blind["overall"] == "true" and set(blind["majority"]) == set(families)
    loaded = QuestionParser.load(tmp_path / "out")
    assert len(loaded.model.members) == 2 and len(loaded.parse_batch(texts[:20])) == 20
    # Members trained in two processes are the same weights.
    train_qparser(cfg, tmp_path / "data", cfg.split("qp-synthetic"), tmp_path / "two", echo=lambda *_: None,
                  workers=2)
    for name in ("model.pt", "question_vocab.json", "program_vocab.json", "parser.json"):
        assert (tmp_path / "two" / name).read_bytes() == (tmp_path / "out" / name).read_bytes(), name


HELDOUT = "qparser-heldout"


@pytest.fixture(scope="module")
def heldout_questions(tmp_path_factory) -> list[dict]:
    """Questions about scenes no shipped weight has seen: a split of its own seed, simulated and annotated here (so
    the test is honest on a clean checkout). Every candidate question of its scenes counts, not only the balanced
    selection: every template, many objects."""
    d = tmp_path_factory.mktemp("qparser")
    (d / "split.toml").write_text(f"[splits.{HELDOUT}]\nseed = 987654\nscenes = 3\n")
    cfg = Config.load(d / "split.toml")
    runner = Runner(cfg, cfg.split(HELDOUT), d / "data", echo=lambda *_: None)
    for stage in ("simulate", "render", "annotate"):
        runner.run(stage, [0, 1, 2])
    return [q for s in runner.split.scene_names()
            for q in read_questions(runner.store.path("annotate", s, CANDIDATES_OUT))]


def test_shipped_weights_parse_held_out_questions(heldout_questions):
    """Every candidate question of scenes the parser never saw (the dataset's texts draw the seen phrasings)."""
    manifest = json.loads((WEIGHTS_DIR / "qparser" / "manifest.json").read_text())
    cfg = Config.load()
    assert cfg.split(manifest["blind_split"]).seed != 987654            # really scenes the parser never saw
    parser = QuestionParser.load()
    got = parser.parse_batch([q["text"] for q in heldout_questions])
    right = sum(g == q["program"].split() for g, q in zip(got, heldout_questions))
    assert len(heldout_questions) >= 200 and right / len(heldout_questions) >= 0.995
    # Issue 13's goals: 99.5% on seen phrasings, 95% on held-out ones (those whose words all occur in training;
    # a synonym never seen is mostly unparsed, see the README).
    assert manifest["val_exact_match"] >= 0.995 and manifest["heldout_known_words_exact_match"] >= 0.95
    assert parser.parse("florp zzk blarg?") is None and parser.parse("") is None
    moving, slowing = parser.analyse_batch(["Is the red sedan moving at the start?",
                                            "Is the red sedan decelerating at the start?"])
    assert moving.program is None and "asks whether an object is moving" in moving.reason
    assert slowing.program is None and "slows down" in slowing.reason      # not WordNet's 'slow', a speed
    # the passive says the other one is faster, the way round from the lexicon's 'outpace' -> 'move faster than':
    # the one outdone is the slower (`wordings.IDIOMS`); another passive is refused
    outpaced, outruns, passed = parser.analyse_batch(["Is the blue bus outpaced by the red sedan at the start?",
                                                      "Does the red sedan outrun the blue bus at the start?",
                                                      "Is the blue bus passed by the red sedan at the start?"])
    assert outpaced.program == ("Objects filter_attributes[blue] filter_attributes[bus] unique Objects "
                                "filter_attributes[red] filter_attributes[sedan] unique start slower_velocity").split()
    assert passed.program is None and "passive" in passed.reason
    assert outruns.program == ("Objects filter_attributes[red] filter_attributes[sedan] unique Objects "
                               "filter_attributes[blue] filter_attributes[bus] unique start faster_velocity").split()


def test_shipped_weights_read_the_papers_and_peoples_wordings():
    """The wordings issue 13 found broken: the authors' own and a casual one."""
    parser = QuestionParser.load()
    red, blue = "Objects filter_attributes[red] filter_attributes[sedan] unique", \
        "Objects filter_attributes[blue] filter_attributes[bus] unique"
    cases = {
        "Is the red sedan's engine on at the beginning?": f"{red} start is_accelerating",
        "Does the red sedan collide with the blue bus in the given frames?":
            f"Events {red} filter_collision {blue} filter_collision exist",
        "Did the red sedan crash into the blue bus?": f"Events {red} filter_collision {blue} filter_collision exist",
        "is the red sedan moving fast at the beginning": f"{red} start is_moving_velocity[fast]",
        "Is the red sedan moving faster than the blue bus when they collide?":
            f"{red} {blue} Events {red} filter_collision {blue} filter_collision unique get_frame faster_velocity",
        "When the red sedan hits the blue bus, is it going slower than the bus?":
            f"{red} {blue} Events {red} filter_collision {blue} filter_collision unique get_frame slower_velocity",
        # a clause of time first, its pronoun before the object it stands for (read with the clause last)
        "When it crashes into the blue bus, how fast is the red sedan going?":
            f"{red} Events {red} filter_collision {blue} filter_collision unique get_frame query_moving_velocity",
        "At the moment the red sedan hits it, is the blue bus standing still?":
            f"{blue} Events {blue} filter_collision {red} filter_collision unique get_frame is_static",
        # a request for the question, read as the grammar's 'tell me'
        "Can you tell me the speed of the red sedan at the start?": f"{red} start query_moving_velocity",
        "I'd like to know whether the red sedan hits the blue bus.":
            f"Events {red} filter_collision {blue} filter_collision exist",
        # terse, a clause naming the object before its pronoun, a shorter mention said first once the clause is last
        "speed of the red sedan at start?": f"{red} start query_moving_velocity",
        "tell me the red sedan's speed at the start?": f"{red} start query_moving_velocity",
        "Once the red sedan shows up, how fast is it moving?": f"{red} {red} come_in_frame query_moving_velocity",
        "At the instant the red sedan and the blue bus collide, is the sedan travelling fast?":
            f"{red} Events {red} filter_collision {blue} filter_collision unique get_frame is_moving_velocity[fast]",
        "At impact, is the red sedan moving slower than the blue bus?":
            f"{red} {blue} Events {red} filter_collision {blue} filter_collision unique get_frame slower_velocity",
    }
    for text, program in cases.items():
        assert parser.parse(text) == program.split(), text
    # the parse says where it moved a clause, and only there
    moved, said = parser.analyse_batch(["When it crashes into the blue bus, how fast is the red sedan going?",
                                        "Did the red sedan crash into the blue bus?"])
    assert moved.reordered == "how fast is the red sedan going when it crashes into the blue bus ?"
    assert said.reordered == ""
    # `ask` shows the second mention's reading among its evidence, and only a merged mention
    said = parser.analyse_batch(["When the red sedan hits the blue bus, is it going slower than the bus?",
                                 "Does the red sedan hit the bus before the sedan is parked, and the school bus?"])
    assert said[0].read_as == (("bus", "blue bus"),)
    assert ("sedan", "red sedan") in said[1].read_as and not any(a == b for a, b in said[1].read_as)


def test_synonym_lexicon_stands_in_only_for_unknown_words_with_known_ones():
    """Every entry of synonyms.txt is live for the shipped parser: an unknown word, known words for it."""
    parser = QuestionParser.load()
    lexicon = synonyms()
    assert len(lexicon) >= 100 and parser.synonyms == lexicon
    red, blue = "Objects filter_attributes[red] filter_attributes[sedan] unique", \
        "Objects filter_attributes[blue] filter_attributes[bus] unique"
    pair = f"Events {red} filter_collision {blue} filter_collision exist".split()
    assert parser.parse("Did the red sedan ram into the blue bus?") == pair
    assert parser.analyse_batch(["Did the red sedan ram into the blue bus?"])[0].read_as == (("ram", "hit"),)
    assert parser.parse("Did the red sedan smack into the blue bus in the footage?") == pair
    assert parser.parse("Was the red sedan immobile at the onset?") == f"{red} start is_static".split()
    # A known word keeps its own meaning: 'still' here is "even so", not "stationary".
    still = parser.parse("If the red sedan had been parked from the start, would it still hit the blue bus?")
    assert still is not None and "Counterfactual_static" in still
    # Colours and vehicles no catalogue has stay unknown.
    assert parser.parse("Did the pink sedan ram into the blue tractor?") is None


def test_a_long_misspelt_word_is_read_as_the_one_known_word_an_edit_away():
    """'acelerating', 'stationery': a sentence word of 7 or more letters one edit from exactly one known word is that
    word (shown among the words read as others); real words stay unknown, and a colour or vehicle no catalogue has
    stays a question about no object."""
    parser = QuestionParser.load()
    red = "Objects filter_attributes[red] filter_attributes[sedan] unique"
    typo = parser.analyse_batch(["Is the red sedan acelerating at the start?"])[0]
    assert typo.program == f"{red} start is_accelerating".split() and ("acelerating", "accelerating") in typo.read_as
    for word in ("sitting", "bouncing", "wreckage"):
        assert parser._words(f"Is the red sedan {word} at the start?")[0][4] == word, word
    assert "fastest" in parser._words("Is the red sedan fastest at the start?")[1]   # a ranking, not 'faster'
    for text in ("Is the magenta sedan floating?", "Is the red limousine fast?"):
        assert parser.parse(text) is None, text


def test_a_slip_of_the_fingers_is_read_as_the_one_word_it_slipped_from():
    """Two letters swapped, a neighbouring key instead or as well, a letter left out or doubled, in a word of any
    length (4+ letters): the one readable word it slipped from; none where two fit; never a real word's neighbour
    that is no slip ('black' is not 'back'). Two words typed together are read apart."""
    words = {"slowly", "color", "object", "speed", "fast", "faster", "back", "stopped", "struck"}
    for typed, meant in (("slolwy", "slowly"), ("oclor", "color"), ("oject", "object"), ("speeed", "speed"),
                         ("sopeed", "speed"), ("shpeed", None), ("stoped", "stopped"), ("tsruck", "struck"),
                         ("spwed", "speed"), ("cloour", "color"), ("black", None), ("fastr", None), ("car", None)):
        assert slipped(typed, words, SPELLINGS) == meant, typed
    assert slipped("spee" + "d" * 5000, words) is None   # a pasted run of letters: no slip, no quadratic work
    # two words run together, where they split one way only
    assert run_together("fastmoving", {"fast", "moving", "fas"}) == "fast moving"
    assert run_together("redcar", {"red", "car", "redc", "ar"}) is None and run_together("fast", words) is None
    parser = QuestionParser.load()
    red = "Objects filter_attributes[red] filter_attributes[sedan] unique"
    assert parser.parse("Is the redsedan movingfast at the start?") == f"{red} start is_moving_velocity[fast]".split()
    assert parser.parse("Is the red sedan moving slolwy at the start?") == \
        f"{red} start is_moving_velocity[slow]".split()
    assert parser.parse("What is the oclor of the thing that the red sedna hits?") == \
        f"Events {red} get_all_col_partners unique query_attributes[color]".split()
    # 'fastr' slips from 'fast' and 'faster', 'fater' from 'after' and 'faster': before 'than', the comparative
    assert slips("fastr", words) == ["fast", "faster"]
    assert parser.parse("Is the red sedan fater than the bus at the start?") == \
        f"{red} Objects filter_attributes[bus] unique start faster_velocity".split()


def test_eval_types_each_question_with_one_slip_deterministically():
    said = "What colour is the vehicle that the yellow sedan crashes into?"
    texts = [typed_with_a_slip(said, np.random.default_rng(k)) for k in range(40)]
    assert sum(t != said for t in texts) >= 30 and len(set(texts)) > 20
    assert all(len(t.split()) == len(said.split()) and t[0] == said[0] for t in texts)
    assert texts == [typed_with_a_slip(said, np.random.default_rng(k)) for k in range(40)]
    assert typed_with_a_slip("Is it red?", np.random.default_rng(0)) == "Is it red?"   # no word of 5+ letters


def test_an_unknown_word_is_read_by_its_stem_but_never_an_object_word():
    parser = QuestionParser.load()
    assert parser._stand_in("zooms") == ["zooming"]          # the known word of its stem with its ending
    assert parser._stand_in("collisions") == ["collision"]
    assert parser._stand_in("hurtles") == ["racing"]         # the stem of a lexicon word ('hurtling')
    assert parser._stand_in("jets") == ["jets"]              # no catalogue has 'jets': the copy path stays exact
    assert parser._stand_in("florp") == ["florp"]


def test_bad_synonym_lexicon_is_one_clear_error(tmp_path):
    bad = tmp_path / "synonyms.txt"
    bad.write_text("# fine\nrammed = hit\nsmacked into\n")
    with pytest.raises(DynclevrError, match=r"synonyms.txt:3: expected 'word = known word\(s\)'"):
        synonyms(bad)
    with pytest.raises(DynclevrError, match="lexicon .* is unreadable .* restore it"):
        synonyms(tmp_path / "missing.txt")


def test_a_counterfactual_changes_the_vehicle_its_condition_names():
    """'Would the car have hit the bus if the bus had been parked?' changes the bus, wherever the condition stands; a
    pronoun in the condition leaves the decoder's reading."""
    words = delexicalise(tokenize("Would the red car have hit the bus if the bus had been static?"))[0]
    assert condition_subject(words) == "<obj2>"
    program = ["<obj1>", "Counterfactual_static", "<obj1>", "filter_collision", "<obj2>", "filter_collision", "exist"]
    assert condition_subject_first(words, program) == \
        ["<obj2>", "Counterfactual_static", "<obj2>", "filter_collision", "<obj1>", "filter_collision", "exist"]
    for text in ("Would the red car have hit the bus if it had been static?",
                 "If the red car had been static, would it have hit the bus?",
                 "Would the red car have hit the bus had the red car been parked?"):
        words = delexicalise(tokenize(text))[0]
        assert condition_subject_first(words, program) == program, text
    parser = QuestionParser.load()
    assert parser.parse("Would the red car have collided with the bus had the bus been moving fast at the start?") \
        == parser.parse("If the bus had been moving fast at the start, would it have collided with the red car?")


def test_the_floating_plane_is_the_floating_vehicle():
    """Only aeroplanes float: 'the floating plane' says no more than 'the floating vehicle'."""
    assert floating_plane_as_vehicle(tokenize("What colour is the floating plane?"))[0] == \
        tokenize("What colour is the floating vehicle?")
    assert floating_plane_as_vehicle(tokenize("Is the red floating plane fast?"))[1] == ()
    assert QuestionParser.load().parse("What is the colour of the floating aeroplane?") == \
        "Objects start filter_floating unique query_attributes[color]".split()


def test_a_time_between_commas_after_the_subject_is_said_last():
    assert inserted_time_last(tokenize("Does the red biplane, at any point, collide with the green sedan?"))[0] == \
        tokenize("Does the red biplane collide with the green sedan at any point?")
    assert inserted_time_last(tokenize("Is the red car, when it hits the bus, moving fast?"))[0] == \
        tokenize("Is the red car moving fast when it hits the bus?")
    # a clause of time that ends the question, or one a question follows, stays where it is
    for text in ("Is the red car fast, at the start?", "When the red car hits the bus, is it fast?",
                 "The red car, at the start, is it fast?"):
        assert inserted_time_last(tokenize(text)) == (tokenize(text), ()), text


def test_a_cause_or_what_happens_is_not_asked():
    """'because' asks why ('did it hit the bus because it was fast?' was read as whether it was fast); 'what would
    happen if ...' asks what happens, unless a question follows it."""
    parser = QuestionParser.load()
    why, happens, asked = parser.analyse_batch([
        "Did the red car hit the bus because it was fast?", "What would happen if the red car were static?",
        "What would happen if the red car had been static: would it have hit the bus?"])
    assert why.program is None and "why" in why.reason
    assert happens.program is None and "what happens" in happens.reason
    assert asked.program is not None and "Counterfactual_static" in asked.program


def test_a_counterfactual_changes_the_motion_from_the_start_only():
    """Every intervention here sets a motion from the start: one at the end or after a collision is refused, 'the
    whole time' and 'when the video starts' (misspelt too) are the start."""
    for text in ("If the red car had been static at the end, would it have hit the bus?",
                 "If the red car had been static after the collision, would it have hit the truck?",
                 "If the red car had stopped halfway, would it have hit the bus?"):
        assert "other than the start" in imagined_otherwise(tokenize(text), tokenize(text)), text
    for text in ("Had the yellow bus kept still the whole time, would it have hit the blue sedan?",
                 "If the red car had been static when the video started, would it have hit the bus?"):
        assert not imagined_otherwise(tokenize(text), tokenize(text)), text
    said = tokenize("Would the red car have hit the bus if it had been slow when the video begisn?")
    assert not imagined_otherwise(said, [w if w != "begisn" else "begins" for w in said])


def test_a_word_the_parser_does_not_know_may_be_an_impact_misspelt():
    """Only then is a collision read where the question says none ('would the bus have been static too?' is no
    collision's question; 'collied' may be one)."""
    assert all(map(impact_like, ["collied", "crahsed", "tocuh", "colision", "smahsed"]))
    assert not any(map(impact_like, ["too", "while", "also", "then", "both"]))
    parser = QuestionParser.load()
    assert parser.parse("If the red car had been static, would the bus have been static too?") is None
    assert parser.parse("Is the red car moving fast while the bus is static?") is None


def test_a_frame_a_vector_or_an_amount_of_acceleration_is_not_asked_but_a_colour_beside_them_is():
    parser = QuestionParser.load()
    frame, vector, angular, amount, colour = parser.analyse_batch([
        "In which frame does the red car hit the bus?", "What is the red sedan's velocity vector at the start?",
        "What is the angular velocity of the jet?", "What is the blue sedan's rate of acceleration at the start?",
        "What is the colour of the object with a positive acceleration at the start?"])
    assert frame.program is None and "when" in frame.reason
    assert vector.program is None and angular.program is None and "physical quantity" in vector.reason
    assert amount.program is None and "how much" in amount.reason
    assert colour.program == "Objects start filter_accelerating unique query_attributes[color]".split()


def test_a_part_of_the_video_two_times_or_a_rank_to_move_are_not_asked():
    """'in the last second' or 'at the end' narrows the video's collisions, 'before the video ends' is no future, 'at
    the start and when it hits the bus' asks two times, 'the first to move' ranks: no program reads them."""
    parser = QuestionParser.load()
    assert_refused(parser, {
        "Does the red car hit the bus in the last second of the video?": "within a time",
        "Does the red car hit the bus during the second half of the video?": "within a time",
        "Will the red car and the bus collide before the video ends?": "asks about the video",
        "Is the red car fast at the start and when it hits the bus?": "two times",
        "Is the red car the first to move?": "ranks"})
    assert times_joined(tokenize("When the red car and the bus collide, is the car fast?")) == ""
    assert parser.parse("Does the red car hit the bus at some point in the video?") is not None


def test_which_vehicle_what_it_does_or_a_part_of_it_is_not_asked():
    """A colour or type reading needs the question to ask an attribute; 'what is it doing' and 'what part of the bus'
    ask what no family answers; 'what speed is it doing' is a speed."""
    parser = QuestionParser.load()
    assert_refused(parser, {
        "What does the red car hit?": "which vehicle",
        "Name the vehicle that the red car hits.": "which vehicle",
        "What is the red car doing at the start?": "what a vehicle does",
        "What part of the bus does the red car hit?": "'part'"})
    assert parser.parse("What speed is the brown sedan doing when the clip begins?") == \
        "Objects filter_attributes[brown] filter_attributes[sedan] unique start query_moving_velocity".split()
    assert parser.parse("What type of vehicle does the red car hit?")[-1] == "query_attributes[shape]"


def test_a_count_a_leaving_a_bare_faster_others_and_a_counterfactual_future_are_not_asked():
    parser = QuestionParser.load()
    assert_refused(parser, {
        "Does the red car hit exactly one vehicle?": "how often",
        "Do the red car and the bus collide at most once?": "how often",
        "How fast is the red car moving when it leaves the view?": "leaves the view",
        "Is the red car faster?": "nothing to compare",
        "Is the red car fast compared with the others at the start?": "ranks",
        "Is the red car at the start faster than the bus at the collision?": "speaks of a collision",
        "If the red car had been static, will it hit the bus after the video ends?": "after the video",
        "Will the red car be faster than the bus after the video?": "other than the start"})
    # ... but 'exactly' as stress, 'the rest of the video', 'getting' or 'going' faster and 'by any chance' read
    for text in ("How fast exactly is the brown wagon moving at the start?",
                 "Will the red car hit the bus in the rest of the video?",
                 "At the start, is the engine of the gray sedan pushing it to go faster?",
                 "By any chance, is the gray bus creeping along slowly as the video opens?"):
        assert parser.parse(text) is not None, text


def test_what_could_happen_or_an_imagined_collision_compared_is_not_asked():
    parser = QuestionParser.load()
    assert_refused(parser, {
        "Is it possible for the red car to hit the bus?": "could happen",
        "Could the red car have hit the bus?": "could happen",
        "Would the red car have hit the bus sooner if it had been fast?": "imagined collision",
        "Would the collision between the red car and the bus have happened later if the car had been slow?":
            "imagined collision"})
    # 'likely' hedges a prediction; 'could' with a condition is a counterfactual
    assert parser.parse("Is the red car likely to hit the bus after the video?")[0] == "futureEvents"
    assert "Counterfactual_moving_fast" in parser.parse(
        "Could the red car have hit the bus if it had been moving fast at the start?")


def test_a_type_checked_two_attributes_a_motions_onset_and_a_partner_at_the_start_are_not_asked():
    parser = QuestionParser.load()
    assert_refused(parser, {
        "Is the vehicle that hits the red car a bus?": "is a 'bus'",
        "What is the colour and type of the floating vehicle at the start?": "two things at once",
        "What colour is the vehicle that starts floating?": "begins or ends",
        "What colour is the vehicle that was moving fast before it stopped?": "other than the start",
        "What colour is the vehicle that hits the red car at the start?": "collision at the start"})
    # ... but a time said by a motion's start, and a vehicle described as stopped, read
    for text in ("Does the purple bus crash into anything after it starts moving?",
                 "At the start of the clip, which color is the stopped thing?"):
        assert parser.parse(text) is not None, text


def test_a_speakers_correction_of_a_vehicles_name_keeps_the_name_said_last():
    """'the red no the blue sedan', 'the gray jet no sorry the gray biplane': the name after the correction stands."""
    cases = {"does the red no the blue sedan hit anything": "does the blue sedan hit anything",
             "is the gray jet no sorry the gray biplane fast": "is the gray biplane fast",
             "does it hit the bus , I mean , the red truck ?": "does it hit the red truck ?",
             "would it run into the blue mountain bike no the blue road bike": "would it run into the blue road bike"}
    for text, said in cases.items():
        assert corrections_dropped(tokenize(text))[0] == tokenize(said), text
    # no correction: an answer's form, an alternative, a 'no' that negates
    for text in ("is the red car fast , yes or no ?", "is the red car or the blue bus faster ?",
                 "does the red car hit no other vehicle ?", "is the red car fast ? no ?"):
        assert corrections_dropped(tokenize(text)) == (tokenize(text), ()), text


def test_spoken_questions_their_fillers_tags_and_slang_read_as_the_grammar_says_them():
    """A voice assistant's transcripts, learners' tags, enthusiasts' slang and formal certainty, each read into its
    family; questions that ask what no family asks stay unparsed."""
    parser = QuestionParser.load()
    school = "Objects filter_attributes[purple] filter_attributes[school_bus] unique"
    dirt = "Objects filter_attributes[purple] filter_attributes[dirtbike] unique"
    scooter = "Objects filter_attributes[purple] filter_attributes[scooter] unique"
    bus, bike = ("Objects filter_attributes[purple] filter_attributes[school_bus] unique",
                 "Objects filter_attributes[gray] filter_attributes[tandem_bike] unique")
    cases = {
        "hey assistant does the red school bus no wait the purple school bus collide with anything":
            f"Events {school} filter_collision exist",
        "so like the purple dirt bike at the very beginning is it going fast or slow or not moving at all":
            f"{dirt} start query_moving_velocity",
        "At the start of video itself, purple scooter is not moving, isn't it?": f"{scooter} start is_static",
        "Is the purple dirt bike at the beginning slower than the purple scooter, or?":
            f"{dirt} {scooter} start slower_velocity",
        "Grandma wants to know, is that purple scooter just parked there when the video begins?":
            f"{scooter} start is_static",
        "is the purple scooter hauling at the start?": f"{scooter} start is_moving_velocity[fast]",
        "Determine the speed at which the purple scooter enters the field of view.":
            f"{scooter} {scooter} come_in_frame query_moving_velocity",
        "How fast is the purple scooter moving when it comes first into the picture?":
            f"{scooter} {scooter} come_in_frame query_moving_velocity",
        "The scooter purple, how fast it is moving at the start of the video?":
            f"{scooter} start query_moving_velocity",
        "Can it be established that a collision occurred between the purple school bus and the gray tandem bike?":
            f"Events {bus} filter_collision {bike} filter_collision exist",
        "Picture this: the purple scooter is going fast at the start. Does it collide with the purple school bus "
        "then?": f"{scooter} Counterfactual_moving_fast {scooter} filter_collision {school} filter_collision exist",
    }
    texts = list(cases)
    for text, parse in zip(texts, parser.analyse_batch(texts)):
        assert parse.program is not None and " ".join(parse.program) == cases[text], (text, parse.reason)
    cases.update({
        'yo how fast is the "purple scooter" going right at the start?? \U0001F697\U0001F4A8':
            f"{scooter} start query_moving_velocity",
        "tbh idk, is the purple scooter moving *slow* at the start of the vid?":
            f"{scooter} start is_moving_velocity[slow]",
        "the purple scooter - is it accelerating when the vid starts?? yes/no pls": f"{scooter} start is_accelerating",
        "spd @ start, purple scooter?": f"{scooter} start query_moving_velocity",
        "purple scooter purple school bus collide in video":
            f"Events {scooter} filter_collision {school} filter_collision exist",
        "Does the purple velocipede collide with the purple motor car?":
            "Events Objects filter_attributes[purple] filter_attributes[bicycle] unique filter_collision "
            "Objects filter_attributes[purple] filter_attributes[car] unique filter_collision exist",
        "is my purple road bike faster than the purple scooter at the start?":
            f"Objects filter_attributes[purple] filter_attributes[road_bike] unique {scooter} start faster_velocity",
        "okay is the red uh wait no the purple scooter floating at the start": f"{scooter} start is_floating",
        "Please tell me, at the beginning, does the purple scooter move faster than the purple school bus?":
            f"{scooter} {school} start faster_velocity"})
    texts = list(cases)
    for text, parse in zip(texts, parser.analyse_batch(texts)):
        assert parse.program is not None and " ".join(parse.program) == cases[text], (text, parse.reason)
    refused = ["At what time, in seconds, does the purple scooter collide with the purple school bus?",
               "Is the green articulated charabanc accelerating at the start?",
               "what's the license plate on the purple school bus lol", "what colour is the boat floating on the water",
               "purple scooter speed end of video",
               "Who's driving the purple school bus?", "In which direction does purple scooter move at end of video?",
               "Which vehicle was at fault in the collision between the purple scooter and the purple school bus?"]
    for text, parse in zip(refused, parser.analyse_batch(refused)):
        assert parse.program is None, (text, parse.program)
    # once refused: the vehicle said first and then 'it' is asked about (`dislocated_as_asked`), in the video
    assert " ".join(parser.parse("The purple scooter, it collide with something in the video?")) == \
        f"Events {scooter} filter_collision exist"


def test_collision_idioms_and_a_translators_wording_read_and_their_wrong_readings_refused():
    parser = QuestionParser.load()
    grief, tangle, plough, lick, foot, begun, compared, which_speed, screen = parser.analyse_batch([
        "Does the brown SUV come to grief with anything during the clip?",
        "What kind of vehicle did the red double-decker tangle with?",
        "Was the blue bendy bus going at a fair lick when it ploughed into the yellow sedan?",
        "Is the gray wagon moving at a good lick at the start?",
        "If the purple sedan had put its foot down right from the start, would it have hit the yellow utility bike?",
        "In the beginning time, is the red sedan moving fast?",
        "At the start, is the brown truck moving faster compared with the cyan airliner?",
        "At the start of video the cyan double-decker bus is moving with which speed?",
        "When the yellow scooter comes into the screen, how fast is it?"])
    assert grief.program[-1] == "exist" and "filter_collision" in grief.program
    assert tangle.program[-2:] == ["unique", "query_attributes[shape]"] and "get_all_col_partners" in tangle.program
    assert plough.program[-1] == "is_moving_velocity[fast]" and "filter_collision" in plough.program
    assert lick.program[-2:] == ["start", "is_moving_velocity[fast]"]
    assert "Counterfactual_accelerating" in foot.program
    assert begun.program[-2:] == ["start", "is_moving_velocity[fast]"]
    assert compared.program[-2:] == ["start", "faster_velocity"]
    assert which_speed.program[-2:] == ["start", "query_moving_velocity"]
    assert "come_in_frame" in screen.program
    # each of these had a wrong reading: leaving the view as coming into it, the video's end as its start, a place
    # as a speed, a speeding up at a collision as a speed there
    refused = parser.analyse_batch([
        "When the gray chopper goes out from the view, with what speed is it moving?",
        "In the end time of video, which color is the vehicle that is not moving?",
        "The brown road bike and the cyan wagon, which one is more close to the camera in the beginning?",
        "Is the red biplane still floating in the air when the cartoon finishes?",
        "Was the purple tandem bike speeding up at the moment it collided with the red sedan?"])
    assert [p.program for p in refused] == [None] * 5
    assert "leaves the view ('goes out')" in refused[0].reason and "speeds up" in refused[4].reason


def test_a_researchers_window_a_phones_mtb_a_label_before_a_time_and_a_race_read_and_sounds_refused():
    parser = QuestionParser.load()
    window, mtb, label, line, carrying = parser.analyse_batch([
        "In the post-observation window, will the blue school bus and the green sedan come into contact?",
        "dose the brown scooter hit the gray mtb in the video",
        "Here's an easy one: at any point in the video, do the green scooter and the red minivan collide?",
        "Right off the line, is the blue station wagon quicker than the green chopper?",
        "Was the green double-decker carrying more speed than the blue cruiser when they collided?"])
    assert window.program[0] == "futureEvents" and window.program[-1] == "exist"
    assert "filter_attributes[mountain_bike]" in mtb.program
    assert label.program[0] == "Events" and label.program[-1] == "exist"   # 'easy' had been read as slow
    assert line.program[-2:] == ["start", "faster_velocity"]
    assert carrying.program[-1] == "faster_velocity" and "filter_collision" in carrying.program
    sound, parking = parser.analyse_batch([
        "And what a noise that was - what sound does the double-decker make when it hits the cyan minivan?",
        "is the brown minivan parked in a parking spot or just on the floor"])
    assert sound.program is None and "heard ('noise')" in sound.reason
    assert parking.program is None and "'parking spot'" in parking.reason


def test_a_letters_greeting_sign_off_and_clip_heading_and_a_remark_after_the_question_ask_nothing():
    parser = QuestionParser.load()
    letter, heading, remark, starts, pickup = parser.analyse_batch([
        "Dear support, if the purple school bus had been moving fast from the start, would it have collided with the "
        "blue road bike? Many thanks, Oksana",
        "Hi team, re clip 3: at the moment the green road bike crashes with the blue truck, is the bike going faster "
        "than the truck? Thx",
        "what kind of vehicle did the blue dirt bike crash into??? couldn't see",
        "Right when it starts, how fast is the red sedan going?",
        "Does the purple pickup run into the blue biplane at any point in the video?"])
    assert "Counterfactual_moving_fast" in letter.program
    assert heading.program[-1] == "faster_velocity" and "filter_collision" in heading.program
    assert remark.program[-1] == "query_attributes[shape]" and "get_all_col_partners" in remark.program
    assert starts.program[-2:] == ["start", "query_moving_velocity"]   # had been read as coming into view
    assert "filter_attributes[truck]" in pickup.program
    # what follows the question and asks something stays: its time, or the property to give
    later, give = parser.analyse_batch(["Hello, is the gray school bus moving fast at the end of the video? Best "
                                        "wishes, Femi", "Which vehicle is accelerating at the beginning? Give its type."])
    assert later.program is None
    assert give.program[-1] == "query_attributes[shape]"


def test_a_dropped_g_is_the_word_in_full_and_jammed_is_hit():
    assert tokenize("How fast is the bus movin' at the start?")[5] == "moving"
    assert tokenize("the 'spin' and Berlin's")[2] == "spin"   # a quoted word and a possessive stay as they are
    parser = QuestionParser.load()
    driver, jammed = parser.analyse_batch(["Who's drivin' the purple SUV, mate?",
                                           "Was the red truck moving fast when it jammed the yellow tandem bike?"])
    assert driver.program is None and "person" in driver.reason
    assert jammed.program[-1] == "is_moving_velocity[fast]" and "filter_collision" in jammed.program


def _context_read(text: str) -> str:
    return " ".join(context_as_question(catalogue_names(tokenize(text))[0])[0])


def test_context_before_the_question_gives_its_vehicles_condition_and_moment():
    assert _context_read("The yellow school bus is near the left edge. I couldn't tell whether it was moving. How "
                         "fast is it going right at the start?") == \
        "how fast is the yellow school bus going right at the start ?"
    assert _context_read("There's a red double-decker and a cyan scooter near the middle. They come really close. Do "
                         "they end up colliding?") == "do the red double bus and the cyan scooter end up colliding ?"
    assert _context_read("The green double-decker and the yellow jet are in frame. Is the double-decker slower than "
                         "the jet at the start?") == \
        "is the green double bus slower than the yellow jet at the start ?"
    assert _context_read("Suppose the gray dirt bike hadn't been moving at the beginning. The blue bus would still "
                         "come through. Would the dirt bike collide with the bus in that case?") == \
        ("suppose the gray dirtbike had not been moving at the beginning . would the dirtbike collide with the blue "
         "bus in that case ?")
    assert _context_read("Picture the gray airliner up in the air from the first frame instead of on the ground. "
                         "Would the airliner crash into the red scooter then?") == \
        ("picture the gray airliner had been up in the air from the first frame . would the airliner crash into the "
         "red scooter then ?")
    assert _context_read("The blue SUV slams into the gray jet near the end. How fast was the SUV going then?") == \
        "when the blue suv and the gray jet collide , how fast was the blue suv going ?"
    assert _context_read("The gray cruiser shows up at some point. How fast is it moving then?") == \
        "when the gray cruiser comes into view , how fast is the gray cruiser moving ?"
    assert _context_read("The red sedan and the blue bus start on the left. Is the former faster than the latter?") \
        == "is the red sedan faster than the blue bus at the start ?"
    assert _context_read("There's a purple jet and a green truck. Will the two collide? ") == \
        "will the purple jet and the green truck collide ?"
    assert _context_read("There's a purple jet and a green truck. Does the jet hit the other one?") == \
        "does the purple jet hit the green truck ?"
    # left whole: a vehicle the context describes but does not name, a context that asks, an ellipsis, 'i.e.'
    for text in ("Something hits the cyan jet. What colour is it?", "The SUV hits a vehicle. What kind is that?",
                 "How about the brown bike? How fast is it at the start?",
                 "when the brown dirtbike and yellow bus crash, which... is the dirtbike faster?",
                 "Do the red bus and the jet come into contact, i.e. collide, at any point?"):
        assert _context_read(text) == " ".join(catalogue_names(tokenize(text))[0]), text


def test_questions_after_their_context_parse_and_a_speed_offered_as_not_at_all_is_asked():
    parser = QuestionParser.load()
    chopper, scooter, condition, then, damaged, late = parser.analyse_batch([
        "I'm trying to sort out the green chopper. It's hard to read. Is it moving fast, slowly, or not at all at "
        "the very beginning?",
        "Toward the end the brown scooter runs into the blue minivan. I want to know about the scooter's speed there. "
        "Is it moving fast, slowly, or standing still when the two of them collide?",
        "What if the brown chopper had been accelerating from the very beginning? The green fighter plane is over on "
        "the right side. Would the chopper collide with the fighter then?",
        "The blue biplane hits the brown sedan at some point. How fast is the biplane going when that happens?",
        "The blue mountain bike crashes into something. Afterward it spins a bit. Does it get damaged?",
        "The purple road bike seems to speed up. Is it accelerating in the last second of the video?"])
    assert chopper.program[-2:] == ["start", "query_moving_velocity"]   # 'not at all' was read as asking 'fast?'
    assert scooter.program[-1] == "query_moving_velocity" and "filter_attributes[minivan]" in scooter.program
    assert condition.program[4] == "Counterfactual_accelerating" and "filter_attributes[fighter]" in condition.program
    assert then.program[-2:] == ["get_frame", "query_moving_velocity"]
    assert damaged.program is None and late.program is None


def test_context_gives_a_collisions_partner_a_conditions_it_and_the_start():
    assert _context_read("The purple tandem bike smacks into the yellow station wagon. At the moment of impact, how "
                         "fast is the bike?") == \
        "when the purple tandem bike and the yellow wagon collide , how fast is the purple tandem bike ?"
    assert _context_read("The blue road bike starts off fast. Imagine it started slow instead. Would it collide with "
                         "the green school bus in that case?") == \
        "imagine the blue road bike had started slow . would it collide with the green school bus in that case ?"
    assert _context_read("ok weird what-if. the cyan biplane is accelerating from the beginning instead. does it "
                         "crash into the brown cruiser then?") == \
        "suppose the cyan biplane had been accelerating from the beginning . does it crash into the brown cruiser " \
        "then ?"
    assert _context_read("The purple dirt bike hits the gray wagon. Suppose the bike had been parked. Would it still "
                         "collide with the wagon?") == \
        "suppose the purple dirtbike had been parked . would it still collide with the gray wagon ?"
    assert _context_read("Two things: the brown utility bike and the cyan minivan. Beginning of the video. Is the "
                         "first one slower than the second?") == \
        "is the brown utility bike slower than the cyan minivan at the start ?"
    # 'it' of the named vehicle, where the context's other is unnamed; a vehicle said with an unknown word is not read
    assert _context_read("The gray pickup hits something. What colour is the thing it collides with?") == \
        "what color is the thing the gray truck collides with ?"
    pink = tokenize("The pink scooter looked like it was speeding up. Is it accelerating at the start?")
    assert context_as_question(pink, known={"the", "scooter"})[0] == pink


def test_a_transcript_without_stops_is_read_as_its_statement_then_its_question():
    assert _context_read("the blue cruiser is still moving at the end will it hit anything after the video is over") \
        == "will the blue cruiser hit anything after the video is over ?"
    assert _context_read("so the green pickup and the blue chopper smash into each other near the bottom when they "
                         "collide is the pickup going faster than the chopper") == \
        "when they collide , is the green truck going faster than the blue chopper ?"
    # one question, a condition said as a note, written with commas: as said
    for text in ("when the red car hits the bus is it moving fast", "purple dirtbike fast from start would it collide "
                 "with yellow truck", "Regarding the purple sedan, how fast does it move at the start?"):
        assert _context_read(text) == " ".join(catalogue_names(tokenize(text))[0]), text


def _after_read(text: str) -> str:
    return " ".join(afterthoughts_read(catalogue_names(tokenize(text))[0])[0])


def test_what_is_said_after_the_question_names_its_vehicle_time_or_property():
    assert _after_read("Is it moving fast at the start? The red car, I mean.") == \
        "is the red car moving fast at the start ?"
    assert _after_read("Does the green double-decker collide with the red minivan? Wait, sorry, the cyan minivan, not "
                       "the red one.") == "does the green double bus collide with the cyan minivan ?"
    assert _after_read("Is the purple mountain bike slower than the bus at the start? The cyan bus, the regular "
                       "one.") == "is the purple mountain bike slower than the cyan regular bus at the start ?"
    assert _after_read("How fast is the yellow jet going? At the very beginning, I mean.") == \
        "how fast is the yellow jet going at the start ?"
    assert _after_read("Which vehicle is accelerating at the beginning? I mean what type of vehicle it is, not its "
                       "colour.") == "what type of vehicle is accelerating at the beginning ?"
    assert _after_read("If the gray biplane had been floating, would it hit the brown SUV? Asking for a friend.") == \
        "if the gray biplane had been floating , would it hit the brown suv ?"
    # as said: another question, a request, a vehicle said with a word the parser does not know
    for text in ("Is the red car fast? And the blue bus?", "Which object collides with the cyan scooter? Tell me its "
                 "color.", "Does the red sedan hit the bus? Sorry, I meant the red helicopter, not the sedan."):
        assert afterthoughts_read(tokenize(text), known={"the", "red", "sedan", "bus"})[0] == tokenize(text), text


def test_a_contexts_plane_van_and_jet_and_an_it_said_first_are_its_vehicles_and_a_speed_in_cm_is_refused():
    assert _context_read("The red airliner is way bigger than the yellow sedan beside it. In the opening moments, is "
                         "the plane going slower than the car?") == \
        "in the opening moments , is the red airliner going slower than the yellow sedan ?"
    assert _context_read("There's a collision involving the blue minivan. What type of vehicle does the van hit?") \
        == "what type of vehicle does the blue minivan hit ?"
    assert _context_read("Near the middle, the brown sedan crashes into the green fighter. When they collided, was the "
                         "sedan moving faster than the jet?") == \
        "when they collided , was the brown sedan moving faster than the green fighter ?"
    assert _context_read("The red jet is sitting on the ground in this one. Had it been floating in the air from the "
                         "start, would the jet and the green utility bike still have collided?") == \
        ("had the red jet been floating in the air from the start , would the red jet and the green utility bike "
         "still have collided ?")
    cm = QuestionParser.load().analyse_batch(["The yellow mountain bike starts on the left. What's its speed in "
                                              "centimetres per second at the start?"])[0]
    assert cm.program is None and "number" in cm.reason


def test_a_vehicle_named_again_in_apposition_and_a_pronoun_chain_are_read_from_the_context():
    assert _context_read("Okay, so the yellow double-decker is cruising along. Then a gray plane - a jet, I think - "
                         "clips it. How fast was the jet moving right when the two hit?") == \
        "how fast was the gray jet moving right when the gray jet and the yellow double bus hit ?"
    assert _context_read("OK so a purple motorbike and a yellow bicycle sit near the left. At the very start, was the "
                         "motorbike going faster than the bicycle?") == \
        "at the very start , was the purple motorbike going faster than the yellow bicycle ?"
    # 'it' goes on about the airliner, not the bus the sentence names; said 'white', it is not read
    known = QuestionParser.load().known
    white = catalogue_names(tokenize("A white airliner floats above the others. It drifts toward the bus. Did it "
                                     "collide with anything?"))[0]
    assert context_as_question(white, known)[0] == white
    assert " ".join(context_as_question(catalogue_names(tokenize(
        "A gray airliner floats above the others. It drifts toward the bus. Did it collide with anything?"))[0],
        known)[0]) == "did the gray airliner collide with anything ?"


def test_an_assumption_that_states_a_fact_is_context_and_one_that_imagines_is_a_condition():
    assert _context_read("Consider a clip in which a brown sedan rolls into a purple jet. Assume the sedan makes "
                         "contact with the jet near the middle. At the moment of impact, is the jet standing still?") \
        == "when the brown sedan and the purple jet collide , is the purple jet standing still ?"
    assert _context_read("Consider the clip. A red fighter jet crosses the floor. Assume instead that the fighter had "
                         "been stationary from the beginning. Would it collide with the bus?") == \
        "assume the red fighter had been stationary from the beginning . would it collide with the bus ?"


def test_a_labelled_intervention_a_learners_he_and_this_moment_are_read_from_the_context():
    assert _context_read("Notes: yellow car; red plane floating nearby. Intervention: the car is slow from t=0. Would "
                         "the car collide with the plane?") == \
        "suppose the yellow car had been slow from the start . would the yellow car collide with the red aeroplane ?"
    assert _context_read("The yellow school bus and the gray SUV crash in the middle. In this moment, how fast the bus "
                         "is going?") == \
        "when the yellow school bus and the gray suv collide , how fast the yellow school bus is going ?"
    assert _context_read("The gray bus drive all the video. Does he crash with any other thing?") == \
        "does the gray bus crash with any other thing ?"
    assert _context_read("There is a cyan double-decker next the green car. At the first moment, the big bus is static "
                         "or no?") == "at the first moment , the cyan double bus is static or no ?"
    # a label that imagines, unread as a condition, leaves the text whole rather than drop the change
    text = "Obs: blue bus. Alternative timeline where the bus waits. Does it hit the car?"
    assert _context_read(text) == " ".join(catalogue_names(tokenize(text))[0])


def test_a_child_s_words_are_read_whom_it_is_asked_a_big_bus_and_a_stretched_word():
    parser = QuestionParser.load()
    texts = {"Mummy, at the very start, how fast is the big yellow school bus going?":
             "Objects filter_attributes[yellow] filter_attributes[school_bus] unique start query_moving_velocity",
             "Daddy, is the little gray biplane already floating up in the air, not touching the floor, when it all "
             "begins?": "Objects filter_attributes[gray] filter_attributes[biplane] unique start is_floating",
             "Can you tell me, sweetie, at the very start is the little green biplane going slower than the gray "
             "fighter jet?": "Objects filter_attributes[green] filter_attributes[biplane] unique Objects "
                             "filter_attributes[gray] filter_attributes[fighter] unique start slower_velocity",
             "Suppose the purple mountain bike was zooming sooo fast since the start. Would the purple mountain bike "
             "crash into the blue dirt bike then?":
             "Objects filter_attributes[purple] filter_attributes[mountain_bike] unique Counterfactual_moving_fast "
             "Objects filter_attributes[purple] filter_attributes[mountain_bike] unique filter_collision Objects "
             "filter_attributes[blue] filter_attributes[dirtbike] unique filter_collision exist"}
    for (text, program), parse in zip(texts.items(), parser.analyse_batch(list(texts))):
        assert parse.program and " ".join(parse.program) == program, (text, parse.reason)
    # two materials set against each other pick by what no vehicle has
    assert_refused(parser, {"Does the metal bus hit the rubber car?": "size or material"})
    assert stretched("sloooow", {"slow", "so"}) == "slow" and stretched("seeeen", {"seen", "sen"}) == "seen"
    assert stretched("slow", {"slow"}) is None and stretched("zzzz", {"slow"}) is None


def test_a_chat_s_mentions_remarks_and_an_echoed_question_are_read():
    assert tokenize("@luna which type is it?") == ["which", "type", "is", "it", "?"]
    assert tokenize("spd @ start") == ["speed", "at", "start"]
    assert interjections_dropped(tokenize("which type of vehicle is accelerating at the start, i missed it"))[0] == \
        tokenize("which type of vehicle is accelerating at the start")
    assert interjections_dropped(tokenize("how fast is the bus at the start ngl cant tell"))[0] == \
        tokenize("how fast is the bus at the start")
    # a question that only echoes the statement before it asks it
    assert _context_read("calling it now: the cyan chopper and the gray station wagon crash after the clip is over. "
                         "will they tho??") == \
        "will the cyan chopper and the gray wagon crash after the clip is over ?"
    assert _context_read("The red car is fast at the start. Is it?") == "is the red car fast at the start ?"
    # ... where the auxiliary fits the statement's verb, and the pronoun its subject
    assert_refused(QuestionParser.load(), ["The red car is fast at the start. Does it?"])
    # 'it' hit by the vehicle the question names is the context's other one
    assert _context_read("cyan fighter jet bonks the yellow airliner. was the fighter moving slow when it collided "
                         "with it?") == \
        "was the cyan fighter moving slow when it collided with the yellow airliner ?"
    # an ellipsis after a statement closes it, after an interjection or a word that cannot end one none
    assert _context_read("the blue mountain bike seems to dodge everything... does it collide with anything?") == \
        "does the blue mountain bike collide with anything ?"
    assert _context_read("when the brown dirtbike and yellow regular bus crash, which... is the dirtbike faster?") \
        == "when the brown dirtbike and yellow regular bus crash , which . . . is the dirtbike faster ?"
    # a transcript's question may open on 'where'
    assert _context_read("the purple jet clipped the red SUV where was the jet headed when they collided") == \
        "where was the purple jet headed when the purple jet and the red suv collided ?"


def test_a_question_typed_as_code_is_said_as_the_grammar_says_it():
    said = {"speed(purple_fighter_jet, t=0) > speed(green_airliner, t=0)?":
            "is the purple fighter jet faster than the green airliner at the start?",
            "collides(yellow sedan, purple mountain bike) -> bool?":
            "do the yellow sedan and the purple mountain bike collide ?",
            "cyanMinivan.velocity == 'slow' when it collides w/ yellowDoubleDecker?":
            "is the cyan minivan slow when it collides w/ the yellow double decker?",
            "SELECT color FROM vehicles WHERE speed = 'static' AND t = start":
            "what colour is the vehicle that is static at the start ?",
            "red_minivan.collides_with(?).color": "what colour is the vehicle the red minivan collides with",
            "speed(gray_suv) @ collision(gray_suv, brown_school_bus) = ?":
            "the speed of the gray suv when the gray suv and the brown school bus collide ?",
            "what_if(red_airliner.static = True from t=0): collides(red_airliner, purple_sedan)?":
            "if the red airliner is static from the start , do the red airliner and the purple sedan collide?"}
    for text, english in said.items():
        assert code_as_said(text)[0] == english, text
    # a text with no mark of code is left as it is, and a colour is 'the' one only before a vehicle's name
    assert code_as_said("Is the bus red or blue at the start?") == ("Is the bus red or blue at the start?", ())
    assert code_as_said("is the bus red or blue at t=0?")[0] == "is the bus red or blue at the start?"
    # a text longer than any question is left to the parser's bound on words (the patterns are not linear)
    pasted = "red_sedan.speed " * 2000
    assert code_as_said(pasted) == (pasted, ())
    parser = QuestionParser.load()
    parse = parser.analyse_batch(["assert blueJet.is_fast at start?"])[0]
    assert " ".join(parse.program) == \
        "Objects filter_attributes[blue] filter_attributes[jet] unique start is_moving_velocity[fast]"
    # a time in seconds is no start ('t=3.2s' once read '3 .' as a remark and the rest at the start)
    assert_refused(parser, ["At t=3.2s, is the blue jet accelerating?"])


def test_a_speech_recogniser_s_hearing_of_names_colours_and_words_is_read():
    known = QuestionParser.load().known
    heard = {"the read sedan": "the red sedan", "the purple said an": "the purple sedan",
             "the yellow s u v": "the yellow suv", "the grey station wag on": "the gray station wagon",
             "the green by plane": "the green bi plane", "the brown chop her": "the brown chopper",
             "the cyan dirt bite": "the cyan dirt bike", "the blew school bus": "the blue school bus"}
    for text, said in heard.items():
        assert " ".join(heard_as_said(tokenize(text), known)[0]) == said, text
    # a colour alone, or before a word that sounds like no name, stays as it is
    for text in ("the red one is fast", "is the blue moving fast", "the red dirt bike", "the read the bus"):
        assert heard_as_said(tokenize(text), known) == (tokenize(text), ())
    assert homophones_as_said(tokenize("is the cyan cruiser faster then the bus sitting their"))[0] == \
        tokenize("is the cyan cruiser faster than the bus sitting there")
    assert homophones_as_said(tokenize("then is their speed fast"))[0] == tokenize("then is their speed fast")


def test_a_worksheet_s_print_around_its_question_is_read():
    said = {"9. What is the speed of the cyan SUV at the moment it crashes into the brown bendy bus? A) static B) "
            "slow C) fast [1 mark]": "what is the speed of the cyan suv at the moment it crashes into the brown "
                                     "bendy bus ?",
            "True or false: at the start the blue school bus is moving slowly. (1 pt)":
            "is it true that at the start the blue school bus is moving slowly ?",
            "(d) Tick the correct box. The purple bike is faster than the brown sedan. ☐ True ☐ False":
            "is it true that the purple bike is faster than the brown sedan ?",
            "Fill in the blank: When the red scooter hits the gray truck, it is moving ______ (static/slow/fast).":
            "when the red scooter hits the gray truck , it is moving static , slow or fast ?",
            "Q3) Was the green wagon stationary when it and the yellow cruiser collided? Yes / No":
            "was the green wagon stationary when it and the yellow cruiser collided ?"}
    for text, question in said.items():
        assert " ".join(worksheet_as_said(tokenize(text))[0]) == question, text
    # a question with none of a worksheet's print is as it is
    assert worksheet_as_said(tokenize("Is the red car (the sedan) fast at the start?")) == \
        (tokenize("Is the red car (the sedan) fast at the start?"), ())


def test_a_vehicle_described_by_its_looks_is_its_sub_type_and_a_colour_said_further_off_is_read():
    described = {"the red plane with two sets of wings": "the red biplane",
                 "the green bus that takes kids to school": "the green school bus",
                 "the brown bike built for two": "the brown tandem bike",
                 "the blue car with the open back": "the blue truck",
                 "the yellow family van": "the yellow minivan", "the red military jet": "the red fighter",
                 "the long yellow bus with the concertina bit in the middle": "the yellow articulated bus",
                 "the brown off-road motorbike": "the brown dirtbike",
                 "the blue little motorbike you stand on": "the blue scooter",
                 "the skinny purple racing bicycle": "the purple road bike", "the plain red car": "the red sedan"}
    for text, said in described.items():
        assert " ".join(described_as_named(catalogue_names(tokenize(text))[0])[0]) == said, text
    # a size alone names no sub-type; a description of no one sub-type stays for the parser to refuse
    for text in ("the big red sedan", "the off-road bike", "the red car with the blue roof"):
        words = catalogue_names(tokenize(text))[0]
        assert described_as_named(words) == (words, ())
    parser = QuestionParser.load()
    assert_refused(parser, {"Does the pink little stand-up motorbike speed up at the start?": "pink",
                            "At exactly what second does the yellow military jet hit the blue bus?": "when"})


def test_a_heading_an_apology_a_vehicle_named_again_a_claim_and_a_wondered_question_are_read():
    assert asides_dropped(tokenize("For my accident-reconstruction class: at the instant the red truck and the blue "
                                   "wagon collide, is the truck standing still?"))[0] == \
        tokenize("at the instant the red truck and the blue wagon collide, is the truck standing still?")
    # a heading that speaks of a collision the question does not say itself stays
    kept = tokenize("For my accident class: is the red truck standing still at the start?")
    assert asides_dropped(kept)[0] == kept
    assert hedges_dropped(tokenize("Sorry if this is a silly question, but does the gray motorbike hit anything?"))[0] \
        == tokenize("does the gray motorbike hit anything?")
    assert asides_dropped(tokenize("How fast is the blue suv (the big car on the left) at the start?"))[0] == \
        tokenize("How fast is the blue suv at the start?")
    assert asides_dropped(tokenize("Is the green bike stationary at the outset (frame 0)?"))[0] == \
        tokenize("Is the green bike stationary at the outset?")
    assert _context_read("My daughter insists the gray tandem bike is accelerating right at the beginning. Is she "
                         "right?") == "is it true that the gray tandem bike is accelerating right at the beginning ?"
    assert _context_read("My kid asked what color the thing floating in the air at the beginning is. Any idea?") == \
        "what color the thing floating in the air at the beginning is ?"
    assert impact_said_first(tokenize("in the crash was the brown suv going slower than the cyan bus"))[0] == \
        tokenize("when the brown suv and the cyan bus collide , was the brown suv going slower than the cyan bus")
    assert tokenize("will the gray chopper collide with something question mark") == \
        tokenize("will the gray chopper collide with something?")


def test_a_question_read_whole_with_its_context_asks_as_its_last_sentence_asks():
    # the hand-written set's one wrong reading: the decoder read the context's plane and asked whether it floats
    assert_refused(QuestionParser.load(), {
        "one of the planes looks like its floating up in the air at the start what color is it": "color",
        "one of the planes is floating up in the air at the start. what color is it?": "color"})


def test_a_comparison_must_be_said_the_way_it_is_read():
    parser = QuestionParser.load()
    # 'inferior' and 'slowpoke' were read as faster: no word the parser reads says which way
    assert_refused(parser, {
        "Establish whether, at the start, the chopper's speed is inferior to that of the minivan.": "other way",
        "At the instant of impact, is the SUV the slowpoke compared with the bus?": "does not read"})
    slower, faster = parser.parse_batch(["At the start, does the red scooter have less speed than the gray minivan?",
                                         "At the start, does the red scooter have more speed than the gray minivan?"])
    assert slower[-1] == "slower_velocity" and faster[-1] == "faster_velocity"


def test_a_category_a_question_after_a_semicolon_and_a_condition_labelled_or_pointed_back_to():
    parser = QuestionParser.load()
    category, after_semicolon, what_if, that_world = parser.parse_batch([
        "Identify the category of the object that is floating in the air at the outset.",
        "There's a plane just hanging in the air as we open; which colour is the vehicle floating at the start?",
        "What if? The cyan tandem starts off crawling slowly instead. Does it wind up hitting the gray sedan?",
        "The red car is parked at the start. In that case, does it hit the bus?"])
    assert category[-1] == "query_attributes[shape]" and after_semicolon[-1] == "query_attributes[color]"
    assert "Counterfactual_moving_slow" in what_if and "Counterfactual_static" in that_world
    # a condition's semicolon keeps its question: 'the jet' is not the airliner of the sentence before
    assert " ".join(parser.parse("Suppose the airliner had started out slow; would it still hit the jet?")) == \
        "Objects filter_attributes[airliner] unique Counterfactual_moving_slow Objects filter_attributes[airliner] " \
        "unique filter_collision Objects filter_attributes[jet] unique filter_collision exist"
    # a ground vehicle 'flying' out of the gate starts, fast; it does not float
    assert " ".join(parser.parse("Run it back with a twist: the blue dirtbike comes flying out of the gate fast from "
                                 "the opening frame. Does it collide with the brown bus then?")) == \
        "Objects filter_attributes[blue] filter_attributes[dirtbike] unique Counterfactual_moving_fast Objects " \
        "filter_attributes[blue] filter_attributes[dirtbike] unique filter_collision Objects filter_attributes[brown] " \
        "filter_attributes[bus] unique filter_collision exist"


def test_regional_names_an_instruction_first_a_video_stopped_part_way_and_choices_in_brackets():
    parser = QuestionParser.load()
    questions = {
        "Does the brown ute end up crashing into the blue sedan at all?":
            "Events Objects filter_attributes[brown] filter_attributes[truck] unique filter_collision "
            "Objects filter_attributes[blue] filter_attributes[sedan] unique filter_collision exist",
        "What kind of vehicle did the yellow cycle collide with?":
            "Events Objects filter_attributes[yellow] filter_attributes[bicycle] unique get_all_col_partners unique "
            "query_attributes[shape]",
        "Would the wee blue scooter be standing still at the very start at all?":
            "Objects filter_attributes[blue] filter_attributes[scooter] unique start is_static",
        "Answer yes or no: is the private jet expected to collide with anything once the video has been stopped?":
            "futureEvents Objects filter_attributes[jet] unique filter_collision exist",
        "Given that the video is halted partway through, will the blue school bus subsequently collide with the "
        "green sedan?": "futureEvents Objects filter_attributes[blue] filter_attributes[school_bus] unique "
                        "filter_collision Objects filter_attributes[green] filter_attributes[sedan] unique "
                        "filter_collision exist",
        "In which direction is the cyan city bike heading during the opening moments of the video?":
            "Objects filter_attributes[cyan] filter_attributes[utility_bike] unique start query_moving_direction",
        "Identify the speed class (static, slow, or fast) of the green SUV at the moment it makes contact with the "
        "yellow double-decker.": "Objects filter_attributes[green] filter_attributes[suv] unique Events Objects "
                                 "filter_attributes[green] filter_attributes[suv] unique filter_collision Objects "
                                 "filter_attributes[yellow] filter_attributes[double_bus] unique filter_collision "
                                 "unique get_frame query_moving_velocity",
        "Imagine the green one never budges, stuck stock-still from the first frame. Does it end up colliding with "
        "the yellow one?": "Objects filter_attributes[green] unique Counterfactual_static Objects "
                           "filter_attributes[green] unique filter_collision Objects filter_attributes[yellow] unique "
                           "filter_collision exist",
        "Sure, was the airliner going slower than the brown sedan when the pair of them bumped into each other?":
            "Objects filter_attributes[airliner] unique Objects filter_attributes[brown] filter_attributes[sedan] "
            "unique Events Objects filter_attributes[airliner] unique filter_collision Objects "
            "filter_attributes[brown] filter_attributes[sedan] unique filter_collision unique get_frame "
            "slower_velocity"}
    for (text, program), read in zip(questions.items(), parser.parse_batch(list(questions))):
        assert read is not None and " ".join(read) == program, text
    # a factual 'never moves' stays a negation; only a condition reads it as staying still
    assert parser.parse("Does the green car never move at the start?") is None


def test_a_physics_class_a_simulation_a_scenario_and_a_colour_in_a_clause_are_read():
    parser = QuestionParser.load()
    questions = {
        "What type of vehicle is at rest under the initial conditions?":
            "Objects start filter_static unique query_attributes[shape]",
        "At t = 0, is the purple biplane not under the influence of gravity?":
            "Objects filter_attributes[purple] filter_attributes[biplane] unique start is_floating",
        "Intervention: set the gray chopper's initial speed to slow. Does the gray chopper collide with the blue SUV?":
            "Objects filter_attributes[gray] filter_attributes[chopper] unique Counterfactual_moving_slow Objects "
            "filter_attributes[gray] filter_attributes[chopper] unique filter_collision Objects "
            "filter_attributes[blue] filter_attributes[suv] unique filter_collision exist",
        "Which colour is the actor in the fast speed bin at t0?":
            "Objects start filter_moving_velocity[fast] unique query_attributes[color]",
        "In the predicted rollout after the cutoff, do the cyan SUV and the gray city bus collide?":
            "futureEvents Objects filter_attributes[cyan] filter_attributes[suv] unique filter_collision Objects "
            "filter_attributes[gray] filter_attributes[regular_bus] unique filter_collision exist",
        "Given the clip, when it starts, then how fast is the red sedan moving: static, slow or fast?":
            "Objects filter_attributes[red] filter_attributes[sedan] unique start query_moving_velocity",
        "Consider the bicycle, which is brown. Is it being ridden slowly in the opening moments?":
            "Objects filter_attributes[brown] filter_attributes[bicycle] unique start is_moving_velocity[slow]",
        "With what speed (static, slow, or fast) does the yellow fighter jet enter the frame?":
            "Objects filter_attributes[yellow] filter_attributes[fighter] unique Objects filter_attributes[yellow] "
            "filter_attributes[fighter] unique come_in_frame query_moving_velocity"}
    for (text, program), read in zip(questions.items(), parser.parse_batch(list(questions))):
        assert read is not None and " ".join(read) == program, text
    assert_refused(parser, {"Is the red biplane still airborne at the final timestep?": "end",
                            '{"target": "grey airliner", "ask": "how high above the ground is it?"}': "high",
                            "Given the clip, when it ends, then how fast is the red sedan moving?": "end"})


def test_a_reading_must_read_what_is_imagined_and_what_floats():
    parser = QuestionParser.load()
    # each was read as a question about the video as it is (the final measure's wrong readings)
    assert_refused(parser, {"brown motorbike starting slow instead, it hits the gray car or not?": "instead",
                            "imagine the chopper begins fast. does it collide with the bus then": "imagine",
                            "quick check, plane floating at the beginning or not?": "floating",
                            "How fast is the school bus moving in the very last frame?": "end"})
    floating, later, wagon, noted = parser.parse_batch([
        "When the clip begins, is the private jet floating rather than sitting on the ground?",
        "given the clip is cut off mid-way, do the fighter jet and the sedan end up colliding afterwards?",
        "Suppose the grey estate wagon had stayed parked from the start - would it have hit the yellow sedan?",
        # (a note's 'cf:' now opens its condition as 'counterfactual:' does; it was refused, as read in the video)
        "cf: gray one starts slow instead -> does gray collide w/ the pickup?"])
    assert floating[-1] == "is_floating" and later[0] == "futureEvents"
    assert "Counterfactual_moving_slow" in noted and noted[-4] == "filter_attributes[truck]"
    assert wagon[:3] == ["Objects", "filter_attributes[gray]", "filter_attributes[wagon]"]
    assert "Counterfactual_static" in wagon


def test_vehicles_said_first_then_asked_as_they_or_it_and_lagging_behind():
    assert dislocated_as_asked(tokenize("Blue minivan and green chopper, they crash into each other?"))[0] == \
        tokenize("do Blue minivan and green chopper crash into each other?")
    assert dislocated_as_asked(tokenize("The green sedan, it collide with something in the video?"))[0] == \
        tokenize("does The green sedan collide with something in the video?")
    # ... or asked about in a question of its own ('the motorbike , once the clip cuts off , is it going to ...')
    assert dislocated_as_asked(tokenize("The red sedan, is it fast?"))[0] == tokenize("is The red sedan fast?")
    parser = QuestionParser.load()
    lagging, together = parser.parse_batch([
        "Is the blue airliner lagging behind the purple suv in speed at the beginning?",
        "Blue minivan and green chopper, they crash together?"])
    assert lagging[-1] == "slower_velocity" and together[-1] == "exist" and "Events" in together


def test_a_doubt_said_before_or_after_the_question_is_dropped():
    assert hedges_dropped(tokenize("Not sure, but did the sedan hit the bus?"))[0] == \
        tokenize("did the sedan hit the bus?")
    assert hedges_dropped(tokenize("Was the grey chopper slower than the green sedan, or am I misremembering?"))[0] \
        == tokenize("Was the grey chopper slower than the green sedan?")
    assert hedges_dropped(tokenize("The bus was parked at the start; is that right?"))[0] == \
        tokenize("The bus was parked at the start, is that right?")
    # what is said first that names a vehicle, a time or what is asked is no doubt ('I noticed something hovering')
    for kept in ("I noticed something hovering in the air at the beginning, which colour was it?",
                 "In which direction, may I ask, is the yellow motorbike proceeding at the beginning?",
                 "When I watch the red car, is it fast?"):
        assert hedges_dropped(tokenize(kept)) == (tokenize(kept), ())
    parser = QuestionParser.load()
    unsure, right_that = parser.parse_batch([
        "I could be off here, but when the red one first came into view, would you call it static, slow or fast?",
        "Am I right that the brown SUV was faster than the blue bike at the very start?"])
    assert unsure[-2:] == ["come_in_frame", "query_moving_velocity"] and right_that[-1] == "faster_velocity"


def test_a_counterfactual_reading_needs_a_condition_and_a_then_its_time():
    parser = QuestionParser.load()
    assert_refused(parser, {
        # read as had the chopper been static: nothing says a condition
        # read as whether the SUV hits the bike: 'would' after a change said as a fact
        "Think about this: the SUV's engine is switched on from the very start, so it keeps getting faster. Would "
        "the SUV hit the red road bike?": "would",
        # read at the start: the sentence before says when 'then' is
        "Think about the last moment of the clip. Is the grey station wagon slower than the school bus then?": "end"})
    assert parser.parse("Will the red fighter jet crash into anything after the video's been stopped?")[0] == \
        "futureEvents"
    # a terse condition needs no 'if': 'fast from start'
    assert "Counterfactual_moving_fast" in parser.parse("cf: blue mountain bike fast from start -> collides w/ "
                                                        "purple regular bus? y/n")


def test_a_ships_and_a_radios_words():
    parser = QuestionParser.load()
    dead, less, unit = parser.parse_batch([
        "Confirm the blue fighter jet is dead in the water at the start of the tape, affirmative?",
        "First moments of the video: is the blue private jet making less way than the grey bus?",
        "Which colour's the unit running at full speed right at the top of the footage?"])
    assert dead[-1] == "is_static" and less[-1] == "slower_velocity"
    assert unit == "Objects start filter_moving_velocity[fast] unique query_attributes[color]".split()


def test_a_report_s_abbreviations_and_brackets_are_read():
    # 'approx.' and 'veh.' end no sentence (the collision said before 'approx.' was lost), 'i.e.' opens a gloss
    assert tokenize("the approx. speed of the veh. at the start") == \
        tokenize("the approx speed of the veh at the start")
    assert tokenize("accelerating (i.e. under power), e.g. now") == [
        "accelerating", "(", "ie", "under", "power", ")", ",", "eg", "now"]
    said, read = glosses_read(tokenize("was the truck accelerating (i.e. under engine power) at the outset?"))
    assert said == tokenize("was the truck accelerating at the outset?") and read[0][1] == "nothing, a gloss"
    said, _ = glosses_read(tokenize("did the insured vehicle (red sedan) hit the third-party vehicle (blue bus)?"))
    assert said == tokenize("did the red sedan hit the blue bus?")
    # a name said before the brackets stays, and a gloss that names a vehicle is no gloss
    for kept in ("is the red sedan (the car) fast?", "is it fast (i.e. the red sedan)?"):
        assert glosses_read(tokenize(kept)) == (tokenize(kept), ())
    parser = QuestionParser.load()
    impact, veh = parser.parse_batch([
        "At the point of impact with the grey sedan, what was the approx. speed class (static, slow, fast) of the "
        "green pickup truck?", "What colour is the veh. that was accelerating at the beginning of the clip?"])
    assert impact[-3:] == ["unique", "get_frame", "query_moving_velocity"] and "sedan" in " ".join(impact)
    assert veh == "Objects start filter_accelerating unique query_attributes[color]".split()
    assert_refused(parser, {"At what approx. height above the ground was the biplane hovering at the start?": "height",
                            "At approx. what time, in seconds, did the red sedan first hit the blue bus?": "when"})


def test_a_witness_s_examination_asks_what_it_puts():
    said, _ = examination_as_asked(tokenize("I put it to you that the bus was parked. Is that correct?"))
    assert said == tokenize("is it true that the bus was parked?")
    said, _ = examination_as_asked(tokenize("You'd concede, wouldn't you, that the bus was parked?"))
    assert said == tokenize("is it true that the bus was parked?")
    said, _ = examination_as_asked(tokenize("What type of vehicle, if you know, was travelling fast?"))
    assert said == tokenize("What type of vehicle was travelling fast?")
    said, _ = examination_as_asked(tokenize("Explain to the jury how fast the bus was going."))
    assert said == tokenize("tell me how fast the bus was going.")
    assert examination_as_asked(tokenize("Is the bus parked? Is that correct?"))[1] == ()   # a question's own tag
    parser = QuestionParser.load()
    opening, opinion, record = parser.parse_batch([
        "Directing your attention to the opening moments of the recording, please characterise the speed of the "
        "red sedan: stationary, slow or fast?",
        "In a scenario where the cyan bus had been accelerating from the outset, is it your opinion that the cyan "
        "bus would have collided with the motorbike?",
        "Correct me if I'm wrong, but the blue fighter jet was hovering in mid-air at the start of the recording?"])
    assert opening[-2:] == ["start", "query_moving_velocity"] and "Counterfactual_accelerating" in opinion
    assert record[-2:] == ["start", "is_floating"]


def test_a_video_stopped_said_alone_or_imagined_going_on_is_after_its_end():
    for text in ("video's cut off early -- does the dirtbike go on to hit the wagon later",
                 "Had the footage continued past the point where it is cut off, would the scooter hit something?",
                 "stream froze halfway, are the cyan motorbike and the bus gonna smash after it cuts",
                 "beyond the truncation point, does the yellow cruiser make contact with anything"):
        said, read = video_end_as_said(tokenize(text))
        assert said.count("after") >= 1 and read and all(r == "after the video ends" for _, r in read), text
        assert "cut" not in said and "cuts" not in said, text
    # the video said to be over is no future ('the video is over. did ...?' may ask about the video), nor is a
    # clause of the question's own
    for kept in ("The video is over. Did the car hit the bus?", "the video stops before they collide, does it?"):
        assert video_end_as_said(tokenize(kept)) == (tokenize(kept), ())
    parser = QuestionParser.load()
    assert parser.parse("Video's been halted partway; from here on, will the blue chopper and the red airliner "
                        "collide?")[0] == "futureEvents"
    assert_refused(parser, ["If the video were longer, would the bus hit the car?"])


def test_a_game_s_words_spawn_afk_full_send_and_trade_paint():
    said, _ = idioms_as_said(tokenize("if the purple suv spawned slow would it clip the gray sedan"))
    assert said == tokenize("if the purple suv started slow would it hit the gray sedan")
    said, _ = idioms_as_said(tokenize("was it afk from spawn, or did it full send when it spawned"))
    assert said == tokenize("was it static from the start, or did it fast at the start")
    parser = QuestionParser.load()
    paint, speed, turbo = parser.parse_batch([
        "did the blue bus and the yellow pickup ever trade paint",
        "speed check on the school bus right at the start of the replay: afk, chill or full send?",
        "if the blue scooter had turbo on from spawn, would it collide with the brown pickup"])
    assert paint[0] == "Events" and paint[-1] == "exist" and speed[-2:] == ["start", "query_moving_velocity"]
    assert "Counterfactual_accelerating" in turbo
    # 'x' is 'and' only between two vehicles' names
    assert shorthand_as_said(tokenize("bendy bus x purple car"))[0] == tokenize("bendy bus and purple car")
    assert shorthand_as_said(tokenize("the 4 x 4")) == (tokenize("the 4 x 4"), ())


def test_a_vehicle_no_catalogue_has_is_refused_where_the_question_names_it():
    parser = QuestionParser.load()
    assert_refused(parser, {"Does the zamboni collide with the red biplane?": "'the zamboni'",
                            "Did the red biplane collide with the zamboni?": "'the zamboni'"})
    # a plane spotter's names are the catalogue's; what a vehicle 'pops into' is no vehicle
    jumbo, bizjet, shot = parser.parse_batch([
        "Does the jumbo trade paint with the red biplane at any point in the video?",
        "At the start, is the blue bizjet hanging in the air?",
        "How fast is the brown dirt bike ripping when it first pops into the shot?"])
    assert "filter_attributes[airliner]" in jumbo and "filter_attributes[biplane]" in jumbo
    assert bizjet[:3] == ["Objects", "filter_attributes[blue]", "filter_attributes[jet]"]
    assert shot[-2:] == ["come_in_frame", "query_moving_velocity"]


def test_a_type_asked_of_what_a_context_describes_and_a_rest_never_said():
    said, _ = type_of_category_as_vehicle(tokenize("Something is hovering. What kind of aircraft is it?"))
    assert said == tokenize("Something is hovering. What kind of vehicle is it?")
    assert type_of_category_as_vehicle(tokenize("What kind of aircraft is it?"))[1] == ()   # no context: no change
    parser = QuestionParser.load()
    hovering, sitting, first = parser.parse_batch([
        "Something is hovering over the road as the feed starts. What kind of aircraft is it?",
        "Is the green scooter just sitting there when the video starts?",
        "From the footage, at what speed does the yellow bicycle enter the frame for the first time - static, slow or "
        "fast?"])
    assert hovering == "Objects start filter_floating unique query_attributes[shape]".split()
    assert sitting[-1] == "is_static" and first[-2:] == ["come_in_frame", "query_moving_velocity"]
    # read as the static one's colour, and a plane's direction: nothing says either
    assert_refused(parser, {"What colour is it at the start?": "standing still",
                            "What type of aeroplane is it at the start?": "a speed or a direction",
                            "Which direction is the green SUV heading at the final whistle?": "end"})


def test_an_order_of_collisions_is_refused():
    assert ordered(tokenize("what does the green suv hit next ?")) and \
        ordered(tokenize("does the suv hit the bus after the school bus ?"))
    for kept in ("will they crash after the red suv ends ?", "after the video ends , will the car hit the bus ?"):
        assert ordered(tokenize(kept)) == ""


def test_another_version_of_the_story_is_a_counterfactual():
    said, _ = told_otherwise_as_imagined(tokenize("In another telling, the bus hovers from the start. Would it hit "
                                                  "the car?"))
    assert said == tokenize("imagine the bus hovers from the start. Would it hit the car?")
    said, _ = told_otherwise_as_imagined(tokenize("Under an alternative ruling where the minivan starts fast, does"))
    assert said[:4] == ["in", "a", "world", "where"]
    assert told_otherwise_as_imagined(tokenize("In this story, does the red car hit the bus?"))[1] == ()
    parser = QuestionParser.load()
    tale, rewrite, story = parser.parse_batch([
        "Spin a tale in which the mountain bike begins at full speed. Would the mountain bike run into the cyan one?",
        "Rewrite the opening so that the yellow station wagon starts out fast. Does the wagon collide with the red one "
        "in that version?", "In this story, does the red car hit the bus?"])
    assert "Counterfactual_moving_fast" in tale and "Counterfactual_moving_fast" in rewrite and story[0] == "Events"


def test_a_referee_s_a_newsroom_s_and_a_mechanic_s_words():
    parser = QuestionParser.load()
    kick, power, carrying, callers, sources, feed, played = parser.parse_batch([
        "Which kind of vehicle has its engine on and is gathering speed at kick-off?",
        "On the whistle, was the chopper picking up speed under its own power?",
        "At the point of contact between the green SUV and the yellow pickup, what speed was the SUV carrying - "
        "static, slow or fast?",
        "Callers on line two want to know how quickly the school bus is travelling in the first moments of the clip. "
        "Stationary, slow or fast?",
        "Sources tell us the blue motorbike was sitting dead still when the feed began; can we confirm that?",
        "The feed cuts before the play finishes: will the blue school bus and the grey scooter go on to collide?",
        "The film stops before the story is finished. Had it played on, would the purple mountain bike and the green "
        "pickup collide?"])
    assert kick == "Objects start filter_accelerating unique query_attributes[shape]".split()
    assert power[-2:] == ["start", "is_accelerating"] and carrying[-2:] == ["get_frame", "query_moving_velocity"]
    assert callers[-2:] == ["start", "query_moving_velocity"] and sources[-2:] == ["start", "is_static"]
    assert feed[0] == "futureEvents" and played[0] == "futureEvents"


def test_a_digression_between_commas_and_a_prompt_s_wrapping_are_dropped():
    said, read = digressions_dropped(tokenize("So, Jen, and this is the part I love, was the red sedan parked?"))
    assert said == tokenize("was the red sedan parked?") and all(r == "nothing, a digression" for _, r in read)
    said, _ = digressions_dropped(tokenize("Was the mountain bike motionless when it hit the bus, my dear fellow?"))
    assert said == tokenize("Was the mountain bike motionless when it hit the bus?")
    # what says a time, a vehicle, a motion, a number or an instruction stays ('Halfway through,', 'On a scale of 1 to
    # 10,', 'State the duration,', 'In the initial frames,', 'static, slow or fast')
    for kept in ("Halfway through, which way is the biplane flying?", "On a scale of 1 to 10, how fast is it?",
                 "State the duration, in seconds, for which it stays parked.", "is it static, slow, or fast?"):
        assert digressions_dropped(tokenize(kept)) == (tokenize(kept), ()), kept
    said, _ = prompt_dropped(tokenize("Act as a physics expert and tell me how fast the bus was going."))
    assert said == tokenize("tell me how fast the bus was going.")
    said, _ = prompt_dropped(tokenize("Q: is the bus parked at the start? A (yes/no):"))
    assert said == tokenize("is the bus parked at the start?")
    assert prompt_dropped(tokenize("Yes or no only: is the biplane hovering?"))[0] == \
        tokenize("is the biplane hovering?")
    parser = QuestionParser.load()
    pray, hue, wonder = parser.parse_batch([
        "Of what colour, pray, was the vehicle that dawdled slowly along when the recording began?",
        "The vehicle hovering at the outset: of what hue was it, pray?",
        "When the purple one collided with the brown car, at what speed, I wonder, was the purple one moving?"])
    # 'pray' is no slip of 'gray': a colour is fixed from a slip only before a vehicle's name
    assert pray == "Objects start filter_moving_velocity[slow] unique query_attributes[color]".split()
    assert hue == "Objects start filter_floating unique query_attributes[color]".split()
    assert parser.parse("Is the pred sedan fast at the start?")[1] == "filter_attributes[red]"
    assert_refused(parser, {"Act as a physics expert and tell me at what second the red sedan hits the bus.": "when",
                            "What colour is the vehicle that the red sedan passed without touching?": "without",
                            "Was the blue scooter going slowly as the tape drew to its close?": "end"})


def test_punctuation_said_in_words_a_post_s_labels_and_a_video_stopped_said_first():
    assert tokenize("the dirt bike comma is it slow full stop") == tokenize("the dirt bike , is it slow .")
    assert tokenize("did it come to a full stop at the start?")[-6:-1] == ["full", "stop", "at", "the", "start"]
    assert tokenize("was it moving? #physics #fyp") == tokenize("was it moving?")
    said, _ = prompt_dropped(tokenize("1/ genuine question: was the red sedan moving at the start?"))
    assert said == tokenize("was the red sedan moving at the start?")
    parser = QuestionParser.load()
    dictated, stopped, show = parser.parse_batch([
        "which direction was the red double decker going when it hit the blue sedan question mark new line",
        "thread video stops partway through. does the sedan end up colliding with the green airliner afterwards?",
        "Ooh, look at the school bus! Right when our show begins, is it parked, puttering along slowly, or zooming "
        "fast?"])
    assert dictated[-1] == "query_moving_direction" and stopped[0] == "futureEvents"
    assert show[-2:] == ["start", "query_moving_velocity"]
    # 'afterwards' is never within the video; a stop said first is not a question's own clause
    assert_refused(parser, {"does the sedan collide with the green airliner afterwards?": "afterwards",
                            "the video stops before they collide, does the red car hit the bus?": "before"})


def test_a_wager_s_stake_is_dropped_and_a_claim_bet_on_is_put_to_be_confirmed():
    said, read = wagers_read(tokenize("Is the grey fighter jet speeding up at the start? Putting a tenner on yes."))
    assert said == tokenize("Is the grey fighter jet speeding up at the start?") and read[0][1] == "nothing, a wager"
    # after the question a stake may name the guess ('My stake's on a motorbike.'); before it, never a vehicle
    assert wagers_read(tokenize("What type of vehicle is fast? My stake's on a motorbike."))[0] == \
        tokenize("What type of vehicle is fast?")
    assert wagers_read(tokenize("Name the colour of whatever is slow at the start and I'll pay out."))[0] == \
        tokenize("Name the colour of whatever is slow at the start")
    assert wagers_read(tokenize("I bet the red sedan hits the blue bus. Does it?"))[0] == \
        tokenize("is it true that the red sedan hits the blue bus ?")
    assert wagers_read(tokenize("Fiver says the tandem is faster than the bus at the start, do I collect?"))[0] == \
        tokenize("is it true that the tandem is faster than the bus at the start ?")
    assert wagers_read(tokenize("With the clip stopped, I'm backing the dirt bike to crash into something. Will it?"))[
        0] == tokenize("With the clip stopped, is it true that the dirt bike will crash into something ?")
    assert wagers_read(tokenize("Is the red car parked at the start?")) == (tokenize("Is the red car parked at the "
                                                                                      "start?"), ())
    parser = QuestionParser.load()
    lock, cliff, fiver = parser.parse_batch([
        "Is it a lock that the blue motorbike is only pootling along slowly at the start?",
        "Cliffhanger wager: once the clip carries on, do the fighter jet and the bus end up crashing?",
        "Say the purple one never moved an inch from the beginning; does it collide with the cruiser then? Fiver says "
        "no."])
    assert lock[-2:] == ["start", "is_moving_velocity[slow]"] and cliff[0] == "futureEvents"
    assert "Counterfactual_static" in fiver
    # a stake dropped leaves a question of no family refused ('at the end')
    assert_refused(parser, {"Is the green SUV faster than the yellow bike at the end of the clip? Tenner on the SUV.":
                            "end"})


def test_a_ticket_s_fields_and_a_condition_assumed_in_the_present():
    said, _ = ticket_fields_read(tokenize("Steps: watch clip; Expected: partner identified; Question: what type of "
                                          "vehicle does the scooter collide with?"))
    assert said == tokenize("what type of vehicle does the scooter collide with?")
    said, _ = ticket_fields_read(tokenize("Summary: clip ends early; prediction needed - do the purple bus and the "
                                          "pickup collide afterwards?"))
    assert said == tokenize("Summary: clip ends early; do the purple bus and the pickup collide afterwards?")
    assert ticket_fields_read(tokenize("Steps: is the bus fast?")) == (tokenize("Steps: is the bus fast?"), ())
    parser = QuestionParser.load()
    assumed, steps, ended, confirm = parser.parse_batch([
        "Assume the gray cruiser starts slow. Does the gray cruiser collide with the brown sedan then?",
        "Steps: assume the gray cruiser starts slow. Expected: collision outcome. Question: would the gray cruiser "
        "collide with the brown sedan?",
        "Summary: clip ends early; prediction needed - do the purple bus and the pickup end up colliding afterwards?",
        "Need confirmation whether the bus is accelerating in the first moments. Field: yes/no."])
    assert "Counterfactual_moving_slow" in assumed and "Counterfactual_moving_slow" in steps
    assert ended[0] == "futureEvents" and confirm[-2:] == ["start", "is_accelerating"]
    # a change assumed and a question of what happens, said in one sentence: refused, never read as what happened
    assert_refused(parser, {"assume the gray cruiser starts slow; does the gray cruiser collide with the brown sedan "
                            "then?": "assume"})


def test_text_speak_an_elder_s_words_and_choices_offered_for_a_colour_or_a_type():
    assert tokenize("wat colour is the cruiser n the bus b4 the crash") == \
        tokenize("what color is the cruiser and the bus before the crash")
    assert tokenize("is it fast (y/n)")[-3:] == ["/", "n", ")"] and tokenize("the faster 1")[-1] == "one"
    assert tokenize("at 1 second") == ["at", "1", "second"]
    said, _ = attributes_offered_dropped(tokenize("At the beginning, which type of aeroplane is it that's floating: an "
                                                  "airliner, a fighter, a jet or one of those old biplanes?"))
    assert said == tokenize("At the beginning, which type of aeroplane is it that's floating?")
    said, _ = glosses_read(tokenize("was the purple town bicycle (utility bike, I think they call it) moving?"))
    assert said == tokenize("was the purple utility bike moving?")
    said, _ = glosses_read(tokenize("what is accelerating (accelerating, is that the word?) at the start?"))
    assert said == tokenize("what is accelerating at the start?")
    parser = QuestionParser.load()
    picture, lorry, elder, carry, one = parser.parse_batch([
        "I wonder if you could tell me how quickly the little red saloon was going when the picture first began: was "
        "it standing still, dawdling along, or going at a fair lick?",
        "At the moment the yellow pickup lorry struck the purple SUV, how fast was the pickup travelling?",
        "Good afternoon. I should very much like to know whether the purple one and the tandem bicycle collide at any "
        "point. Thank you ever so much.",
        "If the film were allowed to carry on after where it's cut off, would the pickup collide with anything?",
        "when the purple cruiser n brown mountain bike crash is the cruiser the faster 1"])
    assert picture[-2:] == ["start", "query_moving_velocity"] and lorry[-2:] == ["get_frame", "query_moving_velocity"]
    assert elder[-1] == "exist" and carry[0] == "futureEvents" and one[-1] == "faster_velocity"
    assert_refused(parser, {
        "After the video is stopped, which vehicle will the green car run into?": "which vehicle",
        "the plane floating at the start, zzq colour is it": "color",
        "is the mountain bike slower , yes or no at the start ?": "slower"})


def test_a_request_in_a_third_person_s_words_an_office_s_preamble_and_a_correction_after_the_question():
    said, _ = requested_as_asked(tokenize("The authors should clarify how fast the red sedan is travelling?"))
    assert said == tokenize("tell me how fast the red sedan is travelling?")
    said, _ = requested_as_asked(tokenize("Reviewer 4 seeks confirmation that the scooter is slow at the start."))
    assert said == tokenize("is it true that the scooter is slow at the start.")
    said, read = requested_as_asked(tokenize("It is not evident from the footage whether the blue motorbike is "
                                             "stationary at the start; confirmation is requested."))
    assert said == tokenize("tell me whether the blue motorbike is stationary at the start.")
    assert read[-1][1] == "nothing, a remark"
    # never a condition ('provided that'), nor a vehicle's own words ('dead certain the biplane ...')
    for kept in ("Provided that the gray bus stays parked, does the green scooter hit it?",
                 "Dead certain the biplane's hovering in the air at the start?"):
        assert requested_as_asked(tokenize(kept)) == (tokenize(kept), ()), kept
    said, _ = preamble_dropped(tokenize("per the brief from leadership, what colour is the vehicle floating?"))
    assert said == tokenize("what colour is the vehicle floating?")
    said, _ = preamble_dropped(tokenize("Because obviously a school bus has nowhere to be: is the yellow school bus "
                                        "parked at the start?"))
    assert said == tokenize("is the yellow school bus parked at the start?")
    for kept in ("In the final frame, is the green biplane in the air?", "Hypothetically: the red jet stays still.",
                 "Because the bus is slow: is it parked?"):
        assert preamble_dropped(tokenize(kept)) == (tokenize(kept), ()), kept
    readable = QuestionParser.load().readable
    assert corrections_starred(tokenize("What direction is the green bust going? bus*"), readable)[0] == \
        tokenize("What direction is the green bus going?")
    assert corrections_starred(tokenize("if the grey sedate (sedan!!) had started"), readable)[0] == \
        tokenize("if the grey sedan had started")
    assert corrections_starred(tokenize("is the red car fast? (yes)"), readable)[0] == tokenize("is the red car fast? "
                                                                                                "(yes)")
    parser = QuestionParser.load()
    fact, cut, people = parser.parse_batch([
        "One wonders whether the chopper is in fact standing still when it comes into contact with the blue minivan.",
        "once the video's cut off is the brown fighter jet gonna collie with anything",
        "What type of vehicle did the people bus hit? *purple"])
    assert fact[-1] == "is_static" and cut[0] == "futureEvents" and "filter_attributes[purple]" in people
    assert_refused(parser, {
        "Can we get clarity on whether the pickup and the purple thing end up bumping into each other?": "after it",
        "Please state the height above the ground at which the grey airliner hovers.": "height",
        "does the red car cut off the blue bus?": "cut off"})


def test_archaic_english_a_question_relayed_and_a_hypothesis_put_to_a_test():
    readable = QuestionParser.load().readable
    said, read = archaic_as_said(tokenize("when the video endeth, whither goeth the bus? it floateth"), readable)
    assert said[3] == "ends" and said[-1] == "floats" and read == (("endeth", "ends"), ("floateth", "floats"))
    said, _ = quoted_question(tokenize('The quiz card reads "Is the blue motorbike standing still?" - help!'))
    assert said == tokenize("Is the blue motorbike standing still?")
    assert quoted_question(tokenize('Is the "red" car fast?')) == (tokenize('Is the "red" car fast?'), ())
    said, _ = hypothesis_as_asked(tokenize("H0: the green motorbike is moving fast at the start. Do the data support "
                                           "it?"))
    assert said == tokenize("is it true that the green motorbike is moving fast at the start ?")
    # asked whether it is rejected, the answer is the other way round: left as it is
    kept = tokenize("H0: the bus is parked. Should H0 be rejected?")
    assert hypothesis_as_asked(kept) == (kept, ())
    parser = QuestionParser.load()
    doth, relayed, level, scene = parser.parse_batch([
        "Doth the green private jet strike aught in all the video?",
        "A coworker asked me how quickly the school bus is going in the first moments of the clip; any idea?",
        "Classify the speed of the red sedan in the opening frames (levels: static, slow, fast).",
        "When first the scene begins to play, how fast goes the school bus on its way - still, slow, or swift as day?"])
    assert doth[-1] == "exist" and relayed[-2:] == ["start", "query_moving_velocity"]
    assert level[-2:] == ["start", "query_moving_velocity"] and scene[-2:] == ["start", "query_moving_velocity"]
    assert_refused(parser, {
        "Wherefore did the blue bus and the yellow car collide?": "why",
        "Is the purple SUV faster than the brown bicycle when the video endeth?": "end",
        "Which came first: the crash of the bus, or the crash of the bicycle?": "came first",
        "Is the red car greater in size than the blue bus?": "size",
        "Near the video's end, my friend, does the brown chopper speed up, engine on?": "other than the start",
        "Which colour level corresponds to the vehicle whose initial speed is recorded as slow?": "speeding up"})
    # the stage a vehicle enters is the moment it comes into view (it was refused before the context read it)
    hark = parser.parse_batch(["Hark, the yellow biplane enters upon the stage! At what pace doth it arrive?"])[0]
    assert hark[-2:] == ["come_in_frame", "query_moving_velocity"] and hark[1:3] == [
        "filter_attributes[yellow]", "filter_attributes[biplane]"]


def test_a_thesaurus_a_logician_a_learners_topic_and_a_radio_caller():
    said, read = class_as_asked(tokenize("into which speed class does the red sedan fall : static , slow or fast ?"))
    assert said == tokenize("which speed class is the red sedan in : static , slow or fast ?")
    assert read == (("into which speed class does the red sedan fall", "which speed class is the red sedan in"),)
    said, _ = dislocated_as_asked(tokenize("Sedan and bus, at the start, sedan is more fast than bus?"))
    assert said == tokenize("at the start, sedan is more fast than bus?")
    parser = QuestionParser.load()
    quiescent, twain, dawdle, affirmed, learner, caller, stalled, onwards = parser.parse_batch([
        "Does the grey dirt bike lie quiescent at the moment it makes contact with the blue one?",
        "Is the grey fighter jet dawdling relative to the blue airliner when the twain collide?",
        "If the blue pickup had set off at a dawdle, would it have jostled the yellow minivan?",
        "May it be affirmed that the bus exceeds the bicycle in speed at the start of the video?",
        "If video continue from where it stop, yellow chopper will hit the blue double-decker bus?",
        "Caller on line five wants the speed of the double-decker the moment it first shows up on screen: stopped, "
        "slow or fast?",
        "Line four's asking, was the yellow motorbike sitting stalled, not moving an inch, right at the beginning?",
        "With the clip stopped partway, is the cyan station wagon going to collide with anything from here on?"])
    assert quiescent[-1] == "is_static" and twain[-1] == "slower_velocity" and "Counterfactual_moving_slow" in dawdle
    assert affirmed[-2:] == ["start", "faster_velocity"] and learner[0] == "futureEvents"
    assert caller[-2:] == ["come_in_frame", "query_moving_velocity"] and stalled[-2:] == ["start", "is_static"]
    assert onwards[0] == "futureEvents" and onwards[-1] == "exist"
    assert_refused(parser, {
        "Is the yellow school bus stationary at the culmination of the footage?": "other than the start",
        "Once the clip is arrested midway, with which vehicle will the yellow cruiser subsequently collide?": "which",
        "Blue bus and green car collide at what second?": "when",
        "Does the blue fighter jet stall at the start?": "stalls"})


def test_everyday_speeds_offered_a_topic_after_a_time_and_an_engineers_words():
    said, _ = dislocated_as_asked(tokenize("When they collide, the blue truck and the gray mountain bike, the truck "
                                           "is more fast than the bike?"))
    assert said == tokenize("When they collide, the blue truck is more fast than the gray mountain bike?")
    # a statement about the pair in a sentence of its own is context, not a topic
    kept = tokenize("Purple road bike and green truck, they crash. Is the bike slower than the truck?")
    assert dislocated_as_asked(kept)[0] != kept[kept.index(",") + 1:]
    parser = QuestionParser.load()
    offered, leisurely, dash, grey, rest, propulsion = parser.parse_batch([
        "In the opening moments, is the cyan scooter sat there, pottering along, or zipping about?",
        "At the instant the brown double-decker clips the yellow sedan, is the double-decker the more leisurely one?",
        "Suppose the grey SUV was standing still from the starting itself, will it dash the red bicycle?",
        "When the airliner grey appears for the first time in the image, it moves slow, fast or it is static?",
        "Given an initial condition of rest for the red SUV, would it still undergo an impact with the blue bicycle?",
        "Which colour is the vehicle with propulsion active at t = 0?"])
    assert offered[-2:] == ["start", "query_moving_velocity"] and leisurely[-1] == "slower_velocity"
    assert "Counterfactual_static" in dash and grey[-2:] == ["come_in_frame", "query_moving_velocity"]
    assert "filter_attributes[gray]" in grey and "Counterfactual_static" in rest
    assert propulsion[-3:] == ["filter_accelerating", "unique", "query_attributes[color]"]
    # an alternative that offers no speed is no choice of one ('..., would it crash the cyan bus, or keep apart?')
    apart = parser.parse("Had the fighter jet hovered in the air from the start, would it crash the cyan bus, or keep "
                         "apart?")
    assert apart[-1] == "exist"


def test_a_vehicle_spelt_by_ear_and_a_label_that_imagines():
    assert sound_key("fiter") == sound_key("fighter") and sound_key("stayshun") == sound_key("station")
    index = sound_index({"fighter", "future", "blue", "school"})
    assert sounded("fiter", index) == "fighter" and sounded("skool", index) == "school"
    assert sounded("fiter", sound_index({"fighter", "fitter"})) is None   # two alike: none clearly the one
    parser = QuestionParser.load()
    said, read = spelt_by_ear(tokenize("is the blu skool bus fast ? the plain red car"), parser.sounds,
                              parser.readable)
    assert said == tokenize("is the blue school bus fast ? the plain red car")
    assert read == (("blu", "blue"), ("skool", "school"))
    # only in a vehicle's description ('beyond the truncation point' is no 'bendy'), and spelt somewhat alike ('on a
    # scale of 1 to 10' is no 'school')
    assert spelt_by_ear(tokenize("beyond the point , is it blu ?"), parser.sounds, parser.readable)[1] == ()
    assert spelt_by_ear(tokenize("on a scale of 1 to 10"), parser.sounds, parser.readable)[1] == ()
    fighter, private = parser.parse_batch([
        "supose the green fiter jet was hovering in the air from the very beginning, would it still hit the yellow car?",
        "does the green privit jet hit anything at all in the video?"])
    assert "filter_attributes[fighter]" in fighter and "Counterfactual_floating" in fighter
    assert private[-1] == "exist" and "filter_attributes[jet]" in private
    assert_refused(parser, {
        "CF: yellow city bike starts fast / hits blue pickup? Y/N": "imagines otherwise",
        "Subject: yellow motorbike; State @ start = not moving? (y/n)": "answer's form",
        "Wasn't the green pickup moving slowly at the moment the video was paused?": "other than the start",
        "Which colour has the ground under the vehicles?": "ground",
        "why did the brown pickup crash into the perple scooter?": "why"})


def test_a_premise_of_the_video_going_on_an_assistants_verb_and_learners_times():
    parser = QuestionParser.load()
    assuming, identify, stands, first, further = parser.parse_batch([
        "Assuming the clip continued past where it stops, is the blue airliner going to collide with the red fighter "
        "jet?",
        "Could you identify what kind of vehicle is picking up speed in the first moments?",
        "How quick is red sedan moving on start - it stands, goes slow or fast?",
        "With which speed the grey car is coming in the picture first time?",
        "If video would continue further, grey one and red one will crash?"])
    assert assuming[0] == "futureEvents" and further[0] == "futureEvents"
    assert identify[-3:] == ["filter_accelerating", "unique", "query_attributes[shape]"]
    assert stands[-2:] == ["start", "query_moving_velocity"]
    assert first[-2:] == ["come_in_frame", "query_moving_velocity"]
    assert_refused(parser, {
        "What is the speed of the brown tandem bike at the exact midpoint of the video?": "other than the start",
        "Assuming the video continued, is the bus fast?": "premise",
        "Is the bus further from the camera than the car?": "where a vehicle is"})


def test_a_scene_set_before_the_question_a_cleft_and_types_offered():
    parser = QuestionParser.load()
    like, pictured, restated, cleft, offered, version = parser.parse_batch([
        "A grey mountain bike shows up in the scene at some point, as far as I can tell; what I'd like to know is how "
        "fast that grey mountain bike is going at the moment it first comes into view.",
        "Picture the moment the green SUV runs into the brown school bus, since those two do bump at some point; how "
        "fast is the green SUV travelling right when it hits the school bus - stopped, slow or fast?",
        "Focusing on the double-decker bus here: the first time it enters the frame, what's its speed like - static, "
        "slow, or fast? In other words, how quickly is the double-decker moving when it first appears?",
        "Is it the grey car that is moving more slowly when it and the brown bus collide?",
        "Is it an airliner, a fighter, a private jet or a biplane that is hovering at the start?",
        "Imagine a different version of this clip where the mountain bike starts off going fast; in that version, "
        "would the mountain bike collide with the brown pickup?"])
    assert like[-2:] == ["come_in_frame", "query_moving_velocity"] and "filter_attributes[mountain_bike]" in like
    assert pictured[-2:] == ["get_frame", "query_moving_velocity"] and "filter_attributes[school_bus]" in pictured
    assert restated[-2:] == ["come_in_frame", "query_moving_velocity"]
    assert cleft[-1] == "slower_velocity" and "filter_attributes[bus]" in cleft
    assert offered == ["Objects", "start", "filter_floating", "unique", "query_attributes[shape]"]
    assert "Counterfactual_moving_fast" in version
    # 'the bus or the car' offers two vehicles, not their types; a scene's aside that imagines is no scene
    assert parser.parse("Is it the bus or the car that is faster at the start?")[-1] == "faster_velocity"
    assert "Counterfactual_moving_fast" in parser.parse(
        "Had the yellow minivan been moving fast from the very start, would it, I wonder, have ended up colliding "
        "with the gray cruiser?")
    assert_refused(parser, {
        "The purple scooter bumps into the cyan pickup in this clip; what colour is the scooter that does the "
        "bumping?": "vehicle it names",
        "Is the grey car moving more slowly when it and the brown bus collide?": "compares speeds",
        "Is the car fast or slow, or does it collide with the bus?": "two questions",
        "Does the car come into view fast?": "comes into view"})


def test_a_templates_colour_after_its_vehicle_and_a_pick_up():
    parser = QuestionParser.load()
    pickup, estate, their = parser.parse_batch([
        "How fast is the cyan-coloured scooter travelling when it crashes into the brown pick-up?",
        "State whether the estate car of grey colour is moving fast when it hits the red minivan.",
        "At their meeting, was the green bendy bus slower than the red motorbike?"])
    assert "filter_attributes[truck]" in pickup and "filter_attributes[brown]" in pickup
    assert ["filter_attributes[gray]", "filter_attributes[wagon]"] == estate[1:3]
    assert estate[-1] == "is_moving_velocity[fast]" and their[-1] == "slower_velocity"


def test_a_quiz_items_label_and_attribute_and_a_creative_paraphrase():
    parser = QuestionParser.load()
    changed, colour, planted, runin, clash = parser.parse_batch([
        "Change one thing: the blue road bike is speeding up from the start with its engine on. Does it now collide "
        "with the green car?",
        "Give the colour only: which vehicle is moving slowly at the start?",
        "Had the yellow SUV stayed planted in place from the start, would it have struck the purple bus?",
        "Is there ever a run-in between the red one and the blue pickup?",
        "Is the red private jet zipping along faster than the yellow one at the instant they clash?"])
    assert "Counterfactual_accelerating" in changed and "Counterfactual_static" in planted
    assert colour == ["Objects", "start", "filter_moving_velocity[slow]", "unique", "query_attributes[color]"]
    assert runin[-1] == "exist" and clash[-1] == "faster_velocity" and "filter_collision" in clash
    assert_refused(parser, {
        "After the red car and the blue bus collide, in which direction does the bus rebound?": "after a collision"})


def test_everyday_users_choices_in_brackets_and_a_video_stopped():
    parser = QuestionParser.load()
    none, stopped = parser.parse_batch([
        "At what speed (none, slow or fast) is the brown car moving as it first enters the picture?",
        "After the point where the video is stopped, will the blue double-decker run into anything?"])
    assert none[-2:] == ["come_in_frame", "query_moving_velocity"]
    assert stopped[0] == "futureEvents" and stopped[-1] == "exist"
    assert_refused(parser, {"what is the grey ground made of": "ground"})


def test_a_casual_speaker_and_african_learners():
    parser = QuestionParser.load()
    offered, booking, sitting, pointed, jammed, going = parser.parse_batch([
        "dude what's the scooter doing speed-wise when the clip kicks off, parked, crawling or booking it?",
        "what kind of vehicle is booking it at the start?",
        "the green one's just sitting there when it starts, right? like not moving at all?",
        "The grey one, did it collide with something at all?",
        "Did the brown sedan and the cyan scooter jam?",
        "When the video is continuing after the stop, will the cyan pickup knock into anything?"])
    assert offered == ["Objects", "filter_attributes[scooter]", "unique", "start", "query_moving_velocity"]
    assert booking == ["Objects", "start", "filter_moving_velocity[fast]", "unique", "query_attributes[shape]"]
    assert sitting == ["Objects", "filter_attributes[green]", "unique", "start", "is_static"]
    assert pointed == ["Events", "Objects", "filter_attributes[gray]", "unique", "filter_collision", "exist"]
    assert jammed[-1] == "exist" and "filter_attributes[scooter]" in jammed
    assert going[0] == "futureEvents" and "filter_attributes[truck]" in going
    # what a vehicle does, with no speeds offered, is still refused; a traffic jam is no collision
    assert_refused(parser, {"what is the red car doing at the start?": "what a vehicle does",
                            "is there a traffic jam?": "arranged"})


def test_a_philosopher_and_a_drafter_and_code_switchers():
    parser = QuestionParser.load()
    world, stipulated, provided, anywhere, ought, particle = parser.parse_batch([
        "Consider the nearest possible world in which the red city bike stands still from the start; does it, in "
        "that world, collide with the cyan SUV?",
        "Let it be stipulated that the blue fighter jet hovered aloft from the outset; under that stipulation, would "
        "it collide with the brown pickup?",
        "Provided the clip stops partway through, will the grey dirt bike afterwards collide with anything?",
        "Is there, anywhere in the footage, a collision between the grey tandem bicycle and the red thing?",
        "Taking only the first moments of the video into account, how ought one to characterise the speed of the "
        "cyan scooter: stationary, slow, or fast?",
        "Video stops midway, accha, after that will the green bus hit anything?"])
    assert "Counterfactual_static" in world and "Counterfactual_floating" in stipulated
    assert provided[0] == particle[0] == "futureEvents" and anywhere[0] == "Events" and anywhere[-1] == "exist"
    assert ought == ["Objects", "filter_attributes[cyan]", "filter_attributes[scooter]", "unique", "start",
                     "query_moving_velocity"]
    assert_refused(parser, {"Consider the blue sedan at the instant it leaves the frame: is it then moving slowly or "
                            "fast?": "leaves the view"})


def test_headlines_and_australian_words():
    parser = QuestionParser.load()
    headline, chat, prang, hanging, pushie = parser.parse_batch([
        "BUS HORROR: how fast was the green motorbike travelling when it stacked it into the blue double-decker - "
        "still, slow or fast?",
        "Was the purple one flat chat right at the beginning?",
        "Did the dirtbike and the brown minivan have a prang at any point?",
        "Reckon the blue biplane was just hanging about up there at the start?",
        "FOOT TO THE FLOOR: if the red bus had been gunning it from the very start, would it have crashed into the "
        "pushie?"])
    # the headline's bus is no vehicle of the question: the motorbike is the one asked
    assert headline[:3] == ["Objects", "filter_attributes[green]", "filter_attributes[motorbike]"]
    assert chat[-1] == "is_moving_velocity[fast]" and hanging[-1] == "is_floating" and prang[-1] == "exist"
    assert "Counterfactual_accelerating" in pushie and "filter_attributes[bicycle]" in pushie
    # a vehicle's name alone before the colon is what the question points at, no headline
    assert parser.parse("Red sedan: is it fast at the start?")[1:3] == ["filter_attributes[red]",
                                                                     "filter_attributes[sedan]"]



def test_gen_z_comments_and_cloze_items():
    parser = QuestionParser.load()
    nah, tripping = parser.parse_batch([
        "the fighter jet at the beginning lowkey crawling?? is it going slow or nah",
        "the double-decker was going fast when it hit the gray station wagon right?? or am i tripping"])
    assert nah == ["Objects", "filter_attributes[fighter]", "unique", "start", "is_moving_velocity[slow]"]
    assert tripping[-1] == "is_moving_velocity[fast]" and "filter_attributes[wagon]" in tripping
    assert_refused(parser, {"Fill in the blank: The purple airliner is hovering about ____ metres above the "
                            "ground.": "length in metres"})


def test_enthusiasts_names():
    parser = QuestionParser.load()
    step, warbird, bendy = parser.parse_batch([
        "How quick is the blue step-through moving as it first rolls into shot?",
        "When the warbird first pops into frame, how fast is it going?",
        "In the opening moments, is the green bendy outpacing the grey estate?"])
    assert step[1:3] == ["filter_attributes[blue]", "filter_attributes[scooter]"]
    assert "filter_attributes[fighter]" in warbird and warbird[-1] == "query_moving_velocity"
    assert "filter_attributes[articulated_bus]" in bendy and "filter_attributes[wagon]" in bendy



def test_lettered_options_complete_their_question():
    said = {
        # yes / no offered leave the question alone, or ask a statement whether it is true
        "Select the correct answer: Is the airliner still? A) Yes B) No": "is the airliner still ?",
        "At the start, the purple one is stationary. A) Yes B) No":
            "is it true that at the start , the purple one is stationary ?",
        # an option and its negation ask whether the first holds, from the statement's last sentence
        "Picture the cruiser accelerating. Then the cruiser A) collides with the bus B) does not collide with the bus.":
            "picture the cruiser accelerating . is it true that then the cruiser collides with the bus ?",
        # other options are offered choices; a blank for a colour or a kind asks what it is
        "Choose one: the school bus is A) standing still B) moving slowly C) moving fast.":
            "the school bus is standing still , moving slowly or moving fast ?",
        "How fast is it? (A) not moving (B) slow (C) fast": "how fast is it ?",
        "The yellow sedan crashes into a A) car B) bus C) bicycle.": "the yellow sedan crashes into what kind of vehicle ?",
        "Fill in the blank (would / would not): If the car had been still, it ____ hit the bus.":
            "is it true that if the car had been still , it would hit the bus ?"}
    for text, question in said.items():
        assert " ".join(worksheet_as_said(tokenize(text))[0]) == question, text
    # 'a' alone is an article: no list without its 'b'
    assert lettered_options(tokenize("Does the car hit a) bus?")) is None
    parser = QuestionParser.load()
    floating, partner = parser.parse_batch([
        "Choose one: In the first moments, the green aeroplane is A) floating in the air B) not floating.",
        "Question: The yellow sedan crashes into a (A) car (B) bus (C) motorbike (D) bicycle (E) aeroplane."])
    assert floating == ["Objects", "filter_attributes[green]", "filter_attributes[aeroplane]", "unique", "start",
                        "is_floating"]
    assert partner[-1] == "query_attributes[shape]" and "get_all_col_partners" in partner


def test_a_model_s_prompt_wrapping_and_a_paraphraser_s_restructurings():
    parser = QuestionParser.load()
    yes_no, choose, letter, stopped, fronted, lag, version, wondered = parser.parse_batch([
        "Based on the video, is the red bus faster than the blue car at the start? Respond with yes or no only.",
        "<video> As the dirt bike first enters the frame, how fast is it moving? Choose from: static, slow, fast.",
        "<video> Is the aeroplane hovering at the beginning of the clip? Options: (A) yes (B) no. Please output only "
        "the letter of the correct option.",
        "Based on the video, which is stopped before the end, is the cruiser going to hit anything afterwards?",
        "Slow - would that describe the pace of the cyan SUV in the first moments of the video?",
        "Does the green pickup lag behind the purple station wagon in speed at the very beginning?",
        "In a version where the blue city bus starts off fast, is there a collision between it and the green sedan?",
        "What sort of speed the school bus has during the opening moments of the clip is what I'd like to know."])
    assert yes_no[-1] == "faster_velocity" and choose[-1] == "query_moving_velocity"
    assert letter == ["Objects", "filter_attributes[aeroplane]", "unique", "start", "is_floating"]
    assert stopped[0] == "futureEvents"
    assert fronted[-1] == "is_moving_velocity[slow]" and lag[-1] == "slower_velocity"
    assert "Counterfactual_moving_fast" in version and wondered[-1] == "query_moving_velocity"
    # how to answer is dropped only where it says nothing more
    assert_refused(parser, {"Is the red car fast at the start? Answer for the blue bus too.": "blue"})


def test_scots_irish_and_northern_words():
    parser = QuestionParser.load()
    bang, owt, clatter = parser.parse_batch([
        "How fast was the wee red sedan going bang on the start, like?",
        "Does the red yin bump into owt, like?",
        "Which way was the red double-decker going when it clattered into the green yin?"])
    assert bang == ["Objects", "filter_attributes[red]", "filter_attributes[sedan]", "unique", "start",
                    "query_moving_velocity"]
    assert owt == ["Events", "Objects", "filter_attributes[red]", "unique", "filter_collision", "exist"]
    assert "filter_attributes[green]" in clatter and clatter[-1] == "query_moving_direction"


def test_an_annotator_s_sizes_and_looks_and_claims_to_verify():
    parser = QuestionParser.load()
    shiny, tiny, short, claim, someone, statement, tagged, confirm = parser.parse_batch([
        "How fast is the shiny blue bus going when it bumps into the little red car?",
        "Is the tiny motorbike moving quicker than the big bus in the first moments of the video?",
        "This short clip is cut off early; is the little brown pickup going to hit anything after that?",
        "Claim: at the start, the blue sedan is moving faster than the green station wagon. Correct?",
        "Someone says the brown car was standing still when it collided with the airliner. Was it?",
        "Statement: the purple bus runs into something during the clip. True or false?",
        "Check this: had the yellow road bike stayed static from the beginning, it would have hit the grey SUV. "
        "Would it?",
        "Please confirm the colour of the vehicle that is floating at the start."])
    assert shiny[:4] == ["Objects", "filter_attributes[blue]", "filter_attributes[bus]", "unique"]
    assert "filter_attributes[red]" in shiny and shiny[-1] == "query_moving_velocity"
    assert tiny == ["Objects", "filter_attributes[motorbike]", "unique", "Objects", "filter_attributes[bus]", "unique",
                    "start", "faster_velocity"]
    assert short[0] == "futureEvents" and "filter_attributes[truck]" in short
    assert claim[-1] == "faster_velocity" and someone[-1] == "is_static" and statement[-1] == "exist"
    assert "Counterfactual_static" in tagged and tagged[-1] == "exist"
    assert confirm[-1] == "query_attributes[color]"
    # a size or a look asked, alone, or two materials set against each other are refused
    assert_refused(parser, ["Is the red sedan large?", "Which is bigger, the bus or the car?",
                            "Is the big one moving at the start?", "Does the metal bus hit the rubber car?",
                            "Is the red sedan shiny?"])


def test_a_speculator_s_hunches_versions_and_a_video_let_run_on():
    parser = QuestionParser.load()
    bet, hunch, forecast, rolled, dreamt, cleft, heavy = parser.parse_batch([
        "Here's my bet: the green motorbike is just crawling along slowly at the beginning. Am I right?",
        "My hunch says the grey bendy bus is barrelling along fast when it hits the red bicycle. Is it?",
        "The clip stops early, and my forecast is that the red fighter jet and the green SUV hit each other "
        "afterwards. Will they?",
        "If we let the action roll on beyond where the video stops, will the grey tandem bike hit anything?",
        "Let's dream up a version where the private jet floats from the beginning: would it run into the purple sedan?",
        "Was it at high speed that the brown chopper hit the red minivan?",
        "At the beginning, is the bizjet taxiing any slower than the heavy?"])
    assert bet[-1] == "is_moving_velocity[slow]" and hunch[-1] == "is_moving_velocity[fast]"
    assert forecast[0] == "futureEvents" and rolled[0] == "futureEvents"
    assert "Counterfactual_floating" in dreamt and cleft[-1] == "is_moving_velocity[fast]"
    assert heavy == ["Objects", "filter_attributes[jet]", "unique", "Objects", "filter_attributes[airliner]", "unique",
                     "start", "slower_velocity"]
    # 'heavy' before a vehicle's name is no airliner
    assert_refused(parser, ["Is the heavy bus moving fast at the start?"])


def test_a_database_s_attribute_clauses_and_a_video_editor_s_words():
    said = {"the vehicle that is a sedan and is red": "the red sedan",
            "the item with colour blue and type SUV": "the blue suv",
            "the object of category bus with colour brown": "the brown bus",
            "the car , which is green , goes": "the green car goes", "the one that's a scooter": "the scooter",
            "the airliner having colour cyan": "the cyan airliner",
            # anything but a colour or a kind leaves the words alone
            "the one that is moving": "the one that is moving", "the car that is fast": "the car that is fast"}
    for text, words in said.items():
        assert " ".join(attributes_as_named(tokenize(text))[0]) == words, text
    parser = QuestionParser.load()
    involving, partner, scrub, unseen, last, shot, edit = parser.parse_batch([
        "Is there any collision involving the motorbike whose colour is yellow?",
        "What is the colour of the vehicle that the sedan with colour green collides with?",
        "Scrubbing through the entire shot, does the green pickup collide with anything at all?",
        "In the part we don't get to see, does the airliner go on to hit the yellow car?",
        "Past the final frame of this truncated clip, is the blue one going to hit something?",
        "If we'd shot the pickup standing still from the very start, would it still have crashed into the yellow bus?",
        "Re-edit it so the SUV is flying along fast from the top of the take: does it run into the brown sedan?"])
    assert involving == ["Events", "Objects", "filter_attributes[yellow]", "filter_attributes[motorbike]", "unique",
                         "filter_collision", "exist"]
    assert "filter_attributes[green]" in partner and partner[-1] == "query_attributes[color]"
    assert scrub[0] == "Events" and unseen[0] == last[0] == "futureEvents"
    assert "Counterfactual_static" in shot and "Counterfactual_moving_fast" in edit


def test_a_vehicle_spoken_to_is_the_question_s_you():
    assert addressed_as_named(tokenize("Blue bus, did you bump into the green car?"))[0] == \
        tokenize("blue bus , did it bump into the green car ?")
    assert addressed_as_named(tokenize("Red sedan, were you faster than it?"))[0] == \
        tokenize("red sedan , was the red sedan faster than it ?")
    assert addressed_as_named(tokenize("Did you see the blue bus?")) == (tokenize("Did you see the blue bus?"), ())
    parser = QuestionParser.load()
    little, engine, would = parser.parse_batch([
        "Little grey biplane, were you sitting perfectly still when the video began?",
        "Blue city bus, was your engine on and were you speeding up at the start?",
        "Grey dirt bike, if you'd come off the line fast, would you and the blue double-decker have collided?"])
    assert little == ["Objects", "filter_attributes[gray]", "filter_attributes[biplane]", "unique", "start", "is_static"]
    assert engine[-1] == "is_accelerating" and "Counterfactual_moving_fast" in would


def test_southern_us_words_and_a_rhetorical_aside():
    parser = QuestionParser.load()
    right_off, fixing = parser.parse_batch([
        "Which kind of vehicle was gainin' speed right off when the video started?",
        "The video stops partway. Do you figure the yellow one and the green chopper are fixin' to crash later on?"])
    assert right_off[-1] == "query_attributes[shape]" and "filter_accelerating" in " ".join(right_off)
    assert fixing[0] == "futureEvents"
    # a rhetorical aside after the question asks nothing
    obvious, = parser.parse_batch(["What colour is the vehicle hovering at the start - wasn't it easy to spot?"])
    assert obvious[-1] == "query_attributes[color]" and "filter_floating" in obvious


def test_a_sceptic_s_leading_questions():
    parser = QuestionParser.load()
    agree, say, tell, believe, wager, surely = parser.parse_batch([
        "You'd agree the green SUV was only crawling along slowly at the start, wouldn't you?",
        "Wouldn't you say the blue road bike was going slower than the city bus at the moment they collided?",
        "Don't tell me the private jet was outpacing the tandem bike right at the beginning?",
        "Am I to believe the brown bicycle crashed into something at some point?",
        "Stopping the clip here, I'd wager the cyan airliner and the yellow biplane end up colliding later, don't they?",
        "Surely you can tell me how quickly the school bus was moving in the opening moments, can't you?"])
    assert agree[-1] == "is_moving_velocity[slow]" and say[-1] == "slower_velocity" and tell[-1] == "faster_velocity"
    assert believe[-1] == "exist" and wager[0] == "futureEvents" and surely[-1] == "query_moving_velocity"
    # a negated claim stays refused
    assert_refused(parser, ["Picture the biplane floating in the air from the very start: it couldn't possibly still "
                            "have hit the grey car, could it?"])


def test_radio_brevity():
    assert radio_as_asked(tokenize("Verify green dirt bike running fast at first frame, over."))[0] == \
        tokenize("is it true that the green dirt bike running fast at first frame.")
    assert radio_as_asked(tokenize("Say again: how fast is the bus?")) == (tokenize("Say again: how fast is the bus?"),
                                                                            ())
    parser = QuestionParser.load()
    say, verify, stopped = parser.parse_batch([
        "Say speed of the blue bus at contact with the green car.",
        "Verify green dirt bike running fast at first frame, over.",
        "Verify: red motorbike dead stopped at time of contact with the blue one, yes or no?"])
    assert say[-1] == "query_moving_velocity" and "filter_collision" in say
    assert verify == ["Objects", "filter_attributes[green]", "filter_attributes[dirtbike]", "unique", "start",
                      "is_moving_velocity[fast]"]
    assert stopped[-1] == "is_static" and "filter_collision" in stopped
    # a time asked is refused, however said
    assert_refused(parser, {"Say time in seconds of first contact between the red sedan and the blue bus.": "when"})


def test_a_scanner_s_misread_print_and_split_words():
    known = {"motorbike", "slower", "into", "bicycle", "collides", "yellow", "color", "red", "reel"}
    assert scanned("rnotorbike", known) == "motorbike" and scanned("s1ower", known) == "slower"
    assert scanned("int0", known) == "into" and scanned("bicyde", known) == "bicycle"
    assert scanned("co1our", known, {"colour": "color"}) == "color"
    assert scanned("tale", known) is None   # no reading of it is a word: left as it is
    assert rejoined("the car col lides with the yel low one".split(), known) == \
        "the car collides with the yellow one".split()
    assert rejoined("col - lides".split(), known) == ["collides"]
    assert rejoined("the red reel".split(), known) == "the red reel".split()   # two words stay two
    parser = QuestionParser.load()
    ocr, split = parser.parse_batch(["At the start. is the yellow rnotorbike moving slowly?",
                                     "What type of vehicle does the road bike col- lide with?"])
    assert ocr == ["Objects", "filter_attributes[yellow]", "filter_attributes[motorbike]", "unique", "start",
                   "is_moving_velocity[slow]"]
    assert split == ["Events", "Objects", "filter_attributes[road_bike]", "unique", "get_all_col_partners", "unique",
                     "query_attributes[shape]"]


def test_plain_language_and_a_persona_s_words():
    parser = QuestionParser.load()
    floating, picture, pair, moment = parser.parse_batch([
        "Look at the red biplane. Is it floating at the start - staying up in the air without falling?",
        "Picture this. At the start, the brown mountain bike moves fast - not slow. Would the mountain bike crash "
        "into the cyan minivan?",
        "Here is the yellow school bus. Here is the grey sedan. Do they ever crash into each other in the video?",
        "The red bendy bus hits the grey car. Think about that moment. Is the bendy bus slower than the car?"])
    assert floating == ["Objects", "filter_attributes[red]", "filter_attributes[biplane]", "unique", "start",
                        "is_floating"]
    assert picture[4] == "Counterfactual_moving_fast"
    assert pair[1:3] == ["Objects", "filter_attributes[yellow]"]   # the pair in the order the context names them
    assert moment[-1] == "slower_velocity" and "get_frame" in moment
    told, = parser.parse_batch(["Tell the colour of the aeroplane that hovers in the air at the beginning."])
    assert told == ["Objects", "start", "filter_floating", "unique", "query_attributes[color]"]
    # a dash that starts a question or a request is no gloss
    assert parser.parse_batch(["Summary: floating object at clip start - report its colour."])[0][-1] == \
        "query_attributes[color]"
    # the video's end, whatever it is called, is refused of a factual question
    assert_refused(parser, {"Is that red pickup faster than the green car when the show's wrappin' up, partner?":
                            "end", "IS THE GRAY SEDAN STATIC AT FINAL TIMESTAMP? BEEP BOOP.": "end"})


def test_creoles_and_pidgins():
    assert creole_as_said(tokenize("Di blue car did a go faster dan di green bus a di start?"))[0] == \
        tokenize("the blue car did go faster than the green bus at the start?")
    # Hawaiian 'wen': 'when' before its clause's subject, a past tense's mark before a verb
    assert creole_as_said(tokenize("Wen da brown one wen smash da gray minivan"))[0] == \
        tokenize("when the brown one smash the gray minivan")
    # without a creole's own words, standard English keeps 'stay', 'for', 'a' and 'jam'
    said = tokenize("Does the bus stay parked for a while in the jam?")
    assert creole_as_said(said) == (said, ())
    parser = QuestionParser.load()
    lick, air, jam = parser.parse_batch(["Di red sedan and di blue scooter did lick up demself?",
                                         "Dat yellow biplane dey float for air for beginning?",
                                         "Dat purple dirt bike jam anything at all for di video?"])
    assert lick == ["Events", "Objects", "filter_attributes[red]", "filter_attributes[sedan]", "unique",
                    "filter_collision", "Objects", "filter_attributes[blue]", "filter_attributes[scooter]", "unique",
                    "filter_collision", "exist"]
    assert air == ["Objects", "filter_attributes[yellow]", "filter_attributes[biplane]", "unique", "start",
                   "is_floating"]
    assert jam == ["Events", "Objects", "filter_attributes[purple]", "filter_attributes[dirtbike]", "unique",
                   "filter_collision", "exist"]


def test_a_shy_speaker_s_apologies_courtesies_and_softeners():
    parser = QuestionParser.load()
    sorry, trouble, possibly = parser.parse_batch([
        "Sorry to ask a what-if, but if the cyan motorbike had started off slowly, would it have collided with the "
        "brown bus?",
        "If it isn't too much trouble, does the red sedan hit the blue bus?",
        "Apologies in advance, but was the brown cruiser possibly going fast when it crashed into the red bus?"])
    assert sorry[4] == "Counterfactual_moving_slow"
    assert trouble[0] == "Events" and trouble[-1] == "exist"
    assert possibly[-1] == "is_moving_velocity[fast]" and "filter_collision" in possibly
    # what could happen stays refused: 'could' and 'might' ask it, and so does 'is it possible'
    assert_refused(parser, {"Is it possible that the red sedan hits the blue bus?": "could happen"})


def test_a_tutor_s_check_ins_are_context():
    parser = QuestionParser.load()
    seen, noticed, moment = parser.parse_batch([
        "You saw the red sedan right at the very start, didn't you? How fast was it going, standing still, slow, or "
        "fast?",
        "Did you notice the blue biplane at the beginning? Was it floating in the air?",
        "Think about the moment the grey mountain bike collides with the cyan minivan. What direction was the "
        "mountain bike travelling in?"])
    assert seen == ["Objects", "filter_attributes[red]", "filter_attributes[sedan]", "unique", "start",
                    "query_moving_velocity"]
    assert noticed == ["Objects", "filter_attributes[blue]", "filter_attributes[biplane]", "unique", "start",
                       "is_floating"]
    assert moment[-1] == "query_moving_direction" and "get_frame" in moment   # the moment the context pictures
    # a claim's tag is no check-in before a question
    assert check_ins_stated(tokenize("the cyan one was standing still at the start, right? Or no?"))[1] == ()


def test_a_bilingual_speaker_s_other_language():
    assert tokenize("début vídeo") == ["debut", "video"]   # accents folded
    assert code_switched_as_said(tokenize("Est-ce que the red car était fast au début?"))[0] == \
        tokenize("the red car was fast at the start?")
    said = tokenize("Also, the red car was fast, ma'am?")   # English 'also' and 'ma' stay, with no other word
    assert code_switched_as_said(said) == (said, ())
    parser = QuestionParser.load()
    colour, = parser.parse_batch(["Qual é a cor of the vehicle floating no começo, tipo?"])
    assert colour == ["Objects", "start", "filter_floating", "unique", "query_attributes[color]"]
    # a clause in a language the parser does not read is no digression: it may say when
    assert_refused(parser, ["Quando eles batem, o red bicycle tava faster than the school bus, tipo?",
                            "the red car zai zuihou is it static ma?"])


def test_a_promo_s_teasers_and_a_signer_s_gloss():
    parser = QuestionParser.load()
    teased, called = parser.parse_batch([
        "Will sparks fly?! Do the red sedan and the yellow school bus crash into each other at any point? You tell us!",
        "Speed demon spotted! What kind of vehicle is zooming along fast at the start? Name it to claim it!"])
    assert teased[0] == "Events" and teased[-1] == "exist"   # in the video, not after it
    assert called == ["Objects", "start", "filter_moving_velocity[fast]", "unique", "query_attributes[shape]"]
    then, = parser.parse_batch(["SCHOOL BUS, BLUE ONE, BUMP. THAT TIME SCHOOL BUS STAND STILL, NOT MOVE, TRUE?"])
    assert then[-1] == "is_static" and "get_frame" in then
    assert_refused(parser, {"GRAY AIRLINER FIRST COME-IN SCREEN, MOVE HOW FAST?": "comes into view",
                            "Red sedan crash blue bus, what second happen?": "when something happens",
                            "Yellow scooter, video start, where located, left or right?": "where a vehicle is"})


def test_emoji_said_for_words_and_a_swipe_keyboard_s_words():
    assert emoji_as_said(tokenize("is the 🔵 🚙 🛑 at the beginning?"))[0] == \
        tokenize("is the blue suv static at the beginning?")
    assert emoji_as_said(tokenize("🎬 how fast is it? 🛑 or 🐢 or 💨"))[0] == \
        tokenize("at the start, how fast is it? static or slow or fast")
    parser = QuestionParser.load()
    scooter, crash, swiped = parser.parse_batch([
        "what speed is the cyan 🛵 doing when the clip begins 🤔 parked, slow or fast?",
        "when the ⚪ road bike 💥 the 🟡 🚗, was the road bike just standing there 🛑?",
        "how fast was the yellow car going when it hot the purple bud"])
    assert scooter == ["Objects", "filter_attributes[cyan]", "filter_attributes[scooter]", "unique", "start",
                       "query_moving_velocity"]   # the emoji names the vehicle: never dropped as a decoration
    assert crash[1:3] == ["filter_attributes[gray]", "filter_attributes[road_bike]"] and crash[-1] == "is_static"
    assert "filter_attributes[bus]" in swiped and swiped[-1] == "query_moving_velocity"
    # a colour the catalogue has not, said as an emoji, is refused like its word
    assert_refused(parser, ["is the 🟠 🚗 moving fast at the start?"])
    # a yes-or-no tag asks yes or no, never which
    assert_refused(parser, ["When the grey pickup is colliding with red bicycle, fast he is going or not?"])


def test_a_telegram_a_pasted_chat_and_a_whiteboard_s_symbols():
    assert telegram_as_said(tokenize("REQUEST ADVISE how fast the motorbike is going when it strikes the gray car "
                                     "STOP"))[0] == \
        tokenize("tell me how fast the motorbike is going when it strikes the gray car.")
    said = tokenize("Does the red car ever stop?")   # 'stop' is a full stop only in a telegram
    assert telegram_as_said(said) == (said, ())
    assert transcript_as_asked(tokenize("Q1: the cyan bus. A1: yes, what about it? Q2: what does it hit?"))[0] == \
        tokenize("the cyan bus. what does it hit?")
    parser = QuestionParser.load()
    wire, chat, setting = parser.parse_batch([
        "FILM STOPPED PART WAY STOP WILL BLUE DOUBLE DECKER AND PURPLE CAR COLLIDE AFTERWARDS QUERY",
        "User: hi, I'm watching the clip now. Assistant: Great, what would you like to know? User: how fast is the red "
        "sedan going at the very start, static, slow or fast?",
        "Set the yellow scooter's initial speed to fast. Does the yellow scooter then hit the purple sedan?"])
    assert wire[0] == "futureEvents" and wire[-1] == "exist"
    assert chat == ["Objects", "filter_attributes[red]", "filter_attributes[sedan]", "unique", "start",
                    "query_moving_velocity"]
    assert setting[4] == "Counterfactual_moving_fast"   # a setting said alone is a condition, not what happened
    # a time named by a symbol, a count and a yes-or-no instruction after a reading of which are refused
    assert_refused(parser, {"for t > T_cut: does the jet hit anything?": "symbol",
                            "Let t_c be the moment the cyan one and the brown one collide. Is the cyan one standing "
                            "still (v = 0) at t_c?": "symbol",
                            "Number of aeroplanes floating at the start = ?": "count",
                            "v(yellow motorbike, t=0) = fast? yes or no.": "yes or no"})


def test_scandinavian_learners_and_a_clinician_s_note():
    parser = QuestionParser.load()
    driven, floor, verbless = parser.parse_batch([
        "Does the purple one drive on the road bike some time in the film?",
        "Does the purple one drive on the grey floor at the start?",
        "At impact w/ green pickup: blue chopper the slower one?"])
    assert driven == ["Events", "Objects", "filter_attributes[purple]", "unique", "filter_collision", "Objects",
                      "filter_attributes[road_bike]", "unique", "filter_collision", "exist"]
    assert floor is None   # 'drive on' the floor is no collision (the floor is refused as no vehicle)
    assert verbless[:4] == ["Objects", "filter_attributes[blue]", "filter_attributes[chopper]", "unique"]
    post, = parser.parse_batch(["?collision blue road bike + red pickup post-cut"])
    assert post[0] == "futureEvents"


def test_a_vehicle_set_apart_and_a_ramble_before_the_question():
    parser = QuestionParser.load()
    ignoring, not_that, of_two, ramble = parser.parse_batch([
        "Ignoring the green bus parked by the curb, how fast was the red sedan going at the start - stopped, slow or "
        "fast?",
        "Not the gray minivan beside it - the yellow SUV: was it standing still at the very start?",
        "Of the two green vehicles, the motorbike: which way was it travelling at the beginning of the clip?",
        "The purple mountain bike weaves around so much that I kept holding my breath, and the red SUV is just parked "
        "there, but like does the mountain bike end up crashing into anything at all?"])
    assert ignoring == ["Objects", "filter_attributes[red]", "filter_attributes[sedan]", "unique", "start",
                        "query_moving_velocity"]
    assert not_that == ["Objects", "filter_attributes[yellow]", "filter_attributes[suv]", "unique", "start",
                        "is_static"]
    assert of_two[1:3] == ["filter_attributes[green]", "filter_attributes[motorbike]"]   # the colour said there
    assert ramble == ["Events", "Objects", "filter_attributes[purple]", "filter_attributes[mountain_bike]", "unique",
                      "filter_collision", "exist"]   # the ramble is context: its fuller mention names the bike
    # a clause of time is no vehicle set apart ('while they collide')
    assert distractors_dropped(tokenize("While the bus and the car collide, is the bus fast?"))[1] == ()


def test_the_inverted_order_reads_its_subject_as_the_one_asked_about():
    parser = QuestionParser.load()
    faster, collide, crash, moving = parser.parse_batch([
        "Faster than the yellow tandem bike at the start, the gray fighter jet is?",
        "Collide with the red tandem bike, did the gray SUV?",
        "After where the clip pauses, into the school bus crash the purple fighter jet will, hmm?",
        "At the beginning, slower than the cyan chopper, moving the school bus was?"])
    # (each was read with the other vehicle first: the answer of the other comparison)
    assert faster[:4] == ["Objects", "filter_attributes[gray]", "filter_attributes[fighter]", "unique"]
    assert faster[-2:] == ["start", "faster_velocity"]
    assert collide[:5] == ["Events", "Objects", "filter_attributes[gray]", "filter_attributes[suv]", "unique"]
    assert crash[:4] == ["futureEvents", "Objects", "filter_attributes[purple]", "filter_attributes[fighter]"]
    assert moving[:3] == ["Objects", "filter_attributes[school_bus]", "unique"] and moving[-1] == "slower_velocity"
    # a comparison's ellipsis is no inverted subject, nor is a question's own order
    for said in ("at the start is the red biplane moving faster than the blue truck is ?",
                 "is the red car faster than the bus at the start ?"):
        assert inverted_as_asked(tokenize(said)) == (tokenize(said), ())
    # a value said first in a condition: 'if slow it had been going' was read as fast
    slow, = parser.parse_batch(["The bus, if slow it had been going at the start, does it hit the cyan dirt bike?"])
    assert "Counterfactual_moving_slow" in slow


def test_an_impact_said_first_and_a_bare_moment_are_times():
    parser = QuestionParser.load()
    striking, moment, topic = parser.parse_batch([
        "Striking the gray minivan, how fast was the cyan bicycle going?",
        "The moment it crashes into the school bus, what speed has the cyan motorbike got?",
        "The motorbike, once the clip cuts off, is it going to hit the grey one, yes or no?"])
    # (the minivan was read as the one asked about; the clause of the moment was dropped as an aside)
    assert striking[:4] == ["Objects", "filter_attributes[cyan]", "filter_attributes[bicycle]", "unique"]
    assert moment[-3:] == ["unique", "get_frame", "query_moving_velocity"] and "filter_collision" in moment
    assert topic[:4] == ["futureEvents", "Objects", "filter_attributes[motorbike]", "unique"]
    # a clause where the vehicle itself collides is no aside (it was dropped as one and the question refused)
    partner, = parser.parse_batch(["The red private jet, the thing it crashes into, what colour is that?"])
    assert partner == ["Events", "Objects", "filter_attributes[red]", "filter_attributes[jet]", "unique",
                       "get_all_col_partners", "unique", "query_attributes[color]"]


def test_chat_formatting_slang_and_a_dropped_g():
    assert tokenize("/ask would the **bicycle** run into it if it'd been fast?")[:3] == ["would", "the", "*"]
    assert "had" in tokenize("if it'd been fast") and tokenize("- where is it?")[0] == "where"
    assert tokenize("the wagon ain't never moved")[2:] == ["never", "moved"]
    assert she_as_it(tokenize("was she hovering? what's her speed?"))[0] == [
        "was", "it", "hovering", "?", "what", "'", "s", "its", "speed", "?"]
    assert tokenize("Bus-senpai (ﾟoﾟ;) is fast") == ["bus", "is", "fast"]
    assert dropped_g("slowin", {"slow"}) == "slowing" and dropped_g("movin", {"moving"}) == "moving"
    assert dropped_g("thin", {"thing"}) is None   # too short to be one
    parser = QuestionParser.load()
    assert_refused(parser, {"the chopper slowin down at the start or nah?": "slows down",
                            "- where in the frame is the school bus at the start, left side or right side?": "where"})
    tag, = parser.parse_batch(["blue one movin faster than the red one when they crash, straight up?"])
    assert tag and tag[-1] == "faster_velocity"


def test_a_story_told_again_otherwise_is_a_condition():
    parser = QuestionParser.load()
    rewrite, head = parser.parse_batch([
        "You rewrite the scene so the grey mountain bike is speeding up from the very start. Would it then collide "
        "with the purple pickup?",
        "You replay it in your head with the car launching fast from the start. Does the car crash into the airliner "
        "then?"])
    # (both were read as what happens in the video, or after it)
    assert "Counterfactual_accelerating" in rewrite and "Counterfactual_moving_fast" in head
    # said where no rule makes it a condition, it is refused rather than read as what happened
    assert_refused(parser, ["DIRECTOR: Rewrite the fighter jet floating from FADE IN. Does it hit the green one?"])


def test_a_vehicle_called_she_fondness_a_script_s_times_and_a_fan_s_words():
    parser = QuestionParser.load()
    she, fond, top, edge, inch, senpai, beauty = parser.parse_batch([
        "The purple biplane, was she hovering right at the beginning?",
        "When things got going at the start, was that sweet blue tandem bike slower than the red motorbike?",
        "DIRECTOR: At the top of the scene, is the pickup accelerating?",
        "At the moment they hit, did the purple dirt bike have the edge in speed over the yellow SUV?",
        "Suppose the yellow bendy bus never moved an inch from the beginning: would she have collided with the gray "
        "car?",
        "Yabai (ﾟoﾟ;) at the start, is the green sedan faster than Bus-senpai, the yellow one?",
        "The red fighter jet, what a beauty: what was her speed the moment she first showed up in the frame?"])
    assert she == ["Objects", "filter_attributes[purple]", "filter_attributes[biplane]", "unique", "start",
                   "is_floating"]
    assert fond[:4] == ["Objects", "filter_attributes[blue]", "filter_attributes[tandem_bike]", "unique"]
    assert top == ["Objects", "filter_attributes[truck]", "unique", "start", "is_accelerating"]
    # (an edge in speed was read as slow, an inch as slow)
    assert edge[-1] == "faster_velocity" and "Counterfactual_static" in inch
    assert senpai[4:8] == ["Objects", "filter_attributes[yellow]", "filter_attributes[bus]", "unique"]
    assert beauty[-2:] == ["come_in_frame", "query_moving_velocity"]   # (read as the start)
    # 'chop her' is a chopper heard apart, not a vehicle called her
    chopper, = parser.parse_batch(["does the brown chop her hit anything"])
    assert chopper[2:4] == ["filter_attributes[brown]", "filter_attributes[chopper]"]
    # the script's end is the end, which no question asks
    assert_refused(parser, ["How fast is the grey SUV moving at FADE OUT: static, slow or fast?"])


def test_a_viewer_s_premise_regional_names_and_walks_of_life_s_motion_words():
    parser = QuestionParser.load()
    seeing, footage, identified, bakkie, stop, better, hammer = parser.parse_batch([
        "If I'm seeing the impact right, was the plane slower than the car when they collided?",
        "Provided the clip isn't edited, how fast is the green SUV moving at the moment it hits the yellow pickup?",
        "If I'm reading the colours right, had the purple one been accelerating from the beginning, would it have "
        "struck the yellow car?",
        "Is the blue bakkie standing still at the start of the clip?",
        "Suppose the yellow mountain bike had been at a dead stop from the beginning; would it and the grey pickup "
        "have collided?",
        "When the clip opens, is the double-decker making better speed than the green station wagon?",
        "If the blue double-decker had been putting the hammer down from the start, would it have struck the red "
        "motorbike?"])
    # (each premise of the viewer's, or of the footage, was refused as a premise or read as a condition)
    assert seeing[-1] == "slower_velocity" and footage[-1] == "query_moving_velocity"
    assert "Counterfactual_accelerating" in identified
    # ('bakkie' was heard as 'bike')
    assert bakkie == ["Objects", "filter_attributes[blue]", "filter_attributes[truck]", "unique", "start",
                      "is_static"]
    assert "Counterfactual_static" in stop and better[-1] == "faster_velocity"
    assert "Counterfactual_accelerating" in hammer
    # a premise about what the vehicles did is no viewer's: 'assuming the bus had stopped' stays a premise
    assert_refused(parser, ["Assuming the footage is accurate up to where it stops, will the brown sedan hit "
                            "anything after that?"])


def test_british_indirectness_and_a_relative_clause_s_that_s():
    parser = QuestionParser.load()
    suppose, right, mind, grateful, wondering, happen, plane = parser.parse_batch([
        "I don't suppose the blue city bus was going terribly fast at the start, was it?",
        "Am I right in supposing the brown station wagon was only going slowly when it ran into the red bicycle?",
        "Which way is the brown chopper heading at the start, if you don't mind my asking?",
        "I'd be ever so grateful to know in what direction the bendy bus is travelling in the opening moments.",
        "One can't help wondering in which direction the scooter was going when it clipped the grey pickup.",
        "Does the yellow bicycle happen to bump into the brown bus at some stage?",
        "What colour is the plane that's hovering in the air at the start?"])
    # ('I don't suppose' was read as a negation, the courtesy after the question as one)
    assert suppose == ["Objects", "filter_attributes[blue]", "filter_attributes[regular_bus]", "unique", "start",
                       "is_moving_velocity[fast]"]
    assert right[-1] == "is_moving_velocity[slow]" and mind[-2:] == ["start", "query_moving_direction"]
    assert grateful[-2:] == ["start", "query_moving_direction"] and wondering[-1] == "query_moving_direction"
    assert happen[0] == "Events" and plane == ["Objects", "start", "filter_floating", "unique",
                                               "query_attributes[color]"]
    # which was hit first asks one of two in turn; what a vehicle hits first is its first partner
    assert_refused(parser, {"Which of the two, the bus or the motorbike, was hit first?": "in turn"})
    first, = parser.parse_batch(["What colour is the vehicle the bus hits first?"])
    assert first[-3:] == ["get_all_col_partners", "unique", "query_attributes[color]"]


def test_the_video_said_to_stop_makes_a_present_collision_one_after_the_cut():
    parser = QuestionParser.load()
    cut, bit, paused = parser.parse_batch([
        "The clip's been cut short. Is the fighter jet headed for a crash with the blue bus?",
        "We only get the first bit of the video. Does the green motorbike bump into anything later?",
        "When the paused video starts up again, does the yellow one make contact with anything?"])
    # (each was read within the video)
    assert cut[:3] == ["futureEvents", "Objects", "filter_attributes[fighter]"] and bit[0] == paused[0] == \
        "futureEvents"
    assert_refused(parser, {"Would the blue sedan have hit the truck if both of them had been standing still?":
                            "several vehicles"})


def test_a_comparison_in_the_passive_or_as_a_contest():
    parser = QuestionParser.load()
    outpaced, beaten, behind, beat, trailing = parser.parse_batch([
        "Is the bus outpaced by the car at the start?",
        "Is the red motorbike beaten for speed by the sedan at the start?",
        "Is the brown tandem bike left behind by the red car at the moment of impact?",
        "Does the cyan chopper beat the green pickup for speed at the very beginning?",
        "At the start, is the pickup trailing the biplane for speed?"])
    # the one outdone is the slower; the one asked about stays first (each was refused)
    assert outpaced == ["Objects", "filter_attributes[bus]", "unique", "Objects", "filter_attributes[car]", "unique",
                        "start", "slower_velocity"]
    assert beaten[-1] == behind[-1] == trailing[-1] == "slower_velocity" and beat[-1] == "faster_velocity"
    assert behind[1:3] == ["filter_attributes[brown]", "filter_attributes[tandem_bike]"]


def test_a_question_word_left_where_the_answer_goes():
    parser = QuestionParser.load()
    fast, partner, speed, up = parser.parse_batch([
        "The red car is moving how fast at the start?",
        "The blue sedan collided with a vehicle of what colour?",
        "At the beginning, is the mountain bike putting on speed?",
        "How quickly is the cyan scooter moving when it first turns up in the video?"])
    assert fast[-2:] == ["start", "query_moving_velocity"] and partner[-1] == "query_attributes[color]"
    assert speed[-1] == "is_accelerating" and up[-2:] == ["come_in_frame", "query_moving_velocity"]
    # a request to describe a property, said first, asks it; 'would that describe the pace' stays a yes or no
    describe, slow = parser.parse_batch(["Describe the speed of the green school bus in the first few frames?",
                                         "Slow - would that describe the pace of the cyan SUV in the first moments?"])
    assert describe[-1] == "query_moving_velocity" and slow[-1] == "is_moving_velocity[slow]"
    # asked 'by what', a reading of yes or no is none ('... gets hit afterwards by what?' was read as a pair's)
    assert_refused(parser, {"The bus that the sedan hit gets hit afterwards by what?": "'what'"})


def test_a_video_paused_or_cut_said_as_a_premise_and_a_collision_near_in_time():
    parser = QuestionParser.load()
    assuming, suppose, were, coming, about, rest = parser.parse_batch([
        "Assuming the footage stops partway through, will the brown pickup and the gray bus collide afterwards?",
        "Suppose the video is cut off midway; in that case, are the green sedan and the purple motorbike going to "
        "hit each other later?",
        "If the clip were paused partway through, would the blue station wagon go on to collide with anything?",
        "Is a crash coming for the minivan?",
        "Is the grey SUV about to crash into the purple bicycle?",
        "In the rest of the video, do the cyan double-decker and the brown estate car collide?"])
    # (refused as a premise or the video imagined otherwise; the last three read within the video)
    assert {assuming[0], suppose[0], were[0], coming[0], about[0], rest[0]} == {"futureEvents"}
    assert suppose[1:4] == ["Objects", "filter_attributes[green]", "filter_attributes[sedan]"]
    # a video imagined longer, or stopped in the past perfect, is still no question here
    assert_refused(parser, {"Would the red sedan have hit the blue bus if the video were longer?": "video itself",
                            "If the clip had been stopped halfway, would the bus hit the car afterwards?":
                                "video itself"})


def test_what_a_vehicle_will_do_its_make_and_a_place_are_refused():
    parser = QuestionParser.load()
    assert_refused(parser, {"Will the purple chopper speed up?": "will do",
                            "Is the purple chopper about to speed up?": "will do",
                            "The brown motorbike hits another vehicle. What make is that other vehicle?": "'make'",
                            "When the blue bus hit the car, was it faster than the yellow pickup near it?": "'near'"})
    shade, shae, anyone, fixing, bump = parser.parse_batch([
        "Which shade is the thing the grey SUV crashes into?",
        "At the very beginning, what shae is the static one?",
        "Does the cyan chopper touch anyone during the video?",
        "What direction was that tandem bike fixin' to go at the very start?",
        "Does the bus make contact with the car?"])
    # 'shade' is a colour, but a slip one letter from it and from 'shape' is still 'shape'; what is hit is a vehicle
    assert shade[-1] == "query_attributes[color]" and shae[-1] == "query_attributes[shape]"
    assert anyone[-2:] == ["filter_collision", "exist"] and fixing[-1] == "query_moving_direction"
    assert bump[0] == "Events" and bump[-1] == "exist"


def test_a_viewers_words_around_the_question():
    parser = QuestionParser.load()
    given, nudged = parser.parse_batch([
        "Given what we see up until the clip is stopped, would you predict that the blue one will bump into something "
        "later?",
        "When the brown chopper nudged the blue city bus, was the chopper moving slower than the bus?"])
    assert given[0] == "futureEvents" and nudged[-1] == "slower_velocity"
    # 'all over the place' is no video's end ('over' read it after the video)
    parse, = parser.analyse_batch(["The brown one seemed to be all over the place, did it ever collide with anything?"])
    assert parse.program is None or parse.program[0] == "Events"


def test_a_motoring_presenter_s_and_an_airfield_s_and_a_biker_s_words():
    parser = QuestionParser.load()
    lights, carrying, harder, shunt, together, paint, deck, blocks = parser.parse_batch([
        "Right as the lights go green, what pace is the red sedan carrying: parked up, crawling, or flat out?",
        "What sort of speed is the cruiser carrying at the moment it makes contact with the red bus?",
        "When the chopper and the green car make contact, is the chopper the one going harder?",
        "Does the purple SUV get into a shunt with anybody over the whole clip?",
        "Is there ever a coming-together between the green scooter and the grey one?",
        "When the green pickup trades paint with the grey estate, how much pace has it got on: stationary, slow, or "
        "quick?",
        "At the start, is the cyan plane hovering rather than sat on the deck?",
        "Had the cyan city bus come out of the blocks flat out, would it have hit the yellow estate?"])
    assert lights[-2:] == ["start", "query_moving_velocity"] and carrying[-2:] == ["get_frame", "query_moving_velocity"]
    assert harder[-1] == "faster_velocity" and "get_frame" in harder
    assert shunt[:2] == ["Events", "Objects"] and shunt[-1] == "exist" and together[-1] == "exist"
    assert paint[-1] == "query_moving_velocity" and "filter_collision" in paint
    assert deck[-1] == "is_floating" and "Counterfactual_moving_fast" in blocks
    taxi, traffic, doored, crawl = parser.parse_batch([
        "Suppose the yellow SUV had started out at a slow taxi: would it have collided with the blue airliner?",
        "What colour was the traffic the gray station wagon collided with?",
        "Was the red pushbike flat out fast when it got doored by the grey cage?",
        "Suppose the yellow double-decker had set off at a crawl: would it have clobbered the red one?"])
    assert "Counterfactual_moving_slow" in taxi and "Counterfactual_moving_slow" in crawl
    assert traffic[-1] == "query_attributes[color]" and "filter_attributes[car]" in doored
    # 'more than one' counts (it was read as whether the cruiser hits anything)
    assert_refused(parser, {"Does the yellow cruiser get into contact with more than one other vehicle during the "
                            "recording?": "more than one"})


def test_a_rambling_viewer_s_context_and_a_contact_in_the_passive():
    parser = QuestionParser.load()
    turned, its, kept, feed, passive = parser.parse_batch([
        # the vehicle a sentence turns to after 'but' is what 'it' means (it was read as the double-decker)
        "I was mostly keeping an eye on the red double-decker, but then this grey fighter jet pops in from the edge. "
        "How fast is it moving when it first comes into view?",
        # 'which vehicle has its engine on': 'its' is the vehicle asked for, not one of the context's
        "At first I assumed everything was cruising. Then I rewatched it on my laptop and it looked different. Which "
        "type of vehicle has its engine on and is accelerating at the start?",
        # once the context says the video stops, 'if it kept going' is the video (it was read as the red fighter)
        "The video cuts off partway, and I saw a red fighter and a cyan sedan before it stopped. If it kept going, "
        "would the green car and the purple bicycle collide?",
        "The feed freezes here: will the cyan estate and the red bicycle have a coming-together after this?",
        # the contact's maker named last is the counterfactual's vehicle (it was read as the bus)
        "Determine whether contact with the green bus would have been made by the scooter had rapid motion been "
        "exhibited by it from the beginning."])
    assert turned[1:3] == ["filter_attributes[gray]", "filter_attributes[fighter]"]
    assert its == ["Objects", "start", "filter_accelerating", "unique", "query_attributes[shape]"]
    assert kept[0] == "futureEvents" and "filter_attributes[fighter]" not in kept and feed[0] == "futureEvents"
    assert passive[:3] == ["Objects", "filter_attributes[scooter]", "unique"] and "Counterfactual_moving_fast" in passive
    # a counterfactual of speeding up needs speeding up said ('absence of any movement' was read so)
    parse, = parser.analyse_batch(["In the hypothetical absence of any movement on the part of the aeroplane from the "
                                   "start, would contact with the bicycle have resulted?"])
    assert parse.program is None or "Counterfactual_accelerating" not in parse.program
    # ... where a slip of one ('ganing') says it, it is read
    slipped, = parser.parse_batch(["If the cyan vehicle had been ganing speed from the start, would it bump into the "
                                   "red car?"])
    assert "Counterfactual_accelerating" in slipped


def test_a_colour_after_its_vehicle_spanish_between_english_words_and_a_course():
    parser = QuestionParser.load()
    than, collide, course, hanging = parser.parse_batch([
        "At the start, the green chopper is more fast than the car red?",
        "The video is cut in the middle. After, the red school bus and the bicycle green are going to chocar?",
        "What course was the scooter on when it struck the green pickup?",
        "At the outset, is the fighter jet hanging in the air without dropping?"])
    assert than[-1] == "faster_velocity" and "filter_attributes[red]" in than
    assert collide[0] == "futureEvents" and collide[-5:-3] == ["filter_attributes[green]", "filter_attributes[bicycle]"]
    # (a course was read as a speed; what does not fall was read as the fall asked)
    assert course[-1] == "query_moving_direction" and hanging[-1] == "is_floating"
    # a colour after its vehicle, asked with a copula, asks the colour: no family's
    assert_refused(parser, ["Is the bus red?"])


def test_a_machine_translation_s_words_and_a_remembered_question():
    parser = QuestionParser.load()
    topic, remember, case = parser.analyse_batch([
        "Blue SUV as for, in the beginning it is stopped state, is it right?",
        "Do you remember what colour the one moving slowly at the beginning was?",
        "In case brown scooter start time was slow speed, brown scooter and blue SUV collision occur?"])
    assert topic.program[-1] == "is_static"
    assert remember.program == ["Objects", "start", "filter_moving_velocity[slow]", "unique", "query_attributes[color]"]
    # 'in case' is a condition (it was read as the scooter's speed at the collision)
    assert case.program is None or "Counterfactual_moving_slow" in case.program
    moment, form = parser.analyse_batch([
        # a clause between commas that names the other vehicle and a collision is the question's time, no aside
        "The brown station wagon, with red scooter bumping moment, is slowly moving one?",
        # 'yes or no' asks yes or no (it was read as which speed)
        "Yellow color chopper motorcycle, the start time, fast running is yes or no?"])
    assert moment.program is None or "get_frame" in moment.program
    assert form.program is None or form.program[-1] == "is_moving_velocity[fast]"


def test_a_condition_in_the_simple_past_or_named_as_a_state_or_a_start():
    parser = QuestionParser.load()
    stayed, never, hovering, start, halts = parser.parse_batch([
        "If the green wagon stayed still, would it hit the brown bus?",
        "Would the cruiser hit the blue sedan if it never moved?",
        "Would a hovering airliner have hit the red road bike?",
        "Would a fast start make the scooter crash into the green car?",
        "Given that the video halts partway, will the grey pickup and the purple school bus collide thereafter?"])
    assert "Counterfactual_static" in stayed and "Counterfactual_static" in never
    assert "Counterfactual_floating" in hovering and hovering[1] == "filter_attributes[airliner]"
    assert "Counterfactual_moving_fast" in start and start[1] == "filter_attributes[scooter]"
    assert halts[0] == "futureEvents"
    # a video's stop said in a condition stays the predictive questions' premise, not a condition on a vehicle
    paused, = parser.parse_batch(["If the clip were paused here, would the bus and the car collide?"])
    assert paused[0] == "futureEvents"
    assert_refused(parser, {"Who collides with the cyan minivan after the yellow bus does?": "order"})


def test_a_collision_in_the_passive_is_the_striker_s():
    parser = QuestionParser.load()
    speed, fast, ever, caused, imagined = parser.parse_batch([
        "By the time the red car is hit by the purple motorbike, at what speed is the motorbike travelling?",
        "Is the brown bus run into by the cyan SUV while the SUV is moving fast?",
        "Is the blue private jet ever hit by the red SUV?",
        "Would a collision with the blue pickup have been caused by the school bus if it had been started fast?",
        "Would the yellow airliner have been collided with by the gray one, had the gray one been held stationary from "
        "the beginning?"])
    # each was asked of, or imagined of, the vehicle struck
    assert speed[:3] == ["Objects", "filter_attributes[purple]", "filter_attributes[motorbike]"]
    assert speed[-1] == "query_moving_velocity" and fast[1:3] == ["filter_attributes[cyan]", "filter_attributes[suv]"]
    # (whether two collide asks of both: said in the passive, its order stays as said)
    assert ever[:4] == ["Events", "Objects", "filter_attributes[blue]", "filter_attributes[jet]"] and ever[-1] == "exist"
    assert caused[1] == "filter_attributes[school_bus]" and "Counterfactual_moving_fast" in caused
    assert imagined[1] == "filter_attributes[gray]" and "Counterfactual_static" in imagined
    # 'am I wrong that ...' is answered the other way round from what it states: refused, not read as 'is it true'
    assert_refused(parser, ["Am I wrong that the yellow one was going faster than the blue double-decker at the "
                            "moment they crashed?",
                            "The yellow bus and the gray car were the first pair to collide, weren't they?"])
    found, = parser.parse_batch(["Find out if the brown SUV bumps into anything during the video."])
    assert found[-1] == "exist" and "filter_attributes[suv]" in found


def test_a_heading_a_fronted_whether_and_the_following_offered():
    parser = QuestionParser.load()
    heading, on_what, fronted, following = parser.parse_batch([
        "What heading is the cyan SUV on when the tape begins?",
        "On what heading was the bus when it hit the red car?",
        "Whether the blue city bike is accelerating at the beginning is what I want to find out; is it?",
        "Which of the following is moving fast when the video begins: a car, a bus, a motorbike, a bicycle, or an "
        "aeroplane?"])
    # a heading asked as a noun is the direction it moves ('on' was no verb the grammar knows)
    assert heading[-2:] == ["start", "query_moving_direction"] and "filter_attributes[suv]" in heading
    assert on_what[-1] == "query_moving_direction" and "get_frame" in on_what
    # the clause said before its request asks what 'is it?' alone could not (it was read without 'accelerating')
    assert fronted[-1] == "is_accelerating" and "filter_attributes[utility_bike]" in fronted
    # the kinds offered ask the kind
    assert following == ["Objects", "start", "filter_moving_velocity[fast]", "unique", "query_attributes[shape]"]


def test_a_remark_after_the_question_and_a_voice_assistant_s_homophone():
    parser = QuestionParser.load()
    lost, partner, imagined, steady, corrected = parser.parse_batch([
        "At the start, what colour is the vehicle that's moving slowly? There's a lot going on so I lost track.",
        "What kind of vehicle did the blue biplane hit? It was pretty low to the ground.",
        "say the city bus was parked the whole time wood it still crash into the brown thing",
        "Suppose the bicycle had been steadily gaining pace from the opening moment, would it hit the yellow bus?",
        "Is the car fast at the start? I mean the red one."])
    # a remark on the viewer or the scene says nothing of what is asked
    assert lost == ["Objects", "start", "filter_moving_velocity[slow]", "unique", "query_attributes[color]"]
    assert partner[-1] == "query_attributes[shape]" and "filter_attributes[biplane]" in partner
    # 'wood it' is 'would it': the condition's counterfactual, not whether the bus was static at the collision
    assert "Counterfactual_static" in imagined and imagined[-1] == "exist"
    assert "Counterfactual_accelerating" in steady
    # a sentence that names the vehicle meant is no remark: it corrects the question
    assert corrected[1:3] == ["filter_attributes[red]", "filter_attributes[car]"]
    # a sentence that says what is asked is no remark, nor is a speed that stays the same speeding up
    assert_refused(parser, ["Is the red car fast at the start? I'm asking about when it hits the bus.",
                            "Does the red car keep a steady speed at the start?"])


def test_a_translation_s_colour_after_its_vehicle_without_an_article_and_a_terse_note_s_times():
    parser = QuestionParser.load()
    pair, airliner, partner, terse, starting, opposed = parser.parse_batch([
        "Minivan yellow and sedan cyan, they hit each other or not?",
        "At the moment the plane airliner grey crash into the fighter jet red, the airliner is going fast or not?",
        "Scooter brown, at the time it bump the car cyan, it move toward which side?",
        "Cyan sedan static from start: hits purple bus?",
        "Red sedan's starting speed?",
        "Is the green motorbike moving slowly at the start, as opposed to standing still or going fast?"])
    # a colour after its vehicle with no article names it, as before it; a category before a sub-type is the sub-type
    assert pair[:4] == ["Events", "Objects", "filter_attributes[yellow]", "filter_attributes[minivan]"]
    assert "filter_attributes[cyan]" in pair and pair[-1] == "exist"
    assert airliner[1:3] == ["filter_attributes[gray]", "filter_attributes[airliner]"]
    assert "filter_attributes[fighter]" in airliner and airliner[-1] == "is_moving_velocity[fast]"
    assert partner[1:3] == ["filter_attributes[brown]", "filter_attributes[scooter]"] and "filter_attributes[cyan]" in \
        partner and partner[-1] == "query_moving_direction"
    # 'from start' is the condition's 'from the start'; a starting speed is the speed at the start
    assert "Counterfactual_static" in terse and terse[-1] == "exist"
    assert starting[-2:] == ["start", "query_moving_velocity"]
    # the speeds a yes-or-no question is asked against say what 'yes' means: not which speed is asked
    assert opposed[-1] == "is_moving_velocity[slow]"
    # a speed said of the start is not the speed at a collision; a colour after a copula is asked
    assert_refused(parser, ["Green pickup starting slow: hits red motorbike?", "Is bus red at the start?"])


def test_a_learner_s_statement_asked_a_note_s_pair_and_a_preamble_that_says_the_end():
    parser = QuestionParser.load()
    offered, pair, ahead, slower, less = parser.parse_batch([
        "The school bus is moving fast or slow or not moving when the video start?",
        "suppose bus never moved from t0: bus/motorbike collide?",
        "Looking ahead past the end of the footage shown, does the cyan city bus collide with something?",
        "The private jet was slow than the gray bus when they bumped?",
        "Is the red chopper going less fast than the green airliner when the two collide?"])
    # speeds offered in a statement asked ask which one (it was read as whether it is fast)
    assert offered[-2:] == ["start", "query_moving_velocity"]
    assert "Counterfactual_static" in pair and "filter_attributes[motorbike]" in pair
    # the preamble said when: after the video (it was dropped as framing, and the question read within the video)
    assert ahead[0] == "futureEvents"
    assert slower[-1] == "slower_velocity" and less[-1] == "slower_velocity"
    # a state said straight after 'if' imagines it: not read as the speed at the collision; a slash pair with more
    # asked than whether they collide stays unread
    assert_refused(parser, ["Tandem bike at beginning if moving slow, with purple car can collide, is it?",
                            "red sedan/blue bus crash - which one hit first?",
                            "3rd vehicle involved in red car / blue bus crash?"])


def test_a_translation_s_coming_to_a_collision_and_courtesy_an_order_of_arrival_and_a_partner_s_partner():
    parser = QuestionParser.load()
    come, possible, clips, engine = parser.parse_batch([
        "Does it come to a collision between the green sedan and the purple school bus?",
        "Would it be possible to know whether the dirt bike crashes into something at all?",
        "The minivan clips something; what kind of vehicle is it?",
        "Does the red city bike start off speeding up, engine running?"])
    # 'does it come to' is whether there is one in the video ('come' had read as the future)
    assert come[0] == "Events" and come[-1] == "exist"
    assert possible == ["Events", "Objects", "filter_attributes[dirtbike]", "unique", "filter_collision", "exist"]
    assert clips[-1] == "query_attributes[shape]" and "get_all_col_partners" in clips
    assert engine[-1] == "is_accelerating"
    # an order of arrival ('last' was WordNet's 'lasting', standing) and a partner's partner are no family's
    assert_refused(parser, {"what kind of vehicle comes in last?": "order",
                            "The collision partner vehicle of the collision partner of the green SUV, which kind is "
                            "it?": "another described vehicle"})


def test_translations_from_arabic_and_romance_languages_and_a_tester_s_abbreviation():
    parser = QuestionParser.load()
    arabic, articulated, same, coll = parser.parse_batch([
        "When the SUV the green hit the bus the grey, with what speed was it moving?",
        "How rapid is the bus articulated when it enters in collision with the road bike cyan?",
        "If the sedan red had stayed stopped since the start, would the same collide with the bus yellow?",
        "blue double-decker faster than red pickup at their coll? y/n"])
    # 'the SUV the green' is the green SUV (Arabic's article on the adjective)
    assert arabic[1:3] == ["filter_attributes[green]", "filter_attributes[suv]"] and arabic[-1] == \
        "query_moving_velocity" and "filter_attributes[gray]" in arabic
    # a sub-type's word after its category names the sub-type (it was read as any bus)
    assert articulated[1] == "filter_attributes[articulated_bus]" and "get_frame" in articulated
    assert "Counterfactual_static" in same and same[1:3] == ["filter_attributes[red]", "filter_attributes[sedan]"]
    # 'coll' is a collision (an unknown word, the comparison was read at the start)
    assert "get_frame" in coll and coll[-1] == "faster_velocity"
    assert_refused(parser, ["Is the motorbike yellow more rapid than the scooter in the final of the video?"])


def test_a_translation_s_postpositions_and_hyphens_and_a_height_asked_in_place():
    parser = QuestionParser.load()
    start, hyphen = parser.parse_batch([
        "The red sedan, the start at, how fast it is going it seems — static, slow or fast, is it?",
        "The speeding-up-at-start vehicle, the engine-on one, which colour it has?"])
    # a clause between commas that says a time is no aside (it was dropped, and the speed read at coming into view)
    assert start[-2:] == ["start", "query_moving_velocity"] and "filter_attributes[sedan]" in start
    assert hyphen == ["Objects", "start", "filter_accelerating", "unique", "query_attributes[color]"]
    assert_refused(parser, {"The grey sedan, the video end at, how fast it is moving, is it?": "end",
                            "Is it so that the purple motorbike, the video middle in, faster than the cyan car is?":
                                "middle",
                            "The airplane is floating at which height from the ground?": "height"})


def test_a_state_from_the_start_said_without_if_and_what_a_question_points_back_at():
    parser = QuestionParser.load()
    speed, dirt = parser.parse_batch(["The scooter was going with which speed at the time it hit the car grey?",
                                      "At the start, is the dirt motorbike increasing its speed?"])
    assert speed[-1] == "query_moving_velocity" and "get_frame" in speed   # (it was read as the direction)
    assert dirt == ["Objects", "filter_attributes[dirtbike]", "unique", "start", "is_accelerating"]
    # a condition said without 'if' was read as what happens in the video or after it; a question that points back
    # with 'that' was read with its vehicles turned round; an unknown word after 'the' was let go with its vehicle
    assert_refused(parser, {
        "double decker not moving from beginning will it still collide blue crew sir": "imagines",
        "private jet hover from beginning do it still hit purple bass": "imagines",
        "Faster than the motorbike, at the moment of their collision, is that what the blue bicycle is?": "that what",
        "Collide with the green mountain bike: would the red motorbike do that, had it started out slowly?": "do that"})


def test_paraphrases_of_the_splits_own_questions():
    parser = QuestionParser.load()
    car, slower, later, within, described, colour, moment, colon, heard = parser.parse_batch([
        "When the purple car and the brown truck collide, is the car the faster of the two?",
        "At the moment the yellow regular bus crashes into the cyan regular bus, is the yellow one moving more slowly?",
        "Does the cyan tandem bike hit anything in the rest of the frames?",
        "Within the frames shown, does the purple bicycle collide with anything?",
        "At the moment of its collision with the brown vehicle, would the cyan car be described as static, slow, or "
        "fast?",
        "Considering the object that crashes into the blue fighter jet, what color does that object have?",
        "Is there any moment when the yellow vehicle crashes with the purple biplane?",
        "When it hits the cyan articulated bus, which way is the gray minivan going: front, back, left, right, up or "
        "down?",
        "yellow motor bike and sian by cycle they collide any time"])
    # a shorter mention is the vehicle whose word it echoes (a truck is a car too)
    assert car[1:3] == ["filter_attributes[purple]", "filter_attributes[car]"] and car[-1] == "faster_velocity"
    assert slower[-1] == "slower_velocity" and slower[1] == "filter_attributes[yellow]"
    assert later[0] == "futureEvents" and within[0] == "Events" and within[-1] == "exist"
    assert described[-1] == "query_moving_velocity" and "get_frame" in described
    assert colour[-2:] == ["unique", "query_attributes[color]"] and "get_all_col_partners" in colour
    assert moment[0] == "Events" and moment[-1] == "exist"
    assert colon[-1] == "query_moving_direction" and "filter_attributes[articulated_bus]" in colon
    # a speaker's 'sian' is cyan with no article before it, and 'scoota' a scooter
    assert heard[7:9] == ["filter_attributes[cyan]", "filter_attributes[bicycle]"]
    assert parser.parse_batch(["is the sian scoota fast at the start"])[0][1:3] == [
        "filter_attributes[cyan]", "filter_attributes[scooter]"]
    # a 'would' that imagines stays refused where nothing is described
    assert_refused(parser, {"At the moment of its collision with the brown car, would the cyan car be fast?": "would"})


def test_paraphrases_a_translation_s_contact_a_speed_as_subject_and_a_question_between_commas():
    parser = QuestionParser.load()
    contact, shown, directly, speed, fronted, um, dash = parser.parse_batch([
        "Did it come to a contact between the green biplane and the blue vehicle?",
        "Will the cyan wagon after the shown frames be involved in a collision?",
        "Is the cyan airliner directly at the start standing still?",
        "Is the green airliner's speed at the start fast?",
        "At the start, is the green airliner's speed fast?",
        "um so the one that's going really fast when the video starts what kind of vehicle is that",
        "At the instant of impact with the yellow double-decker bus, which way is the purple bus travelling — forward, "
        "backward, left, right, up, or down?"])
    assert contact[0] == "Events" and contact[-1] == "exist"   # (it was read after the video)
    assert shown[0] == "futureEvents"
    assert directly[-2:] == ["start", "is_static"]
    assert speed == fronted == ["Objects", "filter_attributes[green]", "filter_attributes[airliner]", "unique", "start",
                                "is_moving_velocity[fast]"]
    assert um == ["Objects", "start", "filter_moving_velocity[fast]", "unique", "query_attributes[shape]"]
    assert dash[-1] == "query_moving_direction" and dash[1:3] == ["filter_attributes[purple]", "filter_attributes[bus]"]


def test_paraphrases_a_blank_without_choices_a_vehicle_to_find_and_would_you_happen_to_know():
    parser = QuestionParser.load()
    colour, kind, found, happen, winged = parser.parse_batch([
        "Fill in: In the first frames, the fast-moving vehicle is coloured ____.",
        "Complete: At the start of the video, the vehicle floating in the air is a ____.",
        "Find the vehicle that the biplane hits. What colour is it?",
        "Would you happen to know the shape of the object that is accelerating at the start?",
        "Further on, is the cyan two-winged biplane going to crash into the yellow coach?"])
    assert colour == ["Objects", "start", "filter_moving_velocity[fast]", "unique", "query_attributes[color]"]
    assert kind == ["Objects", "start", "filter_floating", "unique", "query_attributes[shape]"]
    # 'it' is the vehicle found, not the biplane its clause names
    assert found == ["Events", "Objects", "filter_attributes[biplane]", "unique", "get_all_col_partners", "unique",
                     "query_attributes[color]"]
    assert happen == ["Objects", "start", "filter_accelerating", "unique", "query_attributes[shape]"]
    assert winged[0] == "futureEvents" and winged[2:4] == ["filter_attributes[cyan]", "filter_attributes[biplane]"]
    # a blank of a vehicle the statement names itself asks nothing a family asks
    assert_refused(parser, ["Fill in: The red car is coloured ____."])


def test_paraphrases_coming_into_view_said_first_and_a_commentator_s_words():
    parser = QuestionParser.load()
    coming, entering, someone, tangle, outpacing, set_to = parser.parse_batch([
        "Coming into view, is the purple bus at a standstill, slow, or fast?",
        "On entering the scene, is the purple bus static, slow, or fast?",
        "Out of the gate, someone's picking up speed! What colour is that one?",
        "They tangle! At that moment, is the minivan going slower than the blue scooter?",
        "And they're off! Is the purple one out-pacing the green aeroplane out of the gate?",
        "Going forward, is the car set to run into the aeroplane?"])
    # a clause of coming into view said first is the question's time, no digression (it was read at the start)
    assert coming[-2:] == entering[-2:] == ["come_in_frame", "query_moving_velocity"]
    # 'someone' of a vehicle whose colour is then asked
    assert someone == ["Objects", "start", "filter_accelerating", "unique", "query_attributes[color]"]
    assert tangle[-1] == "slower_velocity" and "get_frame" in tangle
    assert outpacing[-2:] == ["start", "faster_velocity"]
    assert set_to[0] == "futureEvents"
    assert_refused(parser, {"Is someone driving the red car at the start?": "person"})


def test_paraphrases_a_vehicle_looked_at_as_it_comes_into_view_and_a_physics_instructor_s_words():
    parser = QuestionParser.load()
    looked, condition, intersect, extrapolated, impact, opens = parser.parse_batch([
        "Look at the green vehicle when it first shows up. Is it still, slow, or fast?",
        "Under the counterfactual initial condition that the brown vehicle had zero initial velocity, would it have "
        "collided with the blue articulated bus?",
        "Under the counterfactual initial condition that the cyan fighter had a slow initial velocity, would its "
        "trajectory still intersect the chopper's in a collision?",
        "In the extrapolated motion after the final frame, do the trajectories of the purple bus and the blue jet "
        "intersect in a collision?",
        "At the instant of impact with the brown truck, is the blue aeroplane's velocity high?",
        "If the motorbike had been zooming along when the clip opens, would it run into the brown jet?"])
    assert looked[-2:] == ["come_in_frame", "query_moving_velocity"]   # (it was read at the start)
    assert "Counterfactual_static" in condition and condition[1] == "filter_attributes[brown]"
    assert "Counterfactual_moving_slow" in intersect
    assert intersect[-4:] == ["filter_attributes[chopper]", "unique", "filter_collision", "exist"]
    assert extrapolated[0] == "futureEvents"
    assert impact[-1] == "is_moving_velocity[fast]" and "get_frame" in impact
    assert "Counterfactual_moving_fast" in opens


def test_paraphrases_a_romance_learner_s_colour_after_the_vehicle_a_negated_counterfactual_and_a_note_s_obj():
    parser = QuestionParser.load()
    truck, initially, goes, movement, wouldnt, obj, speed = parser.parse_batch([
        "If the blue object had started rapid, would be there a collision between the blue object and the truck green?",
        "Which velocity has the motorbike brown initially?",
        "Just at the start, in which direction goes the cruiser cyan?",
        "Supposing that the bus purple was not in movement at the start of the clip, would it have crashed against the "
        "scooter green?",
        "Suppose the red bus had been standing still at the beginning; wouldn't it have hit the green school bus?",
        "If cyan obj fast @ start, collides w/ tandem bike?",
        "Purple double bus @ start: speed?"])
    # a colour after its vehicle, after 'and the', before a time or after a verb put first, is the vehicle's own
    assert truck[-5:-3] == ["filter_attributes[green]", "filter_attributes[truck]"]
    assert initially[1:3] == ["filter_attributes[brown]", "filter_attributes[motorbike]"]
    assert goes[1:3] == ["filter_attributes[cyan]", "filter_attributes[cruiser]"] and goes[-1] == \
        "query_moving_direction"
    assert "Counterfactual_static" in movement and movement[1:3] == ["filter_attributes[purple]",
                                                                    "filter_attributes[bus]"]
    assert "Counterfactual_static" in wouldnt   # (a negated auxiliary after a condition's semicolon asks the same)
    assert "Counterfactual_moving_fast" in obj and obj[1] == "filter_attributes[cyan]"
    assert speed[-2:] == ["start", "query_moving_velocity"]
    # a colour asked of a vehicle stays a colour asked ('is the car red?'), which no family asks
    assert_refused(parser, ["Is the car red?"])


def test_paraphrases_indian_english_a_chinese_learner_s_if_let_and_the_property_asked_before_a_colon():
    parser = QuestionParser.load()
    dashing, whether, kindly, starting, let, colour = parser.parse_batch([
        "What is the speed of the red bus at the time of dashing with the green jet?",
        "At the time of dashing with the wagon, whether the blue bus is moving faster than the wagon?",
        "Kindly tell the colour of the object which is dashing with the motorbike.",
        "Is the red car moving fast in the starting of the video?",
        "If let yellow airliner increase speed from start, it will hit yellow jet or not?",
        "Which colour: the thing that is accelerating at the start?"])
    assert dashing[-1] == "query_moving_velocity" and "get_frame" in dashing
    assert whether[-1] == "faster_velocity" and whether[1:3] == ["filter_attributes[blue]", "filter_attributes[bus]"]
    assert kindly == ["Events", "Objects", "filter_attributes[motorbike]", "unique", "get_all_col_partners", "unique",
                      "query_attributes[color]"]
    assert starting[-2:] == ["start", "is_moving_velocity[fast]"]
    assert "Counterfactual_accelerating" in let
    assert colour == ["Objects", "start", "filter_accelerating", "unique", "query_attributes[color]"]
    # 'its' compared with the vehicle said after 'than' was read as that vehicle: the vehicle after 'than' is the
    # one compared with
    its, = parser.parse_batch(["When yellow bus hit purple articulated bus, its speed lower than purple articulated "
                               "bus or not?"])
    assert its[1:3] == ["filter_attributes[yellow]", "filter_attributes[bus]"] and its[-1] == "slower_velocity"


def test_paraphrases_the_shown_frames_are_the_video_and_a_nigerian_jam():
    parser = QuestionParser.load()
    shown, jam = parser.parse_batch(["Has the brown object been in a crash in the shown frames?",
                                     "Later on, will the red vehicle jam another vehicle?"])
    assert shown == ["Events", "Objects", "filter_attributes[brown]", "unique", "filter_collision", "exist"]
    assert jam == ["futureEvents", "Objects", "filter_attributes[red]", "unique", "filter_collision", "exist"]
    assert_refused(parser, {"Is there a traffic jam at the start?": "arranged"})


def test_paraphrases_a_translation_s_let_and_classifier_and_a_speed_class_said_the_other_way():
    parser = QuestionParser.load()
    let, classifier, colour, topic = parser.parse_batch([
        "If the bicycle gray let be fast from the start, then it crash into the minivan blue or not?",
        "If the vehicle bus green let move quickly from the start of clip, then it collide with the car yellow or not?",
        "What type is the vehicle which strikes the vehicle of brown colour?",
        "The aeroplane purple, does it fly at the time of beginning?"])
    assert "Counterfactual_moving_fast" in let and let[1:3] == ["filter_attributes[gray]", "filter_attributes[bicycle]"]
    assert "Counterfactual_moving_fast" in classifier and classifier[1:3] == ["filter_attributes[green]",
                                                                            "filter_attributes[bus]"]
    # 'of brown colour' names the vehicle (it was read as its colour asked)
    assert colour == ["Events", "Objects", "filter_attributes[brown]", "unique", "get_all_col_partners", "unique",
                      "query_attributes[shape]"]
    assert topic[1:3] == ["filter_attributes[purple]", "filter_attributes[aeroplane]"]
    assert_refused(parser, {"If articulated bus when video begins at low speed had been moving, red double bus still "
                            "would it hit?": "the other",
                            # (read as the colour asked before 'of brown colour' named the vehicle)
                            "The vehicle which strikes the vehicle of brown colour, it is which type?": "read"})
    # a speed class asked as yes or no, in a translation's order, was read as which speed
    assert_refused(parser, {"Blue articulated bus when into tandem bike bumps, slow it was moving?": "asks whether"})


def test_a_vehicle_said_first_then_asked_with_the_question_word_in_place():
    parser = QuestionParser.load()
    way, = parser.parse_batch(["The biplane of blue colour, it is moving which way at the time it collides with the "
                               "truck?"])
    # (turned into 'is the blue biplane moving which way ...', it was refused as yes or no)
    assert way[-1] == "query_moving_direction" and way[1:3] == ["filter_attributes[blue]", "filter_attributes[biplane]"]


def test_paraphrases_a_partner_found_then_asked_of_its_property_and_times_said_of_the_frames():
    parser = QuestionParser.load()
    its, fronted, after, this, later, fall, smaller, doubt, cls = parser.parse_batch([
        "Something runs into the red jet over the course of the clip; what is its colour?",
        "At any point in the video, something crashed into the car; what model is it?",
        "After the visible frames, is the brown dirtbike going to collide with the yellow vehicle?",
        "after this will the cyan road bike hit anything",
        "Will green articulated bus bang into something later or no?",
        "At t = 0, into which speed category does the cyan mountain bike's initial velocity fall?",
        "At t = 0, is the magnitude of the purple school bus's velocity smaller than that of the gray aeroplane?",
        "I couldn't quite tell on my first watch: at the beginning, does the yellow plane go faster than the sedan?",
        "When the brown vehicle collides with the cyan wagon, what is the class of speed of the brown vehicle?"])
    # 'its' is the something found, not the red jet (it was read as the jet's own colour, and refused)
    assert its == ["Events", "Objects", "filter_attributes[red]", "filter_attributes[jet]", "unique",
                   "get_all_col_partners", "unique", "query_attributes[color]"]
    assert fronted[-1] == "query_attributes[shape]" and "get_all_col_partners" in fronted
    assert after[0] == this[0] == later[0] == "futureEvents"
    # a speed that falls into a class is no slowing down, and a speed smaller than another's no size
    assert fall == ["Objects", "filter_attributes[cyan]", "filter_attributes[mountain_bike]", "unique", "start",
                    "query_moving_velocity"]
    assert smaller[-2:] == ["start", "slower_velocity"] and smaller[1:3] == ["filter_attributes[purple]",
                                                                            "filter_attributes[school_bus]"]
    assert doubt[-2:] == ["start", "faster_velocity"]
    assert cls[-2:] == ["get_frame", "query_moving_velocity"]
    # ... while a vehicle's own size, and a speed that falls, stay refused
    assert_refused(parser, {"Is the red car smaller than the bus?": "size",
                            "Does the red car's speed fall at the start?": "slows down"})


def test_two_colours_sharing_a_plural_noun_are_two_vehicles_and_a_collision_said_as_an_absolute_clause():
    parser = QuestionParser.load()
    shared, absolute = parser.parse_batch([
        "Do the green and blue articulated buses collide?",
        "Collision with the green car happening, the gray bicycle into which direction is it then heading?"])
    # (read as 'the green' one, of any kind, and the blue articulated bus)
    assert shared == ["Events", "Objects", "filter_attributes[green]", "filter_attributes[articulated_bus]", "unique",
                      "filter_collision", "Objects", "filter_attributes[blue]", "filter_attributes[articulated_bus]",
                      "unique", "filter_collision", "exist"]
    # (read of the green car)
    assert absolute[1:3] == ["filter_attributes[gray]", "filter_attributes[bicycle]"]
    assert absolute[-1] == "query_moving_direction"


def test_a_speech_recogniser_s_initialism_and_list_without_commas_and_a_speed_denied():
    parser = QuestionParser.load()
    spelt, listed, off, run_on = parser.parse_batch([
        "was the s u v going slow when it hits the bicycle",
        "when the red scooter comes into view is it not moving slow or fast",
        "What type of vehicle is the one whose engine is running at the off?",
        "can you tell me when the cyan jet and the articulated bus collide is the cyan jet going slower than the "
        "articulated bus"])
    assert spelt[1] == "filter_attributes[suv]" and spelt[-1] == "is_moving_velocity[slow]"
    assert listed[-2:] == ["come_in_frame", "query_moving_velocity"]
    assert off == ["Objects", "start", "filter_accelerating", "unique", "query_attributes[shape]"]
    assert run_on[-1] == "slower_velocity" and run_on[1:3] == ["filter_attributes[cyan]", "filter_attributes[jet]"]
    # motion denied is rest, a speed denied no question's (it was read as the speed asked)
    assert_refused(parser, {"Is the red car not moving fast at the start?": "negated",
                            "Was the bus not moving slowly when it hit the car?": "negated"})
    rest, = parser.parse_batch(["Is the red car not moving at the start?"])
    assert rest[-1] == "is_static"


def test_words_that_turn_the_predicate_round_are_refused_not_read_as_it():
    parser = QuestionParser.load()
    # each was read as the predicate after the reversing words (static, fast, faster, the collision)
    assert_refused(parser, {"Is the red car anything but static at the start?": "anything but",
                            "Is it false that the red car is fast at the start?": "false that",
                            "Is the red car no faster than the blue bus at the start?": "no faster",
                            "Would it be wrong to say that the red car is fast at the start?": "wrong to say",
                            "Do you doubt that the red car is accelerating at the start?": "doubt that",
                            "Is the red car's engine not running at the start?": "negated",
                            "Does the red car go slower than the blue bus, or faster, at the start?": "slower or faster",
                            # ... and a collision prevented, escaped or not there (each read as the collision)
                            "Would the crash between the red car and the blue bus have been prevented if the car had "
                            "been static?": "prevented",
                            "Does the red car survive the video without a collision?": "without a collision",
                            "Is there no collision between the red car and the blue bus?": "is there no collision"})
    tagged, = parser.parse_batch(["Is the red car moving fast, or is it not?"])
    assert tagged[-1] == "is_moving_velocity[fast]"


def test_a_caller_s_remark_after_the_question_and_a_motion_said_again_are_read_away():
    parser = QuestionParser.load()
    remark, hang_up, meant, there, kicks = parser.parse_batch([
        "Does the purple city bus crash into the green thing, I wanna get y'all's take on it?",
        "What color is the one that's up in the air at the very beginning, I'll hang up and listen.",
        "When that green SUV crashes with the red chopper, is the SUV hauling, I mean going fast, right at that "
        "moment?",
        "Now how quick is the red sedan moving right there at first in the video, that's my question.",
        "Okay so I gotta ask, right when it kicks off, is the green school bus going faster than the green city bus?"])
    assert remark[-1] == "exist" and remark[-4] == "filter_attributes[green]"
    assert hang_up == ["Objects", "start", "filter_floating", "unique", "query_attributes[color]"]
    assert meant[-2:] == ["get_frame", "is_moving_velocity[fast]"]   # (read as a speed class asked as which)
    assert there[-2:] == ["start", "query_moving_velocity"]         # ('right' read as a direction)
    assert kicks[-2:] == ["start", "faster_velocity"]               # (read at a collision)
    # a remark that says what is asked stays: its speeds, its vehicle
    restated, = parser.parse_batch(["Is the SUV going slow, I mean fast, at the start?"])
    assert restated[-1] == "is_moving_velocity[fast]"


def test_a_note_s_comparison_counterfactual_label_and_time_after_the_video():
    parser = QuestionParser.load()
    compared, label, post, appearance, premise = parser.parse_batch([
        "@ start red sedan vel < red school bus vel? y/n",
        "counterfactual - cyan fighter starts slow -> hits bicycle?",
        "post-video: purple bus collides w/ blue jet?",
        "As soon as its appearance occurs, is the red tandem bike stationary, slow or fast?",
        "Assuming school bus was standing still in opening frames itself, it would run into green minivan?"])
    assert compared[-2:] == ["start", "slower_velocity"] and compared[2] == "filter_attributes[sedan]"
    assert "Counterfactual_moving_slow" in label and label[-1] == "exist"
    assert post[0] == "futureEvents"                                 # (read within the video)
    assert appearance[-2:] == ["come_in_frame", "query_moving_velocity"]   # (its clause dropped: the start)
    assert "Counterfactual_static" in premise
    assert_refused(parser, {"Given that the bus is parked, does the sedan hit it?": "premise"})


def test_a_vehicle_told_apart_only_as_another_of_its_kind_two_times_or_motion_by_indefinite_are_refused():
    parser = QuestionParser.load()
    # each was read as a question it does not ask: any collision, a collision's time alone, a direction
    assert_refused(parser, {"Does the red bus collide with another bus?": "another of its kind",
                            "Does the red car hit another red object?": "another of its kind",
                            "Does the red car hit a moving object?": "by its motion",
                            "Is the red car moving fast at the start or when it hits the bus?": "two times",
                            "Which direction is the red car not moving at the start?": "negated"})
    other, offered = parser.parse_batch(["Does the red car collide with another bus?",
                                         "When the motorbike comes into view, is it not moving, slow or fast?"])
    assert other[-4] == "filter_attributes[bus]" and other[-1] == "exist"
    assert offered[-2:] == ["come_in_frame", "query_moving_velocity"]


def test_a_letter_s_courtesies_old_names_and_a_scenario_that_sets_the_scene():
    parser = QuestionParser.load()
    grateful, trouble, ordinary, motor_car, consequence, scenario, labelled = parser.parse_batch([
        "I should be most grateful to learn whether the yellow biplane was aloft in the opening moments of the "
        "picture.",
        "Might I trouble you for the kind of thing that is floating in the air at the start of the film?",
        "I should very much like to know whether the mountain bicycle and the purple omnibus (the ordinary sort) ran "
        "into one another in the picture.",
        "May I ask whether the yellow SUV motor car is to be involved in a crash later on, beyond the end of the film?",
        "Supposing the grey saloon car had been standing still at first, I should be grateful to know whether it "
        "would have struck the bicycle.",
        "Scenario: blue articulated bus hits the tandem bike. What is the bus's speed at impact: static, slow or fast?",
        "Scenario: the red object is stationary when the video begins (counterfactual). Would it have collided with "
        "the purple articulated bus?"])
    assert grateful[-2:] == ["start", "is_floating"]
    assert trouble == ["Objects", "start", "filter_floating", "unique", "query_attributes[shape]"]
    assert "filter_attributes[regular_bus]" in ordinary and ordinary[-1] == "exist"
    assert motor_car[:4] == ["futureEvents", "Objects", "filter_attributes[yellow]", "filter_attributes[suv]"]
    assert "Counterfactual_static" in consequence and consequence[-1] == "exist"
    # (a scene set by a collision is no condition: it was read as one, and refused)
    assert scenario[-3:] == ["unique", "get_frame", "query_moving_velocity"]
    assert "Counterfactual_static" in labelled
    assert_refused(parser, {"Counterfactual: the red car hits the bus. Is it fast then?": "imagines"})


def test_a_partner_in_turn_a_collision_with_one_alone_and_a_still_that_goes_on_are_refused():
    parser = QuestionParser.load()
    # read as the first partner, whether it hits the bus, and whether it is static
    assert_refused(parser, {"What colour is the vehicle that hits the red car last?": "in turn",
                            "Does the red car hit only the bus?": "nothing else",
                            "Is the red car still fast when it hits the bus?": "asks a speed",
                            # ... as standing still, and as after the video
                            "If the red car had kept moving, would it have hit the bus?": "moving",
                            "Would the red car have hit the bus anyway?": "would ... have"})
    rest, kept, later = parser.parse_batch(["Is the red car still at the start?",
                                            "If the red car had kept still, would it have hit the bus?",
                                            "Had the video continued, would the red car have hit the bus?"])
    assert rest[-1] == "is_static" and "Counterfactual_static" in kept and later[0] == "futureEvents"


def test_a_comparison_read_turned_round_is_read_with_the_vehicle_after_than_as_the_one_compared_with():
    parser = QuestionParser.load()
    guy, fronted, started = parser.parse_batch([
        "When the gray bus hits the blue SUV, is this guy movin' faster than the SUV?",
        "Driving quicker than the brown bendy bus, is it, the cyan minivan, right at the moment they collide?",
        "When the video starts, quicker than the yellow double-decker it's going, the blue SUV, is it?"])
    # each was read as whether the vehicle after 'than' is the faster
    assert guy[1:3] == ["filter_attributes[gray]", "filter_attributes[bus]"] and guy[-1] == "faster_velocity"
    assert fronted[1:3] == ["filter_attributes[cyan]", "filter_attributes[minivan]"]
    assert started[1:3] == ["filter_attributes[blue]", "filter_attributes[suv]"] and started[-2] == "start"
    it, = parser.parse_batch(["When the red car hits the blue bus, is it faster than the car?"])
    assert it[1:3] == ["filter_attributes[blue]", "filter_attributes[bus]"]


def test_scots_taglish_and_jamaican_words_similes_and_echoed_tags():
    parser = QuestionParser.load()
    scots, taglish, jamaican, simile, tractor, echoed, pressed = parser.parse_batch([
        "If the yellow saloon hadnae been movin at the very start, wid it hae run intae the cyan mountain bike?",
        "At the start po, is yung yellow fighter slower than the cyan scooter?",
        "Di SUV did a go slow when it collide wid di bicycle?",
        "In the opening frames, is the suv still as a sleeping stone, slow as a wandering cloud, or fast as a falling "
        "star?",
        "Suppose the car had been crawlin' along tractor-slow from the start, would it have collided with the yellow "
        "scooter?",
        "The yellow one and the cyan motorbike, do they crash into each other, do they?",
        "This chopper - does it get into a collision, or what?"])
    assert "Counterfactual_static" in scots and scots[-4:-2] == ["filter_attributes[mountain_bike]", "unique"]
    assert taglish[-2:] == ["start", "slower_velocity"] and taglish[2] == "filter_attributes[fighter]"
    # (Jamaican 'wid' is 'with', a Scot's 'would')
    assert jamaican[-2:] == ["get_frame", "is_moving_velocity[slow]"] and "filter_attributes[bicycle]" in jamaican
    assert simile[-2:] == ["start", "query_moving_velocity"]
    assert "Counterfactual_moving_slow" in tractor                  # (a tractor: no vehicle here)
    assert echoed[-1] == "exist" and echoed[2] == "filter_attributes[yellow]"
    assert pressed[-1] == "exist" and pressed[-4] == "filter_attributes[chopper]"
    # a time after a speed is no simile, nor a dash before the choices, nor 'like mad' (fast)
    footage, choices, mad = parser.parse_batch([
        "One vehicle is crawling along slowly as the footage begins. What type of vehicle is that?",
        "At what speed does the yellow bicycle enter the frame for the first time - static, slow or fast?",
        "Say the cyan city bike had started out going like mad, would it have knocked into the yellow sedan?"])
    assert footage[-3:] == ["filter_moving_velocity[slow]", "unique", "query_attributes[shape]"]
    assert choices[-2:] == ["come_in_frame", "query_moving_velocity"]
    assert "Counterfactual_moving_fast" in mad


def test_a_direction_read_where_none_is_said_is_refused():
    parser = QuestionParser.load()
    # read as which way it moves: 'right' there is a time's
    assert_refused(parser, {"What is the motion of the green scooter right at the start?": "no direction"})
    back, state = parser.parse_batch(["Back at the start, which way is the red car moving?",
                                      "In what state of motion, pray, does the green scooter find itself right at the "
                                      "start?"])
    assert back[-1] == "query_moving_direction"
    assert state[-2:] == ["start", "query_moving_velocity"]   # (read as a direction, 'pray' unknown)


def test_a_pit_wall_a_briefing_hong_kong_and_london_words():
    parser = QuestionParser.load()
    flying, lights, post, report, kinetic, hong_kong, motor, engine, butcher = parser.parse_batch([
        "One machine is flying at full pace as the lights go out, what kind of vehicle is it?",
        "Lights out, is the red car moving fast?",
        "Assess whether the red jet impacts another vehicle post-footage.",
        "Report the colour of the vehicle accelerating at H-hour.",
        "Did the blue tandem bike make kinetic contact with the car? Confirm.",
        "Video start ar, the red dirt bike quicker than the cyan aeroplane hai mai?",
        "Which way's the sedan moving when it prangs the brown motor?",
        "Is the red car's motor running at the start?",
        "Have a butcher's at the kick-off - what colour's the thing going proper fast?"])
    # read as floating, within the video, and of any brown vehicle
    assert flying == ["Objects", "start", "filter_moving_velocity[fast]", "unique", "query_attributes[shape]"]
    assert lights[-2:] == ["start", "is_moving_velocity[fast]"]
    assert post[0] == "futureEvents"
    assert report == ["Objects", "start", "filter_accelerating", "unique", "query_attributes[color]"]
    assert kinetic[-1] == "exist" and "filter_attributes[tandem_bike]" in kinetic
    assert hong_kong[-2:] == ["start", "faster_velocity"] and hong_kong[2] == "filter_attributes[dirtbike]"
    assert motor[-7:-4] == ["filter_attributes[brown]", "filter_attributes[car]", "unique"]
    assert engine[-1] == "is_accelerating"                              # (its motor is its engine)
    assert butcher[-3:] == ["filter_moving_velocity[fast]", "unique", "query_attributes[color]"]


def test_a_clause_of_a_collision_is_never_dropped_to_read_at_the_start():
    parser = QuestionParser.load()
    bash, unmarked, assumed = parser.parse_batch([
        "As they bash, is the brown wagon going less fast than the yellow utility bike?",
        "once the red car hits the bus is the bus fast?",
        "Assume the blue road bike static at the start. Would the blue road bike and the wagon make contact?"])
    # read at the start (its clause a digression), of the red car (its clause's subject), after the video
    assert bash[-3:] == ["unique", "get_frame", "slower_velocity"]
    assert unmarked[1] == "filter_attributes[bus]" and unmarked[-1] == "is_moving_velocity[fast]"
    assert "Counterfactual_static" in assumed
    # (once read at the start, then refused; a collision told before the question is its time now)
    assert parser.parse("lol when the blue bicycle smashes into the green airliner is it going fast?")[-3:] == [
        "unique", "get_frame", "is_moving_velocity[fast]"]


def test_a_market_s_words_kenyan_ama_and_newfoundland_s_tag():
    parser = QuestionParser.load()
    outperforming, ama, offered, tag, drifting = parser.parse_batch([
        "Is the cyan school bus outperforming the brown bicycle at the open?",
        "Is the red car fast ama slow at the start?",
        "When the chopper becomes visible, is it stationary, slow ama fast?",
        "Would ya say the sedan is stock still at the start of the video, b'y?",
        "Early on, is the red car drifting along slowly?"])
    assert outperforming[-2:] == ["start", "faster_velocity"] and outperforming[2] == "filter_attributes[school_bus]"
    # 'ama' is 'or' before the choices are read: 'fast ama slow' read as 'fast' when a synonym stood in for it
    assert ama[-1] == "query_moving_velocity" and offered[-2:] == ["come_in_frame", "query_moving_velocity"]
    assert tag[-2:] == ["start", "is_static"]
    assert drifting[-1] == "is_moving_velocity[slow]"                 # (refused as a turn)
    # a stop's 'in' alone is no time after the video ('at any point in the session' was read after it)
    assert_refused(parser, ["Is the gray chopper exposed to a crash at any point in the session?"])


def test_irish_english_s_yer_man_and_a_traffic_report_s_times():
    parser = QuestionParser.load()
    yer_man, socks, budged, off_air, top = parser.parse_batch([
        "As the video starts, is yer man the brown bendy bus going faster than the red yoke?",
        "Ah here, if the gray truck had started off giving it socks, would it have collided with the blue double-decker?",
        "Picture it now: if the green tandem bike hadn't budged an inch right at the start, would it have collided with "
        "the blue utility bike?",
        "Are we expecting the yellow motorbike to smash into the regular bus once we come off air?",
        "Reports coming in on the green regular bus: is it going fast as we hit the top of the hour?"])
    # 'yer man' was a person, 'budged' was read as 'bumped'
    assert yer_man[-2:] == ["start", "faster_velocity"] and yer_man[2] == "filter_attributes[articulated_bus]"
    assert "Counterfactual_moving_fast" in socks
    assert "Counterfactual_static" in budged
    assert off_air[0] == "futureEvents"
    assert top[-2:] == ["start", "is_moving_velocity[fast]"]


def test_northern_english_elisions_and_trinidadian_de_read_as_articles():
    parser = QuestionParser.load()
    assert tokenize("at t' start o' the video, would it 'ave hit the purple 'un?") == [
        "at", "the", "start", "of", "the", "video", ",", "would", "it", "have", "hit", "the", "purple", "one", "?"]
    assert tokenize("de t'ing dat smash into somet'in'") == ["de", "thing", "dat", "smash", "into", "something"]
    yorkshire, trinidad, buss = parser.parse_batch([
        "Is t' red mountain bike gannin' quicker than the red bendy bus at first, our kid?",
        "Right at de start, de red plane going faster than de yellow wagon or not?",
        "De gray school bus going slow just as it buss into de bicycle?"])
    # 't'' was refused as a time named by a symbol, 'de' as an unknown word
    assert yorkshire[-2:] == ["start", "faster_velocity"] and yorkshire[1] == "filter_attributes[red]"
    assert trinidad[-2:] == ["start", "faster_velocity"] and trinidad[2] == "filter_attributes[aeroplane]"
    assert buss[-1] == "is_moving_velocity[slow]" and "filter_attributes[bicycle]" in buss
    # a symbol's t' stays one
    assert_refused(parser, {"At t' > t_c, does the red car hit the bus?": "symbol"})


def test_a_bare_holding_is_refused_and_a_pilot_s_block_in_and_sight_are_read():
    parser = QuestionParser.load()
    # read as standing still, where its writer meant a holding pattern (in the air)
    assert_refused(parser, {"Say the green one had been holding from the start, would it have made contact with the "
                            "blue SUV?": "'holding'", "Did the red car hold on when it hit the bus?": "'holding'"})
    pattern, position, airborne, block_in, sight, hold_on = parser.parse_batch([
        "Is the red plane in a holding pattern at the start?",
        "Suppose the red one had been holding in position right from the beginning: does it still run into the bus?",
        "Confirm the biplane is holding, airborne, at first?",
        "After block-in, do we expect contact between the blue tandem bike and the gray truck?",
        "Blue jet, as soon as it's in sight, say its speed: stationary, slow or fast?",
        "hold on was the purple minivan just sitting there at the start??"])
    assert pattern[-1] == "is_floating" and "Counterfactual_static" in position and airborne[-1] == "is_floating"
    assert block_in[0] == "futureEvents"                               # (read within the video)
    assert sight[-2:] == ["come_in_frame", "query_moving_velocity"]    # (read at the start)
    assert hold_on[-1] == "is_static"


def test_a_heading_s_post_and_a_statement_asked_by_its_tag_are_kept():
    parser = QuestionParser.load()
    los, rollout, check, tagged, scene = parser.parse_batch([
        "Post-LOS projection: does the cyan regular bus smash into the blue wagon?",
        "Post-rollout, does the SUV get into any contact event?",
        "After the video ends: does the red car hit the bus?",
        "At the moment it dashes with the purple car, the blue truck is simply not moving, is it?",
        "By the time the scene ends, has the cyan aeroplane run into something?"])
    # the headings were dropped (read within the video), the statement taken for an aside
    assert los[0] == rollout[0] == check[0] == "futureEvents"
    assert tagged[-1] == "is_static" and tagged[2] == "filter_attributes[truck]"
    assert scene[0] == "Events"                                         # (read after the video)
    assert parser.parse("Per the post-mortem: had the bus stayed parked from the beginning, would the bus and the "
                        "grey car have collided?")[1] == "filter_attributes[bus]"


def test_a_race_caller_a_cook_a_skater_and_spanglish():
    parser = QuestionParser.load()
    gates, standing, simmer, choices, spanglish, knots = parser.parse_batch([
        "Is the blue chopper picking up speed as they come out of the gates?",
        "Had the blue one been left standing at the break, would it have bumped into the purple bicycle?",
        "The one sitting at a simmer from the get-go - what kind of vehicle is that, chefs?",
        "When the bicycle crashes into the car, is it chilling, rolling slow, or shredding?",
        "How fast va la purple minivan when it crashes into the green mountain bike: stationary, slow o fast?",
        "As we weigh anchor, is the yellow car making more knots than the brown truck?"])
    assert gates[-2:] == ["start", "is_accelerating"]
    assert "Counterfactual_static" in standing
    assert simmer[:3] == ["Objects", "start", "filter_moving_velocity[slow]"]   # (read as standing still)
    assert choices[-1] == "query_moving_velocity"                              # (read as whether it is slow)
    assert spanglish[-1] == "query_moving_velocity" and "filter_attributes[minivan]" in spanglish
    assert knots[-2:] == ["start", "faster_velocity"]
    # a place said before 'standing' stays one
    assert_refused(parser, ["Is the car on the left standing still at the start?"])


def test_a_moment_no_rule_reads_is_refused_and_a_dispatcher_a_trader_and_bajan_are_read():
    parser = QuestionParser.load()
    # read at the start: the moment's words were dropped
    assert_refused(parser, {"At the moment of the 20-30, was the utility bike faster than the gray bus?": "a moment",
                            "At the point of entry, how fast is the bus?": "a moment"})
    ten_fifty, call, flat, close, gine = parser.parse_batch([
        "At the 10-50, was the cyan minivan going faster than the brown bendy bus? Advise.",
        "At time of call, is the cyan school bus running faster than the brown bicycle, copy?",
        "If the regular bus had been flat at the open, would it crash into the red one?",
        "Looking past the close, does the green jet end up in a collision, yes or no?",
        "Wha gine happen next, cuh: de purple double-decker gine hit de airliner?"])
    assert ten_fifty[-3:] == ["unique", "get_frame", "faster_velocity"]     # (read at the start)
    assert call[-2:] == ["start", "faster_velocity"]                         # (read at a collision)
    assert "Counterfactual_static" in flat                                   # (read as floating)
    assert close[0] == gine[0] == "futureEvents"                             # (read within the video)
    for fast in ("Is the red car flat out at the start?", "Was the purple one flat chat right at the beginning?"):
        assert parser.parse(fast)[-1] == "is_moving_velocity[fast]", fast
    # 'up in the air' after a preamble's speed word ('gently' read as 'slowly') was read as a speed
    assert_refused(parser, ["Quick check on the monitor - at the start of the tape, is the gray airliner up in the air?"])


def test_an_auctioneer_s_calls_offer_the_answers_and_a_post_heading_no_rule_reads_is_refused():
    parser = QuestionParser.load()
    speed, fast, model, engine = parser.parse_batch([
        "Lot number seven, the aeroplane, right off the block at the beginning of the video: how fast is it moving, "
        "do I hear static, do I hear moving slowly, do I hear moving fast?",
        "Is the brown aeroplane going fast when it bumps into the gray one, do I hear a yes, do I hear a no, going "
        "once, going twice?",
        "What model is the vehicle the purple aeroplane crashed into, do I hear a model, going once, going twice, sold!",
        "Right off the block, is the purple road bike's engine running, gimme a yes or a no, lot twenty-one, going "
        "once, going twice!"])
    assert speed[-2:] == ["start", "query_moving_velocity"]
    assert fast[-3:] == ["unique", "get_frame", "is_moving_velocity[fast]"]
    assert model[-1] == "query_attributes[shape]" and "get_all_col_partners" in model
    assert engine[-2:] == ["start", "is_accelerating"]
    # a lab's 'post-trial' heading is after the video; one no rule reads was read within it
    assert parser.parse("Post-trial, do we expect contact between the yellow mountain bike and the SUV?")[0] == \
        "futureEvents"
    assert_refused(parser, {"Post-haste, do the bus and the car collide?": "post - haste"})


def test_a_moment_said_before_a_premise_heard_and_regional_words():
    parser = QuestionParser.load()
    tense, rumour, premise, true, lying, subject, tandem = parser.parse_batch([
        "The green airliner collides with the yellow bus; in that tense moment, what is the green airliner's motion "
        "state: static, moving slowly or moving fast?",
        "Rumour has it the green bendy bus smashed into something, darling, so what colour is the item it smashes "
        "into?",
        "My sources say one vehicle is getting faster in the first frames, darling; what kind of vehicle is it?",
        "Rumour has it the airliner is creeping along when the video begins; is that true, darling?",
        "Had the cyan scooter been lying perfectly still at first, would it have struck the green one?",
        "Had the red biplane stayed airborne, would it have run into the purple subject?",
        "Suppose that green bicycle-built-for-two had started out slowly, would it have hit the cyan bicycle?"])
    assert tense[-3:] == ["unique", "get_frame", "query_moving_velocity"]       # (read at the start)
    assert rumour[-1] == "query_attributes[color]" and "get_all_col_partners" in rumour   # (read as yes or no)
    assert premise[-3:] == ["filter_accelerating", "unique", "query_attributes[shape]"]
    assert true[-2:] == ["start", "is_moving_velocity[slow]"]
    assert "Counterfactual_static" in lying                                   # ('lying' was read as 'flying')
    assert subject[-4:] == ["filter_attributes[purple]", "unique", "filter_collision", "exist"]   # (a lab's word)
    assert "filter_attributes[tandem_bike]" in tandem                          # (read as any bicycle)
    # a moment said before, that no rule reads, is no start
    assert_refused(parser, {"The bus is parked; in that quiet moment, is the red car fast?": "a moment"})
    # ... but one the first sentence says is
    assert parser.parse("The video starts. The green motorbike is waiting. How fast is it going at that moment: "
                        "static, slow, or fast?")[-2:] == ["start", "query_moving_velocity"]
    small, brummie, track, ah, eer = parser.parse_batch([
        "Da cyan bicycle, at da start it static, moving small-small or moving fast?",
        "If the car hadn't bin movin' at the beginnin', would it've crashed into the brown regular bus, ar or no?",
        "Brown tandem bike crashes into somethin' on the track, what colour is that thing?",
        "The truck ah, does it smash into any other vehicle?",
        "Do the articulated bus and the purple biplane e'er collide with one another?"])
    assert small[-2:] == ["start", "query_moving_velocity"]                    # (read as whether it is fast)
    assert "Counterfactual_static" in brummie
    assert track[-1] == "query_attributes[color]" and "filter_attributes[truck]" not in track
    assert ah[:2] == ["Events", "Objects"] and eer[0] == "Events"


def test_remarks_on_people_or_vehicles_at_large_are_no_correction_and_a_showman_a_coach_and_a_caster_are_read():
    parser = QuestionParser.load()
    tandem, bus, jets, hogs = parser.parse_batch([
        "Is the blue tandem bike picking up speed at the start? Two people on one bike, I ask you.",
        "If the regular bus had been speeding up at the start of the clip, would it still have hit the mountain bike? "
        "Back in my day bus drivers knew better.",
        "Jets bumping into cars, what's the world coming to - when the gray jet hits the car, is it static, slow, or "
        "fast?",
        "Blasted road hogs - is the blue sedan going quicker than the red truck when the two of them collide?"])
    assert "filter_attributes[tandem_bike]" in tandem                          # (read as any bicycle)
    assert "filter_attributes[regular_bus]" in bus                             # (read as any bus)
    assert jets[:3] == ["Objects", "filter_attributes[gray]", "filter_attributes[jet]"]   # (read about the car)
    assert hogs[-1] == "faster_velocity"
    # a correction after the question still corrects, and a remark that names a colour is no remark
    assert parser.parse("Is the sedan fast at the start? The red one, I mean.")[1:3] == [
        "filter_attributes[red]", "filter_attributes[sedan]"]
    eyes, unpack, rotates, softly = parser.parse_batch([
        "Keep your eyes on the blue wagon, friends: at the moment it collides with the cyan regular bus, is it static, "
        "moving slowly or moving fast?",
        "Let's unpack this moment of impact: which direction is the car moving when it collides with the bicycle?",
        "The gray wagon rotates in, how fast is it moving when it first shows up?",
        "Softly now, in the first frames, which model is the stopped one, if you please?"])
    assert eyes[-3:] == ["unique", "get_frame", "query_moving_velocity"]
    assert unpack[-1] == "query_moving_direction" and "get_frame" in unpack
    assert "come_in_frame" in rotates                                          # (refused as a turn)
    assert softly[-3:] == ["filter_static", "unique", "query_attributes[shape]"]


def test_a_call_centre_agent_s_courtesies_and_requests_and_a_butler_s_are_read():
    parser = QuestionParser.load()
    confirm, ask, could, enquire = parser.parse_batch([
        "Thank you for holding; may I confirm whether the yellow truck is zooming along at the start?",
        "Thanks ever so much for holding; may I ask which direction the car is moving in when it collides with the "
        "bicycle?",
        "Thank you for your patience; could you confirm the motion state of the brown mountain bike at the outset?",
        "What model, if I may enquire, is the thing that is in the air at the start of the video?"])
    assert confirm[-2:] == ["start", "is_moving_velocity[fast]"]
    assert ask[-1] == "query_moving_direction" and "get_frame" in ask
    assert could[-2:] == ["start", "query_moving_velocity"]                    # (read as yes or no)
    assert enquire[-3:] == ["filter_floating", "unique", "query_attributes[shape]"]


def test_a_collision_told_before_the_question_is_its_time_and_a_teller_s_and_is_no_question():
    parser = QuestionParser.load()
    heading, faster, struck, aeroplane = parser.parse_batch([
        "The yellow car came crashing into the green motorbike, and then... which direction was the yellow car "
        "heading: left, right, front, back, up or down?",
        "And lo, the green tandem bike and the blue wagon crash together; is the tandem bike going more rapidly than "
        "the wagon?",
        "And then the SUV hit the gray minivan... in what direction was that SUV travelling when it struck?",
        "And when the brown aeroplane shows up at the crossing, is it static, moving slowly or moving fast, sir?"])
    assert heading[-3:] == ["unique", "get_frame", "query_moving_direction"]   # (read at the start)
    assert faster[-3:] == ["unique", "get_frame", "faster_velocity"]          # (read at the start)
    assert struck[-3:] == ["unique", "get_frame", "query_moving_direction"]    # (refused)
    assert aeroplane[-2:] == ["come_in_frame", "query_moving_velocity"]      # (read at the start)
    # a collision of another vehicle leaves the question at the start, and a time of its own stays
    assert parser.parse("The SUV hit the gray minivan. Is the red car moving fast?")[-2:] == [
        "start", "is_moving_velocity[fast]"]
    assert parser.parse("The SUV hit the gray minivan. Was the SUV moving fast at the start?")[-2:] == [
        "start", "is_moving_velocity[fast]"]


def test_a_controller_a_preacher_an_estate_agent_a_teacher_and_a_meditation_guide_are_read():
    parser = QuestionParser.load()
    again, flock, home, anyone = parser.parse_batch([
        "Say again, had the tandem bike been picking up speed from the start, would it have collided with the jet?",
        "Let us consider the red biplane, dear flock: was it flying aloft in the first frames?",
        "Is the minivan's engine running at the beginning, as you'd expect in a well-appointed family home?",
        "Right at the start, can anyone tell me what colour the one that's getting faster is?"])
    assert again[3] == "Counterfactual_accelerating" and again[-1] == "exist"   # (refused as how often)
    assert flock[-2:] == ["start", "is_floating"]
    assert home[-2:] == ["start", "is_accelerating"]
    assert anyone[-1] == "query_attributes[color]"
    breathe, rest, nobody = parser.parse_batch([
        "As the brown truck hits the cyan object, breathe softly and notice: is the truck travelling more slowly "
        "than that cyan object?",
        "At the beginning of the video, let your eyes rest on the vehicle that is stationary; what colour is it?",
        "At the beginning, something was speeding up, nobody knows why... what was the type of that thing?"])
    assert breathe[-1] == "slower_velocity" and "get_frame" in breathe      # (refused: 'softly' a collision's)
    assert rest[-3:] == ["filter_static", "unique", "query_attributes[color]"]
    assert nobody[-1] == "query_attributes[shape]"                           # (refused as asking why)
    # a description after the last comma that names a vehicle or offers answers is no aside
    for said in ("which vehicle hits the bus , a car or a truck ?", "is it fast , a yes or a no ?"):
        assert interjections_dropped(said.split())[0] == said.split()


def test_a_news_anchor_a_regency_lady_a_quest_giver_and_a_grandmother_are_read():
    parser = QuestionParser.load()
    clips, reports, pray, mark = parser.parse_batch([
        "The jet comes in and clips the red scooter; what was the jet's speed on that play: stationary, slow or fast?",
        "Reports are coming in about the yellow minivan: is it involved in a collision?",
        "I dare say something is keeping itself aloft as the video starts; pray, what colour is that object staying in "
        "the air?",
        "Mark well the moment the cyan car and the yellow SUV collide, seeker: is the cyan car going faster than the "
        "yellow SUV?"])
    assert clips[-3:] == ["unique", "get_frame", "query_moving_velocity"]     # (read as it came into view)
    assert reports[:3] == ["Events", "Objects", "filter_attributes[yellow]"] and reports[-1] == "exist"
    assert pray[-3:] == ["filter_floating", "unique", "query_attributes[color]"]
    assert mark[-3:] == ["unique", "get_frame", "faster_velocity"]
    bless, nan, true = parser.parse_batch([
        "Bless them both, at the beginning is the blue biplane going slower than the yellow biplane?",
        "Tell your old nan, pet, what colour is the one that's zooming along fast at the very start of the clip?",
        "Tell me true, Traveller: is the minivan standing still when it bumps into the gray one?"])
    assert bless[-2:] == ["start", "slower_velocity"]
    assert nan[-3:] == ["filter_moving_velocity[fast]", "unique", "query_attributes[color]"]
    assert true[-3:] == ["unique", "get_frame", "is_static"]
    # a report of something ('Reports are coming in of ...') is no premise but the context; 'in the clip' is the video
    assert parser.parse("Reports are coming in of the blue SUV bumping into the brown car; in which direction was the "
                        "blue SUV travelling at that moment?")[-3:] == ["unique", "get_frame", "query_moving_direction"]
    assert parser.parse("Does the bus in the clip hit anything?") == [
        "Events", "Objects", "filter_attributes[bus]", "unique", "filter_collision", "exist"]


def test_a_safari_guide_a_lifeguard_a_submarine_captain_and_a_fitness_influencer_are_read():
    parser = QuestionParser.load()
    magnificent, heads, building, somebody = parser.parse_batch([
        "Look there, a magnificent red double-decker! At the beginning, is it stationary, slow or fast?",
        "Heads up, swimmers: at the beginning, what type is the object that's up in the air?",
        "Real talk squad, if the brown cruiser had been building up speed from the very start, would it bump into the "
        "dirt bike?",
        "Somebody strikes the mountain bike in this scene — tell me, what colour is the one that hits it?"])
    assert magnificent == ["Objects", "filter_attributes[red]", "filter_attributes[double_bus]", "unique", "start",
                           "query_moving_velocity"]
    assert heads[-3:] == ["filter_floating", "unique", "query_attributes[shape]"]   # (refused: 'heads up' a place)
    assert building[4] == "Counterfactual_accelerating"                           # (read as 'frame up speed')
    assert somebody[-3:] == ["get_all_col_partners", "unique", "query_attributes[color]"]   # (refused: a person)
    steady, knots, sonar = parser.parse_batch([
        "Steady as she goes; later in the video, will the purple vehicle strike any other vehicle?",
        "At the time the scooter and the brown articulated bus collide, is the scooter running at fewer knots than the "
        "bus?",
        "Sonar reports something up in the air as the video starts; what colour is that object, over?"])
    assert steady[0] == "futureEvents"                                           # (refused: 'steady' a kept speed)
    assert knots[-3:] == ["unique", "get_frame", "slower_velocity"]
    assert sonar[-3:] == ["filter_floating", "unique", "query_attributes[color]"]


def test_set_off_similes_a_conductor_a_sailor_a_bingo_caller_and_a_scribe_are_read():
    parser = QuestionParser.load()
    stop, scree, climber, drifting = parser.parse_batch([
        "Next stop, the future, folks: will the biplane slam into the green utility bike after the clip ends?",
        "The one creeping along slowly as the video starts, like a tired rope team on the scree: what kind of vehicle "
        "is it?",
        "Does the biplane pick up speed at first, like a lead climber breaking trail toward the summit?",
        "Had the yellow truck been driftin' slow at the beginnin' of the video, would she have crashed into the red "
        "car, matey?"])
    assert stop[0] == "futureEvents"                                         # (refused: 'stop' a halt)
    assert scree[-3:] == ["filter_moving_velocity[slow]", "unique", "query_attributes[shape]"]
    assert climber[-2:] == ["start", "is_accelerating"]                       # (refused: 'toward' a relation)
    assert drifting[4] == "Counterfactual_moving_slow"                        # (refused: 'drifting' a turn)
    vessel, scribe, eyes = parser.parse_batch([
        "What colour be the vessel pickin' up speed at the start of the video, matey?",
        "The thing that travelleth slowly in the first frames: of what model is it, that it may be inked in the ledger?",
        "Eyes down for the brown truck, my lovelies: does it make contact with anything at all in the frames we've "
        "got?"])
    assert vessel[-3:] == ["filter_accelerating", "unique", "query_attributes[color]"]
    assert scribe[-3:] == ["filter_moving_velocity[slow]", "unique", "query_attributes[shape]"]
    assert eyes == ["Events", "Objects", "filter_attributes[brown]", "filter_attributes[truck]", "unique",
                    "filter_collision", "exist"]
    # a simile of a vehicle is no aside
    assert parser.parse("Is the red car fast, like a bus?") is None


def test_a_war_correspondent_a_rodeo_announcer_a_birdwatcher_a_lecturer_and_a_helpdesk_are_read():
    parser = QuestionParser.load()
    front, chute, binoculars, week = parser.parse_batch([
        "Reporting from the front as the green bicycle collides with the gray bendy bus: at that instant, is the "
        "bicycle static, slow or fast?",
        "Right out of the chute at the start of the clip, is the blue one stationary, slow or fast?",
        "How fast is the blue SUV driving when the video starts, by what I can make out through the binoculars?",
        "A counterfactual, as we covered last week: if the articulated bus had started slowly, would it have "
        "collided with the cyan mountain bike?"])
    assert front[-3:] == ["unique", "get_frame", "query_moving_velocity"]     # (refused: 'front' a direction)
    assert chute == ["Objects", "filter_attributes[blue]", "unique", "start", "query_moving_velocity"]
    assert binoculars[-2:] == ["start", "query_moving_velocity"]
    assert week[3] == "Counterfactual_moving_slow"
    turning, drifts, spot, somebody = parser.parse_batch([
        "Turning to the fighter jet: did it crash into anything at any point in the video?",
        "When the blue tandem bike drifts into view, what do the cards reveal: is it static, slow, or fast?",
        "As the clip begins I spot one going fast through my binoculars; what type of vehicle is it?",
        "Somebody tangles with the brown plane: what colour is the one that hits the brown plane?"])
    assert turning == ["Events", "Objects", "filter_attributes[fighter]", "unique", "filter_collision", "exist"]
    assert drifts[-2:] == ["come_in_frame", "query_moving_velocity"]          # (refused: 'drifts' a turn)
    assert spot[-3:] == ["filter_moving_velocity[fast]", "unique", "query_attributes[shape]"]   # ('spot' as 'slow')
    assert somebody[-3:] == ["get_all_col_partners", "unique", "query_attributes[color]"]


def test_a_statement_joined_by_but_is_context_and_a_salesman_a_presenter_and_a_jazz_host_are_read():
    parser = QuestionParser.load()
    but, praise, cats, boys = parser.parse_batch([
        "The purple double-decker hits the minivan in a twist nobody saw coming, but is the double-decker quicker than "
        "the minivan at that moment?",
        "In a world where the purple motorbike had started off slow, would she have collided with the green one? Real "
        "smooth ride, that bike.",
        "Which direction does the bendy bus drive at the beginning, cats: left, right, front, back, up or down?",
        "Ooh, boys and girls, after the video stops, will the gray one get into a bump with anything? What do you "
        "think?"])
    assert but[-3:] == ["unique", "get_frame", "faster_velocity"]
    assert "filter_attributes[bicycle]" not in praise and praise[-1] == "exist"   # (read the green one as a bike)
    assert cats[-2:] == ["start", "query_moving_direction"]                    # ('cats' read as 'car')
    assert boys[0] == "futureEvents"
    # two questions joined by 'but' stay two; a dash before the choices is no '-slow' compound
    assert parser.parse("Is the car fast, but is the bus slow?") is None
    assert parser.parse("How fast is the brown jet going when the brown jet and the red car collide - static, slow, "
                        "or fast?")[-3:] == ["unique", "get_frame", "query_moving_velocity"]


def test_a_lighthouse_keeper_s_scene_a_fisherman_s_similes_and_a_therapist_s_colon_are_read():
    parser = QuestionParser.load()
    glow, sees, patient, sure = parser.parse_batch([
        "Which colour is the one that's speeding up as the video starts, by the old lamp's glow?",
        "When the video begins, in which direction is the purple bendy bus travelling, as the old lamp sees it?",
        "When the green motorbike and the green bus collide, was the green motorbike standing still, patient as an "
        "old angler?",
        "When the clip begins, is the car going slower than the blue one, sure as the tide turns?"])
    assert glow == ["Objects", "start", "filter_accelerating", "unique", "query_attributes[color]"]
    assert sees[-2:] == ["start", "query_moving_direction"]
    assert patient[-3:] == ["unique", "get_frame", "is_static"]
    assert sure[-2:] == ["start", "slower_velocity"]                          # (refused: 'turns' a turn)
    # a clause of time closed by a colon is read as by a comma: its 'it' is the question's vehicle
    sit = parser.parse("Let's sit with the moment it collides with the yellow tandem bike: was the car standing still "
                       "then?")
    assert sit[:3] == ["Objects", "filter_attributes[car]", "unique"]        # (read the bike colliding with itself)
    # a scene's clause names no vehicle; one that does, or asks, stays
    assert parser.parse("Is the red car moving fast, with the blue bus?") is None


def test_a_forecaster_s_look_ahead_a_ringmaster_a_wizard_and_a_gangster_are_read():
    parser = QuestionParser.load()
    paths, casting, feast, boys = parser.parse_batch([
        "Projecting the paths forward past the end of the recording, will the red double-decker strike the yellow "
        "bus?",
        "Casting an eye past the line: will the green one go on to hit another object later?",
        "Feast your eyes on the one soaring in the air at the opening of our show: what colour is it?",
        "Which direction is the double-decker travellin' at the start of the video? The boys need to know."])
    assert paths[0] == "futureEvents" and "filter_attributes[double_bus]" in paths   # (refused: 'paths' a shape)
    assert casting[0] == "futureEvents"
    assert feast == ["Objects", "start", "filter_floating", "unique", "query_attributes[color]"]   # ('feast': fast)
    assert boys[1] == "filter_attributes[double_bus]"                         # ('boys' heard as 'bus')
    runes, glass, stalls, behold = parser.parse_batch([
        "By the ancient runes, was the green airliner caught up in a collision?",
        "My scrying glass shows the car as the clip begins; at what speed does it go: static, moving slowly or moving "
        "fast?",
        "Had the gray minivan come out of the stalls slowly, would it have crashed into the blue one?",
        "Behold the bus, children of all ages: once the observed frames are over, will it crash into something?"])
    assert runes == ["Events", "Objects", "filter_attributes[green]", "filter_attributes[airliner]", "unique",
                     "filter_collision", "exist"]
    assert glass == ["Objects", "filter_attributes[car]", "unique", "start", "query_moving_velocity"]
    assert stalls[4] == "Counterfactual_moving_slow"
    assert behold[:3] == ["futureEvents", "Objects", "filter_attributes[bus]"]
    # 'accelerating steadily' is accelerating, not a speed kept; a look that names a vehicle is no look ahead
    assert parser.parse("Suppose the cyan scooter had been accelerating steadily from the very start: would it bump "
                        "into the green SUV?")[4] == "Counterfactual_accelerating"
    assert parser.parse("Is the red car moving at a steady speed?") is None


def test_a_historian_a_pharmacist_a_boxing_announcer_a_scout_leader_and_a_bartender_are_read():
    parser = QuestionParser.load()
    later, purpose, corner, troop = parser.parse_batch([
        "At the opening of the clip, historians would later ask, was the gray aeroplane moving faster than the car?",
        "When the red vehicle first shows up, is it not moving, slow or fast, just so I have it right?",
        "In this corner, the red SUV! Had it come out of its corner fast right from the start, would it have crashed "
        "into the green minivan?",
        "Right, troop, the brown cruiser bumps into something: what colour is the thing it hits?"])
    assert later[-2:] == ["start", "faster_velocity"]                    # (refused: 'later' a time)
    assert purpose[-2:] == ["come_in_frame", "query_moving_velocity"]    # (refused: 'right' a direction)
    assert corner[4] == "Counterfactual_moving_fast"
    assert troop[-3:] == ["get_all_col_partners", "unique", "query_attributes[color]"]
    pressure, stool, orders, hour = parser.parse_batch([
        "Just a little pressure now — if the purple fighter had been moving slowly at the start of the video, would "
        "it have hit the red motorbike?",
        "Pull up a stool, friend — now, the one that's going slow right at the start, what kind of vehicle would that "
        "be?",
        "Last orders, so settle this: when the brown one strikes the gray fighter jet, is the brown one standing "
        "still?",
        "At the hour the brown sedan and the red double-decker collided, was the brown sedan the quicker of the two?"])
    assert pressure[4] == "Counterfactual_moving_slow"                   # (refused: 'pressure' a quantity)
    assert stool[-3:] == ["filter_moving_velocity[slow]", "unique", "query_attributes[shape]"]
    assert orders[:3] == ["Objects", "filter_attributes[brown]", "unique"] and orders[-1] == "is_static"
    assert hour[-3:] == ["unique", "get_frame", "faster_velocity"]


def test_a_speaker_s_remark_before_a_dash_a_zookeeper_a_nurse_a_herald_and_a_cabbie_are_read():
    parser = QuestionParser.load()
    gently, smoker, glass, resident = parser.parse_batch([
        "Gently, gently — does the brown fighter run into the bicycle in the video?",
        "Steady with the smoker now — if the gray one had been moving at a low speed at the very beginning, would it "
        "have banged into the brown tandem bike?",
        "Please don't tap the glass — is the blue biplane speeding up at the outset?",
        "Our resident cyan airliner, folks — is there an impact involving it?"])
    assert gently[0] == "Events" and gently[-1] == "exist"
    assert smoker[3] == "Counterfactual_moving_slow"                     # (refused: 'steady' a speed kept)
    assert glass == ["Objects", "filter_attributes[blue]", "filter_attributes[biplane]", "unique", "start",
                     "is_accelerating"]                                 # (refused: 'not' a negation)
    assert resident[0] == "Events" and "filter_attributes[airliner]" in resident
    patient, house, gentles, guv = parser.parse_batch([
        "Next patient, the gray mountain bike: is it involved in a bump, yes or no?",
        "Feeding time in the bus house: did the brown regular bus and the cyan bus smash into each other?",
        "Suppose the purple jet had set forth quickly, good gentles; would it have run into the cyan vehicle?",
        "The yellow one crashes into something, right, so what colour's the thing it hits?"])
    assert patient[0] == "Events"                                       # ('next' read as later)
    assert house[:4] == ["Events", "Objects", "filter_attributes[brown]", "filter_attributes[regular_bus]"]
    assert gentles[4] == "Counterfactual_moving_fast"                   # ('gentles' read as slowly)
    assert guv[-3:] == ["get_all_col_partners", "unique", "query_attributes[color]"]
    # a choice of directions keeps its 'right'
    assert parser.parse("Which way is the bus moving at the start: left, right, up or down?")[-1] == \
        "query_moving_direction"


def test_a_knight_a_tabloid_a_trainspotter_a_physio_and_a_scene_without_a_comma_are_read():
    parser = QuestionParser.load()
    honour, sources, first, hall = parser.parse_batch([
        "Upon mine honour, at the moment it clashes with the brown one, is the purple regular bus static, slow, or "
        "fast?",
        "Sources close to the race reveal a vehicle getting faster at the beginning of the video: what colour is it?",
        "What model is the one that's airborne at the start? Ooh, that'll be a first for me.",
        "Did the red biplane smash into the brown double-decker while the hall was meant to be quiet?"])
    assert honour[:3] == ["Objects", "filter_attributes[purple]", "filter_attributes[regular_bus]"]   # (the brown)
    assert sources == ["Objects", "start", "filter_accelerating", "unique", "query_attributes[color]"]
    assert first == ["Objects", "start", "filter_floating", "unique", "query_attributes[shape]"]
    assert hall[0] == "Events"                                          # ('hall' fixed as 'shall': the future)
    stride, anywhere, gallop = parser.parse_batch([
        "In the opening frames, who's got the better stride: is the yellow road bike moving faster than the purple "
        "scooter?",
        "Right, anywhere in the video, is there a crash between the aeroplane and the minivan?",
        "When they collide, doth the bus gallop more quickly than the gray minivan, I ask upon mine honour?"])
    assert stride[-2:] == ["start", "faster_velocity"]
    assert anywhere[0] == "Events" and anywhere[-1] == "exist"
    assert gallop[-3:] == ["unique", "get_frame", "faster_velocity"]
    # a clause of a vehicle's own is no scene, and 'Right,' before another direction stays
    assert parser.parse("Is the red car moving while the bus is parked?") is None
    assert parser.parse("Right, left or up: which way is the bus moving at the start?")[-1] == "query_moving_direction"


def test_trailing_off_stage_directions_brackets_and_a_barker_a_colonel_and_a_spelling_bee_are_read():
    parser = QuestionParser.load()
    whisper, choices, faster, bracket = parser.parse_batch([
        "*soft whisper* when the cyan double-decker and the gray one collide, what's the double-decker's speed... "
        "stationary, slow, or fast?",
        "*whispers* when the purple bicycle hits the blue regular bus, which way is it moving... left, right, front, "
        "back, up, or down?",
        "*soft whisper* at the start of the clip, is the double-decker going faster... and faster... and faster?",
        "Supposing the minivan had been moving rapidly from the start (mark this, apprentice), would it bump into the "
        "cyan airliner?"])
    assert whisper[-3:] == ["unique", "get_frame", "query_moving_velocity"]
    assert choices[-3:] == ["unique", "get_frame", "query_moving_direction"]
    assert faster == ["Objects", "filter_attributes[double_bus]", "unique", "start", "is_accelerating"]
    assert bracket[3] == "Counterfactual_moving_fast"
    shy, carry, word = parser.parse_batch([
        "Don't be shy, folks, which way is the brown road bike moving at the beginning?",
        "After the shown frames, will the cyan minivan crash into any other object, or will it carry on unscathed?",
        "Your word is 'fast', F-A-S-T: suppose the red jet had started out fast, would it run into the brown "
        "biplane?"])
    assert shy[-2:] == ["start", "query_moving_direction"]              # (refused: 'not' a negation)
    assert carry[0] == "futureEvents"
    assert word[4] == "Counterfactual_moving_fast"
    # markdown's bold is no stage direction, and one starred word is a correction
    assert parser.parse("**what if** the cyan SUV was accelerating from the very beginning... would it collide with "
                        "the brown cruiser?")[4] == "Counterfactual_accelerating"
    assert parser.parse("Is the red cat* car moving fast at the start?") == [
        "Objects", "filter_attributes[red]", "filter_attributes[car]", "unique", "start", "is_moving_velocity[fast]"]


def test_a_football_manager_s_end_of_the_day_a_comic_a_dinner_lady_a_tax_inspector_and_a_bard_are_read():
    parser = QuestionParser.load()
    day, crowd, pet, writing = parser.parse_batch([
        "When they crash, at the end of the day, is the school bus slower than the grey saloon?",
        "What velocity has the blue fighter jet got in the first frames? Anybody? Is this thing on?",
        "Is it right, pet, that the red utility bike is going slow when the video starts? Come on, eat up.",
        "Supposing the double-decker had been zooming from the start, and I will need this in writing, would it have "
        "crashed into the blue car?"])
    assert day[-3:] == ["unique", "get_frame", "slower_velocity"]       # (refused: 'end' a time)
    assert crowd == ["Objects", "filter_attributes[blue]", "filter_attributes[fighter]", "unique", "start",
                     "query_moving_velocity"]                          # (refused: 'anybody' a person)
    assert pet[-2:] == ["start", "is_moving_velocity[slow]"]
    assert writing[3] == "Counterfactual_moving_fast"
    quiet, fala, careful, listeners = parser.parse_batch([
        "Was there a bump between the gray mountain bike and the yellow car, or was it all quiet?",
        "A tale of a purple motorbike, fa-la-la: is it caught up in any collision?",
        "Green SUV, one careful owner — is it picking up speed at the start of the video?",
        "Our listeners wrote in about the biplane: does it have a collision at some point, yes or no?"])
    assert quiet[0] == "Events" and quiet[-1] == "exist"               # ('quiet' read as still at the collision)
    assert fala == ["Events", "Objects", "filter_attributes[purple]", "filter_attributes[motorbike]", "unique",
                    "filter_collision", "exist"]
    assert careful[-2:] == ["start", "is_accelerating"]
    assert listeners == ["Events", "Objects", "filter_attributes[biplane]", "unique", "filter_collision", "exist"]


def test_a_ventriloquist_s_remarks_a_cat_s_domain_an_esports_caster_and_a_poet_s_still_field_are_read():
    parser = QuestionParser.load()
    sawdust, plank, who, dummy = parser.parse_batch([
        "Don't listen to him, folks, he's all sawdust — is the bus moving slowly when it bumps into the green chopper?",
        "Don't listen to him, he's a plank — at the moment they collide, is the blue wagon going more slowly than the "
        "purple wagon?",
        "Who's asking? I'm asking, not you! Is the blue tandem bike getting faster initially?",
        "Don't listen to the dummy — right at the start, is the green one going less quickly than the purple bus?"])
    assert sawdust[-2:] == ["get_frame", "is_moving_velocity[slow]"]   # (refused: 'not listen' a negation)
    assert plank[-2:] == ["get_frame", "slower_velocity"]
    assert who == ["Objects", "filter_attributes[blue]", "filter_attributes[tandem_bike]", "unique", "start",
                   "is_accelerating"]
    assert dummy[-2:] == ["start", "slower_velocity"]
    # a remark that names the vehicle the question then calls 'it' stays: the question's context
    assert "filter_attributes[red]" in parser.parse("He says the red car is parked — is it?")
    domain, cat, notice, concerns = parser.parse_batch([
        "Which colour is the object hovering above my domain when the video starts?",
        "As the video starts, is the blue SUV sitting perfectly still, as any sensible cat would?",
        "Right at the start, what kind of vehicle is the slowly moving thing? Hardly worth my notice, but tell me "
        "anyway.",
        "At the start of the clip, in what direction is the green dirt bike going, not that it truly concerns me?"])
    assert domain == ["Objects", "start", "filter_floating", "unique", "query_attributes[color]"]
    assert cat[-2:] == ["start", "is_static"]
    assert notice == ["Objects", "start", "filter_moving_velocity[slow]", "unique", "query_attributes[shape]"]
    assert concerns[-2:] == ["start", "query_moving_direction"]
    someone, edge, moment, field = parser.parse_batch([
        "Someone's zooming off the line fast in the first frames, what type is that fast thing?",
        "At the beginning of the video, is the blue sedan moving faster than the brown cruiser? Who's got the edge?",
        "The green chopper collides with the blue airliner, what a moment! How fast is the green chopper going as it "
        "hits: static, slow, or fast?",
        "Purple fighter over the still field — does it ever smash into the bicycle?"])
    assert someone == ["Objects", "start", "filter_moving_velocity[fast]", "unique", "query_attributes[shape]"]
    assert edge[-2:] == ["start", "faster_velocity"]
    assert moment[-6:] == ["filter_attributes[airliner]", "unique", "filter_collision", "unique", "get_frame",
                           "query_moving_velocity"]                     # (read as it came into view)
    assert field[-1] == "exist"                                         # ('still' read as static)


def test_a_fortune_teller_s_visions_a_critic_s_asides_a_scribe_s_notes_and_a_host_s_call_are_read():
    parser = QuestionParser.load()
    crash, instant, first, focus = parser.parse_batch([
        "I see the green one and the yellow bicycle crashing together, and the cards never lie! At that crash, is the "
        "green one going faster than the yellow bicycle?",
        "The cinematography peaks when the mountain bike meets the green SUV; at that very instant of impact, is the "
        "mountain bike static, slow or fast?",
        "The yellow SUV appears as the vision opens, my child. Is it not moving, slow or fast at first?",
        "The red one and the purple cruiser swim into focus as the video starts... is the red one moving slower than "
        "the purple cruiser at that moment?"])
    assert crash[-2:] == ["get_frame", "faster_velocity"]   # (the remark that told the crash was dropped)
    assert instant[-2:] == ["get_frame", "query_moving_velocity"]
    assert first[-2:] == ["start", "query_moving_velocity"]   # (read as it came into view)
    assert focus[-2:] == ["start", "slower_velocity"]          # (read at a collision)
    scarlet, minimal, shot, note = parser.parse_batch([
        "Is the red scooter, that scarlet flourish against an otherwise drab grey palette, zooming along fast when "
        "the film opens?",
        "Is it genuinely the case, amid all this self-indulgent minimalism, that the SUV hits the cyan motorbike?",
        "Had the cyan bicycle been utterly motionless from the opening shot, would it have collided with the gray "
        "double-decker?",
        "Doth the cyan one come into contact with anything at all during the video? (Marginal note: the cyan ink is "
        "nearly spent.)"])
    assert scarlet == ["Objects", "filter_attributes[red]", "filter_attributes[scooter]", "unique", "start",
                       "is_moving_velocity[fast]"]
    assert minimal[0] == "Events" and minimal[-1] == "exist"
    assert shot[4] == "Counterfactual_static"
    assert note == ["Events", "Objects", "filter_attributes[cyan]", "unique", "filter_collision", "exist"]
    reader, prize, beans = parser.parse_batch([
        "O gentle reader, did the cruiser smash into something?",
        "Studio audience, hush now! As the video begins, is the green school bus standing perfectly still? Say yes or "
        "no and the prize is yours!",
        "Was the green station wagon going fast at the beginning? Faster than my runner beans climb, I expect."])
    assert reader == ["Events", "Objects", "filter_attributes[cruiser]", "unique", "filter_collision", "exist"]
    assert prize[-2:] == ["start", "is_static"]
    assert beans == ["Objects", "filter_attributes[green]", "filter_attributes[wagon]", "unique", "start",
                     "is_moving_velocity[fast]"]


def test_a_diplomat_s_courtesies_and_a_support_agent_s_confirmation_are_read():
    parser = QuestionParser.load()
    inquire, presume, confirm = parser.parse_batch([
        "When the red pickup collides with the gray station wagon, is it, if I may respectfully inquire, moving "
        "slowly?",
        "What sort of vehicle, if I might so presume to inquire, is the one floating at the start?",
        "Thank you for your patience; could you confirm the motion state of the brown mountain bike at the outset?"])
    assert inquire[-2:] == ["get_frame", "is_moving_velocity[slow]"]   # ('if' read as a condition)
    assert presume == ["Objects", "start", "filter_floating", "unique", "query_attributes[shape]"]
    assert confirm == ["Objects", "filter_attributes[brown]", "filter_attributes[mountain_bike]", "unique", "start",
                       "query_moving_velocity"]                          # (read as asking yes or no)
    # a clause that imagines, or names a vehicle, is no courtesy
    assert _courtesy("if i may ask".split())
    assert not _courtesy("if you had parked it".split()) and not _courtesy("if i may say , the bus".split())


def test_a_vet_s_closing_remarks_a_lecturer_s_exercises_and_a_postman_s_cut_film_are_read():
    parser = QuestionParser.load()
    biscuit, rabbit, letter, given, proof, suffice, cut, doubt = parser.parse_batch([
        "Which kind of vehicle is picking up speed at the outset? I'll ask while the Labrador finishes his biscuit.",
        "Suppose the cyan bicycle had been sitting motionless right from the start, the way a frightened rabbit "
        "freezes: would it collide with the grey double-decker?",
        "Let W denote the vehicle that is accelerating, engine on, at the outset. Find the colour of W.",
        "Given that the red mountain bike collides with a certain vehicle, find the kind of that vehicle.",
        "Show that the brown aeroplane is moving slowly when the video starts, or else show that it is not.",
        "The clip is cut off part-way. Predict whether the gray bus and the green airliner will collide "
        "afterwards; a yes or no is expected.",
        "They've cut the film short on us! After it stops, is the biplane going to bump into the car?",
        "So did the blue SUV and the blue city bus crash into each other, or is that just Mr Jenkins stirring?"])
    assert biscuit == ["Objects", "start", "filter_accelerating", "unique", "query_attributes[shape]"]
    assert rabbit[4] == "Counterfactual_static" and rabbit[-1] == "exist"
    assert letter == ["Objects", "start", "filter_accelerating", "unique", "query_attributes[color]"]
    assert given == ["Events", "Objects", "filter_attributes[red]", "filter_attributes[mountain_bike]", "unique",
                     "get_all_col_partners", "unique", "query_attributes[shape]"]
    assert proof == ["Objects", "filter_attributes[brown]", "filter_attributes[aeroplane]", "unique", "start",
                     "is_moving_velocity[slow]"]
    assert suffice[0] == cut[0] == "futureEvents"
    assert doubt[0] == "Events" and doubt[-1] == "exist"   # ('stirring' had been read as moving, at the collision)
    # a premise of motion stays a premise, a remark that names what is asked stays, and a claim to prove alone
    # presumes its answer
    assert parser.parse("Given that the bus is parked, does it hit the car?") is None
    assert _remarked_after("i ' ll ask while the labrador finishes its biscuit .".split())
    assert not _remarked_after("i mean the blue one .".split()) and not _remarked_after("at the start .".split())
    assert proof_as_asked("show that the red car hits the bus .".split()) == (
        "show that the red car hits the bus .".split(), ())


def test_a_speed_offered_after_the_time_is_one_of_the_choices():
    parser = QuestionParser.load()
    after, other, adjacent = parser.parse_batch(["Is the red car fast at the start or slow?",
                                                 "Is the red car slow when it hits the bus, or is it fast?",
                                                 "Is the red car fast at the start?"])
    assert after == ["Objects", "filter_attributes[red]", "filter_attributes[car]", "unique", "start",
                     "query_moving_velocity"]   # (was read as 'is it fast?')
    assert other[-1] == "query_moving_velocity" and adjacent[-1] == "is_moving_velocity[fast]"


def test_a_physicist_s_changed_initial_conditions_a_customs_officer_s_fragments_and_a_shepherd_s_similes_are_read():
    parser = QuestionParser.load()
    variation, pin, grant, should, fragments, between, simile, heading = parser.parse_batch([
        "Here's a variation on the initial conditions: the school bus speeding up, engine on, from the very first "
        "instant. Under that assumption, does the school bus collide with the cruiser?",
        "Pin the gray mountain bike in place from the start, standing still, a fixed point in the ground frame. Would "
        "the gray mountain bike collide with the green airliner then?",
        "Grant the gray plane a slow start instead, a modest initial velocity, nothing dramatic; would the gray plane "
        "then collide with the purple city bus?",
        "Should the cyan scooter have been fast as the clip begins, would it have run into the bicycle? Hmph.",
        "The bus. Right at the start. Static, slow or fast? Choose one, I haven't all day.",
        "The car, at the moment it collides with the bicycle. Direction of travel? Eyes up, traveller.",
        "When that grey sedan first shows itself, like a ewe coming out of the mist, is it standing still, going "
        "slow, or going fast?",
        "green suv crashes into the cyan one, what heading is the suv on? l/r/front/back/up/down"])
    # (the first three were read as what happens in the video, or after it)
    assert [variation[3], pin[4], grant[4], should[4]] == ["Counterfactual_accelerating", "Counterfactual_static",
                                                          "Counterfactual_moving_slow", "Counterfactual_moving_fast"]
    assert fragments == ["Objects", "filter_attributes[bus]", "unique", "start", "query_moving_velocity"]
    assert between[-3:] == ["unique", "get_frame", "query_moving_direction"]
    assert simile[-2:] == ["come_in_frame", "query_moving_velocity"]
    assert heading[-1] == "query_moving_direction"   # (was read as its speed)
    # a normative 'should' stays refused, and a reading within the video is no answer to 'over the whole clip, first
    # moment to last' when its nearest reading is after it, nor a vehicle's state from the start to a factual one
    assert parser.parse_batch(["Should the truck have stopped?",
                               "gray dirtbike first pops in -- stationary, slow or fast?"]) == [None, None]


def test_a_priest_s_addresses_a_count_s_similes_and_a_visitor_s_other_history_are_read():
    parser = QuestionParser.load()
    smote, entrance, history, guest, angels, pushing, tailor, offered, thanks = parser.parse_batch([
        "And when the yellow fighter jet smote the green pickup, tell me, beloved, was the fighter jet going slower "
        "than the pickup in that hour?",
        "The red airliner makes its entrance at last, like a late guest at my midnight ball. At that first "
        "appearance, is it static, slow or fast?",
        "Consider a different history, earthling: the bus began at fast speed. In that history, would it hit the "
        "blue tandem bicycle?",
        "Suppose, dear guest, the brown cruiser had begun its journey slowly. Would it then have collided with the "
        "cyan dirt bike?",
        "At first, is the red fighter jet hovering up there, as though borne by angels?",
        "Is the brown tandem bicycle's engine running at the beginning, pushing it ever faster?",
        "Shortening the sleeve a whisker; if the brown motorbike had started out slow, would it have run into the "
        "yellow one?",
        "Static, slow or fast: which describes the cyan road bike at the very moment it strikes the bus?",
        "At the moment of their collision, is the utility bike going faster than the grey double-decker? Thank you "
        "for flying with us, and mind the overhead lockers."])
    # (the first three were read wrong: at the start, at the start, and after the video)
    assert smote[-3:] == ["unique", "get_frame", "slower_velocity"]
    assert entrance[-2:] == ["come_in_frame", "query_moving_velocity"]
    assert [history[3], guest[4], tailor[4]] == ["Counterfactual_moving_fast", "Counterfactual_moving_slow",
                                                 "Counterfactual_moving_slow"]
    assert angels == ["Objects", "filter_attributes[red]", "filter_attributes[fighter]", "unique", "start",
                      "is_floating"]
    assert pushing[-1] == "is_accelerating" and offered[-1] == "query_moving_velocity"
    assert thanks[-1] == "faster_velocity"
    # a world referred back to that no sentence describes is refused, not read as the video's future ('this tale' is
    # the video itself); appearing before another vehicle stays an order no question asks
    assert parser.parse_batch(["In that world, would the bus hit the blue tandem bicycle?",
                               "Does the bus appear before the car?"]) == [None, None]
    assert parser.parse("Good sir knight, did the yellow biplane and the brown city bus come to blows anywhere in "
                        "this tale?")[0] == "Events"


def test_the_speaker_s_own_clauses_are_read_only_where_a_word_would_refuse_the_question():
    parser = QuestionParser.load()
    know, ask = parser.analyse_batch([
        "Something runs into the gray minivan, contestants, and I want to know: what kind of vehicle is it?",
        "At this time, we'd like to ask: what colour is the thing that struck the bicycle?"])
    assert know.program == ["Events", "Objects", "filter_attributes[gray]", "filter_attributes[minivan]", "unique",
                            "get_all_col_partners", "unique", "query_attributes[shape]"]
    assert know.read_as[0] == ("and I want to know", "nothing, the speaker's own words")
    assert ask.program[-1] == "query_attributes[color]"
    # a clause of the speaker's that names a direction, a vehicle or a person stays, and so the refusal
    assert speaker_clauses_dropped("Which way is it heading at the start, so I label it right: left or right?",
                                   {"so", "i", "label"}) is None
    assert parser.parse("Is the bus fast, I wonder what the driver thinks?") is None
    assert speaker_clauses_dropped("Is the bus fast? I keep wondering.", {"keep", "wondering"}) == (
        "Is the bus fast?", "I keep wondering.")


def test_the_part_not_seen_a_state_left_in_and_a_vehicle_s_victim_are_read():
    parser = QuestionParser.load()
    unseen, shown, left, foot, ugh, victim, debut = parser.parse_batch([
        "Vitals are holding. Now, the yellow airliner: does it hit anything in the frames we haven't seen?",
        "Is it to be anticipated that the red aeroplane will hit anything in the part of the video not shown?",
        "Had the fighter jet been left hovering in the air from the start, would the green scooter have been hit by "
        "it?",
        "Right at the start, is the red sedan on the back foot, going slower than the red school bus?",
        "Ugh, right, the brown SUV at the beginning: is it static, moving slowly, or moving fast?",
        "The gray utility bike hits something, darling, so spill: what type of vehicle is its victim?",
        "The biplane's debut: is it stationary, slow or fast when it first appears?"])
    assert unseen[0] == shown[0] == "futureEvents"
    assert left[3] == "Counterfactual_floating" and foot[-2:] == ["start", "slower_velocity"]
    assert ugh == ["Objects", "filter_attributes[brown]", "filter_attributes[suv]", "unique", "start",
                   "query_moving_velocity"]
    assert victim == ["Events", "Objects", "filter_attributes[gray]", "filter_attributes[utility_bike]", "unique",
                      "get_all_col_partners", "unique", "query_attributes[shape]"]
    assert debut[-2:] == ["come_in_frame", "query_moving_velocity"]
    # the part seen stays the video's own time, and 'right' among directions stays a direction
    assert parser.parse("Does the bus hit the car in the part we have seen?")[0] == "Events"
    assert parser.parse("Right, is the bus moving left at the start?") is None


def test_a_limerick_s_lines_a_quiz_host_s_stakes_and_a_monk_s_unseen_time_are_read():
    parser = QuestionParser.load()
    limerick, world, points, audience, breath, unseen, blink = parser.analyse_batch([
        "When the clip has just started to hum, / There's one with its engine on, vrum! / It is gaining in speed, / "
        "Growing faster, agreed; / Now, which sort of vehicle is that one, chum?",
        "In a world where the red mountain bike had started off fast... would it have run into the cyan dirt bike? "
        "Oh, I love this one!",
        "Contestant, for double points: does the brown pickup collide with anything at all during the video?",
        "Something's hovering up there in the opening moments! Can you tell our studio audience what colour that "
        "floating vehicle is?",
        "Imagine, just for a breath, that the cruiser had been resting in stillness from the start... would it then "
        "have bumped into the purple car?",
        "After the frames we have been shown, in the time not yet seen, will the blue bus be in a collision?",
        "Here's a brown one and a red aeroplane. At the very first blink, is the brown one going faster than that red "
        "aeroplane?"])
    # the verse's line breaks read as spaces, and its rhyme's filler ('vrum!', 'agreed;') as nothing
    assert limerick.program == ["Objects", "start", "filter_accelerating", "unique", "query_attributes[shape]"]
    assert limerick.read_as[0] == ("vrum / agreed", "nothing, a verse's filler")
    assert world.program[4] == "Counterfactual_moving_fast" and breath.program[3] == "Counterfactual_static"
    assert points.program[0] == "Events" and audience.program[-1] == "query_attributes[color]"
    assert unseen.program[0] == "futureEvents" and blink.program[-2:] == ["start", "faster_velocity"]
    # a slash between answers or a form's fields is no line of verse
    assert not in_verse("Item: purple SUV / When: beginning / Record: direction it is heading")
    assert not in_verse("Choose one (front / back / left / right / up / down): Which way is the bus moving?")
    assert parser.parse("Q11) Does the blue chopper hit anything during the video? Yes / No")[0] == "Events"


def test_a_game_master_s_creatures_a_tarot_reader_s_cards_and_an_email_s_reminders_are_read():
    parser = QuestionParser.load()
    creature, beast, card, circling, bother = parser.parse_batch([
        "Does the yellow creature ever smash into the minivan at any moment in this encounter? Speak true, adventurers.",
        "Gaze upon the field as the scene opens: one creature is moving fast. What colour is that speedy beast?",
        "Draw the first card, the beginning: is the road bike moving faster than the blue bendy bus?",
        "Circling back once more: was there contact between the cyan tandem bike and the brown bus anywhere in the "
        "video? Cheers.",
        "Sorry to bother you again (not really): what colour is the vehicle whose engine is turned on in the first "
        "frames?"])
    assert creature == ["Events", "Objects", "filter_attributes[yellow]", "unique", "filter_collision", "Objects",
                        "filter_attributes[minivan]", "unique", "filter_collision", "exist"]
    assert beast == ["Objects", "start", "filter_moving_velocity[fast]", "unique", "query_attributes[color]"]
    assert card == ["Objects", "filter_attributes[road_bike]", "unique", "Objects", "filter_attributes[blue]",
                    "filter_attributes[articulated_bus]", "unique", "start", "faster_velocity"]
    assert circling[0] == "Events" and bother[-1] == "query_attributes[color]"
    # a card is no car ('Mark the gray aeroplane's card' had asked whether it hit a car)
    assert parser.parse("Mark the gray aeroplane's card, querent: was it involved in a crash anywhere in the video?") \
        != ["Events", "Objects", "filter_attributes[gray]", "filter_attributes[aeroplane]", "unique",
            "filter_collision", "Objects", "filter_attributes[car]", "unique", "filter_collision", "exist"]


def test_an_address_a_simile_a_listing_s_heading_and_an_auditor_s_requests_are_read():
    parser = QuestionParser.load()
    lord, sign, heading, per, sought, asserted, should, along, completeness, line, entry = parser.analyse_batch([
        "When it all kicks off, is the green one outrunnin' the gray road bike? Lord, reminds me of racin' Earl to "
        "the good spot.",
        "Aries, is the red mountain bike going to bump into the yellow dirtbike after the video ends?",
        "Rich brown tones, sporty attitude: in the opening frames, is the brown sedan travelling faster than the "
        "purple car?",
        "Per our review of the footage, please confirm whether the blue airliner was party to any collision at all "
        "during the video, yes or no.",
        "We seek assurance that the purple fighter jet increases its speed right at the start; is that the case?",
        "Management asserts that the red aeroplane is floating in the air in the first frames. Can you confirm the "
        "assertion?",
        "Should the cyan one have started out slow, would it have run into the red one?",
        "If the biplane had been floating all along from the start, would it have crashed into the yellow dirt bike?",
        "The cyan airliner sustained an impact; for completeness of the file, what colour is the object that smashed "
        "into it?",
        "Once the picture cuts off, will the gray chopper end up bumpin' into anything further down the line?",
        "Upon the red motorbike's entry into view, what was its speed: static, slow or fast?"])
    assert lord.program[-2:] == ["start", "faster_velocity"]
    assert lord.read_as[0] == ("Lord", "nothing, the speaker's own words")
    assert sign.program[0] == "futureEvents" and sign.read_as[0] == ("aries", "nothing, a digression")
    assert heading.program == ["Objects", "filter_attributes[brown]", "filter_attributes[sedan]", "unique", "Objects",
                               "filter_attributes[purple]", "filter_attributes[car]", "unique", "start",
                               "faster_velocity"]
    assert per.program == ["Events", "Objects", "filter_attributes[blue]", "filter_attributes[airliner]", "unique",
                           "filter_collision", "exist"]
    assert sought.program[-2:] == ["start", "is_accelerating"] and asserted.program[-2:] == ["start", "is_floating"]
    assert should.program[3] == "Counterfactual_moving_slow" and along.program[3] == "Counterfactual_floating"
    assert completeness.program[-1] == "query_attributes[color]" and line.program[0] == "futureEvents"
    assert entry.program[-2:] == ["come_in_frame", "query_moving_velocity"]
    # a simile that says something of the domain stays, and so the refusal; 'should' alone asks an ought
    assert parser.parse("Did that plane ever hit anything, the way my line tangled with every stump in the lake?") \
        is None
    assert parser.parse("Should the truck have stopped?") is None
    assert parser.parse("Is the red car moving fast at the start, like my old Evinrude?")[-1] == \
        "is_moving_velocity[fast]"
    evinrude = parser.analyse_batch(["Had the purple city bus been pickin' up speed from the start, engine open like "
                                     "my old Evinrude, would it and the yellow biplane have collided?"])[0]
    assert evinrude.program[4] == "Counterfactual_accelerating" and evinrude.read_as[0][0] == "like my old Evinrude"
    assert parser.parse("Anywhere in the whole video, does the green road bike get into a bump with somethin'?")[0] \
        == "Events"
    # the video's stop however its premise goes on ('the footage stops but the future doesn't:')
    stops, rolls = parser.parse_batch([
        "Gemini, the footage stops but the future doesn't: will the city bus hit anything?",
        "The video stops, but the story goes on: will the red car hit the bus?"])
    assert stops[0] == rolls[0] == "futureEvents"


def test_a_form_letter_s_references_and_a_field_note_s_predicates_are_read():
    parser = QuestionParser.load()
    reference, undersigned, purpose, note, surging, ascertain = parser.parse_batch([
        "Kindly advise this office of the kind of vehicle that is moving fast when the video begins (reference "
        "VF-041).",
        "This office seeks written confirmation as to whether the cyan dirtbike and the red station wagon collided with "
        "each other.",
        "Please give the colour of whatever is hovering in the air as the reel begins, for the item level description.",
        "Yellow pickup in the first frames. Moving fast? Yes or no.",
        "Purple pickup, opening frames. Going faster and faster?",
        "Be advised that the undersigned must ascertain whether the blue vehicle is moving slowly at the beginning of "
        "the footage. Kindly tick yes or no."])
    assert reference == ["Objects", "start", "filter_moving_velocity[fast]", "unique", "query_attributes[shape]"]
    assert undersigned[0] == "Events" and undersigned[-1] == "exist"
    assert purpose[-1] == "query_attributes[color]" and ascertain[-1] == "is_moving_velocity[slow]"
    assert note[-2:] == ["start", "is_moving_velocity[fast]"] and surging[-2:] == ["start", "is_accelerating"]
    # a speed compared with something that is no vehicle is no comparison of two vehicles
    assert parser.parse("When the purple minivan hits the red pickup: moving fast? Faster than any ice.") is None
    # a note's predicate after a sentence that says something of its own stays unread
    assert parser.parse("The yellow pickup is fast. Moving fast?") is None


def test_an_instruction_a_remark_after_the_question_a_sign_off_and_a_stage_direction_are_read():
    parser = QuestionParser.load()
    swap, ablation, remark, over, spoken, bracket, stalls, carry = parser.parse_batch([
        "swap in a fast initial speed for the brown biplane: does it then crash into the purple biplane?",
        "ablation: freeze the gray cruiser, static from the first frame. would it still hit the gray dirtbike?",
        "is the station wagon static at the start? looks parked but the motion estimate is noisy",
        "Give me the cyan cruiser's speed as the video opens. Static, slow or fast? Over.",
        "Brown aircraft, you hit the cyan chopper. Were you slow at the moment of impact? Over.",
        "Q. The brown one, in the first frames [indicating], was it merely creeping along, moving slowly?",
        "If the brown tandem bike had flown out of the stalls fast from the start, would it still have hit the green "
        "station wagon?",
        "What speed does the bus carry as it appears?"])
    assert swap[4] == "Counterfactual_moving_fast" and ablation[4] == "Counterfactual_static"
    assert remark == ["Objects", "filter_attributes[wagon]", "unique", "start", "is_static"]
    assert over[-2:] == ["start", "query_moving_velocity"] and spoken[-1] == "is_moving_velocity[slow]"
    assert bracket[-1] == "is_moving_velocity[slow]" and stalls[4] == "Counterfactual_moving_fast"
    assert carry[-2:] == ["come_in_frame", "query_moving_velocity"] and "filter_attributes[car]" not in carry
    # a change told without its time is refused, never read as what the video shows; 'freeze the film' and 'give me'
    # tell none, and 'start of the clip' is no 'start the bus'
    told = parser.analyse_batch(["swap in a fast speed for the brown biplane. does it then crash into the purple "
                                 "biplane?"])[0]
    assert told.program is None and "tells a change" in told.reason
    film, start = parser.parse_batch([
        "Freeze the film at the event where the car hits the cyan jet: what's the car's speed there, static, slow or "
        "fast?", "Start of the clip, the bus is parked. Does it hit the car?"])
    assert film[-1] == "query_moving_velocity" and start[0] == "Events"
    # an answer's form after the question stays with it, and so does a remark that names a vehicle
    assert parser.parse("Subject: yellow motorbike; State @ start = not moving? (y/n)") is None
    assert remark_after_dropped("At the start, is the yellow bus slower than the green airliner? (bus vs plane, odd "
                                "pair, but ok)") is None
    assert remark_after_dropped("Is the bus fast? Looks it.") == ("Is the bus fast?", "Looks it.")


def test_a_bug_report_an_architect_s_elements_and_a_speed_to_be_classified_are_read():
    parser = QuestionParser.load()
    report, heading, element, ground, classed, shaded, along = parser.parse_batch([
        "At the start of the clip, is the yellow bicycle moving faster than the cyan scooter? Expected yes/no -- "
        "actual answer flips on reload. 7.2.1",
        "Regression since 2.0.5 -- did the dirtbike and the cruiser collide at any point in the video? Expected "
        "answer: yes or no; actual: the tool hangs.",
        "At the outset, is the red element slower than the purple cruiser?",
        "As the clip opens, is the cyan tandem bike moving at a slow pace across the ground plane?",
        "For the speed schedule, how should the brown car be classified in the opening moments: static, slow or fast?",
        "Where the cyan double-decker meets the purple double-decker, how should I shade the cyan double-decker's "
        "speed at that moment: static, slow or fast?",
        "Along what heading is the cyan cruiser travelling at the instant it strikes the brown scooter?"])
    assert report[-1] == "faster_velocity" and heading[0] == "Events" and element[-1] == "slower_velocity"
    assert ground == ["Objects", "filter_attributes[cyan]", "filter_attributes[tandem_bike]", "unique", "start",
                      "is_moving_velocity[slow]"]
    assert classed[-2:] == ["start", "query_moving_velocity"] and shaded[-1] == "query_moving_velocity"
    assert along[-1] == "query_moving_direction"
    # a label of a condition said after it, and a runner's stalls
    what_if, straight = parser.parse_batch([
        "What-if for you: bicycle stopped dead from the start. Does it hit the blue station wagon in that case? Over.",
        "Red double-decker, cyan motorbike, side by side down the straight: did the red double-decker and the cyan "
        "motorbike collide at any point?"])
    assert what_if[3] == "Counterfactual_static" and straight[0] == "Events"


def test_a_simile_closing_the_question_and_a_heading_that_says_nothing_new_are_read_as_nothing():
    parser = QuestionParser.load()
    meringue, dragon, strictly, instant = parser.parse_batch([
        "Just as the video starts, is the red jet hovering in the air, like a meringue that won't settle?",
        "Is the gray car quickening its pace when the video begins, its engine awake like a dragon stirring from its "
        "hoard?",
        "When the brown cruiser and the blue vehicle collide, is the speed of the brown cruiser strictly smaller than "
        "that of the blue vehicle?",
        "Is there an instant in the video at which the red vehicle and the green city bus collide?"])
    assert meringue[-1] == "is_floating" and dragon[-1] == "is_accelerating"
    assert strictly[-1] == "slower_velocity" and instant[0] == "Events" and instant[-1] == "exist"
    # a simile that is the question's other side, or stands before a sentence of its own, stays
    assert simile_closing_dropped("Did the green bus bump into the plane, or'd they pass like two boats on the lake "
                                  "at dawn?") is None
    assert simile_closing_dropped("The red utility bike slams into a vehicle, like rockfall hitting the route: what "
                                  "kind of vehicle does it hit?") is None
    # a heading goes only where it says nothing the question does not say again
    assert heading_dropped("Family-sized and refreshingly cyan: when the cyan station wagon hits the gray one, is it "
                           "moving slower than the gray one?")[1] == "Family-sized and refreshingly cyan"
    assert heading_dropped("for t > T_cut: does the jet hit anything?") is None
    assert heading_dropped("Put the brown bus and the green sedan side by side at the start of the video: is the "
                           "brown bus travelling faster than the green sedan?") is None


def test_a_field_log_s_clock_and_a_contract_s_parties_are_read_as_nothing():
    parser = QuestionParser.load()
    speed, conjecture, party, bound = parser.parse_batch([
        "1849h. Car at the start of the clip. Speed class: static, slow or fast?",
        "1655h. Conjecture: city bus moving fast at the beginning. Would it have slammed into the SUV?",
        "At the commencement of the video, does the brown car, hereinafter the Party of the First Part, move faster "
        "than the brown biplane, hereinafter the Party of the Second Part?",
        "Is the brown fighter jet moving fast at the commencement of the video, the parties being duly bound?"])
    assert speed == ["Objects", "filter_attributes[car]", "unique", "start", "query_moving_velocity"]
    assert conjecture[3] == "Counterfactual_moving_fast" and party[-1] == "faster_velocity"
    assert bound[-1] == "is_moving_velocity[fast]"
    # a watch log's midnight is the video's start, not a log's clock
    assert log_stamp_dropped(["0000h", ".", "is", "it", "fast", "?"])[1] == ()


def test_a_screenplay_s_cues_a_textbook_s_comparison_and_a_stream_s_emotes_are_read():
    parser = QuestionParser.load()
    felix, hale, june, briggs, flynn = parser.parse_batch([
        "INT. EDIT SUITE - NIGHT. FELIX (half to himself) Which way is the blue sedan heading when this thing starts?",
        "INT. SIMULATION LAB - DAY. DR. HALE (thoughtfully, tapping the glass) Suppose the red bus had had its engine "
        "on from the very start. Would it bump into the cyan bendy bus?",
        "INT. CONTROL ROOM - LATE. The playback halts mid-clip. JO (pausing the clip) Later on, after where this "
        "stops, will the city bike crash into another vehicle?",
        "COACH BRIGGS (pausing on the opening frame, skeptical) When the clip begins, is the red mountain bike moving "
        "slower than the yellow dirt bike?",
        "INT. TOUR COMPANY OFFICE - DAY. FLYNN (disbelieving) The double-decker, when it crashes into the biplane. Is "
        "it going fast? Is that right?"])
    assert felix == ["Objects", "filter_attributes[blue]", "filter_attributes[sedan]", "unique", "start",
                     "query_moving_direction"]
    assert hale[4] == "Counterfactual_accelerating" and june[0] == "futureEvents" and briggs[-1] == "slower_velocity"
    assert flynn[-1] == "is_moving_velocity[fast]" and "get_frame" in flynn
    # a parenthetical that says a time the line does not, or a collision, stays with its cue
    assert script_cues_dropped("MAX (rewinding to the opening frame) How fast is the red car going?") is None
    assert script_cues_dropped("ANA (after the crash) Is the red car fast?") is None
    assert script_cues_dropped("Is the red car fast at the start?") is None
    # a textbook's comparison said first, its 'second body' and 'observed to collide'; a streamer's emotes and chat
    faster, slower, body, paused, kekw = parser.parse_batch([
        "16. Compare the initial speeds of the brown motorbike and the cyan cruiser. Is the brown motorbike the "
        "faster of the two?",
        "63. At the initial instant, compare the gray station wagon with the red pickup. Is the gray station wagon "
        "the slower?",
        "5. The cyan dirt bike is observed to collide with a second body. Identify the type of that body.",
        "Clip's paused here chat PauseChamp, is the gray school bus gonna crash into anything after this?",
        "Is the red car moving fast at the start KEKW, or is it slow?"])
    assert faster == ["Objects", "filter_attributes[brown]", "filter_attributes[motorbike]", "unique", "Objects",
                      "filter_attributes[cyan]", "filter_attributes[cruiser]", "unique", "start", "faster_velocity"]
    assert slower[-2:] == ["start", "slower_velocity"] and body[-2:] == ["unique", "query_attributes[shape]"]
    assert paused[0] == "futureEvents" and kekw is not None
    # 'Quick one,' is a label, not a speed; 'end to end' is the whole video, not its end; 'more and more' says nothing
    quick, ends, more = parser.parse_batch([
        "Quick one, is the red car static at the start?",
        "At any point in the clip, does the gray double-decker hit the yellow minivan? Check it end to end.",
        "Which kind of vehicle is speeding up more and more when the video begins?"])
    assert quick[-1] == "is_static" and ends[0] == "Events" and more[-1] == "query_attributes[shape]"


def test_a_menu_s_flourishes_a_claim_said_right_and_lagging_in_speed_are_read():
    parser = QuestionParser.load()
    entrance, duet, beside, pairing, right, lag = parser.parse_batch([
        "The brown pickup, making its grand entrance from the kitchen doors as it first comes into view: is it not "
        "moving, slow or fast upon arrival?",
        "A daring duet of the dirtbike and the cruiser, tossed together over the course of the video: do the two "
        "ever collide?",
        "The brown tandem bike, plated beside the green one at the start of the video: is the brown tandem bike "
        "moving faster than the green one?",
        "A pairing of the yellow pickup and the red pickup, simmered together over the whole video: do they collide?",
        "She asks whether it's right that the blue SUV was moving slowly when it crashed into the cruiser.",
        "When first the tale is told, does the gray chopper lag in speed behind the yellow motorbike?"])
    assert entrance[-2:] == ["come_in_frame", "query_moving_velocity"] and duet[0] == "Events"
    # (the green one beside the tandem bike is another vehicle, named by its colour alone)
    assert beside == ["Objects", "filter_attributes[brown]", "filter_attributes[tandem_bike]", "unique", "Objects",
                      "filter_attributes[green]", "unique", "start", "faster_velocity"]
    assert pairing[0] == "Events" and right[-1] == "is_moving_velocity[slow]" and lag[-1] == "slower_velocity"
    # a flourish goes only where it says nothing more: not a state, a stop or a collision the question does not ask
    assert description_dropped("The red car, served sizzling off the grill at the start of the video: is it moving "
                               "fast?")[1] == "served sizzling off the grill"
    assert description_dropped("The red car, parked by the kitchen at the start of the video: is it moving?") is None
    assert description_dropped("The red car, crashing through the kitchen at the start of the video: is it fast?") \
        is None
    assert description_dropped("The red car, at the start of the video: is it fast?") is None
    # ... nor a heading that asks, a heading with symbols or the vehicles' plural; a coming into view is kept
    for heading in ("As the cyan tandem bike steps into view upon this stage, what is its speed category: static, "
                    "slow, or fast?",
                    "Set v0(yellow scooter) := fast. Does the yellow scooter then hit the purple sedan?",
                    "Of the two minivans, the grey one: what colour was the vehicle it collided with?"):
        assert description_dropped(heading) is None
    assert description_dropped("Eyes on the cyan scooter as it rolls into view here: is it static, moving slowly or "
                               "moving fast?") == ("the cyan scooter as it rolls into view here: is it static, moving "
                                                  "slowly or moving fast?", "eyes on")


def test_a_deposition_s_leading_questions_a_thread_s_emoji_and_a_eulogy_s_blessings_are_read():
    parser = QuestionParser.load()
    correct, agree, true, describe = parser.parse_batch([
        "Q. Is it not correct that the blue cruiser's engine was on when the clip began?",
        "Q. You would agree, would you not, that the cyan utility bike was stationary at the time it struck the gray "
        "double-decker?",
        "Q. It is true, is it not, that the brown biplane collided with another vehicle?",
        "Q. Describe for us the speed of the yellow utility bike as the video starts: not moving, slow, or fast?"])
    assert correct[-1] == "is_accelerating" and agree[-1] == "is_static" and true[-1] == "exist"
    assert describe[-2:] == ["start", "query_moving_velocity"]
    numbered, emoji, hot_take, true_or_false = parser.parse_batch([
        "(9/74) does the gray pickup collide w/ anything at any point in the vid? yes/no pls",
        "62/ at the moment the cyan school bus hits the green station wagon, which direction is the school bus going? "
        "(bus emoji)",
        "30/ hot take: the yellow chopper is tearing along fast right from the start. am I right?",
        "19/ unpopular opinion incoming: when the clip opens, the red airliner is slower than the mountain bike. true "
        "or false? lol"])
    assert numbered[0] == "Events" and emoji[-1] == "query_moving_direction"
    assert hot_take[-1] == "is_moving_velocity[fast]" and true_or_false[-1] == "slower_velocity"
    peace, spared, unseen, subscribe = parser.parse_batch([
        "Did the purple jet and the red motorbike ever meet in a collision during the video, may they both find peace?",
        "Supposing the regular bus had started out slow, would it have struck the purple aeroplane, or would it have "
        "been spared?",
        "Once the video is stopped, in the time we are not allowed to see, will the gray motorbike collide with "
        "anything?",
        "Is the red car fast at the start? Hit like if you spotted it!"])
    assert peace[0] == "Events" and "Counterfactual_moving_slow" in spared and unseen[0] == "futureEvents"
    assert subscribe[-1] == "is_moving_velocity[fast]"
    # a remark after the question that names a vehicle is no call to the viewers
    assert remark_after_dropped("Is the red car fast at the start? Like the blue one below?") is None


def test_terse_prose_a_patent_s_claims_a_manual_s_parts_and_a_melodrama_s_asides_are_read():
    parser = QuestionParser.load()
    might, floated, remark, together = parser.parse_batch([
        "The brown mountain bike might have started fast. Suppose it had. Would it have hit the bus?",
        "The yellow fighter might have floated from the start. Held there in the air. If it had, would it have hit "
        "the yellow biplane?",
        "The yellow mountain bike and the grey fighter crash. It is bad. When they do, is the yellow mountain bike "
        "going faster than the grey fighter?",
        "The brown bus and the grey aeroplane come together. At that moment, is the brown bus faster than the grey "
        "aeroplane?"])
    assert might[4] == "Counterfactual_moving_fast" and floated[4] == "Counterfactual_floating"
    assert remark[-1] == together[-1] == "faster_velocity" and "get_frame" in remark and "get_frame" in together
    # what might have been is no condition where the question asks no collision, nor a collision supposed
    assert parser.parse("The red car could have hit the bus. Would it have been going fast?") is None
    said, stopping, parts, part = parser.parse_batch([
        "15. Is said brown fighter jet, as depicted in the video, involved in a collision of any kind?",
        "26. Will the yellow car, in the remaining frames subsequent to the stopping of the video, hit another object?",
        "Step 2: At the outset, set [C] gray dirt bike next to [D] blue SUV. Check: is [C] slower than [D]?",
        "Step 14: When the video begins, one part is stopped, not moving. What colour does that part have?"])
    assert said[0] == "Events" and stopping[0] == "futureEvents"
    assert parts == ["Objects", "filter_attributes[gray]", "filter_attributes[dirtbike]", "unique", "Objects",
                     "filter_attributes[blue]", "filter_attributes[suv]", "unique", "start", "slower_velocity"]
    assert part == ["Objects", "start", "filter_static", "unique", "query_attributes[color]"]
    dashes, trailing, fate, last = parser.parse_batch([
        "The red scooter — reckless, wild, untamed — is it racing fast the moment the video begins?",
        "Had the SUV been racing fast from the very start... would there have been a collision between the SUV and "
        "the yellow biplane?",
        "If only the SUV had been moving slowly from the start... would it have collided with the yellow biplane, or "
        "would fate have spared them?",
        "After the last frame we're shown... does a collision await the biplane, with anything at all?"])
    assert dashes[-1] == "is_moving_velocity[fast]" and trailing[3] == "Counterfactual_moving_fast"
    assert fate[3] == "Counterfactual_moving_slow" and last[0] == "futureEvents"
    # an aside between dashes that names a vehicle or a time stays
    assert dashed_aside_dropped("Is the red car — like the blue bus — moving fast?") is None
    assert dashed_aside_dropped("Is the red car — at the very start — moving fast?") is None


def test_a_paper_s_figure_is_read_as_nothing_and_a_collision_is_never_read_as_coming_into_view():
    parser = QuestionParser.load()
    figure, hit = parser.parse_batch([
        "Upon its entry into the field of view (Fig. 1a), which speed class, static, slow or fast, is observed for the "
        "gray biplane?",
        "Red plane hit motorbike. Red plane stand still, go slow, or go fast when hit?"])
    assert figure[-2:] == ["come_in_frame", "query_moving_velocity"]
    # ('when hit' was read as the plane coming into view: refused rather than read so)
    assert hit is None
    assert collision_unread(["how", "fast", "is", "it", "when", "hit", "?"],
                            ["Objects", "filter_attributes[red]", "unique", "Objects", "filter_attributes[red]",
                             "unique", "come_in_frame", "query_moving_velocity"])


def test_a_note_to_self_s_shorthand_and_a_proverb_before_the_question_are_read():
    parser = QuestionParser.load()
    first, hypothesis, proverb = parser.parse_batch([
        "- car, 1st shows up → static, slow or fast?",
        "- yellow double-decker not moving at first (hypoth.) → bumps blue SUV?",
        "Where the heart goes, the meeting follows. At the moment it hits the brown scooter, which way is the cyan "
        "cruiser heading? Lucky numbers 6, 27, 33."])
    # ('1st' was read at the start, '(hypoth.)' as a collision of the SUV alone, and the proverb's 'it' as the scooter)
    assert first[-2:] == ["come_in_frame", "query_moving_velocity"]
    assert hypothesis[4] == "Counterfactual_static"
    assert proverb[:4] == ["Objects", "filter_attributes[cyan]", "filter_attributes[cruiser]", "unique"]


def test_a_ticker_s_headlines_are_read_as_nothing_where_the_question_says_all_they_say():
    parser = QuestionParser.load()
    still, forecast = parser.parse_batch([
        "STANDSTILL WATCH /// OPENING SECONDS /// Was the red motorbike sitting completely still when the clip began?",
        "FOOTAGE FROZEN MID-CLIP /// FORECAST DESK /// Will the yellow plane and the green car collide after the "
        "cut-off?"])
    assert still == ["Objects", "filter_attributes[red]", "filter_attributes[motorbike]", "unique", "start",
                     "is_static"]
    assert forecast[0] == "futureEvents" and forecast[-1] == "exist"
    # a headline that says a time, a vehicle or a state the question does not stays
    assert headlines_dropped("AT THE START /// Is the red car fast?") is None
    assert headlines_dropped("RED CAR /// Is the sedan moving fast at the start?") is None
    assert headlines_dropped("HOVER WATCH • Is the red plane fast at the start?") is None
    assert headlines_dropped("BUS NEWS >>> Is the red bus static at the start?") == (
        "Is the red bus static at the start?", "BUS NEWS")


def test_a_sphinx_s_unveiled_scene_and_stopped_frames_and_an_infomercial_s_asides_are_read():
    parser = QuestionParser.load()
    unveiled, beyond, bangs, watcher, something = parser.parse_batch([
        "When the scene is first unveiled, what is the motion of the gray double-decker, traveller: static, slow, or "
        "fast?",
        "Pluto, keeper of hidden futures, knows what lies beyond the stopped frames: will the blue SUV hit the brown "
        "bendy bus afterwards?",
        "The cyan road bike bangs right into the brown bus, can you believe it? At that moment of impact, is the cyan "
        "road bike standing completely still?",
        "How fast goes the gray scooter when first it appears before the watcher, traveller? Static, slow or fast?",
        "Feast your eyes on the green motorbike, isn't it something? At the beginning, which direction is it moving? "
        "Call now!"])
    # (the scene unveiled was read as the bus coming into view)
    assert unveiled == ["Objects", "filter_attributes[gray]", "filter_attributes[double_bus]", "unique", "start",
                        "query_moving_velocity"]
    assert beyond[0] == "futureEvents" and bangs[-2:] == ["get_frame", "is_static"]
    assert watcher[-2:] == ["come_in_frame", "query_moving_velocity"] and something[-2:] == ["start",
                                                                                            "query_moving_direction"]
    # before another vehicle is still an order, which no question asks
    assert parser.parse("Does the red car appear before the blue bus?") is None


def test_a_quiz_host_s_points_and_final_answer_and_a_letter_s_news_are_read_as_nothing():
    parser = QuestionParser.load()
    points, final, demon, news = parser.parse_batch([
        "Contestants, the cyan dirt bike slams into something! For 500 points, what kind of vehicle did it hit?",
        "Here's a sneaky one! At the moment the brown pickup collides with the cyan bus, is the pickup standing "
        "still? Final answer?",
        "The category is Need for Speed! One vehicle is racing along at the start of the video. What colour is that "
        "speed demon?",
        "My dear, the vicar's wife made a trifle that nobody could finish; suppose the yellow dirt bike had started "
        "off fast, would it have run into the yellow cruiser?"])
    # ('points' was read as which way a vehicle faces)
    assert points[-3:] == ["get_all_col_partners", "unique", "query_attributes[shape]"]
    assert final[-2:] == ["get_frame", "is_static"]
    assert demon == ["Objects", "start", "filter_moving_velocity[fast]", "unique", "query_attributes[color]"]
    assert news[:5] == ["Objects", "filter_attributes[yellow]", "filter_attributes[dirtbike]", "unique",
                        "Counterfactual_moving_fast"]
    # a letter's news that names a vehicle or the film is not dropped as news
    assert speaker_clauses_dropped("Dear, the red bus was parked by the gate; is it fast at the start?",
                                   {"gate"}) is None


def test_a_desk_s_ticket_a_member_s_minister_a_voicemail_s_news_and_a_koan_s_riddle_are_read():
    parser = QuestionParser.load()
    ticket, confirm, minister, voicemail, koan = parser.parse_batch([
        "I'm sorry to hear about the trouble you've had. For ticket #27159, which type of vehicle is accelerating at "
        "the beginning?",
        "Hello, and thank you for contacting support regarding ticket 31148. Could you please confirm the colour of "
        "the vehicle that is moving fast when the video begins?",
        "Will the Minister kindly tell this House the colour of the thing that is hovering in the opening frames?",
        "Hey it's me, I've been sitting in the garden all day, anyway, when the chopper first comes into view, is it "
        "stationary, slow or fast? Call me back.",
        "Does the wind touch the pine, or the pine the wind? Did the bus crash into any other object in the video?"])
    assert ticket == ["Objects", "start", "filter_accelerating", "unique", "query_attributes[shape]"]
    assert confirm == ["Objects", "start", "filter_moving_velocity[fast]", "unique", "query_attributes[color]"]
    assert minister == ["Objects", "start", "filter_floating", "unique", "query_attributes[color]"]
    assert voicemail[-2:] == ["come_in_frame", "query_moving_velocity"] and koan[0] == "Events"
    # a frame's number is no ticket's, and a riddle that says a time or a state the question does not stays
    assert reference_dropped(["is", "it", "fast", "at", "frame", "120", "?"])[1] == ()
    assert riddles_dropped("What happens at the start? Is the red car fast?") is None
    assert riddles_dropped("Something was parked. Is the red car fast at the start?") is None


def test_a_narrator_s_asides_and_similes_and_a_best_man_s_story_are_read_as_nothing():
    parser = QuestionParser.load()
    astonished, composure, least, story = parser.parse_batch([
        "When the utility bike and the grey double-decker collide, is the utility bike, to the considerable "
        "astonishment of all who observe it, faster than the grey double-decker?",
        "Is the green fighter jet floating in the air at the beginning, with all the serene composure of a lady above "
        "reproach?",
        "Was the red one standing perfectly still, not moving in the least, at the moment it collides with the cyan "
        "dirtbike?",
        "Tom once tried skydiving and screamed the whole way down; anyway, which colour is the vehicle floating at the "
        "start?"])
    assert astonished[-2:] == ["get_frame", "faster_velocity"]
    assert composure == ["Objects", "filter_attributes[green]", "filter_attributes[fighter]", "unique", "start",
                         "is_floating"]
    # ('the least' was read as ranking a vehicle among all)
    assert least[-2:] == ["get_frame", "is_static"]
    assert story == ["Objects", "start", "filter_floating", "unique", "query_attributes[color]"]
    # a story that says a state, or an aside that says a time the rest does not, stays
    assert speaker_clauses_dropped("Tom was parked all day; is the red car fast at the start?", {"tom"}) is None
    assert speaker_clauses_dropped("Is the red car, as the minutes tick, fast at the start?", {"tick"}) is None


def test_a_texter_s_afterthought_never_narrows_a_vehicle_to_its_category_and_spelt_emoji_are_decorations():
    parser = QuestionParser.load()
    drama, emoji, unseen, stopping = parser.parse_batch([
        "is the gray mountain bike slower than the blue motorbike initially? bike drama fr",
        "sparkles emoji sparkles emoji what kind of vehicle is floating at the very beginning of the vid",
        "The footage stops here, like a rope team halted below the Hillary Step. In the frames we cannot yet see, "
        "will the aeroplane collide with anything?",
        "Does the red car hit the bus after the stopping?"])
    # (the afterthought's 'bike' made the mountain bike any bicycle)
    assert drama[:4] == ["Objects", "filter_attributes[gray]", "filter_attributes[mountain_bike]", "unique"]
    assert emoji == ["Objects", "start", "filter_floating", "unique", "query_attributes[shape]"]
    assert unseen[0] == stopping[0] == "futureEvents"
    # an afterthought that names another kind still corrects the question
    assert parser.parse("Is the red car fast at the start? The sedan, I mean.")[:3] == [
        "Objects", "filter_attributes[red]", "filter_attributes[sedan]"]
