"""Surface readings: how a question's words are written or said, read as the words meant. They are the first of
`QuestionParser._words`' rewrites (each `f(words) -> (words, read_as)`), before any other reads the words: a word
autocorrect changed, put right after the question ('... ? *SUV': `corrections_starred`), a verb's Early Modern '-eth'
(`archaic_as_said`), a question quoted by someone who relays it (`quoted_question`), a worksheet's print around its
question (`worksheet_as_said`), a note's shorthand ('? y/n', 'w/', 'static/slow/fast': `shorthand_as_said`), a speech
recogniser's words that sound like the ones said ('faster then the car': `homophones_as_said`), a colour said in a
clause after its vehicle (`colour_clause_as_named`) and a report's glosses in brackets (`glosses_read`)."""

from __future__ import annotations

import re
import unicodedata
from difflib import SequenceMatcher

from dynclevr.colors import COLOR_NAMES
from dynclevr.language.references import EVERYDAY_NAMES, OBJECT_WORDS, mentions, phrase_table, phrases_as_said
from dynclevr.language.tokenize import SPELLINGS
from dynclevr.language.vocab import slips, sounded
from dynclevr.language.words import (CLOSING_INTERJECTIONS, COMPARISONS, DETERMINERS, DIRECTION_CHOICES, GENERIC,
                                     GENERIC_NOUNS, NAMING, NEGATIONS, OTHER_COLOURS, OTHER_VEHICLES, QUERY_NOUNS,
                                     QUESTION_OPENERS, SPEED_CHOICES, START_WORDS, YES_NO_OPENERS, asks_impact)

# A worksheet's or an exam paper's print around its question ('9. ... ? A) static B) slow C) fast [1 mark]', 'True or
# false: the red sedan is moving fast.', 'Circle one: static / slow / fast', 'it is moving ______ (static/slow/fast).')
MARKS = {"mark", "marks", "pt", "pts", "point", "points"}
BOXES = {"☐", "□", "◯", "○", "[", "]"}
ANSWER_WORDS = {"yes", "no", "true", "false", "none", "of", "these", "the", "above", "static", "slow", "fast", "/", ",",
                "or", "."} | set(COLOR_NAMES) | OBJECT_WORDS | {w for name in EVERYDAY_NAMES for w in name.split()}
INSTRUCTIONS = (("answer", "in", "one", "word"), *(("answer", "yes", "or", "no", *end) for end in (
                    ("at", "the", "end"), ("at", "the", "very", "end"), ("in", "the", "end"))),
                ("answer", "yes", "or", "no"), ("answer", "yes", "/", "no"),
                ("explain", "nothing", ",", "just", "answer"), ("just", "answer"), ("circle", "one"), ("circle",),
                ("tick", "one"), ("tick", "the", "correct", "box"), ("tick",), ("choose", "one"), ("select", "one"),
                ("yes", "or", "no"), ("yes", "/", "no"), ("true", "/", "false"),
                *((v, "the", a, n) for v in ("choose", "select", "pick") for a in ("correct", "right", "best")
                  for n in ("answer", "option")), ("pick", "one"))


def _numbered(words: list[str]) -> int:
    """How many words a worksheet's number takes before its question ('9 .', 'q4 )', '( c )', 'q25 .'); 0 where none."""
    first = words[0] if words else ""
    if (first.isdigit() or re.fullmatch(r"q\d+", first)) and words[1:2] and words[1] in (".", ")", ":"):
        return 2
    if re.fullmatch(r"q\d+", first):
        return 1
    if first == "(" and words[2:3] == [")"] and re.fullmatch(r"[a-z]|[ivx]+|\d+", words[1]):
        return 3
    return 0


def _marker(words: list[str], k: int, letter: str) -> int:
    """How many words an option's letter takes at words[k] ('( b )', 'b )', 'b .'); 0 where none."""
    if words[k:k + 3] == ["(", letter, ")"]:
        return 3
    return 2 if words[k:k + 1] == [letter] and words[k + 1:k + 2] in ([")"], ["."], [":"]) else 0


def lettered_options(words: list[str]) -> tuple[int, list[list[str]], int] | None:
    """Lettered options offered in a question's words ('... ? A) static B) slow C) fast', '(a) yes (b) no'): where
    they start, each option's words, and where the last ends (its full stop, or the words' end); None where none.
    'a' alone is an article, so a list needs its 'b' too."""
    for start in range(len(words)):
        n = _marker(words, start, "a")
        if not n or not any(_marker(words, k, "b") for k in range(start + n, len(words))):
            continue
        options, k, letter = [], start + n, "b"
        while True:
            nxt = next((j for j in range(k, len(words)) if _marker(words, j, letter)), None)
            stop = next((j for j in range(k, nxt if nxt is not None else len(words)) if words[j] in (".", "?", "!")),
                        None) if nxt is None else None
            end = nxt if nxt is not None else stop if stop is not None else len(words)
            options.append([w for w in words[k:end] if w not in (",", ";")])
            if nxt is None:
                break
            k, letter = nxt + _marker(words, nxt, letter), chr(ord(letter) + 1)
        if len(options) >= 2 and all(options):
            return start, options, end + (end < len(words))
    return None


def options_as_asked(words: list[str]) -> tuple[list[str], tuple[str, str] | None]:
    """The question its lettered options complete: yes / no offered leave the question alone, or ask a statement
    whether it is true; an option and its negation ask whether the first holds; other options are offered choices
    ('the bus is A) still B) slow C) fast.' -> 'the bus is still , slow or fast ?'). With what was read so."""
    found = lettered_options(words)
    if found is None:
        return words, None
    start, options, end = found
    before, after = words[:start], words[end:]
    while before and (before[-1] in (":", "-", ",") or before[-1] in CHOICE_LABELS and before[-2:-1] != ["the"]):
        before = before[:-1]   # ('... ? Options: (A) yes (B) no')
    offered = " ".join(words[start:end])
    asked = before[-1:] == ["?"]
    body = before[:-1] if before[-1:] in (["?"], ["."]) else before
    # a statement is asked from its last sentence ('Picture ... . Then the cruiser A) collides ... B) does not ...')
    said = next((k + 1 for k in range(len(body) - 1, -1, -1) if body[k] in (".", ":", ";")), 0)
    judged = [*body[:said], "is", "it", "true", "that", *body[said:]]
    # after a question the options are its answers offered, whatever their words ('A. It is not moving. B. ...')
    if all(o[0] in ("yes", "no", "true", "false", "y", "n") for o in options) or asked:
        return (before if asked else [*judged, "?"]) + after, (offered, "nothing, the options")
    if len(options) == 2 and NEGATIONS & set(options[1]) and not NEGATIONS & set(options[0]):
        return (body if asked else judged + options[0]) + ["?"] + after, (offered, "whether " + " ".join(options[0]))
    # a statement's blank for a colour or a kind ('The sedan crashes into a A) car B) bus ...')
    named = ["color"] if all(set(o) <= set(COLOR_NAMES) for o in options) else \
        ["kind", "of", "vehicle"] if all(set(o) <= OBJECT_WORDS | {"a", "an"} for o in options) else None
    if named and not asked:
        body = body[:-1] if body[-1:] in (["a"], ["an"], ["the"]) else body
        return [*body, "what", *named, "?"] + after, (offered, "what " + " ".join(named))
    said = [w for o in options[:-1] for w in (*o, ",")][:-1] + ["or", *options[-1]]
    return body + ([","] if asked else []) + said + ["?"] + after, (offered, " ".join(said))


def _choices(words: list[str]) -> list[list[str]]:
    """The choices a blank offers ('static / slow / fast', 'would / would not', 'static, slow or fast')."""
    out = [[]]
    for w in words:
        if w in ("/", ",", "or"):
            out.append([])
        else:
            out[-1].append(w)
    return [c for c in out if c]


def worksheet_as_said(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """The question a worksheet prints, without its number, marks, options and instructions; a statement to judge
    true or false asked whether it is true; a blank to fill from choices asked as the choices. With what was read
    so, or the words as they are and ()."""
    out, read = list(words), []
    n = _numbered(out)
    if n:
        read.append((" ".join(out[:n]), "nothing, a number"))
        out = out[n:]
    # an instruction said first ('Answer yes or no: is the jet ...?', 'Yes or no - does ...')
    lead = next((i for i in INSTRUCTIONS if i[0] in ("answer", "explain", "just", "yes", "choose", "select", "pick")
                 and tuple(out[:len(i)]) == i
                 and out[len(i):len(i) + 1] in ([":"], [","], ["."], ["-"]) and out[len(i) + 1:]), None)
    if lead:
        read.append((" ".join(out[:len(lead) + 1]), "nothing, an instruction"))
        out = out[len(lead) + 1:]
    while len(out) > 3 and (out[-1] in ("]", ")") and out[-2] in MARKS and out[-3].isdigit() and out[-4] in ("[", "(")):
        read.append((" ".join(out[-4:]), "nothing, the marks"))
        out = out[:-4]
    out, offered = options_as_asked(out)
    read += [offered] if offered else []
    asked = next((k for k, w in enumerate(out) if w == "?"), None)
    if asked is not None:
        rest = out[asked + 1:]
        while rest:
            said = next((i for i in INSTRUCTIONS if tuple(rest[:len(i)]) == i), None)
            if said is None:
                break
            end = len(said)
            while end < len(rest) and rest[end] in ANSWER_WORDS | BOXES | {":", "!"}:
                end += 1
            read.append((" ".join(rest[:end]), "nothing, an instruction"))
            rest = rest[end:]
        out = out[:asked + 1] + rest
    # a statement to judge ('true or false : the bus is fast .', 'circle one : ... true / false', '☐ true ☐ false')
    judged = out[:4] == ["true", "or", "false", ":"]
    label = next((i for i in INSTRUCTIONS if i[0] in ("circle", "tick") and tuple(out[:len(i)]) == i
                  and out[len(i):len(i) + 1] in ([":"], ["."])), None)
    tail = [w for w in out[-5:] if w not in BOXES]
    if judged or label and tail[-3:] in (["true", "/", "false"], ["true", "false"]) or \
            out[-1:] != ["?"] and [w for w in out if w not in BOXES][-2:] == ["true", "false"]:
        body = out[4:] if judged else out[len(label) + 1:] if label else out
        body = [w for w in body if w not in BOXES]
        while body and body[-1] in ("true", "false", "/", ".", "?"):
            body = body[:-1]
        read.append(("true or false", "is it true that"))
        out = ["is", "it", "true", "that", *body, "?"]
    given = []
    # ('Fill in: ... is coloured ____.', 'Complete: ...')
    if out[:3] in (["fill", "in", ":"], ["fill", "in", "-"]) or out[:2] == ["complete", ":"]:
        said = 2 + (out[0] == "fill")
        read.append((" ".join(out[:said]), "nothing, an instruction"))
        out = ["fill", "in", "the", "blank", *out[said:]]
    if out[:4] == ["fill", "in", "the", "blank"]:
        # its choices may be said with the instruction ('Fill in the blank (would / would not): ...')
        close = out.index(")", 4) if out[4:5] == ["("] and ")" in out[4:] else None
        given = _choices(out[5:close]) if close else []
        read.append((" ".join(out[:close + 1 if close else 4]), "nothing, an instruction"))
        out = out[close + 1 if close else 4:]
        out = out[(out[:1] == [":"]):]
    blank = next((k for k in range(len(out) - 1) if out[k] == out[k + 1] == "_"), None)
    if blank is not None:
        end = blank
        while end < len(out) and out[end] == "_":
            end += 1
        close = out.index(")", end) if out[end:end + 1] == ["("] and ")" in out[end:] else None
        choices = _choices(out[end + 1:close]) if close else given
        close = close if close else end - 1
        rest = ["?" if w == "." else w for w in out[close + 1:]]
        if len(choices) == 2 and NEGATIONS & set(choices[1]) and not NEGATIONS & set(choices[0]):
            # a choice and its negation ask whether the first holds
            read.append((" ".join(out[blank:close + 1]), "whether " + " ".join(choices[0])))
            out = ["is", "it", "true", "that", *out[:blank], *choices[0], *rest]
        elif len(choices) >= 2:
            said = [w for c in choices[:-1] for w in (*c, ",")][:-1] + ["or", *choices[-1]]
            read.append((" ".join(out[blank:close + 1]), " ".join(said)))
            out = out[:blank] + said + rest
        elif not choices and (asked := _blank_asked(out[:blank])):
            read.append((" ".join(out[:blank + 1]), " ".join(asked)))
            out = asked + rest
    return out, tuple(read)


BLANK_NOUNS = {("coloured",): ["what", "color"], ("colored",): ["what", "color"], ("a",): ["what", "kind", "of",
                                                                                           "vehicle"],
               ("an",): ["what", "kind", "of", "vehicle"]}


def _blank_asked(before: list[str]) -> list[str] | None:
    """A statement's blank without choices asked as what fills it: '..., the fast-moving vehicle is coloured' ->
    '..., what color is the fast-moving vehicle'; '... is a' -> 'what kind of vehicle is ...'."""
    noun = next((v for k, v in BLANK_NOUNS.items() if tuple(before[-len(k):]) == k), None)
    be = len(before) - 2
    if noun is None or be < 1 or before[be] not in ("is", "was"):
        return None
    start = max((k + 1 for k in range(be) if before[k] in (",", ":")), default=0)
    return before[:start] + noun + [before[be]] + before[start:be]


# A speech recogniser's words that sound like the ones said ('is the bus faster then the car', 'sitting their',
# 'weather it hits'), where the words around them say which was said
CLIPPED = {"clips": "hits", "clipped": "hit", "clipping": "hitting", "clip": "hit"}


def homophones_as_said(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'faster then the' -> 'faster than the', 'sitting their not' -> 'sitting there not', 'weather the bus' ->
    'whether the bus'; and a verb that sounds like a noun of the footage: 'the jet clips the scooter' -> 'the jet hits
    the scooter'. With the words read so."""
    out, read = list(words), []
    for k, w in enumerate(out):
        after = out[k + 1] if k + 1 < len(out) else ""
        said = ("than" if w == "then" and k and out[k - 1] in COMPARISONS | {"more", "less"} else
                # ('at the moment of their collision' is theirs)
                "there" if w == "their" and after not in NAMING | GENERIC | QUERY_NOUNS and not after.endswith("s")
                and not asks_impact([after])
                else "whether" if w == "weather" and after in DETERMINERS | {"it", "they"}
                else "would" if w == "wood" and after in DETERMINERS | {"it", "they", "that", "this"}
                else CLIPPED.get(w) if w in CLIPPED and k and out[k - 1] not in DETERMINERS | {"of", "in", "both"}
                and after in DETERMINERS | {"it", "into", "something", "another", "anything"} else None)
        if said:
            read.append((w, said))
            out[k] = said
    return out, tuple(read)


def colour_clause_as_named(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'the bicycle , which is brown ,' -> 'the brown bicycle'; 'the biplane that is blue' -> 'the blue biplane': a
    colour said in a clause after its vehicle (the decoder read the vehicle without it). With the words read so,
    or the words as they are and ()."""
    out, read, k = list(words), [], 0
    while k < len(out):
        j = k
        while j < len(out) and (out[j] in NAMING or out[j] in ("vehicle", "object", "thing")) and \
                out[j] not in COLOR_NAMES:
            j += 1
        clause = j + (out[j:j + 1] == [","])
        if j > k and (k == 0 or out[k - 1] not in COLOR_NAMES) and out[clause:clause + 1] and \
                out[clause] in ("which", "that", "who") and out[clause + 1:clause + 2] in (["is"], ["was"]) and \
                out[clause + 2:clause + 3] and out[clause + 2] in COLOR_NAMES:
            end = clause + 3 + (out[clause + 3:clause + 4] == [","] and out[j:j + 1] == [","])
            read.append((" ".join(out[k:end]), " ".join([out[clause + 2], *out[k:j]])))
            out[k:end] = [out[clause + 2], *out[k:j]]
            k += j - k + 1
        elif j > k and out[j:j + 1] == ["of"] and out[j + 1:j + 2] and out[j + 1] in COLOR_NAMES and \
                out[j + 2:j + 3] in (["colour"], ["color"]):   # 'the vehicle of brown colour' (a translation's)
            read.append((" ".join(out[k:j + 3]), " ".join([out[j + 1], *out[k:j]])))
            out[k:j + 3] = [out[j + 1], *out[k:j]]
            k = j + 1
        else:
            k = max(j, k + 1)
    return (out, tuple(read)) if read else (words, ())


GLOSS_OPENERS = (["ie"], ["eg"], ["that", "is"], ["meaning"], ["namely"], ["in", "other", "words"])
CHOICE_LABELS = {"levels", "options", "choices", "classes", "categories", "answers"}
CHOICES_SAID = {"static", "stationary", "parked", "still", "moving", "slow", "slowly", "fast", "quick", "quickly",
                "yes", "no", "or", ",", "/", "left", "right", "front", "back", "up", "down", "none", "zero"}
# states a gloss after a dash says again ('speeding up - going faster and faster because its engine is on', 'moves
# fast - not slow'), and the words of a clause after a dash that asks more than a gloss ('fast - or slow?')
GLOSSED_STATES = {"fast", "slow", "slowly", "quickly", "static", "still", "stationary", "parked", "floating",
                  "hovering", "accelerating", "speeding", "up", "moving", "standing"}
GLOSS_KEEPS = {"or", "when", "while", "as", "if", "whether", "than", "but", "then", "after", "before", "what", "which",
               "how", "who", "where", "whose"}
GLOSS_STARTS = {"not", "meaning", "ie", "no", "without", "like", "with", "so", "in"}   # or a participle
# the words of a speaker's aside in brackets, about how they say it ('I think they call it', 'is that the word?')
SPEAKING = {"i", "we", "they", "say", "call", "called", "word", "think", "believe", "hope", "mean", "gather", "reckon",
            "?"}


def glosses_read(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """A report's brackets: a gloss ('accelerating (i.e. under engine power)') says again what the words before it
    say and is dropped, where it names no vehicle; a vehicle named in brackets after a description of it ('the
    insured vehicle (the red sedan)', 'the third-party vehicle (blue pickup)') is that vehicle, the description
    dropped. With the words read so, or the words as they are and ()."""
    out, read, a = list(words), [], 0
    while "(" in out[a:]:
        a = out.index("(", a)
        b = out.index(")", a) if ")" in out[a:] else None
        if b is None:
            break
        inside = out[a + 1:b]
        name = inside[inside[:1] in (["the"], ["a"], ["an"]):]
        # (or after the state it glosses, as the brief to writers says it: 'floating (hovering, not falling)',
        # 'speeding up (engine on)')
        if (any(inside[:len(g)] == g for g in GLOSS_OPENERS) or a and out[a - 1] in GLOSSED_STATES and inside and (
                inside[0].endswith("ing") or inside[0] in GLOSS_STARTS | {"engine"}) and not set(inside) & GLOSS_KEEPS
                and not asks_impact(inside)) and not NAMING.intersection(inside):
            read.append((" ".join(out[a:b + 1]), "nothing, a gloss"))
            out[a:b + 1] = []
            continue
        d = next((d for d in range(a - 1, max(a - 6, -1), -1) if out[d] in DETERMINERS), None)
        described = out[d + 1:a] if d is not None else []
        levels = inside[2:] if inside[1:2] == [":"] and inside[0] in CHOICE_LABELS else None   # '(levels: ...)'
        if ("or" in inside or levels) and set(levels or inside) <= CHOICES_SAID:   # '(static, slow or fast)'
            read.append((" ".join(out[a:b + 1]), "nothing, the choices offered"))
            out[a:b + 1] = []
            continue
        if SPEAKING & set(inside):   # a speaker's aside: '(the motorbike, i should say)', '(is that the word?)'
            said = name[:name.index(",")] if "," in name else name
            named = said and all(w in NAMING for w in said) and any(w in OBJECT_WORDS for w in said) and described
            colours = [w for w in described if w in COLOR_NAMES]
            read.append((" ".join(out[d if named else a:b + 1]), " ".join(["the", *colours, *said]) if named
                         else "nothing, an aside"))
            out[d if named else a:b + 1] = ["the", *colours, *said] if named else []
            continue
        if name and all(w in NAMING for w in name) and any(w in OBJECT_WORDS for w in name) and described and \
                not set(described) & (OBJECT_WORDS | {"grey", "and", "or", ","}):
            read.append((" ".join(out[d:b + 1]), " ".join(["the", *name])))
            out[d:b + 1] = ["the", *name]
            a = d + 1
            continue
        a = b + 1
    for k in range(len(out) - 2, 0, -1):   # plain language's gloss after a dash ('is it floating - staying up?')
        end = next((j for j in range(k + 1, len(out)) if out[j] in (".", "?", "!")), len(out))
        clause = out[k + 1:end]
        if out[k] == "-" and clause and out[k - 1] in GLOSSED_STATES | START_WORDS and \
                (clause[0].endswith("ing") or clause[0] in GLOSS_STARTS) and \
                not set(clause) & (NAMING | GLOSS_KEEPS) and not asks_impact(clause):
            read.append((" ".join(out[k:end]), "nothing, a gloss"))
            out[k:end] = []
    return (out, tuple(read)) if read else (words, ())


# A note's shorthand: an answer's form after the question ('? y/n', '(yes/no)'), 'w/' for 'with', '+' or 'vs' for 'and',
# choices split by slashes ('(static/slow/fast)'), as the grammar says them; read so, the decoder sees no unknown '/'.
ANSWER_FORMS = (["y", "/", "n"], ["yes", "/", "no"], ["true", "/", "false"])   # ', yes or no?': `tail_as_question`


def _decoration(word: str) -> bool:
    """An emoji or a mark that only decorates ('"red sedan"', '*slow*', '#crash', '🚗')."""
    return word in ('"', "*", "#", "~", "`", "_") or len(word) == 1 and unicodedata.category(word) in (
        "So", "Sk", "Mn", "Me", "Cf", "Co", "Cs")


def _complete(words: list[str], k: int) -> bool:
    """Whether a vehicle's name that begins with the colour at k goes on with a sub-type or category."""
    return words[k + 1:k + 2] != [] and words[k + 1] in NAMING and words[k + 1] not in COLOR_NAMES


def quoted_question(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """A question quoted by someone who relays it ('The quiz card reads "Is the blue motorbike standing still ...?" -
    help!', 'My teacher wrote this on the board: "..." What should I put down?'): the quoted question, where the
    words around it name no vehicle. With the words around it read as nothing, or the words as they are and ()."""
    marks = [k for k, w in enumerate(words) if w == '"']
    if len(marks) != 2:
        return words, ()
    a, b = marks
    quoted, around = words[a + 1:b], words[:a] + words[b + 1:]
    if not quoted or not around or NAMING & set(around) or not (quoted[-1] == "?" or quoted[0] in QUESTION_OPENERS):
        return words, ()
    return quoted + ["?"] * (quoted[-1] not in ("?", ".")), ((" ".join(around), "nothing, the question relayed"),)


# verse's elisions ('do they e'er collide': its 'er' was dropped as a speaker's filler)
ELIDED = {("e", "'", "er"): "ever", ("ne", "'", "er"): "never", ("o", "'", "er"): "over"}


def archaic_as_said(words: list[str], readable) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """A verb's Early Modern '-eth' as its '-s' ('floateth' -> 'floats', 'goeth' -> 'goes', 'stoppeth' -> 'stops'),
    where the parser reads that form, and verse's elisions ('e'er' -> 'ever'); with the words read so."""
    out, read = list(words), []
    for k in reversed(range(len(out) - 2)):
        if (said := ELIDED.get(tuple(out[k:k + 3]))):
            read.append((" ".join(out[k:k + 3]), said))
            out[k:k + 3] = [said]
    for k, w in enumerate(out):
        if w in readable or len(w) < 5 or not w.endswith("eth"):
            continue
        said = next((f for f in (w[:-3] + "s", w[:-3] + "es", w[:-4] + "s") if f in readable), None)
        if said:
            read.append((w, said))
            out[k] = said
    return out, tuple(read)


# A word autocorrect changed, put right after the question as a phone's user does ('Is the green sub static? *SUV',
# '... bust ...? bus*', '... (cyan)', '... meant collided') or in brackets after it ('the red bruiser (cruiser)'): the
# word said wrong is the one the correction is most like; only a word the parser reads corrects, and only one it is
# like (half its letters at least).
STARRED = (["*", None], [None, "*"], ["(", None, ")"], ["meant", None], ["i", "meant", None], ["*", "*", None])


STAGE_UNSAID = {"what", "which", "how", "when", "if", "had", "suppose", "imagine", "is", "was", "did", "does", "will",
                "would", "not", "no"}   # a stage direction asks nothing


def trailing_off_read(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """A speaker's stage directions and trailing off, read as the grammar's marks: '* soft whisper * when ...' ->
    'when ...' (two words or more between stars, naming no vehicle: one starred word is a correction, read by
    `corrections_starred`); 'which way is it moving . . . left , right ...' -> '... moving , left , right ...' (the
    choices after it), 'faster . . . and faster' -> 'faster and faster', and 'had the bus stood still . . . would it
    ...' -> 'had the bus stood still , would it ...' (and a time: 'after the last frame . . . does ...'). Elsewhere
    trailing off ends a sentence, as it is read. With the words read so, or the words as they are and ()."""
    read, out, k = [], [], 0
    while k < len(words):
        close = next((j for j in range(k + 3, min(len(words), k + 7)) if words[j] == "*"), None) \
            if words[k] == "*" else None
        # (not markdown's bold: '** what if ** the cyan suv ...')
        if close is not None and "*" not in (words[k - 1] if k else "", words[close + 1:close + 2] or "") and all(
                w.isalpha() and w not in OBJECT_WORDS | STAGE_UNSAID and w not in COLOR_NAMES
                for w in words[k + 1:close]):
            read.append((" ".join(words[k:close + 1]), "nothing, a stage direction"))
            k = close + 1 + (words[close + 1:close + 2] in ([","], [":"], ["."]))
            continue
        # (and a condition or a time trailing off before the question: 'Had the bus stood still ... would it ...?',
        # 'After the last frame we're shown ... does a collision await ...?')
        start = max((j + 1 for j, w in enumerate(out) if w in (".", "?", "!")), default=0)
        offered = words[k + 3:k + 4] == ["and"] and out[-1:] and out[-1] in COMPARISONS or \
            words[k + 3:k + 4] and words[k + 3] in SLASHED and words[k + 4:k + 5] in ([","], ["or"]) or \
            words[k + 3:k + 4] in (["would"], ["will"]) and out[start:start + 1] in (["had"], ["if"], ["suppose"]) or \
            words[k + 3:k + 4] and words[k + 3] in YES_NO_OPENERS and out[start:start + 1] in (
                ["after"], ["once"], ["past"], ["beyond"]) and not mentions(out[start:])
        if words[k:k + 3] == [".", ".", "."] and out and offered:
            said = [] if words[k + 3] == "and" or out[-1] in (",", ":", ";") else [","]
            read.append((". . .", " ".join(said) or "nothing"))
            out += said
            k += 3
            continue
        out.append(words[k])
        k += 1
    return (out, tuple(read)) if read else (words, ())


def corrections_starred(words: list[str], readable) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'is the green sub statistic when the video starts ? * static' -> 'is the green sub static when the video
    starts ?'; 'the red bruiser ( cruiser )' -> 'the red cruiser'. With the words read so, or the words as they are
    and ()."""
    end = len(words)
    while end and words[end - 1] in ("!", "."):
        end -= 1
    for form in STARRED:
        tail = words[end - len(form):end] if end >= len(form) else []
        if len(tail) != len(form) or any(f is not None and f != w for f, w in zip(form, tail)):
            continue
        said = tail[form.index(None)]
        before = words[:end - len(form)]
        if said not in readable or not said.isalpha() or said in before or not before:
            continue
        like = lambda w: SequenceMatcher(None, w, said).ratio()
        unread = [(like(w), k) for k, w in enumerate(before) if w.isalpha() and w not in readable and like(w) >= 0.5]
        candidates = unread or [(like(w), k) for k, w in enumerate(before) if w.isalpha() and len(w) > 2
                                and w not in DETERMINERS and like(w) >= 0.6]
        if not candidates:
            continue
        _, k = max(candidates)
        out = [*before[:k], said, *before[k + 1:]]
        return out, ((f"{before[k]} ... {' '.join(tail)}", said),)
    # in brackets after the word ('the grey sedate (sedan!!)')
    for k in range(1, len(words) - 2):
        if words[k] == "(" and words[k + 2:k + 3] in ([")"], ["!"]) and words[k + 1] in readable and \
                words[k - 1] not in readable and words[k - 1].isalpha() and \
                SequenceMatcher(None, words[k - 1], words[k + 1]).ratio() >= 0.5:
            close = words.index(")", k) if ")" in words[k:k + 5] else None
            if close is None or any(w != "!" for w in words[k + 2:close]):
                continue
            return [*words[:k - 1], words[k + 1], *words[close + 1:]], \
                ((" ".join(words[k - 1:close + 1]), words[k + 1]),)
    return words, ()


# Emoji said for words, as chat puts them ('is the 🔵 🚙 🛑 at the beginning?', 'when it 💥 into the red sedan'): a
# colour's circle or heart, a vehicle's picture, a crash; a speed's picture where it stands for a word ('going 💨',
# '🛑 or 🐢 or 💨?'), the start's or the cut's where the words say no time. Any other emoji only decorates.
EMOJI_WORDS = {"🔴": "red", "❤": "red", "🔵": "blue", "💙": "blue", "🟢": "green", "💚": "green", "🟡": "yellow",
               "💛": "yellow", "🟣": "purple", "💜": "purple", "🟤": "brown", "🤎": "brown", "⚪": "gray",
               "\U0001fa76": "gray", "⚫": "black", "🖤": "black", "🟠": "orange", "🧡": "orange", "🤍": "white",
               "🚗": "car", "🚘": "car", "🚕": "car", "🚙": "suv", "🚌": "bus", "🚍": "bus", "🚎": "bus",
               "🏍": "motorbike", "🛵": "scooter", "🚲": "bicycle", "✈": "aeroplane", "🛩": "aeroplane",
               "🛫": "aeroplane", "🛬": "aeroplane", "🛻": "pickup", "🚐": "minivan", "🚚": "truck", "🚁": "helicopter",
               "🚜": "tractor", "🚑": "ambulance", "🚓": "police car", "🚒": "fire engine", "🚂": "train"}
EMOJI_CLASSES = {"🛑": "static", "🐢": "slow", "🐌": "slow", "💨": "fast", "🚀": "fast", "⚡": "fast"}
EMOJI_VERBS = {"is", "was", "are", "were", "be", "been", "being", "going", "moving", "goes", "went", "started",
               "starts", "off", "or", ","}


def emoji_as_said(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """The emoji that say words (`EMOJI_WORDS`, `EMOJI_CLASSES`, '💥', '⏱️', '⏭️', '❓') read as those words.
    With the words read so, or the words as they are and ()."""
    out = [w for w in words if w != "\ufe0f"]   # (the emoji presentation selector)
    # an emoji written out in words decorates ('sparkles emoji sparkles emoji what kind ...', 'plane emoji, the red
    # jet: ...'): it is no vehicle
    # (one in brackets is a post's: `asides.prompt_dropped`)
    named = [k for k in range(len(out) - 1) if out[k + 1] in ("emoji", "emojis") and out[k].isalpha()
             and out[:k].count("(") <= out[:k].count(")")]
    spelt = tuple((" ".join(out[k:k + 2]), "nothing, a decoration") for k in named)
    out = [w for k, w in enumerate(out) if k not in named and k - 1 not in named]
    if spelt and out[:1] == [","]:
        out = out[1:]
    if not set(out) & {*EMOJI_WORDS, *EMOJI_CLASSES, "💥", "⏱", "🎬", "⏭", "❓"}:
        return (out, spelt) if spelt else (words, ())
    timed = bool(START_WORDS & set(out)) or "after" in out
    # after the question's mark, or beside the vehicle's own name ('... at the start?? 🚗💨', 'the green airliner
    # ✈️'), an emoji only decorates
    last = max((k for k, w in enumerate(out) if w in ("?", "!", ".")), default=len(out))
    said, read = [], []
    for k, w in enumerate(out):
        before, after = (said[-1] if said else ""), (out[k + 1] if k + 1 < len(out) else "")
        word = EMOJI_WORDS.get(w) if k < last and not (w in EMOJI_WORDS and EMOJI_WORDS[w] not in COLOR_NAMES and
                                                        before in OBJECT_WORDS - set(COLOR_NAMES)) else None
        if w in EMOJI_CLASSES and (before in EMOJI_VERBS | OBJECT_WORDS and k < last or before == "or"
                                   or after == "or"):
            word = EMOJI_CLASSES[w]
        elif w == "💥" and said and before not in ("?", "!", ".", ":") and k < last:
            word = "crash"
        elif w in ("⏱", "🎬") and not timed and not said:
            word, timed = "at the start ,", True
        elif w == "⏭" and not timed and not said:
            word, timed = "after the video ends ,", True
        elif w == "❓" and "?" not in out[k + 1:]:
            word = "?"
        if word is None:
            said.append(w)
            continue
        read.append((w, word))
        said += word.split()
    return (said, spelt + tuple(read)) if read or spelt else (words, ())


# A telegram's marks and words ('RED SEDAN SPEED AT START QUERY', 'FILM STOPPED PART WAY STOP WILL ... COLLIDE
# QRY', 'REQUEST ADVISE ...', 'COLL', 'ACCEL'): read only in a text that ends on one of its marks or says 'QRY'
TELEGRAM_MARKS = {"stop": ".", "query": "?", "qry": "?"}
TELEGRAM_WORDS = {"accel": "accelerating", "aft": "after", "init": "start", "veh": "vehicle", "vehs": "vehicles"}


def telegram_as_said(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'request advise how fast the bus is going stop' -> 'tell me how fast the bus is going .'; 'stop' is a full
    stop, 'query' a question mark, 'request advise' a request, 'request confirm' a claim to check. With the words
    read so, or the words as they are and ()."""
    ended = [w for w in words if w not in ("?", ".", "!")][-1:]
    if not ("qry" in words or ended and ended[0] in ("query", "qry") or ended == ["stop"] and {
            "request", "advise", "confirm"} & set(words)):
        return words, ()
    out, read = [], []
    for w in words:
        before = out[-1] if out else ""
        said = TELEGRAM_MARKS.get(w) if before not in ("to", "a", "the", "will", "would", "could", "did", "does",
                                                       "not", "it", "they", "") else None
        if w == "coll":
            said = "collide" if before in ("to", "then", "will", "would", "it", "they", "does", "did") else "collision"
        said = said or TELEGRAM_WORDS.get(w)
        if said and said != w:
            read.append((w, said))
        out.append(said or w)
    out = [w for k, w in enumerate(out) if not (w in (".", "?") and out[k + 1:k + 2] in ([w], ["?"], ["."]))]
    text = " ".join(out)
    for opener, asked in (("request advise . ", ""), ("request advise ", "tell me "), ("request advice ", "tell me "),
                          ("advise ", "tell me "), ("request confirm ", "is it true that ")):
        if text.startswith(opener):
            text, read = asked + text[len(opener):], read + [(opener.strip(), asked.strip() or "nothing")]
    for tag in (" confirm or negative", " affirm or negative", " confirm"):
        if text.endswith(tag + " ?") or text.endswith(tag):
            text = text[:text.rindex(tag)].rstrip(" ?") + " ?"
            read.append((tag.strip(), "?"))
    return text.split(), tuple(read)


# English-based creoles and pidgins (Nigerian Pidgin, Jamaican Patois, Hawaiian Pidgin, Singlish) as written: read
# only in a question that has one of their own function words (`CREOLE_MARKERS`), so that standard English 'stay',
# 'for', 'a', 'pass' and 'jam' keep their meanings elsewhere
CREOLE_WORDS = {"di": "the", "da": "the", "dat": "that", "dis": "this", "dem": "them", "dan": "than", "wetin": "what",
                "wah": "what", "wat": "what", "weh": "that", "wey": "that", "inna": "in", "nuh": "not", "mo": "more",
                "afta": "after", "ting": "thing", "anyting": "anything", "someting": "something", "wit": "with",
                "woulda": "would", "abi": "or", "bumbye": "later", "langgar": "collide", "lick": "hit",
                "demself": "each other", "e": "it", "bin": "had", "dey": "is",
                # Jamaican's 'wid' is 'with' (a Scot's 'would', synonyms.txt), 'neva', 'anodda', 'seh'
                "wid": "with", "neva": "never", "anodda": "another", "seh": "say", "mi": "me",
                # Trinidadian's ('de', 'yuh', 'buss', 'real fast fast'), Bajan's ('gine', 'wunna', 'lef')
                "de": "the", "yuh": "you", "wha": "what", "buss": "crash", "real": "very", "gine": "will",
                "wunna": "you", "lef": "left",
                # Guyanese ('de one dat deh moving fast', 'when de bus bounce de aeroplane')
                "deh": "is", "bounce": "hit"}
CREOLE_MARKERS = {"di", "da", "dat", "dey", "wey", "wetin", "inna", "nuh", "dan", "demself", "woulda", "abi", "anot",
                  "langgar", "bumbye", "afta", "wah", "weh", "wen", "lah", "leh", "lor", "abeg", "don", "neva",
                  "anodda", "seh", "yuh", "doh", "gine", "wunna", "cuh", "deh"}
CREOLE_PHRASES = phrase_table([
    (("a", "di"), ("at", "the")), (("did", "a"), ("did",)), (("o", "wat"), ("or", "what")),
    (("anot",), ("or", "not")), *(((p,), ()) for p in ("lah", "leh", "lor", "sia", "meh", "ah", "abeg")),
    *(((f, s), ("at", "the", s)) for f in ("for", "a") for s in ("beginning", "start")),
    (("for", "air"), ("in", "the", "air")), (("for", "di", "video"), ("in", "the", "video")),
    (("for", "middle"), ("partway",)), (("e", "for"), ("it", "would")), (("for", "still"), ("would", "still")),
    (("e", "for", "don"), ("it", "would", "have")), (("for", "don"), ("would", "have")), (("e", "don"), ("it", "has")),
    *(((a, "pass"), (b, "than")) for a, b in (("slow", "slower"), ("fast", "faster"))),
    *((("a", v), ("is", v + "ing" if v[-1] != "e" else v[:-1] + "ing")) for v in (
        "go", "move", "head", "hover", "speed", "float", "drive", "zoom", "race", "travel", "cruise", "fly")),
    # 'smash inna di truck', 'bounce inna' (crash into), 'same time it collide' (when), 'tell mi nuh' (a plea)
    *(((v, "inna"), (h, "into")) for v, h in (("smash", "smash"), ("crash", "crash"), ("bounce", "crash"),
                                              ("run", "run"), ("slam", "slam"), ("bump", "bump"), ("lick", "hit"),
                                              ("drive", "drive"))),
    (("same", "time"), ("when",)), (("tell", "mi", "nuh"), ("tell", "me")), (("tell", "me", "nuh"), ("tell", "me")),
    (("one", "place"), ("still",)), (("mo", "fast"), ("faster",)), (("mo", "slow"), ("slower",)),
    (("beginning", "time"), ("at", "the", "beginning")), (("kind", "a"), ("kind", "of")),
    # Trinidadian's 'buss up into' and 'lick up' (crash), 'go' before a verb (will), 'fast fast' (very), its tags
    # ('or wha', 'or it doh', 'tell me nah') and its 'eh-eh'
    (("buss", "up"), ("crash",)), (("lick", "up"), ("collide",)), (("lick", "down"), ("hit",)),
    *((("go", v), ("will", v)) for v in ("crash", "hit", "collide", "buss", "lick", "bump", "smash", "slam", "run")),
    *(((w, w), (w,)) for w in ("fast", "slow")), (("or", "wha"), ("or", "not")), (("or", "it", "doh"), ("or", "not")),
    (("or", "doh"), ("or", "not")), (("tell", "me", "nah"), ("tell", "me")), (("eh", "-", "eh"), ()), (("eh",), ()),
    (("cuh", ","), ()), (("cuh",), ()), (("dat", "lef"), ("that", "are", "left"))])


def creole_as_said(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'di blue car did a go faster dan di green bus a di start ?' -> 'the blue car did go faster than the green bus
    at the start ?': a creole's function words as standard English says them (`CREOLE_WORDS`, `CREOLE_PHRASES`);
    Hawaiian 'wen' is 'when' before its clause's subject and a past tense's mark before a verb, 'stay' before a
    participle is 'is', Pidgin 'jam' before what is hit is 'hit', a coloured 'motor' is a car. With the words read
    so, or the words as they are and ()."""
    # (Trinidadian 'de' is an article before a vehicle, a colour or the video, not pinyin's 'zhuang de shihou')
    article = any(w == "de" and (after in NAMING or after in START_WORDS | {"video", "clip", "one", "ting", "first"})
                  for w, after in zip(words, words[1:]))
    if not CREOLE_MARKERS & set(words) and not article:
        return words, ()
    out, read = phrases_as_said(words, CREOLE_PHRASES)
    read, said = list(read), []
    for k, w in enumerate(out):
        after = out[k + 1] if k + 1 < len(out) else ""
        before = said[-1] if said else ""
        if w == "wen":
            w = "when" if after in CREOLE_WORDS or after in DETERMINERS | NAMING | {"it", "they", "he", "she"} else ""
        elif w == "stay" and (after.endswith("ing") or after in ("parked", "still")) and before not in (
                "to", "would", "will", "did", "does"):
            w = "is"
        elif w == "jam" and (after in CREOLE_WORDS or after in DETERMINERS | {"anything", "something", "it"}):
            w = "hit"
        elif w == "jam" and (before in ("go", "will", "would", "", ",") or after in (",", "later", "?", "")):
            w = "collide"
        elif w == "motor" and before in COLOR_NAMES:
            w = "car"
        elif w == "dey" and before in ("when", "if", "as", "after", "before", "till", "until", "", ","):
            w = "they"   # a clause's subject (Trinidadian's 'when dey collide'), Jamaican's 'is' after one
        else:
            w = CREOLE_WORDS.get(w, w)
        if w != out[k]:
            read.append((out[k], w or "nothing, a past tense's mark"))
        said += w.split()
    return said, tuple(read)


# A bilingual speaker's other language between English words (French, German, Portuguese, Mandarin in pinyin,
# Arabizi): its words of time, joining and comparing as English says them, its tags and fillers dropped; read only
# in a question that has one of its own words (`SWITCH_MARKERS`), so English 'also', 'ma' or 'que' stay as they are
CANTONESE_PARTICLES = ("ar", "ga", "wor", "meh")   # ("la" and "lor" are read before: Spanish and Singlish)
TAGALOG_PARTICLES = ("po", "ba", "lang", "naman", "nga", "pala", "talaga", "diba", "kasi", "sige")
SWITCH_PHRASES = phrase_table([
    *(((*p,), ("at", "the", "start")) for p in (
        ("au", "debut"), ("au", "tout", "debut"), ("am", "anfang"), ("no", "comeco"), ("zai", "kaishi", "de", "shihou"),
        ("zai", "kaishi"), ("ganggang", "kaishi"))),
    *(((*p,), ("from", "the", "start")) for p in (
        ("depuis", "le", "debut"), ("von", "anfang", "an"), ("desde", "o", "inicio"), ("desde", "o", "comeco"),
        ("cong", "kaishi", "jiu"), ("cong", "kaishi"))),
    *(((*p,), ("in", "the", "video")) for p in (("dans", "la", "video"), ("im", "video"), ("no", "video"))),
    (("est", "-", "ce", "qu", "'"), ()), (("est", "-", "ce", "que"), ()), (("du", "coup"), ()), (("hui", "bu", "hui"),
                                                                                            ("will",)),
    (("you", "mei", "you"), ("did",)), (("shi", "bu", "shi"), ("is",)), (("la", "video"), ("the", "video")),
    (("o", "video"), ("the", "video")), (("apres",), ("afterwards",)), (("depois",), ("afterwards",)),
    *(((w,), ()) for w in ("genre", "tipo", "ne", "halt", "ma", "le", "ya3ni", "wallah", "yalla", "khalas", "oder")),
    # Spanish ('cuando the bus chocar with the car', 'el', 'la', 'o sea', 'desde el inicio')
    *(((w,), ("collide",)) for w in ("chocar", "chocan", "chocaron", "choco", "chocado")),
    (("choca",), ("collides",)), (("chocaria",), ("would", "collide")), (("el",), ("the",)), (("la",), ("the",)),
    (("o", "sea"), ()), (("cuando",), ("when",)),
    # ... and a US Latino's Spanglish ('how fast va la purple minivan', 'slow o fast', 'la cosa que', 'un choque',
    # 'al mero principio', '¿...?')
    (("del",), ("of", "the")), (("los",), ("the",)), (("un",), ("a",)), (("una",), ("a",)), (("cosa",), ("thing",)),
    (("que",), ("that",)), (("que", "tan"), ("how",)), (("es",), ("is",)), (("esta",), ("is",)), (("va",), ("is",)),
    (("va", "a", "haber"), ("will", "there", "be")), (("se", "mueve"), ("is", "moving")), (("tiene",), ("has",)),
    (("parado",), ("parked",)), (("bien",), ("very",)), (("mas",), ("more",)), (("en",), ("in",)), (("o",), ("or",)),
    (("choque",), ("collision",)), (("dime",), ("tell", "me")), (("oye",), ()), (("oye", ","), ()), (("\u00bf",), ()),
    (("al", "mero", "principio"), ("at", "the", "start")),
    *(((*p, w), ("from", "the", "start")) for p in (("desde", "el"), ("desde", "la")) for w in (
        "inicio", "principio", "comienzo")),
    *(((*p, w), ("at", "the", "start")) for p in (("al",), ("en", "el")) for w in ("inicio", "principio", "comienzo")),
    *(((w,), ("when",)) for w in ("quand", "quando", "wenn")), (("ruguo",), ("if",)), (("zhuang",), ("hit",)),
    *(((w,), ("or",)) for w in ("ou", "haishi")), *(((w,), ("is",)) for w in ("ist", "est")),
    *(((w,), ("was",)) for w in ("tava", "era", "etait", "estava", "war")),
    *(((c, w), (c, "than")) for c in ("faster", "slower", "quicker") for w in ("que", "als", "do", "bi")),
    (("qual", "e", "a", "cor"), ("what", "is", "the", "color")), (("a", "cor"), ("the", "color")),
    (("welche", "farbe", "hat"), ("what", "color", "is")), (("welche", "farbe"), ("what", "color")),
    (("welche", "art"), ("what", "kind", "of")), (("was", "fur", "ein"), ("what", "kind", "of")),
    (("quelle", "couleur"), ("what", "color")), (("quel", "type", "de"), ("what", "kind", "of")),
    # a time said in the other language is read, so that one the questions do not ask is refused, not dropped
    *(((*p,), ("at", "the", "end")) for p in (("zai", "zuihou"), ("zuihou",), ("a", "la", "fin"), ("am", "ende"),
                                              ("no", "final"))),
    *(((*p,), ("in", "the", "middle")) for p in (("zai", "zhongjian"), ("au", "milieu"), ("in", "der", "mitte"),
                                                 ("no", "meio"))),
    # Taglish: 'yung' is 'the', its particles of politeness and emphasis say nothing ('At the start po, is yung yellow
    # fighter slower than the cyan scooter?', 'Sige, do ...', 'Ano, if ...')
    (("yung",), ("the",)), *(((w,), ()) for w in TAGALOG_PARTICLES), (("sige", ","), ()), (("ano", ","), ()),
    # Kenyan English: 'ama' (or: 'static, slow ama fast?'), before the rules that read choices offered; its fillers
    (("ama",), ("or",)), *(((w,), ()) for w in ("sasa", "aki", "manze", "kwani")),
    # Hong Kong English: Cantonese particles, and 'hai mai' (is it or not) as a yes-or-no tag
    (("hai", "mai"), ()), *(((w,), ()) for w in CANTONESE_PARTICLES)])
SWITCH_MARKERS = {"au", "debut", "anfang", "comeco", "kaishi", "shihou", "depuis", "desde", "genre", "tipo", "du",
                  "est", "quand", "quando", "wenn", "ist", "tava", "etait", "estava", "haishi", "ruguo", "zhuang",
                  "ya3ni", "wallah", "yalla", "khalas", "oder", "halt", "dans", "apres", "depois", "hui", "qual",
                  "welche", "fur", "quelle", "quel", "zai", "zuihou", "fin", "ende", "milieu", "mitte", "meio",
                  "cuando", "chocar", "chocan", "chocaron", "choco", "chocado", "choca", "chocaria", "inicio",
                  "principio", "yung", *TAGALOG_PARTICLES, "ar", "ga", "wor", "hai", "ama", "sasa", "aki", "manze",
                  "kwani", "del", "que", "es", "esta", "va", "cosa", "choque", "parado", "mueve", "oye", "dime",
                  "tiene", "mero", "bien", "\u00bf"}


def code_switched_as_said(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'est-ce que the red car etait fast au debut ?' -> 'the red car was fast at the start ?' (`SWITCH_PHRASES`).
    With the words read so, or the words as they are and ()."""
    if not SWITCH_MARKERS & set(words):
        return words, ()
    return phrases_as_said(words, SWITCH_PHRASES)


def shorthand_as_said(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'is it fast ? y/n' -> 'is it fast ?', 'collides w/ the bus' -> 'collides with the bus', 'the car + the bus'
    (or 'vs') -> 'the car and the bus', 'its speed (static/slow/fast)' -> 'its speed : static , slow or fast'. With
    the words read so, or the words as they are and ()."""
    # a chat's decorations: emoji, quotes and asterisks around words, a hashtag's '#', '!' beside '?', '??'
    out = [w for w in words if not _decoration(w)]
    out = [w for k, w in enumerate(out) if not (w in ("!", "?") and "?" in out[k + 1:k + 2] + out[k - 1:k] and
                                                 (w == "!" or out[k + 1:k + 2] == ["?"]))]
    read = [(" ".join(w for w in words if _decoration(w) or w == "!") or "?", "nothing, a decoration")] \
        if len(out) < len(words) else []
    end = len(out) - (out[-1:] in (["?"], ["."]))
    while end > 0 and out[end - 1] in CLOSING_INTERJECTIONS and any(   # 'yes/no pls'
            out[end - 1 - len(form):end - 1] == form for form in ANSWER_FORMS):
        end -= 1
    for form in ANSWER_FORMS:
        for bracketed in (["(", *form, ")"], form):
            if out[end - len(bracketed):end] == bracketed:
                start = end - len(bracketed) - (out[end - len(bracketed) - 1:end - len(bracketed)] in ([","], [":"]))
                read.append((" ".join(out[start:end]), "nothing, an answer's form"))
                out = out[:start] + out[end:]
                end = start
    k = 0
    while k < len(out):
        if out[k:k + 2] == ["w", "/"]:
            out[k:k + 2] = ["with"]
            read.append(("w /", "with"))
        elif (out[k] in ("+", "&", "vs", "versus") or out[k] == "x" and out[k - 1:k] and out[k - 1] in NAMING and
              out[k + 1:k + 2] and out[k + 1] in NAMING) and 0 < k < len(out) - 1 and out[k - 1].isalnum() and \
                (out[k + 1].isalpha() or out[k + 1:k + 2] == ["."] and out[k] == "vs"):   # 'bus x purple car'
            read.append((out[k], "and"))
            out[k:k + 1 + (out[k + 1] == ".")] = ["and"]
        elif out[k] == "/" and 0 < k < len(out) - 1 and out[k - 1] in NAMING and out[k - 1] not in COLOR_NAMES and \
                _pair_collides(out, k):   # two vehicles said as a pair: 'red bus/blue car collide?'
            out[k] = "and"
            read.append(("/", "and"))
        elif out[k] == "/" and 0 < k < len(out) - 1 and {out[k - 1], out[k + 1]} <= SLASHED:
            last = not (out[k + 2:k + 3] == ["/"])
            out[k] = "or" if last else ","
            read.append(("/", out[k]))
        k += 1
    # a search box's two vehicles side by side ('blue bus green truck collide'), where a collision is asked
    if asks_impact(out):
        k = 1
        while k < len(out) - 1:
            if out[k] in COLOR_NAMES and _complete(out, k) and out[k - 1] in NAMING and \
                    out[k - 1] not in COLOR_NAMES:
                out.insert(k, "and")
                read.append((f"{out[k - 1]} {out[k + 1]}", f"{out[k - 1]} and {out[k + 1]}"))
            k += 1
    # choices in brackets inside the question ('identify the speed (static, slow, or fast) of the suv when ...')
    a = out.index("(") if "(" in out else None
    b = out.index(")", a) if a is not None and ")" in out[a:] else None
    if b is not None and out[b + 1:] not in ([], ["?"], ["."]) and set(out[a + 1:b]) <= SLASHED | {",", "or", "/"} \
            and len(set(out[a + 1:b]) & SLASHED) >= 2:
        read.append((" ".join(out[a:b + 1]), "nothing, the choices"))
        out = out[:a] + out[b + 1:]
    if "(" in out and ")" in out[out.index("("):] and any(w == "/" for w, _ in read):
        a = out.index("(")
        b = out.index(")", a)
        if out[b + 1:] in ([], ["?"], ["."]):
            out = [*out[:a], ":", *out[a + 1:b], *out[b + 1:]]
    # (after a radio's sign-off: '... as the video opens. Static, slow or fast? Over.')
    over = next((e for e in SIGNED_OFF if out[-len(e):] == e), None)
    if over:
        read.append((" ".join(over[1:]), "nothing, a sign-off"))
        out = out[:1 - len(over)]
    # choices said as a sentence of their own ('How fast is the bus at the start. Stationary, slow or fast?'): the
    # question's own (the last sentence was read as the question)
    stop = max((k for k, w in enumerate(out[:-1]) if w in (".", "?")), default=None)
    if stop and out[-1:] == ["?"] and "or" in out[stop + 1:] and \
            set(out[stop + 1:-1]) <= SLASHED | {",", "or"} and len(set(out[stop + 1:-1]) & SLASHED) >= 2:
        read.append((out[stop], ":"))
        out = [*out[:stop], ":", *out[stop + 1:]]
    # a field note's predicate, asked of the vehicle its sentence before names ('Yellow pickup in the first frames.
    # Moving fast?', 'Purple pickup, opening frames. Going faster and faster?'), or what is asked of it ('Car at the
    # start of the clip. Speed class: static, slow or fast?')
    stop = max((k for k, w in enumerate(out[:-1]) if w in (".", "?")), default=None)
    if stop and out[stop] == "." and out[-1:] == ["?"] and out[stop + 1] in NOTED_PREDICATES | NOTED_QUERIES and \
            mentions(out[:stop]) and not (QUESTION_OPENERS | {".", "?", "it", "they"}) & set(out[:stop]) and \
            not mentions(out[stop + 1:]):
        read.append((".", ":"))
        out = [*out[:stop], ":", *out[stop + 1:]]
    if not read:
        return words, ()
    return out, tuple(dict.fromkeys(read))


SIGNED_OFF = [["?", "over", *out, *stop] for out in ((), ("and", "out")) for stop in ((), (".",))]
NOTED_QUERIES = {"speed", "pace", "velocity", "direction", "bearing", "heading", "colour", "color", "motion",
                 "movement"}
NOTED_PREDICATES = {"moving", "going", "travelling", "traveling", "driving", "static", "stationary", "parked", "still",
                    "slow", "fast", "hovering", "floating", "airborne", "accelerating", "speeding", "gaining",
                    "picking", "heading", "headed", "speedier", "faster", "slower", "quicker"}


def _pair_collides(words: list[str], k: int) -> bool:
    """Whether the vehicles said around a slash at words[k] are a pair whose collision the note asks, and nothing
    more ('red bus/blue car collide?', '...: bus/motorbike collide?'; not 'red sedan/blue bus crash - which one hit
    first?', '3rd vehicle involved in red car / blue bus crash?')."""
    i, j = k - 1, k + 1
    while i > 0 and words[i - 1] in NAMING:
        i -= 1
    while j < len(words) and words[j] in NAMING:
        j += 1
    return j > k + 1 and words[i - 1:i] in ([], [":"], [","], ["-"]) and asks_impact(words[j:j + 1]) and \
        words[j + 1:] in ([], ["?"], ["."])


# the words a note offers split by slashes ('static/slow/fast', 'left/right')
SLASHED = {w for choices in (SPEED_CHOICES, DIRECTION_CHOICES) for said in choices for w in said}


# what a word spelt by ear is read as: a colour or a word of a vehicle's name only. Real words the parser does not know
# carry a question's meaning ('end' is no 'and', 'weight' no 'what', 'clear' no 'colour', 'pile-up' no 'people'),
# and without a dictionary a misspelling of a sentence's word cannot be told from a word of its own
SPELT_BY_EAR = set(COLOR_NAMES) | NAMING | {"private", "station", "decker", "pickup", "city", "dirt", "airplane",
                                            "motorcycle"}
# ... and never from a word that names what no vehicle is ('white', 'tractor'), nor from a real word said like a
# vehicle's ('the plain red car')
# (a place said is no vehicle heard: 'crashes into something on the track' was read as 'on the truck')
NOT_SPELT_BY_EAR = OTHER_COLOURS | OTHER_VEHICLES | {"plain", "read", "rode", "great", "tricky", "track", "tracks",
                                                      "boys"}   # a gangster's ('The boys need to know.')
NAME_SAID = SPELT_BY_EAR - set(COLOR_NAMES)
# the first words of two-word names ('school bass' is a school bus; 'the bus carry' is no 'bus car')
NAME_OPENERS = {"articulated", "city", "decker", "dirt", "double", "fighter", "mountain", "pickup", "private",
                "regular", "road", "school", "station", "tandem", "utility"}
BEFORE_REAL_NAME = set(COLOR_NAMES) | NAME_OPENERS
BEFORE_NAME = DETERMINERS | SPELT_BY_EAR
NAMED_AFTER = NAME_SAID | GENERIC | GENERIC_NOUNS


def spelt_by_ear(words: list[str], index: dict[str, list[str]], readable: set[str], real: frozenset[str] = frozenset()
                 ) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'is the blu skool bus ...' -> 'is the blue school bus ...', 'the privit jet' -> 'the private jet': a word
    the parser cannot read (not of `readable`), spelt as it sounds, read as the colour or name's word of `index`
    (`vocab.sound_index` of SPELT_BY_EAR) it sounds like (`vocab.sounded`), where it stands in a vehicle's
    description. With the words read so, or the words as they are and ()."""
    # (a slip of the fingers is read as one first: 'cash' is 'crash', 'fater' 'faster')
    # (nor a vehicle's everyday name: 'bakkie' is a pickup, not a 'bike')
    heard = {w: k for w in set(words) if w not in readable and w not in SPELT_BY_EAR | NOT_SPELT_BY_EAR
             and w not in EVERYDAY_NAMES
             and not slips(w, readable, SPELLINGS) and (k := sounded(w, index))}
    if not heard:
        return words, ()
    fixed = [heard.get(w, w) for w in words]
    # in a vehicle's description: a colour before a vehicle's name, a name's word after a determiner, a colour or
    # another name's word, or before one ('beyond the truncation point' is no 'bendy'); a common English word of
    # `real` only after a colour or a name's first word, where no other word could stand ('the yellow bass', 'the
    # school bass'; 'the boys' are no 'bus', 'what speed does the bus carry' no 'bus car')
    out = [w if said not in heard or (nxt in NAMED_AFTER if w in COLOR_NAMES else
                                      (before in BEFORE_REAL_NAME if said in real else before in BEFORE_NAME)
                                      or nxt in NAMED_AFTER and said not in real)
           else said for w, said, before, nxt in zip(fixed, words, [""] + fixed, fixed[1:] + [""])]
    read = tuple((said, w) for said, w in zip(words, out) if said != w)
    return (out, tuple(dict.fromkeys(read))) if read else (words, ())


# a vehicle called 'she' ('was she hovering at the start, the purple biplane?', 'what was her speed'): the videos
# show no people, so 'she' is 'it'
HER_NOUNS = {"speed", "velocity", "direction", "heading", "engine", "pace", "way", "color", "kind", "type", "own",
             "motion", "path"}


def she_as_it(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'was she fast' -> 'was it fast', 'her speed' -> 'its speed', 'hit her' -> 'hit it'; the West Country's 'he'
    ('would he have hit the bus', 'the one with his engine running'). (After the words heard as others: 'chop her'
    is a chopper.) With the words read so, or the words as they are and ()."""
    out = [("its" if w == "her" and words[k + 1:k + 2] and words[k + 1] in HER_NOUNS else "it")
           if w in ("she", "her", "hers", "he", "him") else "its" if w == "his" else w for k, w in enumerate(words)]
    read = tuple(dict.fromkeys((w, k) for w, k in zip(words, out) if w != k))
    return (out, read) if read else (words, ())


# other words for a vehicle ('the still item in the first frames')
THINGS_SAID = {"item", "items", "entity", "toy", "toys", "machine", "unit", "model", "craft", "contraption",
               "conveyance", "runner", "agent", "actor", "ones", "things", "objects", "vehicles"}


def still_as_adjective(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'over the still field' -> 'over the field': 'still' between an article and a noun that is no vehicle describes
    the scenery (a poet's 'still pond'), not a vehicle's speed; 'the still red car' and 'the still one' keep it. With
    the words read so, or the words as they are and ()."""
    drop = {k for k in range(1, len(words) - 1) if words[k] == "still" and words[k - 1] in DETERMINERS | {"its", "my"}
            and words[k + 1].isalpha() and words[k + 1] not in NAMING | GENERIC_NOUNS | GENERIC | THINGS_SAID
            and not words[k + 1].endswith(("ing", "ed"))}
    return ([w for k, w in enumerate(words) if k not in drop], (("still", "nothing, of the scenery"),)) if drop \
        else (words, ())
