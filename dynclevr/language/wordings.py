"""Wordings recast as the grammar's: the decoder learnt only the grammar's phrasings, so `QuestionParser._words`'
rewrites (each `f(words) -> (words, read_as)`) read what English says another way as the words the grammar says it in.
Idioms ('flat out': `idioms_as_said`), a vehicle's kind ('what kind of plane' as 'what type of plane': `type_as_said`;
'what kind of aircraft is it' as 'what kind of vehicle': `type_of_category_as_vehicle`), 'the floating plane' as 'the
floating vehicle' (`floating_plane_as_vehicle`), an object pointed at first (`attention_as_subject`), a request for the
question as the grammar's 'tell me' and closed with a full stop (`request_as_imperative`, `imperative_as_stated`), a
negated auxiliary or a tag (`negative_question_as_asked`), a noun phrase as its question (`noun_phrase_as_question`), a
height as aloft (`height_as_aloft`), a heading as a direction (`heading_as_direction`), a speed as the subject
(`speed_as_subject`), 'more fast' as 'faster' (`comparative_as_said`), the asking said last ('..., yes or no?', '... is
what?': `tail_as_question`), and attributes or alternatives offered (`attributes_offered_dropped`,
`alternatives_as_asked`)."""

from __future__ import annotations

import re

from dynclevr.colors import COLOR_NAMES
from dynclevr.language.asides import ADDRESS_ADJECTIVES, ADDRESSED, VOCATIVES, _says_something
from dynclevr.language.context import PARTICIPLES, STATES_SAID
from dynclevr.language.references import OBJECT_WORDS, mentions, phrase_table, phrases_as_said
from dynclevr.language.times import FILM_WORDS, cut_premise
from dynclevr.language.words import (AFLOAT_SAID, AGREEING_TAGS, ASKING, ATTRIBUTE_NOUNS, AUXILIARIES, CHECKING_TAGS,
                                     CLASS_NOUNS, CLAUSE_CONJUNCTIONS, CLAUSE_MARKS, COMPARISONS, DEFINITE,
                                     DETERMINERS, DIRECTION_CHOICES, IMAGINING, IMPERATIVES, MOTION_NOUNS,
                                     MOTION_WORDS, NAMING, NEGATIONS, NOUNS_SAID, QUERY_NOUNS, QUESTION_OPENERS,
                                     REVERSERS, SENTENCE_ENDS, SHAPE_ASKED, SPEED_CHOICES, SPEED_CLASS_WORDS,
                                     START_ADJECTIVES, START_WORDS, TIME_OPENERS, YES_NO_OPENERS, _head, asks_impact)


def type_of_category_as_vehicle(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'... . what kind of aircraft is it ?' -> '... . what kind of vehicle is it ?': the category in a question of
    the type of what 'it' is names no other object (it was read as a plane of its own, the context's description of
    'it' lost). With the words read so, or the words as they are and ()."""
    for k in range(len(words) - 4):
        if SENTENCE_ENDS.intersection(words[:k]) and words[k] in ("what", "which") and words[k + 1] in SHAPE_ASKED and \
                words[k + 2] == "of" and words[k + 3] in NOUNS_SAID | PLANE_SAID and \
                words[k + 4:k + 6] in (["is", "it"], ["was", "it"]):
            return words[:k + 3] + ["vehicle"] + words[k + 4:], ((f"of {words[k + 3]}", "of vehicle"),)
    return words, ()


def type_as_said(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'what kind of plane is ...' -> 'what type of plane is ...': the grammar asks a vehicle's kind or sort only of a
    'vehicle', its type of any noun (the decoder read 'what kind of plane is floating?' as whether it floats). With
    the words read so, or the words as they are and (). 'the category of' and 'the class of' ask it too ('identify
    the category of the object that floats' was read as its colour)."""
    for k in range(1, len(words) - 2):
        if words[k - 1] in ASKING and words[k] in ("kind", "sort") and words[k + 1] == "of" and \
                words[k + 2] in NAMING and words[k + 2] not in COLOR_NAMES or \
                words[k - 1] in ASKING | {"the"} and words[k] in ("category", "class") and words[k + 1] == "of":
            return words[:k] + ["type"] + words[k + 1:], ((f"{words[k]} of", "type of"),)
    return words, ()


PLANE_SAID = {"plane", "aeroplane", "airplane", "aircraft"}


def floating_plane_as_vehicle(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'the floating plane' -> 'the floating vehicle': only aeroplanes float, so the noun says nothing more, and the
    decoder read a bare plane after 'floating' as a second object ('what colour is the floating plane?' as a collision
    partner's). With the words read so, or the words as they are and ()."""
    for k in range(2, len(words)):
        if words[k] in PLANE_SAID and words[k - 1] in AFLOAT_SAID and words[k - 2] in DETERMINERS:
            return words[:k] + ["vehicle"] + words[k + 1:], ((f"{words[k - 1]} {words[k]}", f"{words[k - 1]} vehicle"),)
        # 'what kind of aircraft was hovering?' (read as whether one was, where 'is floating' read right)
        after = words[k + 1 + (words[k + 1:k + 2] in (["is"], ["was"], ["are"], ["were"])):][:1]
        if words[k] in PLANE_SAID and words[k - 2:k] in ([t, "of"] for t in SHAPE_ASKED) and after and \
                after[0] in AFLOAT_SAID:
            return words[:k] + ["vehicle"] + words[k + 1:], ((f"of {words[k]}", "of vehicle"),)
    return words, ()


# A first sentence or phrase that points at an object ('Watch the yellow bus. Does it hit anything?', 'How about the
# blue bus, is it fast?', 'This is about the red sedan. Does it ...', 'There is a red sedan in the video. Is it ...'):
# the question about it. A sentence of pointing words only: one that says more ('The red sedan is parked.', 'The
# cruiser shows up at some point.') may set what the question asks, and stays.
ATTENDING = (["look", "at"], ["look", "closely", "at"], ["look", "carefully", "at"], ["watch"], ["consider"],
             ["circling", "back", "on"], ["circling", "back", "to"], ["following", "up", "on"],
             ["focus", "on"], ["observe"], ["notice"], ["check"],
             ["how", "about"], ["what", "about"], ["about"], ["regarding"], ["concerning"], ["as", "for"],
             ["did", "you", "hear", "about"], ["have", "you", "heard", "about"],   # a gossip's
             ["as", "to"], ["turning", "to"], ["turning", "now", "to"], ["now", "turning", "to"],
             # a preacher's ('Let us consider the red biplane, dear flock: ...')
             *([*us, v, *m, *on] for us in (["let", "us"], ["let", "'", "s"]) for v, ons in (
                 ("consider", ([],)), ("reflect", (["on"], ["upon"])), ("turn", (["to"],)), ("look", (["at"],)))
               for m in ([], ["a", "moment"]) for on in ons))
POINTING_ENDS = {".", ":", ";", ",", "?", "-"}
POINTING_WORDS = {"this", "that", "it", "is", "s", "'", "am", "m", "are", "i", "we", "you", "my", "our", "me", "one",
                  "question", "questions", "about", "regarding", "concerning", "concerns", "interested", "in", "have",
                  "has", "got", "a", "an", "the", "quick", "let", "us", "talk", "look", "at", "watch", "consider",
                  "focus", "on", "observe", "notice", "check", "out", "take", "there", "here", "now", "want", "to",
                  "ask", "see", "saw", "spot", "video", "clip", "scene", "of", "please", "just", "ve", "d", "like"}


def _pointed_at(words: list[str]) -> int | None:
    """Where the object begins in a first sentence of pointing words ('this is about the red sedan .'), or None."""
    k = 0
    while k < len(words) and words[k] in POINTING_WORDS and words[k] not in OBJECT_WORDS and not (
            words[k] in DEFINITE and words[k + 1:k + 2] and words[k + 1] in OBJECT_WORDS):
        k += 1
    return k if k < len(words) and (words[k] in DEFINITE or words[k] in OBJECT_WORDS) else None


def attention_as_subject(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'watch the yellow bus . does it hit anything ?' -> 'does the yellow bus hit anything ?': the object a first
    sentence or phrase points at ('how about the blue bus , is it ...', 'this is about the blue bus . is it ...') put
    for the question's first 'it' (or its 'its'), two objects ('how about the red car and the bus , do they ...') for
    its first 'they', and the pointing left out. With the words read so, or the words as they are and ()."""
    verb = next((v for v in ATTENDING if words[:len(v)] == v), None)
    start = len(verb) if verb else _pointed_at(words)
    if start is None:
        return words, ()

    def mention(k: int) -> tuple[list[str], int]:
        """The object named from word k on ('the', 'a', 'that' or 'this' first; 'the gray one') and where it ends."""
        j = k = k + (words[k:k + 1] != [] and words[k] in DEFINITE)
        while words[j:j + 1] and words[j] in OBJECT_WORDS:
            j += 1
        j += j > k and words[j:j + 1] in (["one"], ["thing"])
        return ["the", *words[k:j]] if j > k else [], j

    first, j = mention(start)
    second = []
    if first and words[j:j + 1] == ["and"]:
        second, j = mention(j + 1)
        if not second:
            return words, ()
    named = j
    while verb is None and j < len(words) and words[j] in POINTING_WORDS:   # 'there is a red sedan in the video .'
        j += 1
    # after pointing words a sentence ends ('this is about X .'); the object alone is set off by a comma too ('X , is
    # it ...')
    ends = POINTING_ENDS if verb or start == 0 and j == named else POINTING_ENDS - {",", "?"}
    # (or a clause of time first: 'look at the bus : once the frames are over , will it crash into something ?')
    timed = words[j + 1:j + 2] and words[j + 1] in CLAUSE_CONJUNCTIONS | {"as", "after"} and any(
        words[c] == "," and words[c + 1:c + 2] and words[c + 1] in QUESTION_OPENERS for c in range(j + 2, len(words)))
    if not first or words[j:j + 1] == [] or words[j] not in ends or not words[j + 1:j + 2] or \
            words[j + 1] not in QUESTION_OPENERS and not (verb and timed):
        return words, ()
    thing, question = first + (["and", *second] if second else []), words[j + 1:]
    pronouns = ("they", "them") if second else ("it", "its")
    for n, w in enumerate(question):
        if w in pronouns:
            question = question[:n] + thing + (["'", "s"] if w == "its" else []) + question[n + 1:]
            break
    else:
        if second or verb is None or words[j + 1] not in QUESTION_OPENERS:
            return words, ()
    return question, ((" ".join(words[:j + 1]), f"nothing; '{pronouns[0]}' as " + " ".join(thing)),)


# A question asked as a request for it: 'Could you tell me ...', 'Do you know ...', 'I'd like to know ...',
# 'I wonder ...', 'I'm curious, ...' (after 'please', 'so', 'hey' or 'ok' said first). The grammar words requests as
# 'Tell me ...'.
REQUEST = re.compile(r"^(?:(?:please|so|hey|ok|okay|well|and|but) (?:, )?)*"
                     r"(?:(?:can|could|would|will) you (?:please |kindly )?(?:be (?:so kind as|good enough) to )?"
                     r"(?:tell me|inform me|tell(?= (?:the|whether|if|which|what|how) )|let me know|advise(?: me)?"
                     r"|describe(?: for me| to me)?(?= (?:which|what|how|whether))"
                     # an assistant's verb of the answer ('could you identify what kind of vehicle ...')
                     r"|(?:identify|determine|specify|indicate|ascertain)(?= (?:which|what|how|whether|if)))"
                     r"|do you (?:happen to )?(?:know|(?:remember|recall)(?= (?:which|what|how|whether|if)))"
                     r"|(?:please )?find out(?= (?:whether|if|which|what|how))"
                     # a translation's courtesy ('Would it be possible to know whether ...')
                     r"|(?:would|could|is) it be possible to (?:know|learn|find out|ask)"
                     r"(?= (?:whether|if|which|what|how|in))"
                     r"|i (?:would |' d |want to |need to |should )(?:very much |so much |really |dearly )?"
                     r"(?:like to |love to )?(?:know|learn)"
                     # a letter's courtesies ('Might I trouble you to tell me ...', 'May I ask whether ...')
                     r"|(?:might|may) i (?:trouble you to tell me|trouble you for|ask you to tell me"
                     r"|ask(?= whether| if))"
                     r"|i (?:am |' m |was )?(?:wondering|wonder) (?:if|whether) you (?:could|would|might|can) "
                     r"(?:possibly |kindly |please )?(?:tell me|let me know|say)"
                     r"|i (?:am |' m |was )?(?:wondering|wonder) (?:if|whether) you (?:could|would|might|can) "
                     r"(?:settle|answer|help me with|clear up) (?:something|a question|a little question|a matter)"
                     r"(?: for me)?(?: :)?"
                     r"|i (?:am |' m |was )?wondering|i wonder|tell me(?= ,)"
                     r"|(?:would|could|will|can) you be able to (?:tell me|say|tell)"
                     r"|(?:can|could|would|will) you (?:please |kindly )?tell (?:an?|this|your) "
                     r"(?:old |elderly |poor )?"
                     r"(?:man|woman|lady|gentleman|fellow|person|pensioner|granny|grandad|grandpa|grandma)"
                     r"|(?:i (?:am |' m )|just )curious(?: to know)?(?! about)|please tell me|let me know"
                     # an after-action report's 'Report the colour of ...'
                     r"|report(?= (?:the|its|which|what|how) )"
                     # a worksheet's bare 'Tell the colour of ...'
                     r"|(?:please )?tell(?= the (?:color|type|kind|shape|category|class|speed|velocity|direction) )"
                     r"|i (?:would |' d |should )be (?:most |very |really |so |much )?(?:grateful|obliged|glad) "
                     r"(?:to know|to learn|to be told|if you could tell me|if you would tell me)"
                     r"|(?:[a-z]+ ){1,4}(?:want|wants|wanted|would like|' d like|need|needs) to know(?! is )"
                     r"|(?:[a-z]+ ){1,3}(?:is|are|was|were|' s) (?:asking|wondering)"
                     r"|(?:i |we )?need(?= the )|(?:customer|user|client|caller|reporter) asks(?= wh| if| how)"
                     # a caller on the radio ('Line three wants the speed of ...', 'Caller on line five wants ...')
                     r"|(?:the )?(?:caller|listener|line)(?: on line)?(?: [a-z]+)? (?:wants|needs)(?= the )"
                     # said after what sets the scene ('..., so what i'd like to know is how fast ...', 'here's
                     # what i'm wondering :', 'i'm curious about its first moments :')
                     r"|(?:so |and )?what i (?:would |' d |want to |need to |wanna )?(?:really )?(?:like to |love to )?"
                     r"(?:know|find out|ask|wonder|am wondering|' m wondering) is(?: this)?(?: :)?"
                     r"|here (?:' s|is) (?:what i (?:' m |am )?(?:wondering|asking|curious about)|my question)(?: :)?"
                     r"|(?:so |and )?my question(?: is| here is)?(?: :| -)?(?! about| is about)"
                     r"|(?:i (?:' m|am) (?:curious|asking|wondering)|i (?:want|' d like|would like) to know"
                     r"|my question(?: is)?) about "
                     r"(?:[a-z']+ ){1,10}(?::|-))"
                     r" (?:, )?(?:please )?")
# whether a statement holds, asked formally ('Can it be established that ...', 'Am I right that ...'): the grammar's
# 'is it true that'
CERTAINTY = re.compile(r"^(?:(?:can|could|would|may|might) (?:it|one|we|you) (?:please |kindly )?(?:be )?"
                       r"(?:established|shown|confirmed|verified|determined|affirmed|asserted|maintained|held|"
                       r"affirm|assert|maintain|"
                       r"concluded|said|demonstrated|establish|show|confirm|verify|determine|conclude|say|tell|"
                       r"demonstrate) (?:that|whether|if)"
                       r"|(?:am i|are we) (?:right|correct) (?:in thinking |to think |to say )?that"
                       # a ticket's ('Need confirmation whether ...', 'Please verify that ...')
                       r"|(?:please )?(?:(?:i |we )?need (?:to )?)?(?:confirm|verify|confirmation|verification)"
                       r"(?: of| on| as to)? (?:that|whether|if)) ")


RESTATING = (["in", "other", "words"], ["that", "is", "to", "say"], ["put", "another", "way"],
             ["to", "put", "it", "another", "way"], ["put", "differently"], ["to", "put", "it", "differently"],
             ["to", "rephrase"], ["rephrased"], ["said", "another", "way"], ["said", "differently"])


def restated_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'... what ' s its speed like ? in other words , how quickly is the bus moving when it first appears ?' ->
    'how quickly is ...': a question asked again in other words asks what it asked, as the last words say it. With
    the words read so, or the words as they are and ()."""
    for k in range(1, len(words) - 1):
        said = next((r for r in RESTATING if words[k - 1] in ("?", ".") and words[k:k + len(r)] == r), None)
        if said and words[-1] == "?" and "?" in words[:k]:
            rest = words[k + len(said) + (words[k + len(said):k + len(said) + 1] == [","]):]
            return rest, ((" ".join(words[:k + len(said)]), "nothing, the question asked again"),)
    return words, ()


SUPPOSING = {"if", "had", "were", "would", "will", "suppose", "supposing", "imagine", "assuming", "what"}


def request_after_setting(words: list[str]) -> list[str]:
    """'there ' s a bike somewhere , and what i ' d like to know is how fast ...' -> 'there ' s a bike somewhere .
    what i ' d like to know is how fast ...': a request for the question said after what sets the scene ends a
    sentence there, so that the scene is read as the question's context and the request as a request (asked, if
    it ends with a full stop)."""
    for k in range(2, len(words) - 2):
        # (a condition said first, then the request for its consequence: 'had the plane been fast , i should like
        # to know whether it would have hit the bike .' -> '... , would it have hit the bike ?')
        if words[k] == "," and SUPPOSING & set(words[:k]) and "?" not in words[:k] and \
                (m := REQUEST.match(" ".join(words[k + 1:]) + " ")):
            rest = " ".join(words[k + 1:])[m.end():].split()
            would = rest.index("would") if "would" in rest[1:6] else None
            if rest[:1] in (["whether"], ["if"]) and would and len(rest) > would + 2:
                asked = ["would", *rest[1:would], *rest[would + 1:]]
                return words[:k + 1] + asked[:-1] + ["?" if asked[-1] in (".", "?") else asked[-1]]
        # (a scene set: a vehicle or the video named, and nothing asked or imagined in it; not a clause of time
        # whose moment the question asks at and does not say again: 'and when the jet smote the pickup , tell me ,
        # was ...')
        if words[k] not in (",", ";", ":", "-", ".") or "?" in words[:k] or \
                not (OBJECT_WORDS | FILM_WORDS) & set(words[:k]) or SUPPOSING & set(words[:k]) or \
                next((w for w in words[:k] if w not in ("and", "so", "but", "now")), "") in CLAUSE_CONJUNCTIONS \
                and not asks_impact(words[k + 1:]):
            continue
        said = " ".join(words[k + 1 + (words[k + 1] in ("and", "so", "but")):]) + " "
        # (not a closing address: '... than the motorbike , tell me , old friend ?')
        if (m := REQUEST.match(said)) and len(rest := said[m.end():].split()) >= 3 and \
                not set(rest) <= ADDRESSED | VOCATIVES | ADDRESS_ADJECTIVES | {",", "?", ".", "!"}:
            # (the request itself dropped where the question follows it whole: 'i'm asking about the pickup :
            # after the clip stops , will it ...?')
            # (and a question word's, as the grammar's 'tell me how fast ...', so that the scene's moment is
            # said before the question, not before the request)
            asked = rest if rest[:1] and rest[0] in YES_NO_OPENERS | TIME_OPENERS else ["tell", "me", *rest] \
                if rest[0] in ("how", "what", "which", "where") else words[k + 1:]
            return words[:k] + ["."] + asked[:-1] + ["?" if asked[-1] == "." else asked[-1]]
    return words


# the request said last, its clause first ('Whether the bus is fast at the start is what I want to find out; is it?')
FRONTED_WHETHER = re.compile(r"^(?:whether|if) (.+?) is (?:what|something|all) (?:i|we) (?:want|' d like|would like"
                             r"|need|wanna|' m trying|am trying)(?: to)? (?:know|find out|learn|check|figure out)"
                             r"(?: [;,:-] (?:is it|does it|was it|did it|is that so|yes or no))? [.?!]$")


def fronted_whether_as_asked(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'whether the bus is fast at the start is what i want to find out ; is it ?' -> 'tell me whether the bus is
    fast at the start .' (before the context's rules, which read the clause as what 'is it ?' asks of). With the
    words read so, or the words as they are and ()."""
    if m := FRONTED_WHETHER.match(" ".join(words)):
        return ["tell", "me", "whether", *m.group(1).split(), "."], ((" ".join(words), "tell me whether ..."),)
    return words, ()


def clause_comma_added(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """A clause of time said first without its comma, the comma put where the question starts: 'once the red car
    hits the bus is the bus fast ?' -> 'once the red car hits the bus , is the bus fast ?' (read without it, the
    clause's subject was taken for the question's). With the words read so, or the words as they are and ()."""
    if not words or words[0] not in CLAUSE_CONJUNCTIONS or "," in words:
        return words, ()
    k = next((k for k in range(3, len(words) - 1) if words[k] in ("how", "what", "which", "where") or words[k] in
              YES_NO_OPENERS and (words[k + 1] in SUBJECT_STARTS or words[k + 1] in COLOR_NAMES)), None)
    said = mentions(words[1:k]) if k else []
    # (its verb after its subject: 'once the cyan bike shows up is it ...')
    if not said or not any(w not in OBJECT_WORDS and w not in COLOR_NAMES and w not in DEFINITE
                           for w in words[1 + said[0][1]:k]):
        return words, ()
    return words[:k] + [","] + words[k:], ((" ".join(words[k - 1:k + 1]), " ".join(words[k - 1:k]) + " , " +
                                            words[k]),)


def request_as_imperative(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """A question that opens with a request for it, the request read as the grammar's 'tell me': 'can you tell me
    the speed of the red car at the start ?' -> 'tell me the speed of ...'; with the words read so (`Parse.read_as`),
    or the words as they are and ()."""
    m = CERTAINTY.match(" ".join(words) + " ")
    if m:
        rest = " ".join(words)[m.end():].split()
        return ["is", "it", "true", "that"] + rest, ((" ".join(words[:len(words) - len(rest)]), "is it true that"),)
    m = REQUEST.match(" ".join(words) + " ")
    if not m:
        return words, ()
    rest = " ".join(words)[m.end():].split()
    said = " ".join(words[:len(words) - len(rest)]).replace(" ' ", "'")
    # ('Our last caller wants to know: is the bike ...?': the question after the colon)
    if rest[:1] in ([":"], ["-"]) and rest[1:2] and rest[1] in YES_NO_OPENERS | QUESTION_OPENERS:
        return rest[1:], ((f"{said} {rest[0]}", "nothing, a request"),)
    # 'I'd like to know, is the bus fast?', '... , at the start, is it fast?': the question itself
    asked = rest.index(",") + 1 if rest[:1] and rest[0] in TIME_OPENERS and "," in rest else \
        next((j for j in range(2, 12) if rest[:1] and rest[0] in TIME_OPENERS and rest[j:j + 1] and rest[j] in
              YES_NO_OPENERS and rest[j + 1:j + 2] and rest[j + 1] in SUBJECT_STARTS | set(COLOR_NAMES)), 0)
    if rest[asked:asked + 1] and rest[asked] in YES_NO_OPENERS:
        return rest, ((said, "nothing, a request"),)
    return ["tell", "me"] + rest, ((said, "tell me"),)


def imperative_as_stated(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """A request closed by a question mark ('Describe the speed of the bus at the start?') as the grammar closes
    one, with a full stop: the question mark made the decoder read it as yes or no. With the words read so, or the
    words as they are and ()."""
    # an indirect question whose verb comes last ('tell me what kind of vehicle the one that keeps speeding up at the
    # outset is .'; the decoder lost its way in the subject): asked directly
    rest = words[2:]
    subject = next((j for j in range(1, 6) if rest[j:j + 1] and rest[j] in SUBJECT_STARTS), None)
    if words[:2] == ["tell", "me"] and rest[:1] in (["what"], ["which"]) and subject and len(rest) > subject + 3 and \
            rest[-2] in ("is", "was") and rest[-1] in (".", "?"):
        out = [*rest[:subject], rest[-2], *rest[subject:-2], "?"]
        return out, ((" ".join(words), " ".join(out)),)
    if words[-1:] != ["?"] or not any(words[:len(i)] == i for i in IMPERATIVES):
        return words, ()
    return [*words[:-1], "."], (("?", "."),)


# A yes/no question asked with its auxiliary negated ('Isn't the red car fast?', 'Doesn't it hit the bus?') asks
# the same as without: English answers it yes where the car is fast. So does a statement with a tag ('The red car is
# fast, isn't it?', '..., right?'). Only a negation inside the clause ('Is the red car not moving?') denies.
SUBJECT_STARTS = {"the", "a", "an", "any", "anything", "something", "anyone", "it", "there", "its", "this", "that",
                  "these", "those", "either", "both", "they", "some", "all"}
TAG_PRONOUNS = {"it", "they", "there", "he", "she"}


# a verb that asks whether a speed said before the question fits ('Slow - would that describe the pace of ...?')
FITTING = {"describe", "describes", "fit", "fits", "match", "matches", "capture", "captures", "characterise",
           "characterises", "characterize", "characterizes", "sum"}


DRIVE_ON = {"drive": "hit", "drives": "hits", "drove": "hit", "driving": "hitting", "driven": "hit"}


def drive_on_as_hit(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """A Scandinavian learner's 'the scooter drives on the grey pickup' (Swedish 'köra på') -> 'the scooter hits the
    grey pickup': 'drive on' a vehicle named next is hitting it ('drives on the grey floor' stays). With the words
    read so, or the words as they are and ()."""
    out, read = list(words), []
    for k in range(len(out) - 2):
        if out[k] in DRIVE_ON and out[k + 1] == "on" and (m := mentions(out[k + 2:])) and \
                m[0][0] == (out[k + 2] in ("the", "a", "an")) and out[k + 1 + m[0][1]] not in COLOR_NAMES:
            read.append((f"{out[k]} on", DRIVE_ON[out[k]]))
            out[k:k + 2] = [DRIVE_ON[out[k]]]
            break
    return (out, tuple(read)) if read else (words, ())


def verbless_comparison_asked(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """A note's 'At impact w/ green pickup: blue chopper the slower one?' -> '...: is the blue chopper the slower
    one?': a vehicle said with 'the slower (faster) one' and no verb, after a clause or at the start, asked whether
    it is (the decoder took the clause's vehicle for the one compared). With the words read so, or the words as
    they are and ()."""
    for k in (0, *(j + 1 for j, w in enumerate(words) if w in (":", ","))):
        j = k + (words[k:k + 1] == ["the"])
        end = j
        while end < len(words) and words[end] in OBJECT_WORDS:
            end += 1
        if end > j and words[end:end + 2] in (["the", "slower"], ["the", "faster"], ["the", "quicker"]) and \
                words[end + 2:] in (["one", "?"], ["of", "the", "two", "?"], ["?"]):
            said = ["is", "the", *words[j:end]]
            lead = [*words[:k - 1], ","] if k else []   # (the clause before it read as the grammar's, with a comma)
            return lead + said + words[end:], ((" ".join(words[max(k - 1, 0):end]), " ".join([*lead[-1:], *said])),)
    return words, ()


def fronted_value_as_asked(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'slow - would that describe the pace of the suv ... ?' -> 'is slow the pace of the suv ... ?': a speed said
    first and pointed at by 'that' is the speed asked; with another verb the speed stands for 'that' ('fast : is
    that how ...' -> 'is fast how ...'). With the words read so, or the words as they are and ()."""
    k = next((k for k in range(1, 4) if words[k:k + 1] in (["-"], [":"], [","])), None)
    if k is None or tuple(words[:k]) not in SPEED_CHOICES or not set(words[k + 1:k + 2]) & YES_NO_OPENERS or \
            words[k + 2:k + 3] not in (["that"], ["this"]):
        return words, ()
    value, rest = words[:k], words[k + 3:]
    rest = rest[1 + (rest[1:2] == ["up"]):] if rest[:1] and rest[0] in FITTING else rest
    said = ["is", *value, *rest] if len(rest) < len(words) - k - 3 else [words[k + 1], *value, *rest]
    return said, ((" ".join(words[:k + 3]), " ".join(said[:len(value) + 1])),)


def negative_question_as_asked(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'is not the red car fast ?' -> 'is the red car fast ?' (the negation on the auxiliary put before the subject,
    first or after a clause said first: 'when they collide , is not the sedan faster ?'); 'the red car is fast , is
    not it ?' and '... , right ?' -> 'the red car is fast ?' (a tag after a statement with no negation of its own).
    With the words read so, or the words as they are and ()."""
    for k in range(len(words) - 2):
        if (k == 0 or words[k - 1] in (",", ";", ":")) and words[k] in YES_NO_OPENERS and words[k + 1] == "not" and \
                (words[k + 2] in SUBJECT_STARTS or words[k + 2] in OBJECT_WORDS) and words[k + 3:] not in ([], ["?"]):
            return words[:k + 1] + words[k + 2:], ((f"{words[k]} not", words[k]),)
    # '..., right? Or no?': the tag asked again as a choice
    again = ((" ".join(words[-4:]), "?"),) if len(words) > 4 and words[-4] == words[-1] == "?" and \
        words[-3] == "or" and words[-2] in ("no", "not", "nah", "nope") else ()
    words = words[:-3] if again else words
    # '... is it going fast ? is that right ?': a yes/no question, then asked whether its statement is right (a
    # statement so asked is `context._checked`'s)
    checked = next((t for t in CHECKING_TAGS if words[-len(t) - 2:] == ["?", *t, "?"]), None)
    if checked and any(w in YES_NO_OPENERS and (k == 0 or words[k - 1] in (",", ".", "?"))
                       for k, w in enumerate(words[:-len(checked) - 2])):
        again += ((" ".join(checked) + " ?", "nothing, the question asked again"),)
        words = words[:-len(checked) - 1]
    end = words[-1:] if words[-1:] in (["?"], ["."]) else []
    body = words[:len(words) - len(end)]
    if body[-2:] == [",", "or"]:   # 'is it slower than the bus , or ?' (a learner's tag)
        return body[:-2] + ["?"], again + ((", or", "?"),)
    # 'does it get into a collision , or what ?' (a question asked, then pressed)
    if body[-3:] == [",", "or", "what"] and any(w in YES_NO_OPENERS and (k == 0 or body[k - 1] == ",")
                                                 for k, w in enumerate(body[:-3])):
        return body[:-3] + ["?"], again + ((", or what", "?"),)
    negative = [[w, "not", p] for w in sorted(YES_NO_OPENERS) for p in sorted(TAG_PRONOUNS)]
    for tag in negative + list(AGREEING_TAGS):
        n = len(tag) + 1
        statement = body[:-n]
        # 'is it going left , right ?' offers a choice: only a statement takes an agreeing tag
        asked = tag[1:2] != ["not"] and statement[:1] and statement[0] in YES_NO_OPENERS | ASKING | {"how"}
        if len(body) <= n or body[-n:] != [","] + tag or asked:
            continue
        # a statement's own negation only as 'not moving', which reads as static ('it is not moving , is not it ?')
        if not any(w in NEGATIONS and not (w == "not" and statement[k + 1:k + 2] and statement[k + 1] in MOTION_WORDS)
                   for k, w in enumerate(statement)):
            return statement + ["?"], again + ((" ".join(body[-n:]), "?"),)
    # a question asked, then its auxiliary echoed as a tag ('do they crash into each other , do they ?', Welsh and
    # Irish English's 'does it hit the bus , does it ?')
    # (asked first, or after a vehicle said first: not after a condition, 'If ..., would it the bus hit, would it?')
    if body[-3:-2] == [","] and body[-2] in YES_NO_OPENERS and body[-1] in TAG_PRONOUNS and any(
            w in YES_NO_OPENERS and (k == 0 or body[k - 1] == "," and body[0] in ("the", "that", "this"))
            for k, w in enumerate(body[:-3])):
        return body[:-3] + ["?"], again + ((" ".join(body[-3:]), "?"),)
    # a tag without its comma ('is it going slow or nah', 'will it bang into something later or no': no choice
    # offered)
    if body[-2:] in (["or", "nah"], ["or", "nope"], ["or", "naw"], ["or", "no"]):
        return body[:-2] + ["?"], again + ((" ".join(body[-2:]), "?"),)
    # a statement tagged 'right' without its comma, after a vehicle or a time ('... when it hit the wagon right ?'; not
    # 'is it moving right ?')
    if body[-1:] == ["right"] and body[-2:-1] and (body[-2] in OBJECT_WORDS | START_WORDS | FILM_WORDS) and \
            body[:1] and body[0] not in YES_NO_OPENERS | ASKING | {"how"}:
        return body[:-1] + ["?"], again + (("right", "?"),)
    return words, again


# a class a vehicle falls into ('into which speed class does the red sedan fall : static , slow or fast ?')
FALLING_INTO = (["fall", "into"], ["fall", "in"], ["fall"], ["fit", "into"], ["fit", "in"], ["fit"], ["belong", "to"],
                ["belong", "in"], ["belong"], ["land", "in"], ["land", "into"])


def class_as_asked(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'into which speed class does the red sedan fall ?' -> 'which speed class is the red sedan in ?' (asked as yes
    or no, 'does it fall into the slow class', it is an idiom). With the words read so, or the words as they are and
    ()."""
    for k, w in enumerate(words):
        j = k + (words[k + 1:k + 2] == ["speed"]) + 1
        if w not in ("which", "what") or words[j:j + 1] == [] or words[j] not in CLASS_NOUNS or \
                words[j + 1:j + 2] not in (["does"], ["did"]):
            continue
        end = next((m for m in range(j + 2, min(j + 12, len(words)))
                    for f in FALLING_INTO if words[m:m + len(f)] == f), None)
        if end is None:
            return words, ()
        into = next(f for f in FALLING_INTO if words[end:end + len(f)] == f)
        start = k - (words[k - 1:k] in (["into"], ["in"], ["to"]))
        subject = words[j + 2:end]
        # a vehicle's speed said as the subject ('... does the cyan bike 's initial velocity fall ?')
        owner = next((m for m in range(len(subject) - 2) if subject[m:m + 2] == ["'", "s"] and subject[-1] in (
            "speed", "velocity") and set(subject[m + 2:-1]) <= {"first", "initial", "starting", "own"}), None)
        subject = subject[:owner] if owner else subject
        out = [*words[:start], *words[k:j + 1], "is", *subject, "in", *words[end + len(into):]]
        return out, ((" ".join(words[start:end + len(into)]), " ".join(out[start:start + end - k + 1])),)
    return words, ()


CLASSING = {"classified", "classed", "categorised", "categorized", "described", "rated", "labelled", "labeled",
            "logged", "recorded", "graded", "filed", "shaded", "marked", "entered", "characterised", "characterized"}


CLASS_VERBS = {"classify", "class", "categorise", "categorize", "describe", "rate", "label", "log", "record",
               "grade", "file", "shade", "mark", "enter", "characterise", "characterize", "put", "color", "colour"}


def classed_as_asked(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'how should the brown car be classified in the opening moments : static , slow or fast ?' -> 'what is the
    speed of the brown car in the opening moments : ...': a vehicle, or its speed, to be put in the class the choices
    offer. With the words read so, or the words as they are and ()."""
    k = next((k for k in range(len(words) - 1) if words[k:k + 2] in (["how", "should"], ["how", "would"],
                                                                     ["how", "shall"], ["how", "do"])), None)
    # (or its classing said by the speaker: 'how should I shade the double-decker's speed at that moment : ...',
    # 'how do I log it : stationary , slow or fast ?')
    if k is not None and words[k + 2:k + 3] in (["i"], ["we"], ["one"], ["you"]) and words[k + 3:k + 4] and \
            words[k + 3] in CLASS_VERBS and {"static", "slow", "fast"} <= set(words):
        asked = ["what", "is", "its", "speed"] if words[k + 4:k + 5] == ["it"] else ["what", "is"]
        out = [*words[:k], *asked, *words[k + 4 + (words[k + 4:k + 5] == ["it"]):]]
        return out, ((" ".join(words[k:k + 4 + (words[k + 4:k + 5] == ["it"])]), " ".join(asked)),)
    be = words.index("be", k + 2) if k is not None and "be" in words[k + 2:k + 10] else None
    if be is None or words[be + 1:be + 2] == [] or words[be + 1] not in CLASSING or not (
            {"static", "slow", "fast"} <= set(words) or {"speed", "velocity", "pace"} & set(words[k + 2:be])):
        return words, ()
    subject = words[k + 2:be]
    asked = ["what", "is", *subject] if {"speed", "velocity", "pace"} & set(subject) else \
        ["what", "is", "the", "speed", "of", *subject]
    return [*words[:k], *asked, *words[be + 2:]], ((" ".join(words[k:be + 2]), " ".join(asked)),)


def noun_phrase_as_question(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """A question said as the noun phrase it asks for ('speed of the red car at the start?', 'the colour of the
    thing that floats?', 'blue scooter speed at the start?'), or asked for by 'tell me' ('tell me the speed of the
    red car', 'tell me the red car's direction': the grammar says 'tell me how fast ...'; 'tell me the colour of
    the plane that floats', which the decoder read as yes or no), read as 'what is ...'; with the words read so, or
    the words as they are and ()."""
    told = words[:2] == ["tell", "me"]
    k = 2 * told + (words[2 * told:2 * told + 1] == ["the"])
    nouns = QUERY_NOUNS
    if words[k:k + 1] and words[k] in nouns and words[k + 1:k + 2] == ["of"]:
        return ["what", "is", "the"] + words[k:], ((" ".join(words[:k + 2]), f"what is the {words[k]} of"),)
    if told and k == 3:   # 'tell me the red car's speed'
        end = next((i for i in range(k, len(words)) if words[i] not in OBJECT_WORDS), k)
        if end > k and words[end:end + 2] == ["'", "s"] and words[end + 2:end + 3] and words[end + 2] in nouns:
            return ["what", "is"] + words[2:], (("tell me", "what is"),)
    # a note's 'speed at start , purple chopper ?': the noun and its time, then the vehicle alone
    cut = next((i for i in range(k + 2, len(words)) if words[i] in (",", ":", "-")), None)
    if not told and words[k:k + 1] and words[k] in MOTION_NOUNS and cut is not None:
        j = cut + 1 + (words[cut + 1:cut + 2] == ["the"])
        end = next((i for i in range(j, len(words)) if words[i] not in OBJECT_WORDS), len(words))
        if end > j and words[end:] in ([], ["?"], ["."]):
            return ["what", "is", "the", words[k], "of", "the", *words[j:end], *words[k + 1:cut], "?"], \
                ((" ".join(words[k:end]), f"what is the {words[k]} of the {' '.join(words[j:end])} "
                  + " ".join(words[k + 1:cut])),)
    # a label's 'blue scooter speed at the start?' (not 'the bus speed up ...', a learner's verb)
    end = next((i for i in range(k, len(words)) if words[i] not in OBJECT_WORDS), k)
    if not told and end > k and words[end:end + 1] and words[end] in MOTION_NOUNS and \
            words[end + 1:end + 2] not in (["up"], ["down"], ["of"]):
        said = " ".join(words[:end + 1])
        return ["what", "is", "the", words[end], "of", "the", *words[k:end], *words[end + 1:]], \
            ((said, f"what is the {words[end]} of the {' '.join(words[k:end])}"),)
    return words, ()


ALOFT_AFTER = {"above", "over", "in", "up", "off", "aloft"}   # words after "high" that make it a height


def height_as_aloft(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'high above the ground', 'high in the sky', 'high up' said of a vehicle: up in the air, which the grammar
    says 'up in the air' ('high' alone is the grammar's speed, as in 'at high speed'); not 'how high up', which
    asks a height."""
    out, read = [], []
    for k, w in enumerate(words):
        after = words[k + 1] if k + 1 < len(words) else ""
        if w == "high" and after in ALOFT_AFTER and words[k - 1:k] != ["how"]:
            read.append((f"high {after}", "up" if after == "up" else f"up {after}"))
            if after != "up":
                out.append("up")
        else:
            out.append(w)
    return out, tuple(read)


def heading_as_direction(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'heading' as a noun ('the heading of the red car', 'its heading', 'the car's heading'): its direction. The
    grammar says 'heading' only as a verb, of motion ('is the red car heading left'), and reads the noun so too
    ('what is the heading of' was read as the speed). 'how is it heading?' asks which way (it was read as its
    speed). 'what heading is it on (at the start) ?', 'on what heading is it ...?' ask which way it moves."""
    h = len(words) - len(_head(words))
    h += words[h:h + 3] in (["on", "what", "heading"], ["on", "which", "heading"])
    # (or after a clause said first: 'green suv crashes into the cyan one , what heading is the suv on ?')
    h = next((k for k in range(h, len(words) - 2) if words[k:k + 2] in (["what", "heading"], ["which", "heading"])
              and words[k - 1] in (",", ":", ";", "-", ".")), h)
    on = next((k for k in range(h + 3, len(words) - 1) if words[k] == "on" and words[k + 1] in ("at", "when", "?",
                                                                                            "as", "while")), None)
    if words[h:h + 2] in (["what", "heading"], ["which", "heading"]) and words[h + 2:h + 3] in (["is"], ["was"]) and \
            (on is not None or words[h - 1:h] == ["on"]):
        out = [*words[:h - (words[h - 1:h] == ["on"])], words[h], "direction", *words[h + 2:]]
        if on is not None:
            out[on - (words[h - 1:h] == ["on"])] = "moving"
        else:
            out.insert(out.index("at") if "at" in out else len(out) - 1, "moving")
        return out, ((" ".join(words), " ".join(out)),)
    if words[h:h + 1] == ["how"] and words[h + 1:h + 2] and words[h + 1] in AUXILIARIES and \
            {"heading", "headed"} & set(words):
        return [*words[:h], "which", "way", *words[h + 1:]], (("how", "which way"),)
    out, read = list(words), []
    for k, w in enumerate(words):
        if w == "heading" and k and (words[k - 1] in ("the", "its") or words[k - 2:k] == ["'", "s"]):
            out[k] = "direction"
            read.append(("heading", "direction"))
    return out, tuple(read[:1])


# Idioms of this domain's properties, read whole before any word is, as the words the grammar says them in: read
# word by word they meant something else ('flat out' was 'floating' through a typo fix, 'tearing along' slow,
# 'sitting tight' fast, 'right off the bat' a direction). The longest phrase at a place wins.
_START = ("at", "the", "start")
STAYED = ("stayed", "remained", "kept", "stood")
STILL = ("still", "put", "stationary", "motionless", "parked", "stopped")
UNSEEN_PARTS = ("part", "frames", "bit", "footage", "portion", "stretch", "section", "rest", "time")
UNSEEN = (*((who, *neg) for who in ("we", "you", "they") for neg in (
    ("never", "get", "to", "see"), ("have", "not", "seen"), ("do", "not", "see"), ("never", "see"), ("did", "not", "see"),
    ("will", "not", "see"), ("can", "not", "see"), ("have", "not", "been", "shown"), ("were", "not", "shown"))),
          *((who, "have", "not", "shown", "us") for who in ("they", "you")), ("not", "shown"), ("not", "yet", "shown"),
          ("not", "seen"), ("not", "yet", "seen"), ("never", "shown"), ("unseen",))
IDIOMS = phrase_table({
    **{p: _START for p in (("right", "off", "the", "bat"), ("off", "the", "bat"), ("from", "the", "get", "-", "go"),
                           ("from", "the", "get", "go"), ("from", "the", "word", "go"), ("out", "of", "the", "gate"),
                           ("out", "of", "the", "gates"), ("out", "of", "the", "blocks"), ("outta", "the", "gate"),
                           ("outta", "the", "gates"), ("outta", "the", "blocks"), ("when", "things", "kick", "off"),
                           ("as", "things", "kick", "off"), ("when", "it", "all", "kicks", "off"),
                           ("when", "everything", "kicks", "off"), ("from", "the", "off"), ("at", "the", "off"),
                           ("from", "the", "jump"), ("off", "the", "jump"), ("when", "it", "kicks", "off"),
                           ("as", "it", "kicks", "off"), ("when", "it", "first", "kicks", "off"))},
    # 'as soon as it starts , is ...': the video's start, its 'it' no vehicle (not 'when it starts moving')
    **{(*when, "it", starts, ","): (*_START, ",") for when in (("when",), ("as",), ("once",), ("as", "soon", "as"))
       for starts in ("starts", "begins", "started", "began")},
    # a script's 'top of the scene' and 'fade in' (its 'fade out' the end, which no question asks)
    **{(*a, "top", "of", "the", f): ("the", "start") for a in ((), ("the",)) for f in (
        "scene", "take", "shot", "clip", "video", "reel", "footage", "hour", "show")},
    # 'should we expect the bus to hit ...' as the grammar's 'do you expect'
    **{(aux, who, "expect"): ("do", "you", "expect") for aux in ("should", "would", "can", "could", "do", "might")
       for who in ("we", "you", "one") if (aux, who) != ("do", "you")},
    # a note's 'post-video:' is after the video, and with a heading's label its end ('Post-rollout check:')
    **{(*p, *label): ("after", "the", "video", *(("ends",) if label else ())) for p in (
        *(("post", *dash, film) for dash in ((), ("-",)) for film in (
            "video", "clip", "footage", "film", "recording", "feed", "rollout", "simulation", "sim", "playback",
            "sequence", "episode", "tape", "reel", "stream", "broadcast", "run", "trial", "test", "session",
            "experiment", "capture", "shoot", "race", "match", "game")), ("after", "the", "video"))
       for label in ((), *((w,) for w in ("check", "prediction", "projection", "forecast", "query", "question")))
       if p != ("after", "the", "video") or label},
    ("fade", "in"): ("the", "start"), ("fade", "out"): ("the", "end"), ("fade", "-", "in"): ("the", "start"),
    ("fade", "-", "out"): ("the", "end"),
    # the whole of the video is the video ('over the whole clip', 'the entire time')
    **{(p, d, w, f): (p, d, f) for p in ("over", "during", "in", "throughout", "across") for d in ("the", "this")
       for w in ("whole", "entire", "full") for f in ("video", "clip", "footage", "film", "recording", "scene")},
    # an edge in speed is more of it ('did the dirt bike have the edge in speed over the suv ?')
    **{(h, "the", "edge", *s, "over"): (g, "faster", "than") for h, g in (("have", "go"), ("has", "goes"),
       ("had", "went")) for s in ((), ("in", "speed"), ("in", "pace"))},
    # a kind of pace is a speed ('what sort of pace was she keeping'), coming to grief a collision
    **{("what", k, "of", "pace"): ("what", "speed") for k in ("kind", "sort", "type")},
    **{(v, "to", "grief", p): (h, "into") for v, h in (("come", "crash"), ("came", "crashed"), ("comes", "crashes"))
       for p in ("against", "on", "with")},
    # not an inch is not at all ('never moved an inch': it was read as slow)
    **{(v, "an", "inch"): (v,) for v in ("moved", "move", "moves", "budged", "budge", "budges")},
    # the video's end said as what someone did to it ('finna hit something after where they stopped the video?')
    **{(*a, "they", v, "the", f): ("after", "the", "video", "ends") for a in (("after", "where"), ("after",), ("past",
       "where")) for v in ("stopped", "cut", "paused", "ended") for f in ("video", "clip", "footage")},
    # British and American similes of speed said whole ('going like the clappers', 'hell for leather')
    **{p: ("fast",) for p in (("like", "the", "clappers"), ("like", "greased", "lightning"), ("like", "stink"),
                              ("hell", "for", "leather"), ("at", "a", "rate", "of", "knots"), ("like", "a", "shot"))},
    # more and more speed is speeding up ('getting faster and faster', 'going quicker an' quicker')
    **{(*v, f, "and", f): (a,) for f in ("faster", "quicker", "speedier") for v, a in (
        (("getting",), "accelerating"), (("going",), "accelerating"), (("moving",), "accelerating"),
        (("gets",), "accelerates"), (("got",), "accelerated"), (("get",), "accelerate"), ((), "accelerating"))},
    # a Nigerian's greeting before the question ('How far, is the red bus ...'), and the frames that are left (the
    # rest of the video: 'In whatever frames are left, is the truck gonna ...')
    **{("how", "far", ",", w): (w,) for w in ("is", "was", "are", "were", "do", "does", "did", "will", "would", "which",
                                               "what", "when", "if", "initially", "at", "in", "right", "suppose")},
    **{(p, *the, "frames", *that, *are, "left"): ("after", "the", "video", "ends") for p in ("in", "during", "over")
       for the in (("the",), ("whatever",), ("what", "ever")) for that in ((), ("that",), ("which",))
       for are in (("are",), ("'", "s"), ("is",))},
    # 'that first appearance' of a vehicle the sentence before brought in ('The airliner makes its entrance at last.
    # At that first appearance, is it ...?'): its own, not the start's
    **{(p, "that", "first", n): (p, "its", "first", n) for p in ("at", "on", "upon", "in")
       for n in ("appearance", "entrance", "arrival")},
    # what an engine does, said again after it ('is its engine running at the start , pushing it ever faster ?')
    **{(",", v, "it", *e, "faster"): () for v in ("pushing", "urging", "driving", "propelling", "spurring")
       for e in ((), ("ever",), ("even",), ("still",))},
    # a state a vehicle was left in is that state ('had the biplane been left floating from the start'), and 'on the
    # back foot' before the slower speed it says ('is the red sedan on the back foot , going slower than ...')
    **{(b, "left", st): (b, st) for b in ("been", "be", "was", "were", "is", "being")
       for st in ("floating", "hovering", "static", "standing", "parked", "still", "stationary", "motionless",
                  "sitting", "idle")},
    ("on", "the", "back", "foot", ","): (),
    # what a vehicle hit, said as its victim, its target or its partner in the crash ('what type of vehicle is its
    # unfortunate victim?' after a sentence that says it hits something)
    **{("its", *adj, n, *tail): ("the", "thing", "it", "hit") for adj in ((), ("unfortunate",), ("unlucky",),
                                                                          ("poor",), ("hapless",))
       for n in ("victim", "target", "partner") for tail in ((), ("in", "the", "crash"), ("in", "the", "collision"))},
    # a newsreel's 'pray tell', 'party to a bump', 'keeping aloft'; a farmer's 'butt heads'
    # spared a collision is not in one, the question's other side ('would it have struck the bus, or would it have
    # been spared?')
    **{(",", "or", "would", w, "have", "been", "spared"): (",", "or", "not") for w in ("it", "both", "they", "he",
                                                                                      "she")},
    **{(",", "or", "would", f, "have", "spared", o): (",", "or", "not") for f in ("fate", "luck", "chance", "fortune")
       for o in ("them", "it", "her", "him")},
    # past the last frame shown is after the video ('After the last frame we're shown... does a collision await ...')
    **{(p, "the", "last", f, *shown): ("after", "the", "video", "ends") for p in ("after", "past", "beyond")
       for f in ("frame", "frames") for shown in (("we", "'", "re", "shown"), ("we", "are", "shown"), ("shown",),
                                                   ("we", "see"), ("we", "get"))},
    # the part of the video no one sees is after it ('in the moments we will never see', 'in the time we are not
    # allowed to see', 'in the frames we don't get to see')
    **{("in", "the", t, "we", *n, "see"): ("after", "the", "video", "ends")
       for t in ("time", "moments", "frames", "part", "bit", "seconds")
       for n in (("will", "never"), ("never",), ("are", "not", "allowed", "to"), ("do", "not", "get", "to"),
                 ("never", "get", "to"), ("can", "not"), ("cannot",), ("do", "not"), ("will", "not"))},
    # a claim said right or correct is said true ('She asks whether it's right that the blue SUV was ...')
    **{(*it, r, "that"): ("it", "is", "true", "that") for r in ("right", "correct")
       for it in (("it", "'", "s"), ("it", "is"))},
    **{("is", "it", r, "that"): ("is", "it", "true", "that") for r in ("right", "correct")},
    # lagging behind in speed is going slower ('does the gray chopper lag in speed behind the yellow motorbike'; not
    # 'lag behind' alone, which may say where it is)
    **{(lag, *s, "behind"): (go, "slower", "than") for lag, go in (("lag", "go"), ("lags", "goes"), ("lagged", "went"),
                                                                   ("lagging", "going"))
       for s in (("in", "speed"), ("in", "pace"))},
    # speeding up 'more and more' is speeding up ('which kind of vehicle is speeding up more and more')
    **{(v, *u, "more", "and", "more"): (v, *u) for v, u in (("speeding", ("up",)), ("accelerating", ()),
                                                           ("picking", ("up", "speed")))},
    # a patent's 'said vehicle' is the vehicle, and ', as depicted in the video,' says nothing the question does not
    **{("said", w): ("the", w) for w in (*OBJECT_WORDS, *COLOR_NAMES, "vehicle", "object", "one")},
    **{(",", "as", v, *tail, ","): () for v in ("depicted", "shown", "recorded", "seen", "captured", "filmed")
       for tail in ((), *((p, "the", f) for p in ("in", "on") for f in ("video", "clip", "footage", "recording")))},
    # a textbook's 'is observed to collide' says it collides, and its 'a second body' is another object, not a time
    **{(b, o, "to", v): (h,) for b in ("is", "was") for o in ("observed", "seen", "found")
       for v, h in (("collide", "collides"), ("hit", "hits"), ("strike", "strikes"))},
    **{("a", "second", n): ("another", n) for n in ("body", "object", "vehicle", "thing")},
    ("pray", "tell", ","): (), ("pray", "tell"): (), ("party", "to"): ("involved", "in"),
    **{(f, "itself", "party", "to"): (g, "involved", "in") for f, g in (("find", "get"), ("finds", "gets"),
                                                                         ("found", "got"))},
    **{(k, "aloft"): ("floating",) for k in ("keeping", "staying", "remaining", "holding")},
    # a postman's 'once things carry on' (the video, past its cut; 'carry' alone asks a load)
    **{(c, "on"): (k,) for c, k in (("carry", "continue"), ("carries", "continues"), ("carried", "continued"),
                                     ("carrying", "continuing"))},
    **{("butt", h): ("collide",) for h in ("heads", "head")}, ("butted", "heads"): ("collided",),
    ("butting", "heads"): ("colliding",),
    # the part seen is the video ('efter the bit we've seen', 'after this part'), a streamer's 'cranking up its
    # speed', New York's 'this guy' of a vehicle ('is this guy movin' faster than the SUV?'; not 'the guy driving it')
    **{("after", d, part, *that, who, "have", *seen): ("after", "the", "video", "ends") for d in ("the", "this")
       for part in ("bit", "part", "moment", "stretch") for that in ((), ("that",)) for who in ("we", "you")
       for seen in (("seen",), ("watched",), ("been", "shown"))},
    **{("after", "this", part): ("after", "the", "video", "ends") for part in ("bit", "part")},
    # ... and the part not seen is after it ('in the frames we haven't seen yet', 'the footage they haven't shown us',
    # 'in the part we never get to see', 'in the part of the video not shown')
    **{(*p, "the", part, *of, *that, *unseen, *yet): ("after", "the", "video", "ends")
       for p in ((), ("in",), ("during",), ("over",)) for part in UNSEEN_PARTS
       for of in ((), ("of", "the", "video"), ("of", "the", "clip"), ("of", "the", "footage")) for that in ((), ("that",))
       for unseen in UNSEEN for yet in ((), ("yet",))},
    **{(d, "guy"): (d, "one") for d in ("this", "that")},
    **{(c, "up", *p, "speed"): ("accelerating",) for c in ("cranking", "ramping", "winding", "revving", "scaling",
                                                            "stepping", "amping", "jacking", "dialing", "dialling")
       for p in (("its",), ("the",), ("her",), ("his",), ())},
    **{("upping", *p, "speed"): ("accelerating",) for p in (("its",), ("the",), ("her",), ("his",), ())},
    # a Londoner's coloured 'motor' is a car ('it prangs the red motor'; 'its motor' is its engine), a pit wall's
    # 'flying at full pace' a speed (not floating)
    **{(c, "motor"): (c, "car") for c in (*COLOR_NAMES, "grey")},
    **{(*fly, "at", "full", p): (*(("moving",) if fly else ()), "fast") for fly in ((), ("flying",))
       for p in ("pace", "speed", "tilt", "throttle", "pelt", "chat")},
    # a briefing's 'kinetic contact' (its hour, 'at H-hour', is read by `tokenize`), a pit wall's 'lights out', 'after
    # the chequered flag', 'carrying less pace than', 'down on pace versus'
    ("kinetic", "contact"): ("contact",),
    ("lights", "out", ",", "and"): ("at", "the", "start", ","), ("lights", "out", ","): ("at", "the", "start", ","),
    **{("after", "the", flag, "flag"): ("after", "the", "video", "ends") for flag in ("chequered", "checkered")},
    **{("carrying", *d, "pace", *than): said for d, than, said in (
        (("less",), ("than",), ("moving", "slower", "than")), (("more",), ("than",), ("moving", "faster", "than")),
        *(((d,), (), ("moving", "fast")) for d in ("big", "serious", "real", "good", "proper", "huge")))},
    **{(*lacking, "compared", "to"): ("slower", "than") for lacking in (("lacking", "pace"), ("down", "on", "pace"))},
    **{("down", "on", "pace", v): ("slower", "than") for v in ("versus", "vs", "to", "against", "on")},
    # a Londoner's 'have a butcher's at' (a look), 'd'ya reckon', 'bang at the start' (exactly); 'straight off'; a
    # bump one gets 'caught up in'; Gen-Alpha's 'no cap'
    ("have", "a", "butcher", "'", "s", "at"): ("at",), ("have", "a", "butcher", "'", "s"): (),
    **{(*c, "d", "'", y, v): () for c in ((), (",",)) for y in ("ya", "you", "yer", "yinz", "youse")
       for v in ("reckon", "think", "know", "suppose")},
    ("bang", "at", "the"): ("right", "at", "the"), ("straight", "off", "at"): ("at",),
    ("straight", "off", ","): ("at", "the", "start", ","),
    **{(g, *itself, caught, "up", "in"): (g, "involved", "in") for g in ("get", "gets", "got", "getting")
       for itself in ((), ("itself",)) for caught in ("caught", "mixed", "tangled")},
    ("no", "cap"): (),
    # Irish English: 'yer man' and 'yer one' point at a vehicle ('is yer man the brown bicycle going to ...', 'would
    # yer man have run into ...'), 'giving it socks' (going fast), 'c'mere till I ask ya', a tag ', would ya say',
    # 'all the same'
    **{("yer", m, "the"): ("the",) for m in ("man", "one", "wan", "woman")},
    **{("yer", m): ("it",) for m in ("man", "woman")}, ("yer", "one"): ("the", "one"), ("yer", "wan"): ("the", "one"),
    **{(g, "it", s): ("going", "fast") for g in ("giving", "givin") for s in ("socks", "welly", "loads", "holly")},
    **{("c", "'", "mere", *till): () for till in ((), ("till", "i", "ask", "you"), ("till", "i", "ask", "ya"),
                                                   ("till", "i", "ask", "ye"))},
    **{(",", "would", y, "say", "?"): ("?",) for y in ("you", "ya", "ye")}, (",", "all", "the", "same"): (),
    ("all", "the", "same", "?"): ("?",),
    # a traffic report's 'once we come off air' (after the video), 'as we hit the top of the hour' (the start), 'any
    # word on whether'
    **{(w, "we", c, "off", "air"): ("after", "the", "video", "ends") for w in ("once", "when", "after")
       for c in ("come", "go", "are")},
    **{("as", "we", h, "the", "top", "of", "the", "hour"): ("at", "the", "start") for h in ("hit", "reach", "start")},
    ("any", "word", "on", "whether"): ("tell", "me", "whether"),
    ("budged",): ("moved",), ("budges",): ("moves",),   # (not 'bumped', which the typo fix made of them)
    # a ship's officer's knots (speed), weighing anchor and first light (the start), its directions glossed ('front
    # (fore)'); a Bostonian's 'wicked fast'; a car vlogger's 'off the line' (the start), 'sitting at the lights'; a
    # flapper's 'putt-putting along', 'at a higher clip than', 'not moving a lick', 'sitting pretty'; a fan's 'or am I
    # delulu'
    **{(m, more, "knots", "than"): ("moving", said, "than") for m in ("making", "doing", "logging")
       for more, said in (("more", "faster"), ("fewer", "slower"), ("less", "slower"))},
    **{(*w, "we", weigh, "anchor"): ("at", "the", "start") for w in (("when",), ("as",), ("right", "as"), ("once",))
       for weigh in ("weigh", "weighed")},
    ("at", "first", "light"): ("at", "the", "start"),
    **{(d, "(", n, ")"): (d,) for d, n in (("front", "fore"), ("back", "aft"), ("left", "port"),
                                             ("right", "starboard"), ("front", "forward"), ("back", "astern"))},
    **{("wicked", s): (s,) for s in ("fast", "slow", "quick", "slowly", "quickly")},
    **{(c, "off", "the", "line"): (s,) for c, s in (("come", "started"), ("came", "started"), ("comes", "starts"),
                                                    ("coming", "starting"))},
    **{(v, "at", "the", "lights"): (v, "still") for v in ("sitting", "sat", "sits", "waiting", "stopped")},
    ("putt", "-", "putting", "along"): ("moving", "slowly"), ("putt", "-", "putting"): ("moving", "slowly"),
    **{("at", "a", h, p, "than"): (f, "than") for h, f in (
        ("higher", "faster"), ("faster", "faster"), ("greater", "faster"), ("lower", "slower"), ("slower", "slower"))
       for p in ("clip", "pace", "speed", "rate")},
    ("moving", "a", "lick"): ("moving", "at", "all"), ("sitting", "pretty"): ("sitting", "still"),
    **{("or", "am", "i", *w): () for w in (("delulu",), ("tripping",), ("crazy",), ("imagining", "it"),
                                            ("making", "it", "up"), ("seeing", "things"))},
    # a cricket commentator's start of play and first ball, stumps (the end), 'a right old collision', 'standing at
    # the crease' (still), 'picking up pace'
    **{p: ("start",) for p in (("start", "of", "play"), ("first", "ball"))}, ("after", "stumps"): (
        "after", "the", "video", "ends"), ("right", "old"): (),
    **{(s, *like, "at", "the", "crease"): (s, "still") for s in ("standing", "stood", "stands", "stand")
       for like in ((), ("like", "a", "statue"))},
    **{(p, "up", "pace"): (p, "up", "speed") for p in ("pick", "picks", "picking", "picked")},
    # a skater's 'shredding' (fast) and 'chilling' (still), 'drops in' (comes into view), 'wrecks into' (crashes into)
    ("shredding",): ("moving", "fast"), ("shredding", "harder", "than"): ("moving", "faster", "than"),
    **{(*j, "chilling", *t): ("standing", "still") for j in ((), ("just",)) for t in ((), ("there",))},
    **{(d, *i): (c, "into", "view") for d, c in (("drops", "comes"), ("drop", "come"), ("dropped", "came"),
                                                 ("dropping", "coming")) for i in (("in",), ("into", "view"))},
    **{(w, "into"): (c, "into") for w, c in (("wrecks", "crashes"), ("wreck", "crash"), ("wrecked", "crashed"),
                                             ("wrecking", "crashing"))},
    # a station announcer's 'passengers are requested to tell', 'at the time of departure' (the start), 'after the
    # final halt' (after the video), 'proceeding' (moving)
    **{("passengers", "are", *k, "requested", "to", "tell", *c): ("tell", "me") for k in ((), ("kindly",))
       for c in ((), (",",), (":",))},
    **{(*a, "the", *v, "time", "of", "departure"): ("at", "the", "start") for a in (("at",), ())
       for v in ((), ("very",))},
    ("after", "the", "final", "halt"): ("after", "the", "video", "ends"),
    ("proceeding",): ("moving",), ("proceeds",): ("moves",),
    # a starship captain's stardate zero (the start), the log (the video), full impulse (fast), 'Number One'
    **{(*a, "stardate", "zero"): s for a, s in ((("since",), ("from", "the", "start")), ((), ("the", "start")))},
    **{(*a, "full", "impulse"): ("fast",) for a in ((), ("at",))},
    ("after", "the", "log", "ends"): ("after", "the", "video", "ends"), ("the", "log"): ("the", "video"),
    **{(*c, "number", "one", *e): () for c, e in (((",",), ()), ((), (",",)), ((), (":",)))},
    # a physicist's translational speed and a collision undergone; a snowboarder's 'bombing' (fast) and 'wipes out
    # into' (crashes into); a football commentator's kick-off (the start), final whistle (the end) and turn of pace
    ("translational", "speed"): ("speed",), ("translational", "velocity"): ("velocity",),
    **{(u, *a, "collision", "with"): (c, "with") for u, c in (("undergoes", "collides"), ("undergo", "collide"),
                                                            ("underwent", "collided"), ("undergoing", "colliding"))
       for a in (("a",), ("its",), ("their",))},
    **{(u, "a", "collision"): (c,) for u, c in (("undergoes", "collides"), ("undergo", "collide"),
                                                ("underwent", "collided"), ("undergoing", "colliding"))},
    ("bombing",): ("moving", "fast"),
    **{("straight", "-", "up", v): (v,) for v in ("bombing", "shredding", "racing", "flying", "zooming", "speeding",
                                                  "crawling", "flooring")},
    **{(w, "out", "into"): (c, "into") for w, c in (("wipes", "crashes"), ("wipe", "crash"), ("wiped", "crashed"),
                                                    ("wiping", "crashing"))},
    **{(w, "out", "together"): (c,) for w, c in (("wipe", "collide"), ("wiped", "collided"), ("wiping", "colliding"))},
    **{(f, "kick", *h, "off"): ("from", "the", "start") for f in ("from", "since") for h in ((), ("-",))},
    ("straight", "from"): ("right", "from"),
    **{("as", "the", *r, b, "for", "kick", *h, "off"): ("at", "the", "start") for r in (("whistle",), ("ref",))
       for b in ("goes", "blows") for h in ((), ("-",))},
    **{(*o, "the", "final", "whistle"): ("after", "the", "video", "ends") for o in (
        ("past",), ("after",), ("once", "we", "'", "re", "past"), ("once", "we", "are", "past"))},
    ("a", "quicker", "turn", "of", "pace", "than"): ("faster", "than"),
    # a trader's 'ripping' (fast), opening so, straight out of the open; Ulster's 'wee' (a little) says nothing
    ("ripping",): ("racing",), **{(o, "ripping"): (s, "fast") for o, s in (("opened", "started"),
                                                                                   ("opens", "starts"))},
    ("straight", "out", "of", "the", "open"): ("at", "the", "start"), ("wee",): (),
    # a yoga teacher's 'let your attention rest softly on', 'gently notice', 'as the video breathes in' (the start)
    **{("let", "your", "attention", "rest", *a, "on"): () for a in ((), ("softly",), ("gently",), ("lightly",))},
    **{(g, v): () for g in ("gently", "softly") for v in ("notice", "observe", "watch")},
    **{("as", "the", f, "breathes", "in"): ("at", "the", "start") for f in ("video", "clip", "film", "footage")},
    # a dispatcher's 10-50 (a collision) and time of call (the start); a trader's close (the end: past it, after the
    # video) and a flat vehicle (still; 'flat out' and 'flat chat' stay fast; 'is the red car flat' was read as
    # floating, a typo's 'float')
    **{(*d, "10", "-", "50"): (*d, "collision") for d in ((), ("the",), ("a",))},
    **{("at", *d, "time", "of", "call"): ("at", "the", "start") for d in ((), ("the",))},
    **{(*l, p, "the", "close"): ("after", "the", "video", "ends") for l in ((), ("looking",))
       for p in ("past", "after")},
    **{(b, "flat", *o): (b, "fast" if o else "static") for b in (
        "been", "is", "was", "sitting", "stays", "stayed", "remained", "remains", "just", "it", "one", *OBJECT_WORDS)
       for o in ((), ("out",), ("-", "out"), ("chat",))},
    # a game master's party watching ('As the scene opens, your party eyes the gray mountain bike - is it ...?',
    # 'before your party's eyes', 'roll for perception:'), and a video said to be over by a time (within it: 'By the
    # time the scene ends, has the cyan aeroplane run into something?' was read after it; said of a motion it asks at
    # the end, refused)
    **{("your", "party", *v): () for v in (("sees",), ("eyes",), ("spots",), ("tracks",), ("watches",),
                                            ("notices",), ("sizes", "up"))},
    **{("before", "your", "party", *e): () for e in ((), ("'", "s", "eyes"))},
    **{("roll", "for", "perception", *c): () for c in ((), (":",), (",",), ("-",))},
    **{("by", "the", "time", d, f, e, ",", aux): ("in", "the", "video", ",", aux) for d in ("the", "this") for f in (
        "video", "clip", "scene", "footage", "film", "recording") for e in ("ends", "finishes", "stops")
       for aux in ("has", "have", "does", "do", "did")},   # (not of a motion: 'by the time it ends, is it fast?')
    # a cook's simmer (slow), rolling boil (fast), resting, 'folds into' (crashes into), the dish (the video), out of
    # the oven (after it)
    **{("at", "a", *a, "simmer"): ("slowly",) for a in ((), ("low",), ("gentle",), ("lazy",))},
    **{("at", "a", *a, "boil"): ("fast",) for a in (("rolling",), ("full",))},
    **{p: ("faster", "than") for p in (("at", "a", "hotter", "boil", "than"), ("on", "a", "hotter", "heat", "than"))},
    **{p: ("slower", "than") for p in (("at", "a", "lazier", "simmer", "than"), ("on", "a", "gentler", "heat", "than"),
                                       ("at", "a", "gentler", "simmer", "than"))},
    **{(f, *r, "into"): (c, "into") for f, c in (("fold", "crash"), ("folds", "crashes"), ("folded", "crashed"),
                                                 ("folding", "crashing")) for r in ((), ("right",))},
    **{(f, "together"): (c,) for f, c in (("fold", "collide"), ("folds", "collides"), ("folded", "collided"),
                                          ("folding", "colliding"))},
    **{("in", "this", d): ("in", "the", "video") for d in ("recipe", "dish")},
    **{("once", "it", *b, "out", "of", "the", "oven"): ("after", "the", "video", "ends")
       for b in (("'", "s"), ("is",))},
    # a formal writer's 'the aforementioned', 'let it be imagined that', 'in the hypothetical case that', 'with great
    # speed'
    ("the", "aforementioned"): ("the",), ("the", "aforesaid"): ("the",),
    ("let", "it", "be", "imagined", "that"): ("imagine", "that"),
    ("in", "the", "hypothetical", "case", "that"): ("if",),
    ("with", "great", "speed"): ("fast",),
    # a streamer's cutscene and a radio ham's transmission: after the video, its top the start; 'QSL?' asks nothing
    ("after", "the", "cutscene"): ("after", "the", "video", "ends"),
    ("after", "qrt"): ("after", "the", "video", "ends"),
    ("at", "the", "top", "of", "the", "transmission"): ("at", "the", "start"), ("qsl", "?"): (),
    # a race caller's start ('as they break from the gates', 'and they're off', 'at the break'), its 'left standing'
    # (not moving), a 'runner' and a 'race' (a vehicle and the video), 'past the post' (after the video)
    **{("as", "they", *v): ("at", "the", "start") for v in (
        ("break",), *((b, *f, "the", "gates") for b, f in (
            ("break", ("from",)), ("break", ("out", "of")), ("come", ("out", "of")), ("leave", ()),
            ("jump", ("from",)), ("jump", ("out", "of")), ("spring", ("from",)), ("burst", ("out", "of")))))},
    **{(a, "the", g): ("at", "the", "start") for a in ("at", "from") for g in ("break", "gates")},
    **{(*a, "they", "'", "re", o, *c): () for a in ((), ("and",)) for o in ("off", "away")
       for c in ((), (",",), ("-",))},
    **{(w, "left", "standing"): (w, "standing", "still")
       for w in (*OBJECT_WORDS, "it", "been", "is", "was", "be", ":")},
    **{("in", "this", r): ("in", "the", "video") for r in ("race", "running", "run", "heat")},
    ("from", "the", "gates", "to", "the", "wire"): ("in", "the", "video"),
    **{(*o, "past", "the", "post"): ("after", "the", "video", "ends") for o in (
        ("once", "they", "'", "re"), ("once", "they", "are"), ("when", "they", "'", "re"), ("after", "they", "'", "re"),
        ("after", "they", "are"), ("once",), ())},
    # South Asian English's 'dash' of a collision ('did the wagon dash into the blue aeroplane', 'it dashes with the
    # car'; 'dashing' alone stays a speed), and a vehicle that dashes into view (enters it)
    **{(d, p): (c, p) for d, c in (("dash", "crash"), ("dashes", "crashes"), ("dashed", "crashed"),
                                   ("dashing", "crashing")) for p in ("into", "with")},
    **{(d, "into", *t, v): (c, "into", "view") for d, c in (("dash", "come"), ("dashes", "comes"), ("dashed", "came"),
                                                            ("dashing", "coming"))
       for t in ((), ("the",)) for v in ("view", "frame", "shot", "scene", "picture", "sight")},
    # ... or rolls or drifts into the scene ('The brown cruiser rolls into the scene, recruit: is it ... at that
    # moment?'; 'drifts' was read as a turn)
    **{(verb, "into", *t, v): (c, "into", "view") for forms in (
        ("rolls", "rolled", "rolling", "roll"), ("cruises", "cruised", "cruising", "cruise"),
        ("trundles", "trundled", "trundling", "trundle"), ("glides", "glided", "gliding", "glide"),
        ("drifts", "drifted", "drifting", "drift"), ("slides", "slid", "sliding", "slide"))
       for verb, c in zip(forms, ("comes", "came", "coming", "come"))
       for t in ((), ("the",)) for v in ("view", "frame", "shot", "scene", "picture", "sight")},
    # a Victorian's 'moving picture' (a video), 'motor-bicycle', 'grows ever swifter' (accelerates), 'dashes itself
    # against' (crashes into), 'at a great pace', 'when first it comes into view', 'the frames we are shown'
    ("moving", "picture"): ("video",), ("of", "the", "picture"): ("of", "the", "video"),
    **{(*c, "motor", *h, b): (*c, "motorbike" + s) for c in ((), *((k,) for k in (*COLOR_NAMES, "grey")))
       for h in ((), ("-",)) for b, s in (("bicycle", ""), ("bicycles", "s"))},
    **{(g, "ever", f): (a,) for g, a in (("grows", "accelerates"), ("grow", "accelerate"), ("grew", "accelerated"),
                                         ("growing", "accelerating")) for f in ("swifter", "faster", "quicker")},
    **{(d, "itself", "against"): (c, "into") for d, c in (("dashes", "crashes"), ("dash", "crash"),
                                                          ("dashed", "crashed"), ("dashing", "crashing"))},
    **{("at", "a", g, p): ("fast",) for g in ("great", "brisk", "furious", "tremendous", "rapid", "lively", "spanking",
                                              "breakneck") for p in ("pace", "clip", "rate", "speed")},
    ("when", "first", "it"): ("when", "it", "first"),
    **{("in", "the", "frames", "we", *b, s): ("in", "the", "video") for b in (
        ("are",), ("were",), ("have",), ("'", "ve"), ("have", "been"), ("'", "ve", "been")) for s in ("shown", "seen")},
    # mission control's 'on station' (holding still; its 'post-LOS' is read by `tokenize`), its 'go or no-go' (yes or
    # no), 'carrying more velocity than'
    ("on", "station"): ("stationary",),
    ("go", "or", "no", "-", "go"): ("yes", "or", "no"), ("go", "or", "no", "go"): ("yes", "or", "no"),
    ("velocity", "call"): ("speed",),
    **{("carrying", d, v, *than): said for v in ("velocity", "speed") for d, than, said in (
        ("less", ("than",), ("moving", "slower", "than")), ("more", ("than",), ("moving", "faster", "than")),
        ("high", (), ("moving", "fast")), ("low", (), ("moving", "slowly")))},
    # a trucker on the CB ('breaker one-nine', 'good buddy', 'hammer down' (fast), 'parked like a bear in the
    # median', 'on this tape' (the video), 'pulls into view')
    **{(b, *n): () for b in ("breaker",) for n in (("one", "-", "nine"), ("one", "nine"), ("19",), ("breaker",), ())},
    **{(*c, "good", "buddy"): () for c in ((), (",",))},
    **{(*w, "the", "hammer", "down"): ("fast",) for w in (("with",), ())}, ("hammer", "down"): ("fast",),
    ("like", "a", "bear", "in", "the", "median"): (),
    **{(p, d, "tape"): ("in", "the", "video") for p in ("on", "in") for d in ("this", "the")},
    **{(v, "into", "view"): (c, "into", "view") for v, c in (("pulls", "comes"), ("pull", "come"),
                                                              ("pulled", "came"), ("pulling", "coming"))},
    # Newfoundland's tag ('..., b'y?', '..., me son?'); a market's open and opening bell (the start); drifting along
    # (slowly moving, not turning)
    **{(*c, *t): () for c in ((), (",",)) for t in (("b", "'", "y"), ("me", "son"))},
    **{(p, "the", *o): ("at", "the", "start") for p in ("at", "from") for o in (("open",), ("opening", "bell"))},
    **{(d, "along"): (m,) for d, m in (("drifting", "moving"), ("drifts", "moves"), ("drifted", "moved"))},
    # a dialect's 'right' before a speed says it more ('goin' right fast'), no direction
    **{("right", s): (s,) for s in ("fast", "slow", "slowly")},
    ("speed", "demon"): ("fast", "vehicle"),
    # 'not moving in the least', 'without the least hurry' (no ranking among all)
    ("in", "the", "least"): ("at", "all"), ("without", "the", "least"): ("without", "any"),
    # a member's question to a minister ('Will the Minister kindly tell this House the colour ...', 'Can the Minister
    # tell honourable Members which kind ...') and a desk's 'could you please confirm the colour' asks to be told
    **{(aux, "the", role, *manner, verb, *house): ("tell", "me") for aux in ("will", "would", "can", "could")
       for role in ("minister", "secretary", "government") for manner in ((), ("kindly",), ("please",),
                                                                         ("be", "good", "enough", "to"))
       for verb in ("tell", "inform", "advise") for house in ((), ("the", "house"), ("this", "house"),
                                                              ("honourable", "members"), ("members",))},
    **{(aux, "you", *please, confirm, what): ("tell", "me", what) for aux in ("can", "could", "would")
       for please in ((), ("please",), ("kindly",)) for confirm in ("confirm", "verify")
       for what in ("the", "what", "which")},
    # an advertiser's 'for a limited time only' (no time of the video), a quiz host's 'For 500 points' (no way it
    # faces) and 'Final answer?'
    **{("for", n, "points"): () for n in ("100", "200", "250", "300", "400", "500", "600", "800", "1000", "a", "the",
                                          "ten", "twenty", "fifty", "double", "bonus", "extra", "all")},
    **{("?", *your, "final", "answer", "?"): ("?",) for your in ((), ("is", "that", "your"), ("your",))},
    **{("for", "a", "limited", "time", *only): () for only in ((), ("only",))},
    # 'bangs right into the brown bus' ('right' is no direction there)
    **{(v, "right", into): (v, into) for into in ("into", "in", "at") for v in (
        "crash", "crashes", "crashed", "crashing", "bang", "bangs", "banged", "banging", "slam", "slams", "slammed",
        "slamming", "smash", "smashes", "smashed", "smashing", "run", "runs", "ran", "running", "drive", "drives",
        "drove", "driving", "plough", "ploughs", "ploughed", "plow", "plows", "plowed", "bump", "bumps", "bumped",
        "ram", "rams", "rammed", "barrel", "barrels", "barrelled", "barreled", "go", "goes", "went", "fly", "flies",
        "flew", "careen", "careens", "careened")},
    # a Scot's 'no' of a motion ('the one that's no movin at aw')
    **{(be, "no", v): (be, "not", v) for be in ("is", "s", "was") for v in (
        "moving", "going", "driving", "flying", "floating", "speeding", "accelerating", "hovering")},
    **{p: ("fast",) for p in (("flat", "out"), ("at", "full", "tilt"), ("at", "full", "throttle"), ("at", "a", "clip"),
                              ("at", "a", "good", "clip"), ("at", "a", "fair", "clip"), ("at", "quite", "a", "clip"),
                              ("like", "a", "rocket"), ("like", "the", "wind"),
                              ("like", "a", "bat", "out", "of", "hell"), ("at", "full", "pelt"), ("full", "pelt"))},
    **{(pootle, "along"): (moving, "slowly") for pootle, moving in (
        ("pootling", "moving"), ("pootles", "moves"), ("pootled", "moved"), ("pootle", "move"))},
    # Gen-Z's opener and 'giving' ('ok but ...', 'is it giving parked, slow or zooming'), 'the first few seconds'
    ("ok", "but"): (), ("okay", "but"): (), **{(be, "it", "giving"): (be, "it") for be in ("is", "was")},
    # a dialect's 'this here', a promo's 'kicking off at top speed'
    ("this", "here"): ("this",), ("kicking", "off"): ("starting",),
    # learners' 'stands on place', 'arrives in view first time', 'to which side is it driving'
    **{(v, p, "place"): (v, "still") for v in ("stand", "stands", "standing", "stood", "stay", "stays", "staying",
                                                 "stayed", "hold", "holds", "holding", "held")
       for p in ("on", "in", "at")},
    **{(v, "first", "time"): (v, "for", "the", "first", "time") for v in (
        "view", "sight", "enters", "enter", "entered", "appears", "appear", "appeared", "arrives", "arrived")},
    ("to", "which", "side"): ("in", "which", "direction"),
    ("fast", "more"): ("faster",), ("slow", "more"): ("slower",),   # a signer's gloss: 'CYAN CAR FAST MORE?'
    **{("post", *d, "cut"): ("after", "the", "video", "ends") for d in ((), ("-",))},   # a clinician's 'post-cut'
    # Scandinavian learners' 'shall' of what will happen, 'crash together (with)'
    ("shall",): ("will",), **{("crash" + e, "together", *w): ("collide" + e, *w) for e in ("", "es", "ed")
                              for w in ((), ("with",))},
    # South Asian learners' 'in beginning itself'; a guide's 'over the course of the film', 'compare, if you will, ...'
    **{(w, "itself"): (w,) for w in ("start", "beginning", "starting", "begin", "first")},
    **{("in", w, "itself"): ("at", "the", "start") for w in ("beginning", "start", "starting")},
    **{("over", "the", "course", "of", "the", f): ("in", "the", "video") for f in (
        "video", "clip", "film", "footage", "recording")},
    # ... and 'at any point in the video', said first of what a collision's partner is ('At any point in the video,
    # something crashed into the car; what model is it?' was read as yes or no)
    **{("at", some, "point", p, "the", f): ("in", "the", "video") for some in ("any", "some") for p in ("in", "during")
       for f in ("video", "clip", "film", "footage", "recording")},
    (",", "if", "you", "will", ","): (",",),
    # a Romance learner's 'the class of speed of' a vehicle is its speed ('which is the class of speed of the brown
    # vehicle?')
    **{("the", cls, "of", sp, "of"): ("the", "speed", "of") for cls in ("type", "kind", "class", "category")
       for sp in ("speed", "velocity")},
    **{("first", "few", m): ("first", m) for m in ("seconds", "moments", "frames", "instants")},
    # a video editor's: the whole video scrubbed through, the part after the cut, the last frame passed, a shot or an
    # edit imagined otherwise ('If we'd shot the pickup standing still ...', 'Re-edit it so the SUV ...'), the take's
    # top (its start)
    **{(scrub, "through", "the", *whole, film): ("in", "the", "video")
       for scrub in ("scrubbing", "scrolling", "skimming", "watching", "looking")
       for whole in ((), ("entire",), ("whole",)) for film in ("shot", "clip", "video", "footage", "reel", "take")},
    **{(*within, "the", part, *who, *cannot, *get, "see"): ("after", "the", "video", "ends")
       for within in (("in",), ()) for part in ("part", "bit", "stretch", "frames")
       for who in (("we",), ("you",), ("that", "we"), ("that", "you"))
       for cannot in (("do", "not"), ("can", "not", "yet"), ("cannot", "yet"), ("do", "not", "yet"))
       for get in (("get", "to"), ())},
    **{(past, "the", last, "frame", *of): ("after", "the", "video", "ends")
       for past in ("past", "beyond", "after") for last in ("final", "last")
       for of in ((), *(("of", the, *cut, film) for the in ("the", "this") for cut in ((), ("truncated",), ("cut",))
                        for film in ("clip", "video", "footage", "shot", "reel", "take")))},
    **{("if", "we", *had, shot): ("imagine",) for had in (("'", "d"), ("had",))
       for shot in ("shot", "filmed", "staged", "recorded")},
    **{(*re, "edit", "it", "so", *that): ("imagine",) for re in (("re", "-"), ("re",)) for that in ((), ("that",))},
    **{("from", "the", "top", "of", "the", take): _START for take in ("take", "clip", "reel", "shot", "video")},
    # Southern US English: 'right off' (at once: the start), 'fixin' to' (going to), 'y'all reckon' and 'do you
    # figure' before what is asked ('reckon' was read as 'imagine')
    ("right", "off"): _START, **{(fix, "to"): ("going", "to") for fix in ("fixing", "fixin")},
    **{(*who, think): () for who in (("y", "'", "all"), ("do", "you"), ("do", "y", "'", "all"), ("you",))
       for think in ("reckon", "figure", "suppose")},
    # 'speedier', a colour's 'shade' (as a synonym it took the slip 'shae' from 'shape')
    ("speedier",): ("faster",), ("shade",): ("color",),
    # a viewer's 'all over the place' (its 'over' was the video's end: a collision read after it), 'given what we see'
    ("all", "over", "the", "place"): ("moving",),
    **{("given", "what", who, *v): () for who in ("we", "you", "i") for v in (("see",), ("saw",), ("can", "see"))},
    **{(t, "up", *where): (a,) for t, a in (("turns", "appears"), ("turned", "appeared"), ("turn", "appear"),
                                             ("turning", "appearing")) for where in ((), ("on", "screen"))},
    # a collision near in time ('Is the grey SUV about to crash into the bike?', 'Is a crash coming for the road
    # bike?'), the rest of a video stopped part-way ('In the rest of the video, do ... collide?')
    ("about", "to"): ("going", "to"),
    **{(be, "a", crash, "coming", *up): ("will", "there", "be", "a", crash) for be in ("is", "'s")
       for crash in ("crash", "collision", "smash", "bump", "smash-up", "pile-up", "impact") for up in ((), ("up",))},
    **{(p, "the", "rest", "of", "the", f): ("after", "the", "video", "ends") for p in ("in", "for", "over", "during")
       for f in ("video", "clip", "footage", "film", "recording")},
    # a sceptic's 'Surely you can tell me ..., can't you?'
    **{("surely", "you", can, "tell", "me"): ("tell", "me") for can in ("can", "could")},
    **{(",", can, "not", "you", "?"): ("?",) for can in ("can", "could")},
    # radio's 'at start of tape', 'at first frame'
    **{("at", "start", "of", film): _START for film in ("tape", "feed", "video", "clip", "footage", "recording")},
    ("at", "first", "frame"): _START,
    # a rhetorical aside after the question ('... at the start - wasn't it obvious?', '- didn't it stand out?')
    **{(sep, aux, "not", "it", *plain): () for sep in ("-", ",") for aux in ("is", "was", "did", "does")
       for plain in (("obvious",), ("clear",), ("plain",), ("evident",), ("easy", "to", "spot"), ("easy", "to", "see"),
                     ("something",), ("amazing",), ("incredible",), ("beautiful",), ("gorgeous",),
                     ("easy", "to", "tell"), ("stand", "out"), ("stick", "out"))},
    # a speed as a database's attribute ('the vehicle whose speed is fast at the start')
    **{("whose", speed, be): ("that", be) for speed in ("speed", "pace", "velocity", "motion", "state")
       for be in ("is", "was")},
    # the video's length ('this short clip': 'short' was fixed to 'soon')
    **{(size, film): (film,) for size in ("short", "brief", "quick", "little", "tiny", "small") for film in FILM_WORDS},
    # a reviewer's stress ('whether the chopper is in fact standing still': 'fact' was fixed to 'fast')
    **{p: () for p in (("in", "fact"), ("in", "actual", "fact"), ("as", "a", "matter", "of", "fact"))},
    **{("following", "the", "point", *at): ("after",) for at in (("at", "which"), ("where",), ("when",))},
    # 'when first the scene begins to play', a poet's start
    **{("when", "first", "the", film, begins): _START for film in ("scene", "video", "clip", "film", "play", "show")
       for begins in ("begins", "starts", "opens", "began", "started", "opened", "beginneth", "openeth")},
    # ... and 'when the scene is first unveiled' (the video's, not a vehicle's coming into view), and what lies past
    # a video stopped ('beyond the stopped frames'; 'stopped' was read as a vehicle's)
    **{(past, "the", stopped, film): ("after", "the", "video", "ends") for past in ("after", "beyond", "past")
       for stopped in ("stopped", "halted", "frozen", "paused") for film in ("frames", "vision", *FILM_WORDS)},
    **{(past, "the", stopping): ("after", "the", "video", "ends") for past in ("after", "beyond", "past")
       for stopping in ("stopping", "pausing", "cutoff")},
    **{("when", "the", film, be, "first", shown): _START for film in ("scene", "video", "clip", "film", "footage")
       for be in ("is", "was") for shown in ("shown", "unveiled", "revealed", "played", "screened", "opened")},
    # 'the picture' as older people say the film ('when the picture first began'), not 'comes into the picture'
    **{("the", "picture", *v): ("the", "video", *v) for v in (
        ("began",), ("begins",), ("started",), ("starts",), ("opened",), ("opens",), ("first", "began"),
        ("first", "started"), ("stopped",), ("stops",), ("halted",), ("ended",), ("ends",), ("has",), ("is",), ("was",),
        ("froze",), ("freezes",), ("cuts",), ("cut",))},
    # the video going on, a bettor's or a commentator's ('once the clip carries on', 'when the action resumes')
    **{(when, "the", film, *resumes): ("after", "the", "video", "ends") for when in ("once", "when", "after", "if")
       for film in ("video", "clip", "footage", "film", "tape", "recording", "feed", "action", "play")
       for resumes in (("resumes",), ("carries", "on"), ("continues",), ("picks", "up", "again"), ("restarts",),
                       ("starts", "again"), ("plays", "on"), ("rolls", "on"), ("goes", "on"), ("keeps", "going"))},
    **{(verb + ending, "along"): (moving, "fast") for verb in ("tear", "belt", "bomb", "barrel", "bowl", "motor",
                                                                 "pelt", "streak", "rocket", "haul", "scream", "zoom",
                                                                 "whizz", "whiz", "race")
       for ending, moving in (("ing", "moving"), ("s", "moves"), ("ed", "moved"), ("in", "moving"))},
    ("hauling",): ("moving", "fast"),
    ("at", "a", "fast", "clip"): ("fast",), ("at", "speed"): ("fast",), ("speed", "reading"): ("speed",),
    # Indian English's 'dash' for a collision ('will it dash the red bicycle?'; 'dashing along' stays a speed), and its
    # 'itself' after a time ('from the starting itself')
    **{(dash, after): (hit, after) for dash, hit in (("dash", "hit"), ("dashes", "hits"), ("dashed", "hit"),
                                                     ("dashing", "hitting")) for after in ("the", "a", "an", "each")},
    **{(start, "itself"): (start,) for start in ("start", "starting", "beginning", "outset")},
    # everyday speeds and starts ('has it got its foot down', 'going like mad', 'when things get going', 'started out')
    **{(got, "its", "foot", "down"): ("accelerating",) for got in ("got", "with")},
    ("like", "mad"): ("fast",), ("like", "crazy"): ("fast",),
    **{p: _START for p in (("when", "things", "get", "going"), ("as", "things", "get", "going"),
                           ("when", "things", "got", "going"))},
    **{(start, "out"): (start,) for start in ("started", "starts", "start", "starting")},
    # an engineer's words ('velocity magnitude class', 'kinematic state', 'undergo an impact with', 'propulsion active',
    # 'positive longitudinal acceleration', 'heading vector', 'holding a hover')
    ("velocity", "magnitude", "class"): ("speed",), ("velocity", "class"): ("speed",),
    ("velocity", "magnitude"): ("velocity",), ("speed", "magnitude"): ("speed",),
    ("kinematic", "state"): ("state",), ("kinematic", "states"): ("state",), ("heading", "vector"): ("direction",),
    **{(undergo, *an, impact, *w): (collide, *w) for undergo, collide in (
        ("undergo", "collide"), ("undergoes", "collides"), ("underwent", "collided"), ("undergoing", "colliding"))
       for an in ((), ("an",), ("a",)) for impact in ("impact", "collision") for w in ((), ("with",))},
    ("propulsion", "active"): ("engine", "on"), ("propulsion", "on"): ("engine", "on"),
    **{(shows, "positive", *longitudinal, "acceleration"): ("is", "accelerating") for shows in (
        "shows", "has", "exhibits", "undergoes", "experiences") for longitudinal in ((), ("longitudinal",))},
    **{(holding, "a", "hover"): ("hovering",) for holding in ("holding", "in", "maintaining")},
    ("over", "the", "duration", "of"): ("during",), ("for", "the", "duration", "of"): ("during",),
    ("field", "of", "view"): ("view",),
    # what follows the stopped video ('is it going to collide with anything from here on?', '... after this point?')
    **{p: ("afterwards",) for p in (("from", "here", "on"), ("from", "this", "point", "on"), ("from", "now", "on"),
                                    ("after", "this", "point"), ("beyond", "this", "point"), ("past", "this", "point"),
                                    ("from", "this", "point", "onwards"), ("from", "here", "onwards"))},
    **{p: ("at", "high", "speed") for p in (("at", "a", "great", "speed"), ("at", "great", "speed"))},
    **{p: _START for p in (("at", "the", "commencement"), ("at", "the", "very", "commencement"))},
    ("manner", "of", "vehicle"): ("kind", "of", "vehicle"), ("what", "manner", "of"): ("what", "kind", "of"),
    # a thesaurus's starts and speeds ('had it set off at a dawdle', 'embarked with alacrity'; 'at a breakneck clip'
    # is with a Victorian's 'at a great pace'), and comparisons ('dawdling relative to the airliner')
    **{(set, off): (started,) for set, started in (("set", "started"), ("sets", "starts"), ("setting", "starting"))
       for off in ("off", "out")},
    **{("at", "a", slow): ("slowly",) for slow in ("dawdle", "crawl", "snail's", "walk", "amble", "trundle")},
    **{p: ("fast",) for p in (("at", "breakneck", "speed"), ("at", "breakneck", "pace"), ("with", "alacrity"),
                              ("with", "great", "alacrity"))},
    **{(pace, "relative", "to"): (said, "than") for pace, said in (
        *((w, "slower") for w in ("slow", "slower", "dawdling", "crawling", "lagging", "sluggish", "leisurely")),
        *((w, "faster") for w in ("fast", "faster", "quick", "quicker", "speedy", "swift", "racing")))},
    # a category by an older name of two words (one word: synonyms.txt)
    ("motor", "car"): ("car",), ("flying", "machine"): ("aeroplane",),
    ("the", "pair", "of", "them"): ("the", "two", "of", "them"),
    ("stock", "-", "still"): ("still",), ("stock", "still"): ("still",),
    # falling behind in speed ('is the airliner lagging behind the suv at the beginning?')
    **{(lag, "behind"): (moving, "slower", "than") for lag, moving in (
        ("lagging", "moving"), ("lags", "moves"), ("lagged", "moved"), ("trailing", "moving"), ("trails", "moves"),
        ("trailed", "moved"))},
    **{p: _START for p in (("right", "off", "the", "gun"), ("off", "the", "gun"), ("from", "the", "gun"),
                           ("right", "off", "the", "top"), ("off", "the", "top"),
                           *(("at", "the", "top", "of", "the", f) for f in ("clip", "video", "footage", "tape",
                                                                             "hour")))},
    # the time after the cut said as what is not seen ('beyond what we see', 'once the paused clip starts up again'),
    # and a collision ahead ('headed for a crash with', 'on course to hit', 'wind up bumping')
    **{p: ("after", "the", "video", "ends") for p in (
        ("beyond", "what", "we", "see"), ("beyond", "what", "we", "get", "to", "see"),
        ("beyond", "what", "we", "are", "shown"), ("beyond", "what", "we", "'", "re", "shown"),
        ("beyond", "the", "end", "of", "what", "we", "'", "re", "shown"),
        ("beyond", "the", "end", "of", "what", "we", "are", "shown"), ("in", "the", "part", "we", "do", "not", "see"),
        ("in", "the", "half", "we", "do", "not", "see"))},
    **{(v, "up", "again"): (c,) for v, c in (("starts", "continues"), ("start", "continue"), ("picks", "continues"),
                                             ("picked", "continued"), ("started", "continued"))},
    **{(h, "for", "a", c, "with"): ("going", "to", "collide", "with") for h in ("headed", "heading") for c in (
        "crash", "collision", "smash")},
    ("on", "course", "to"): ("going", "to"), ("wind", "up"): ("end", "up"), ("winds", "up"): ("ends", "up"),
    # a comparison in the passive: the one outdone is the slower ('Is the bus outpaced by the car?', 'beaten for speed
    # by', 'left behind by')
    **{(w, *f, "by"): ("slower", "than") for w in (
        "outpaced", "outrun", "outran", "overtaken", "outstripped", "beaten", "outsped", "outdone", "surpassed",
        "bested", "outdistanced", "outraced") for f in ((), ("for", "speed"), ("in", "speed"), ("on", "speed"),
                                                        ("for", "pace"), ("on", "pace"))},
    ("left", "behind", "by"): ("slower", "than"),
    # putting on speed is speeding up; turning up is appearing ('when it first turns up in the video')
    **{(p, "on", "speed"): (a,) for p, a in (("putting", "accelerating"), ("puts", "accelerates"),
                                              ("put", "accelerate"))},
    **{(t, "up", "in"): (a, "in") for t, a in (("turns", "appears"), ("turn", "appear"), ("turned", "appeared"))},
    # British understatement: 'does it happen to bump into', 'manage to collide', 'terribly fast', 'at some stage'
    **{(h, "to", v): (v,) for h in ("happen", "happens", "happened", "manage", "manages", "managed") for v in (
        "bump", "hit", "collide", "crash", "touch", "run", "strike", "smash", "knock", "clip", "graze", "tap", "meet",
        "be", "move", "go", "float", "hover", "have", "speed", "accelerate", "come", "get", "end")},
    **{(i, v): (v,) for i in ("terribly", "awfully", "frightfully", "dreadfully") for v in (
        "fast", "slow", "slowly", "quickly", "quick")},
    ("at", "some", "stage"): ("at", "some", "point"),
    # a rider's, a runner's and a driver's words ('at a dead stop', 'at a gallop', 'jogging along', 'making better
    # speed than', 'at a gentler pace than', 'putting the hammer down', 'fetched up against')
    ("at", "a", "dead", "stop"): ("static",), ("at", "anchor"): ("static",),
    **{p: ("fast",) for p in (("at", "a", "gallop"), ("at", "full", "gallop"), ("at", "a", "sprint"),
                              ("at", "full", "sprint"))},
    **{p: ("slowly",) for p in (("at", "a", "jog"), ("at", "a", "trot"))},
    ("jogging", "along"): ("moving", "slowly"),
    **{("making", m, "speed", "than"): ("moving", said, "than") for m, said in (
        ("better", "faster"), ("more", "faster"), ("less", "slower"), ("worse", "slower"))},
    **{("at", "a", m, "pace", "than"): (said, "than") for m, said in (
        ("gentler", "slower"), ("slower", "slower"), ("lower", "slower"), ("faster", "faster"), ("quicker", "faster"),
        ("higher", "faster"), ("brisker", "faster"))},
    **{(w, "up", "the", "pace"): (a,) for w, a in (("winding", "accelerating"), ("winds", "accelerates"))},
    **{(p, "the", "hammer", "down"): (a,) for p, a in (("putting", "accelerating"), ("puts", "accelerates"),
                                                       ("put", "accelerated"))},
    **{(f, "up", "against"): (c, "into") for f, c in (("fetched", "crashed"), ("fetches", "crashes"),
                                                       ("fetch", "crash"))},
    **{(*i, "throttle", "open"): ("engine", "on") for i in ((), ("the",))},
    # a ship's words for moving and standing ('dead in the water', 'making less way than')
    ("dead", "in", "the", "water"): ("static",), ("making", "way"): ("moving",), ("make", "way"): ("move",),
    **{("making", more, "way", "than"): ("moving", said, "than") for more, said in (("less", "slower"),
                                                                                    ("more", "faster"))},
    **{(crash, "together"): (collide,) for crash, collide in (
        ("crash", "collide"), ("crashes", "collides"), ("crashed", "collided"), ("smash", "collide"),
        ("bump", "collide"), ("come", "collide"), ("came", "collided"))},
    ("in", "mid", "-", "air"): ("in", "the", "air"), ("in", "midair"): ("in", "the", "air"),
    # a physics class's and a simulation's words for the start, floating and collisions
    **{p: _START for p in (("in", "its", "initial", "state"), ("in", "their", "initial", "states"),
                           ("under", "the", "initial", "conditions"), ("under", "initial", "conditions"),
                           ("at", "the", "first", "timestep"), ("at", "the", "first", "time", "step"),
                           ("at", "the", "initial", "timestep"), ("at", "the", "first", "time", "-", "step"),
                           ("in", "the", "initial", "conditions"))},
    **{(*no, "the", "influence", "of", "gravity"): ("floating",) for no in (("not", "under"), ("free", "from"),
                                                                             ("free", "of"), ("outside"))},
    ("unaffected", "by", "gravity"): ("floating",), ("free", "of", "gravity"): ("floating",),
    ("contact", "event"): ("collision",), ("contact", "events"): ("collisions",),
    **{(have, "zero", v): (stand, "still") for v in ("velocity", "speed") for have, stand in (
        ("have", "stand"), ("has", "stands"), ("had", "stood"), ("having", "standing"))},
    **{(w, "zero", v): ("static",) for v in ("velocity", "speed") for w in ("at", "with")},
    # a speed class said as a simulation's bin ('the actor in the fast speed bin', 'does it fall in the slow bin')
    **{(*fall, p, "the", c, *n, b): (*verb, moving if fall else c)
       for c, moving in (("static", "static"), ("slow", "slowly"), ("fast", "fast"))
       for n in ((), ("speed",), ("velocity",), ("velocity", "magnitude"), ("speed", "magnitude"))
       for b in ("bin", "bucket", "class", "category") for p in ("in", "into")
       for fall, verb in (((), ()), (("fall",), ("move",)), (("falls",), ("moves",)))},
    **{(be, passed, "by"): (be, "slower", "than") for be in ("is", "was", "be", "being")
       for passed in ("outpaced", "outrun", "outran", "overtaken", "outstripped")},
    # acceleration said as a noun ('what kind of vehicle is undergoing acceleration at the start?')
    **{(verb, *positive, "acceleration"): ("accelerating",) for verb in ("undergoing", "experiencing", "showing",
                                                                         "under") for positive in ((), ("positive",))},
    # a physics instructor's condition and initial state ('Under the counterfactual initial condition that the red road
    # bike had a high initial velocity, would ...'), and the extrapolated future ('In the extrapolated motion after the
    # final frame, ...')
    **{("under", "the", *kind, condition, "that"): ("if",) for kind in (
        ("counterfactual",), ("counterfactual", "initial"), ("hypothetical",), ("hypothetical", "initial"),
        ("alternative",), ("alternative", "initial")) for condition in ("condition", "assumption", "scenario")},
    **{("had", *a, level, "initial", v): ("had", "been", said, "at", "the", "start")
       for v in ("velocity", "speed") for level, said, a in (
           ("high", "fast", ("a",)), ("large", "fast", ("a",)), ("low", "slow", ("a",)), ("small", "slow", ("a",)),
           ("slow", "slow", ("a",)), ("fast", "fast", ("a",)), ("zero", "static", ()), ("no", "static", ()))},
    **{(*extrapolated, "after", "the", final, "frame"): ("after", "the", "video", "ends")
       for extrapolated in ((), ("in", "the", "extrapolated", "motion"), ("in", "the", "extrapolated", "trajectory"))
       for final in ("final", "last")},
    # on a screen is in view ('when it first shows up on screen')
    **{("on", *the, "screen"): ("in", "view") for the in ((), ("the",))},
    **{p: ("fast",) for p in (("full", "speed"), ("at", "full", "speed"), ("full", "throttle"), ("fast", "fast"))},
    ("bombing", "it"): ("moving", "fast"),
    # 'the green one's just sitting there' ('one's' as 'one is': the decoder read "one 's just" as nothing)
    **{("one", "'", "s", w): ("one", "is", w) for w in ("just", "still", "not", "really", "actually", "totally",
                                                         "sitting", "moving", "going", "parked", "hovering", "floating",
                                                         "speeding", "accelerating", "standing", "driving", "flying")},
    # a commenter's doubt of their own eyes ('... or am i tripping'), and 'no bc' (no because) opening a question
    **{("or", "am", "i", *doubt): () for doubt in (("tripping",), ("trippin",), ("seeing", "things"), ("crazy",),
                                                    ("wrong",), ("imagining", "it"), ("imagining", "things"),
                                                    ("hallucinating",), ("blind",))},
    ("no", "because"): (),   # ('bc' is 'because' to the tokenizer)
    # Australian and New Zealand words: 'flat chat' (fast), 'heaps fast', 'stacked it into' and 'cleaned up' (hit),
    # 'have a prang' (collide), 'hanging about up there' (floating), 'winding up speed' (accelerating)
    ("flat", "chat"): ("fast",),
    **{("heaps", pace): (pace,) for pace in ("fast", "slow", "quick", "quickly", "slowly", "faster", "slower")},
    **{(stack, "it", "into"): (crash, "into") for stack, crash in (("stacked", "crashed"), ("stacks", "crashes"),
                                                                  ("stack", "crash"), ("stacking", "crashing"))},
    **{(clean, "up", the): (hit, the) for clean, hit in (("cleaned", "hit"), ("cleans", "hits"), ("clean", "hit"),
                                                        ("cleaning", "hitting")) for the in ("the", "a", "an")},
    **{(have, "a", prang, *w): (collide, *w) for have, collide in (("have", "collide"), ("has", "collides"),
                                                                    ("had", "collided"), ("having", "colliding"))
       for prang in ("prang", "bingle") for w in ((), ("with",))},
    **{(prang, the): (hit, the) for prang, hit in (("prang", "hit"), ("prangs", "hits"), ("pranged", "hit"),
                                                   ("pranging", "hitting")) for the in ("the", "a", "an", "into")},
    **{(hang, about, *there): ("floating",) for hang in ("hanging", "hangs", "hung") for about in ("about", "around")
       for there in (("up", "there"), ("in", "the", "air"), ("up", "in", "the", "air"), ("in", "the", "sky"))},
    **{(wind, "up", "speed"): (accelerating,) for wind, accelerating in (
        ("winding", "accelerating"), ("winds", "accelerates"), ("wound", "accelerated"), ("wind", "accelerate"))},
    # Scots, Irish and Northern English: 'bang on the start' (right at it), 'stood still' at a collision
    **{("bang", "on", *start): ("right", *(start if start[0] in ("at", "from") else ("at", *start)))
       for start in (("the", "start"), ("the", "beginning"), ("the", "off"), ("at", "the", "start"),
                     ("at", "the", "beginning"), ("from", "the", "start"))},
    # a paraphraser's restructurings: 'lag behind' (slower than), 'in a version where' (if), a pseudo-cleft's 'is what
    # I'd like to know' after the question asked, 'I'm curious about' the thing asked
    **{(lag, "behind"): (move, "slower", "than") for lag, move in (("lag", "move"), ("lags", "moves"),
                                                                   ("lagged", "moved"), ("lagging", "moving"))},
    **{("in", a, version, *of, *where): ("if",) for version in ("version", "world", "timeline", "scenario", "variant")
       for a in ("a", "another") for of in ((), ("of", "events"), ("of", "the", "video"), ("of", "the", "clip"))
       for where in (("where",), ("in", "which"))},
    **{("is", "what", *i, *like, "to", "know"): () for i in (("i", "'", "d"), ("i", "would"), ("we", "'", "d"))
       for like in (("like",), ("love",))},
    **{("is", "what", "i", want, "to", "know"): () for want in ("want", "wanna", "need")},
    **{(*i, "curious", "about"): ("tell", "me") for i in (("i", "'", "m"), ("i", "am"), ("i", "'", "m", "really"))},
    # the video's end as the whole thing's ('when it's all finished', 'once it's all over')
    **{(when, "it", "'", "s", "all", done): (when, "the", "video", "ends") for when in ("when", "once", "after")
       for done in ("finished", "over", "done")},
    # ... as a speculator lets it ('if we let the action roll on beyond where the video stops, will ...')
    **{(*when, "let", "the", film, roll, "on", *beyond): ("after", "the", "video", "ends")
       for when in (("if", "we"), ("if", "you"), ("if", "i"), ("once", "we"), ("when", "we"))
       for film in ("video", "clip", "footage", "film", "action", "play", "tape", "recording")
       for roll in ("roll", "run", "play", "go", "carry", "keep")
       for beyond in ((), *((past, "where", "the", f, stops) for past in ("beyond", "past")
                            for f in ("video", "clip", "footage", "film") for stops in ("stops", "ends", "cuts")),
                      *((past, "the", cut) for past in ("beyond", "past") for cut in ("cut", "stop", "end")))},
    # the video going on 'after the stop' (its own stop: 'when the video is continuing after the stop, will ...')
    **{(*goes, "after", "the", stop): goes for stop in ("stop", "pause", "cut", "freeze")
       for goes in (("continuing",), ("continues",), ("continued",), ("continue",), ("resumes",), ("resumed",),
                    ("resuming",), ("going", "on"), ("goes", "on"), ("carries", "on"), ("carrying", "on"),
                    ("plays", "on"), ("playing", "on"), ("rolls", "on"), ("rolling", "on"))},
    # a casual speaker's 'booking it' (fast), 'when the clip kicks off' (the start), 'pauses right there' (no direction)
    **{(pauses, "right", there): (pauses, there) for there in ("there", "here")
       for pauses in ("pauses", "paused", "stops", "stopped", "ends", "ended", "cuts", "freezes", "froze")},
    **{(book, "it"): (moving, "fast") for book, moving in (("booking", "moving"), ("books", "moves"),
                                                           ("booked", "moved"))},
    **{(when, "the", film, kicks, "off"): _START for when in ("when", "as", "once", "right", "where")
       for film in ("video", "clip", "footage", "film", "recording", "vid", "action") for kicks in ("kicks", "kicked")},
    ("budging",): ("moving",),
    **{(punch, *gas): (accelerate,) for punch, accelerate in (("punching", "accelerating"), ("punches", "accelerates"),
                                                              ("punched", "accelerated"), ("punch", "accelerate"))
       for gas in (("the", "gas"), ("it",))},
    # a vehicle as its rider calls it ('what kinda ride is ...', 'the ride that's ...')
    **{(*before, "ride"): (*said, "vehicle") for before, said in (
        (("the",), ("the",)), (("kind", "of"), ("kind", "of")), (("sort", "of"), ("sort", "of")),
        (("type", "of"), ("type", "of")), (("kinda",), ("kind", "of")), (("sorta",), ("sort", "of")))},
    **{(verb, "along"): (moving, "slowly") for forms in (("poking", "pokes", "poked"), ("inching", "inches", "inched"),
                                                          ("puttering", "putters", "puttered"),
                                                          ("pottering", "potters", "pottered"),
                                                          ("trundling", "trundles", "trundled"),
                                                          ("plodding", "plods", "plodded"))
       for verb, moving in zip(forms, ("moving", "moves", "moved"))},
    # coming into view said of the picture's edge ('enters the field of view', 'comes first into the picture')
    **{(enter, *seen): (come, "into", "view") for enter, come in (("enters", "comes"), ("entered", "came"),
                                                                  ("enter", "come"), ("entering", "coming"))
       for seen in (("the", "field", "of", "view"), ("the", "camera", "'", "s", "field", "of", "view"),
                    ("the", "frame"), ("the", "shot"), ("the", "image"),
                    ("first", "in", "the", "view"), ("first", "into", "the", "view"), ("first", "into", "view"))},
    **{(come, "first", "into"): ("first", come, "into") for come in ("comes", "came", "come", "coming")},
    # a learner's 'coming in the picture', 'when just come inside the video'
    **{(come, inside, *the, view): (come, "into", "view") for come in ("comes", "came", "come", "coming")
       for inside in ("in", "inside") for the in ((), ("the",))
       for view in ("view", "picture", "frame", "shot", "image", "video", "clip", "screen")},
    # a pair's collision said as a moment ('at the moment of their collision, is the plane faster than the jet?')
    **{(*at, "their", crash): ("when", "they", "collide") for crash in ("collision", "crash", "impact")
       for at in (*((p, "the", m, "of") for p in ("at", "in", "during") for m in ("moment", "instant", "time")),
                  ("at",), ("during",), ("upon",), ("on",))},
    # a run-in, and never budging or staying planted in place ('had the suv never budged from the outset')
    ("run", "-", "in"): ("collision",), ("run", "-", "ins"): ("collisions",),
    **{("had", "never", moved): ("had", "been", "static") for moved in ("budged", "moved", "stirred")},
    ("planted", "in", "place"): ("still",), ("rooted", "to", "the", "spot"): ("still",),
    # a learner's past ('purple one got collide with something?') and first moment ('in the first moment, ...')
    **{(got, verb): (past,) for got in ("got", "get") for verb, past in (("collide", "collided"),
                                                                          ("crash", "crashed"), ("bump", "bumped"))},
    **{(p, "the", "first", "moment"): _START for p in ("in", "at")},
    # ... and a verse's first blink (WordNet reads 'blinking' as 'crashing')
    **{(p, "the", *very, "first", "blink"): _START for p in ("in", "at") for very in ((), ("very",))},
    **{("for", "a", b): ("for", "a", "moment") for b in ("breath", "heartbeat", "blink")},
    # a learner's 'is stop' ('the dirtbike is stop already?')
    **{(be, "stop"): (be, "static") for be in ("is", "was", "are", "were")},
    **{(make, its, *grand, "entrance"): (come, "into", "view") for make, come in (("makes", "comes"), ("made", "came"),
                                                                              ("make", "come"), ("making", "coming"))
       for its in ("its", "an", "his", "her") for grand in ((), ("grand",), ("big",))},
    # a small collision by its everyday name
    **{("fender", *dash, bender): (crash,) for bender, crash in (("bender", "collision"), ("benders", "collisions"))
       for dash in ((), ("-",))},
    **{(clip, the): (hit, the) for clip, hit in (("clips", "hits"), ("clipped", "hit"), ("clipping", "hitting"),
                                                 ("clip", "hit")) for the in ("the", "a", "an", "into")},
    # a game's words: a vehicle spawns at the start, is afk (away from the keyboard: still), full-sends (fast),
    # trades paint (collides), has its turbo on (accelerating)
    **{p: _START for p in (("at", "spawn"), ("on", "spawn"), ("off", "spawn"), ("right", "at", "spawn"),
                           ("at", "the", "spawn"), *((w, "it", spawned) for w in ("when", "as", "once")
                                                     for spawned in ("spawned", "spawns", "spawn")))},
    **{(p, *the, "spawn"): (p, "the", "start") for p in ("from", "since") for the in ((), ("the",))},
    **{(spawn, *how): (start, *how) for spawn, start in (("spawned", "started"), ("spawns", "starts"),
                                                        ("spawn", "start"), ("spawning", "starting"))
       for how in (("slow",), ("fast",), ("static",), ("moving",), ("parked",), ("still",), ("floating",),
                   ("hovering",), ("accelerating",))},
    ("afk",): ("static",),
    # a referee's start ('at kick-off', 'on the whistle'), an engine's power, a clause's start ('as things get under
    # way'), a stop said 'dead still'
    **{(*at, *kick): (("from", "the", "start") if at[:1] == ("from",) else _START)
       for at in (("at",), ("at", "the"), ("right", "at", "the"), ("right", "at"), ("from",), ("from", "the"))
       for kick in (("kick", "-", "off"), ("kickoff",), ("kick", "off"))},
    **{p: _START for p in (("on", "the", "whistle"), ("at", "the", "whistle"), ("at", "the", "opening", "whistle"),
                           ("at", "the", "first", "whistle"), ("on", "the", "opening", "whistle"))},
    **{("under", *own, "power"): ("with", "its", "engine", "on") for own in ((), ("its", "own"), ("engine",),
                                                                              ("its", "engine's"))},
    **{("under", *own, engine): ("with", "its", "engine", "on") for own in (("its", "own"), ("its",))
       for engine in ("engine", "steam", "propulsion")},
    # a philosopher's possible world and stipulation ('consider the nearest possible world in which ...; does it, in
    # that world, ...', 'let it be stipulated that ...; under that stipulation, would ...'), 'is it to be expected'
    **{(*consider, "the", nearest, "possible", "world", *which): ("imagine",)
       for consider in (("consider",), ("in",), ("take",), ("suppose",), ("imagine",))
       for nearest in ("nearest", "closest")
       for which in (("in", "which"), ("where",))},
    **{(under, that, world): ("in", "that", "case") for under, world in (
        ("in", "world"), ("under", "stipulation"), ("under", "supposition"), ("under", "assumption"),
        ("on", "assumption"), ("on", "supposition"), ("under", "hypothesis")) for that in ("that", "this")},
    **{("let", "it", "be", said, "that"): ("suppose",) for said in ("stipulated", "supposed", "assumed", "granted")},
    ("is", "it", "to", "be", "expected", "that"): ("is", "it", "likely", "that"),
    # a philosopher's 'how ought one to characterise ...', and the start 'taking only the first moments into account'
    **{("how", ought, "one", "to", describe): ("how", "would", "you", "describe")
       for ought in ("ought", "should", "would", "might", "must") for describe in (
           "characterise", "characterize", "describe", "classify", "categorise", "categorize")},
    **{(take, *only, "the", first, moments, *of, *account): ("in", "the", "first", "moments")
       for take in ("taking", "considering", "counting") for only in ((), ("only",), ("just",))
       for first in ("first", "opening", "initial", "earliest") for moments in ("moments", "frames", "seconds")
       for of in ((), ("of", "the", "video"), ("of", "the", "clip"), ("of", "the", "footage"))
       for account in ((), ("into", "account"))},
    **{(w, "things", get, *way): _START for w in ("as", "when") for get in ("get", "got", "are", "were")
       for way in (("under", "way"), ("underway",))},
    ("dead", "still"): ("still",),
    # a show's start ('right when our show begins')
    **{(w, our, show, begins): _START for w in ("when", "as") for our in ("our", "the", "this")
       for show in ("show", "episode", "programme", "program") for begins in ("begins", "starts", "opens")},
    **{("let", *us, v): (v,) for us in (("us",), ("'", "s")) for v in ("suppose", "assume", "imagine", "pretend")},
    ("let", "us", "say"): ("suppose",),
    **{(draw, "to", its, close): (ends,) for draw, ends in (("draws", "ends"), ("drew", "ended"), ("drawing", "ending"))
       for its in ("its", "a", "an") for close in ("close", "end")},
    **{(t, p): (c, p) for t, c in (("tangle", "collide"), ("tangles", "collides"), ("tangled", "collided"))
       for p in (",", "?", ".")},
    ("going", "back", "over"): ("looking", "at"),
    **{(*at, than, *dash, "speed"): (said,) for than, said in (("lower", "slower"), ("higher", "faster"))
       for dash in ((), ("-",)) for at in ((), ("at", "a"))},
    **{("speed", "check", on): ("what", "is", "the", "speed", "of") for on in ("on", "for")},
    **{("full", send): said for send, said in (("send", ("fast",)), ("sending", ("going", "fast")),
                                               ("sent", ("gone",)), ("sends", ("goes", "fast")))},
    **{(trade, "paint"): (collide,) for trade, collide in (("trade", "collide"), ("trades", "collides"),
                                                          ("traded", "collided"), ("trading", "colliding"))},
    **{(*had, "turbo", "on"): said for had, said in (((), ("accelerating",)), (("had",), ("had", "been",
                                                                                           "accelerating")),
                                                     (("has",), ("is", "accelerating")),
                                                     (("with",), ("accelerating",)))},
    **{("w", the): ("with", the) for the in ("the", "a", "an", "anything", "something", "any")},
    **{(verb, "along"): (moving, "fast") for verb, moving in (("barrelling", "moving"), ("barrelled", "moved"),
                                                             ("flying", "moving"), ("flies", "moves"),
                                                             ("flew", "moved"),
                                                             ("haring", "moving"), ("careering", "moving"),
                                                             ("careening", "moving"))},
    **{(verb, adverb): (stay, "still") for verb, stay in (("sitting", "staying"), ("sits", "stays"), ("sit", "stay"),
                                                          ("going", "staying"), ("goes", "stays"), ("go", "stay"))
       for adverb in (("tight",) if verb.startswith("s") else ("nowhere",))},
    ("on", "the", "move"): ("moving",),
    ("stayed", "where", "it", "was"): ("been", "static"),
    **{(stay, "put"): (stay, "still") for stay in ("stay", "stays", "stayed", "staying")},
    # a counterfactual's condition: 'had it stayed still' was read as had it stayed in the air
    **{("had", stayed, still): ("had", "been", "static") for stayed in STAYED for still in STILL},
    # said of a plane: 'does it come down on the wagon?' (on the ground, a landing: refused as one)
    **{(come, "down", "on", *top): (crash, "into") for come, crash in (("come", "crash"), ("comes", "crashes"),
                                                                      ("came", "crashed"), ("coming", "crashing"))
       for top in ((), ("top", "of"))},
    # within the video, not after it ('has it hit anything by the end of the video?')
    **{("by", "the", "end", "of", "the", film): ("during", "the", "video") for film in ("video", "clip", "footage",
                                                                                       "film", "recording", "movie")},
    # a learner's 'how much fast' asks how fast (not how many)
    **{("how", "much", pace): ("how", pace) for pace in ("fast", "quickly", "quick", "speedy", "rapidly")},
    # 'quick' is 'fast' ('the quick car', 'is it quick' were read as nothing); 'non-moving' is 'stationary'
    ("quick",): ("fast",),
    **{("non", *dash, "moving"): ("stationary",) for dash in ((), ("-",))},
    **{(gather, speed): (accelerate,) for gather, accelerate in (
        ("gathering", "accelerating"), ("gathers", "accelerates"), ("gathered", "accelerated"),
        ("gather", "accelerate")) for speed in ("speed", "velocity", "pace", "momentum")},
    # a comparative said as a class ('the slower-moving vehicle'), as the grammar says the class
    **{(comparative, *dash, "moving"): said for comparative, said in (("slower", ("slow", "-", "moving")),
                                                                     ("faster", ("quickly", "moving")))
       for dash in ((), ("-",))},
    **{("rear", "-", end): (hit,) for end, hit in (("end", "hit"), ("ends", "hits"), ("ended", "hit"),
                                                   ("ending", "hitting"))},
    **{("t", "-", bone): (hit,) for bone, hit in (("bone", "hit"), ("bones", "hits"), ("boned", "hit"),
                                                  ("boning", "hitting"))},
    # 'does it end up hitting' is 'does it hit', said of the verbs of a collision (and 'getting into a wreck')
    **{(end, "up", gerund): (forms[k],) for k, end in enumerate(("end", "ends", "ended"))
       for gerund, forms in {"hitting": ("hit", "hits", "hit"), "colliding": ("collide", "collides", "collided"),
                             "crashing": ("crash", "crashes", "crashed"), "smashing": ("smash", "smashes", "smashed"),
                             "bumping": ("bump", "bumps", "bumped"), "running": ("run", "runs", "ran"),
                             "striking": ("strike", "strikes", "struck"), "slamming": ("slam", "slams", "slammed"),
                             "ramming": ("ram", "rams", "rammed"), "getting": ("get", "gets", "got")}.items()},
    **{(adverb, verb): (verb, "slowly") for adverb in ("barely", "hardly", "scarcely")
       for verb in ("moving", "moves", "move", "moved")},
    **{(verb, *rest): (accelerate,) for verb, accelerate in (("hitting", "accelerating"), ("hits", "accelerates"),
                                                              ("hit", "accelerate"), ("stepping", "accelerating"),
                                                              ("steps", "accelerates"), ("step", "accelerate"),
                                                              ("stepped", "accelerated"))
       for rest in ((("the", "gas"),) if verb.startswith("hit") else (("on", "the", "gas"), ("on", "it")))},
    **{(verb, *rest): (accelerate,) for verb, accelerate in (("putting", "accelerating"), ("puts", "accelerates"),
                                                              ("put", "accelerate"), ("flooring", "accelerating"),
                                                              ("floors", "accelerates"), ("floor", "accelerate"),
                                                              ("gunning", "accelerating"), ("guns", "accelerates"),
                                                              ("gun", "accelerate"), ("having", "accelerating"),
                                                              ("has", "accelerates"), ("have", "accelerate"),
                                                              ("floored", "accelerated"), ("gunned", "accelerated"),
                                                              ("had", "accelerated"))
       for rest in ((("its", "foot", "down"),) if verb.startswith("put") else (("it",),) if verb[0] in "fg"
                    else (("its", "foot", "on", "the", "gas"),) if verb != "had" else (("its", "foot", "down"),))},
    ("had", "put", "its", "foot", "down"): ("had", "accelerated"),
    **{p: ("fast",) for p in (("at", "a", "lick"), ("at", "a", "fair", "lick"), ("at", "a", "good", "lick"),
                              ("at", "quite", "a", "lick"))},
    # a collision as an idiom says it ('did it come to grief with the bus?', 'tangled with', 'ploughed into')
    **{(*come, "with"): (collide, "with") for come, collide in (
        (("come", "to", "grief"), "collide"), (("comes", "to", "grief"), "collides"),
        (("came", "to", "grief"), "collided"), (("coming", "to", "grief"), "colliding"), (("tangle",), "collide"),
        (("tangles",), "collides"), (("tangled",), "collided"), (("tangling",), "colliding"))},
    **{(plough, "into"): (crash, "into") for plough, crash in (
        ("plough", "crash"), ("ploughs", "crashes"), ("ploughed", "crashed"), ("ploughing", "crashing"),
        ("plow", "crash"), ("plows", "crashes"), ("plowed", "crashed"), ("plowing", "crashing"))},
    # a translator's time of the video ('in the beginning time', 'at the end time of video')
    **{(at, *the, when, "time"): ("at", "the", "end") if when == "end" else _START
       for at in ("at", "in") for the in ((), ("the",)) for when in ("beginning", "start", "starting", "end")},
    # a learner's preposition before the start ('moving fast on start', 'in beginning')
    **{(on, when): _START for on in ("on", "in") for when in ("start", "beginning")},
    # a translator's comparison ('faster compared with the bus') and direction ('heading for what direction')
    **{(comparative, "compared", to): (comparative, "than") for comparative in ("faster", "slower", "quicker")
       for to in ("with", "to")},
    **{(prep, which, "direction"): ("in", which, "direction") for prep in ("for", "to", "toward", "towards")
       for which in ("what", "which")},
    ("how", "much", "speed"): ("how", "fast"),
    **{("this", film): ("the", film) for film in ("video", "clip", "footage", "film", "recording", "movie")},
    **{("right", "when", "it", starts): _START for starts in ("starts", "begins", "opens")},
    # a race's start ('right off the line') and a commentator's speed ('carrying more speed than the cruiser')
    **{(*right, "off", "the", *starting, "line"): _START for right in ((), ("right",))
       for starting in ((), ("starting",))},
    **{(carrying, "more", "speed", "than"): (going, "faster", "than") for carrying, going in (
        ("carrying", "going"), ("carries", "goes"), ("carried", "went"), ("carry", "go"))},
    # a researcher's time of the video ('during the observation window', 'in the post-observation window')
    **{(*the, "observation", window): (*the, "video") for the in ((), ("the",)) for window in ("window", "period")},
    **{(*at, "the", "post", "-", "observation", window): ("after", "the", "video") for at in ((), ("in",), ("during",))
       for window in ("window", "period")},
    **{(into, *the, "screen"): ("into", "view") for into in ("into", "onto") for the in ((), ("the",))},
    **{(when, "it", "all", *began): ("at", "the", "start") for when in ("when", "as") for began in (
        ("started",), ("starts",), ("began",), ("begins",), ("kicked", "off"), ("kicks", "off"))},
    # 'jam' said for 'hit' ('when it jammed the bike', 'will they jam each other?', 'did they jam?', 'when it jam with
    # the bus'; a traffic jam is refused)
    **{(jam, after): (hit, after) for jam, hit in (("jam", "hit"), ("jams", "hits"), ("jammed", "hit"),
                                                   ("jamming", "hitting")) for after in ("the", "each", "into")},
    **{(jam, after): (collide, after) for jam, collide in (("jam", "collide"), ("jams", "collides"),
                                                           ("jammed", "collided"), ("jamming", "colliding"))
       for after in ("with", "?", ".")},
    **{p: ("accelerating",) for p in (("on", "the", "gas"), ("with", "its", "foot", "on", "the", "gas"),
                                      ("pedal", "to", "the", "metal"), ("with", "the", "pedal", "to", "the", "metal"))},
    # a motoring presenter's: the race's start ('as the lights go green', 'at the drop of the flag', 'straight out of
    # the blocks'), pace ('how much pace has it got on', 'down on pace against', 'going harder than'), the throttle,
    # a collision as a 'coming-together' or 'trading paint', a parked car 'on the grid', the ground as 'the deck'
    **{(*right, when, "the", "lights", go, "green"): _START for right in ((), ("right",)) for when in ("as", "when")
       for go in ("go", "went", "turn", "turned")},
    **{p: _START for p in (("at", "the", "drop", "of", "the", "flag"), ("as", "the", "flag", "drops"),
                           ("when", "the", "flag", "drops"), ("as", "the", "flag", "dropped"),
                           ("when", "the", "flag", "dropped"), ("when", "the", "flag", "falls"),
                           *(("straight", "out", "of", "the", g) for g in ("blocks", "gate", "gates")))},
    ("how", "much", "pace"): ("how", "fast"), ("got", "on"): ("got",),
    **{(down, "on", "pace", than): (compared, "than") for down, compared in (("down", "slower"), ("up", "faster"))
       for than in ("against", "to", "on", "compared", "relative")},
    **{(go, hard): (moving, fast) for go, moving in (("going", "going"), ("goes", "goes"), ("went", "went"),
                                                    ("go", "go"), ("gone", "gone"))
       for hard, fast in (("hard", "fast"), ("harder", "faster"))},
    # a car vlogger's 'launch hard' and 'pulling hard' (speeding up), 'sending it' (going fast)
    **{(v + e, "hard"): (a,) for v in ("launch", "pull") for e, a in (
        ("", "accelerate"), ("es" if v == "launch" else "s", "accelerates"), ("ed", "accelerated"),
        ("ing", "accelerating"))},
    **{(*a, "sending", "it"): ("going", "fast") for a in ((), ("absolutely",), ("fully",))},
    **{("the", "slowcoach", compared, to): ("slower", "than") for compared in ("compared", "relative")
       for to in ("with", "to")},
    **{(*how, "on", "the", "throttle"): ("accelerating",) for how in (
        (), ("stamping",), ("stamped",), ("hard",), ("its", "foot"), ("with", "its", "foot"), ("getting",),
        ("foot", "down"))},
    **{(d, "coming", *hyphen, "together"): (d, "collision") for d in ("a", "the", "its", "their", "that", "any", "no")
       for hyphen in ((), ("-",))},
    **{(trade, "paint", "with"): (collide, "with") for trade, collide in (
        ("trades", "collides"), ("traded", "collided"), ("trade", "collide"), ("trading", "colliding"))},
    # nothing yet happening is the start ('slower than the grey one before anything happens?', chat's 'b4 anything?')
    **{("before", "anything", *happens): (*_START, *end) for happens, end in (
        (("happens",), ()), (("happened",), ()), (("kicks", "off"), ()), (("kicked", "off"), ()), (("?",), ("?",)))},
    # an airfield's: ground speed, holding, a slow taxi, the throttle forward, wheels chocked or off the ground, the
    # feed's loss (its end), traffic (what there is to hit), coming off the start
    ("ground", "speed"): ("speed",), ("holding", "static"): ("static",),
    # ... a holding pattern (in the air), block-in (at the gate: after the flight, the video), a vehicle once in sight
    # (come into view)
    **{(*i, "a", "holding", "pattern"): ("floating",) for i in ((), ("in",))},
    ("holding", "pattern"): ("floating",),
    **{(h, *i, "position"): (st, "still") for h, st in (("holding", "standing"), ("holds", "stands"), ("held", "stood"))
       for i in ((), ("its",), ("in",))},
    **{(a, "block", *h, "in"): ("after", "the", "video", "ends") for a in ("after", "post") for h in ((), ("-",))},
    **{(*w, "it", *b, "in", v): (*w, "it", "comes", "into", "view") for w in (("as", "soon", "as"), ("once",))
       for b in (("'", "s"), ("is",)) for v in ("sight", "view")},
    **{(*at, "a", "slow", "taxi"): ("slow",) for at in ((), ("at",))}, ("throttle", "forward"): ("accelerating",),
    ("with", "its", "wheels", "chocked"): (), ("with", "its", "wheels", "off", "the", "ground"): ("in", "the", "air"),
    **{("loss", "of", f): ("the", "video", "ends") for f in ("feed", "signal", "picture")},
    ("any", "traffic"): ("anything",), ("the", "traffic"): ("the", "vehicle"), ("some", "traffic"): ("something",),
    **{(c, "traffic"): (c, "vehicle") for c in (*COLOR_NAMES, "grey", "stationary", "static", "other")},
    **{("traffic", w): ("the", "vehicle", w) for w in ("that", "which", "striking", "hitting")},
    **{(come, "off", "the", "start"): (start,) for come, start in (("come", "started"), ("came", "started"),
                                                                  ("comes", "starts"))},
    # a biker's: taken out (hit), set off at a crawl (started slow), its foot down (the throttle open)
    # ('taken out of the scene' is removed)
    **{(take, "out", *of): (hit, *of) if not of else (take, "out", *of) for take, hit in (
        ("taken", "hit"), ("took", "hit"), ("take", "hit"), ("takes", "hits"), ("taking", "hitting"))
       for of in ((), ("of",))},
    **{(set_, "off"): (start,) for set_, start in (("set", "started"), ("sets", "starts"), ("setting", "starting"))},
    **{(start, "out"): (start,) for start in ("started", "starts", "start", "starting")},
    ("at", "a", "crawl"): ("slow",), ("had", "its", "foot", "down"): ("been", "accelerating"),
    ("its", "foot", "down"): ("accelerating",),
    ("slow", "taxi"): ("slow",),
    **{(t, "up"): (a,) for t, a in (("throttling", "accelerating"), ("throttles", "accelerates"),
                                    ("throttled", "accelerated"), ("throttle", "accelerate"))},
    # a case file's 'the subject car', 'at kick-off'; a technical writer's nominalised time, rate and class
    ("the", "subject"): ("the",), ("at", "kick", "-", "off"): _START, ("at", "kickoff"): _START,
    **{(under, "the", premise, "that"): ("suppose",) for under in ("under", "on")
       for premise in ("supposition", "hypothesis", "assumption")},
    **{("at", "a", lower, rate): (slower,) for lower, slower in (("reduced", "slower"), ("lower", "slower"),
                                                                 ("higher", "faster"), ("greater", "faster"))
       for rate in ("rate", "speed", "pace")},
    **{(upon, "its", *first, entry, *into): ("when", "it", "first", "comes", "into", "view")
       for upon in ("upon", "on", "at") for first in ((), ("initial",), ("first",)) for entry in ("entry", "entrance")
       for into in ((), ("into", "view"), ("into", "the", "frame"), ("into", "the", "field", "of", "view"),
                    ("into", "the", "scene"), ("into", "the", "shot"))},
    ("classification", "applicable", "to"): ("class", "of"), ("classification", "of"): ("class", "of"),
    # what floats says so again ('hanging in the air without dropping'; the fall was read as what is asked)
    **{("without", fall, *down): () for fall in ("dropping", "falling", "sinking", "descending")
       for down in ((), ("down",))},
    **{(*comma, "neither", rise, "nor", fall): () for comma in ((), (",",))
       for rise in ("rising", "climbing", "ascending") for fall in ("sinking", "falling", "dropping", "descending")},
    # held up in the air ('What sort of aircraft is suspended in the air ...?' was read as yes or no)
    **{(hang, *there): (floating,) for hang, floating in (("suspended", "floating"), ("hanging", "floating"),
                                                          ("hangs", "floats"))
       for there in (("in", "the", "air"), ("in", "midair"), ("in", "mid", "-", "air"), ("in", "the", "sky"))},
    # a machine translator's verbs of a noun ('is doing acceleration', 'is taking part' in a collision)
    **{(do, "acceleration"): (accelerating,) for do, accelerating in (
        ("doing", "accelerating"), ("making", "accelerating"), ("does", "accelerates"), ("makes", "accelerates"),
        ("do", "accelerate"), ("make", "accelerate"), ("did", "accelerated"), ("made", "accelerated"))},
    **{(be, "taking", "part"): (be, "involved") for be in ("is", "was", "are", "were")},
    # a Romance language's translation: 'the same' for it, a reflexive collision ('crashes itself with'), 'enters in
    # collision', 'in the final of the video' (its end, which was read as the start), 'in which sense' (direction),
    # 'with bigger speed than'
    **{("the", "same", verb): ("it", verb) for verb in (
        "collide", "collides", "collided", "crash", "crashes", "crashed", "hit", "hits", "enters", "entered",
        "comes", "came", "bumps", "bumped", "strikes", "struck", "is", "was", "would", "will", "moves", "goes")},
    **{(crash, "itself", prep): (crash, "into") for crash in ("crash", "crashes", "crashed", "crashing", "hit", "hits")
       for prep in ("with", "against", "into", "on")},
    **{(enter, "in", "collision", "with"): (collide, "with") for enter, collide in (
        ("enter", "collide"), ("enters", "collides"), ("entered", "collided"), ("entering", "colliding"))},
    **{(enter, "in", "the", scene, *first): (*first, come, "into", "view") for enter, come in (
        ("enter", "come"), ("enters", "comes"), ("entered", "came"), ("entering", "coming"))
       for scene in ("scene", "view", "image", "frame") for first in ((), ("first",))},
    **{("in", "the", "final", "of"): ("at", "the", "end", "of")},
    **{("in", which, "sense"): ("in", which, "direction") for which in ("which", "what")},
    **{(go, "with", which, "speed"): (move, "at", which, "speed") for which in ("which", "what")
       for go, move in (("going", "moving"), ("goes", "moves"), ("went", "moved"), ("go", "move"))},
    **{("with", big, "speed", "than"): (faster, "than") for big, faster in (
        ("bigger", "faster"), ("greater", "faster"), ("higher", "faster"), ("more", "faster"), ("lower", "slower"),
        ("smaller", "slower"), ("less", "slower"))},
    **{(move, "itself"): (move,) for move in ("moves", "moved", "move", "moving")},
    # a Turkish or Hungarian translation's postpositions ('the start at', 'the video end at', 'the video middle in':
    # the end and the middle were read as the start or as coming into view), and a compound's hyphens
    # ('speeding-up-at-start', whose 'speeding' alone was read as fast)
    **{("the", start, "at"): ("at", "the", start) for start in ("start", "beginning", "outset")},
    **{("the", video, "end", "at"): ("at", "the", "end", "of", "the", video) for video in ("video", "clip")},
    **{("the", video, "middle", "in"): ("in", "the", "middle", "of", "the", video) for video in ("video", "clip")},
    **{(speed, "-", way): (speed, way) for speed, way in (("speeding", "up"), ("speed", "up"), ("speeds", "up"),
                                                          ("slowing", "down"), ("slow", "down"))},
    # a German or Polish translation's 'does it come to a collision' (is there one; 'come' was read as the future)
    # ('did it come to a contact between ...')
    **{(do, "it", "come", "to", *a, impact): said for do, said in (
        ("does", ("is", "there", "a", "collision")), ("did", ("was", "there", "a", "collision")),
        ("will", ("will", "there", "be", "a", "collision")), ("would", ("would", "there", "be", "a", "collision")))
       for a in ((), ("a",), ("an",)) for impact in ("collision", "contact", "crash", "impact", "clash")},
    # an engine said again after speeding up asked ('... start off speeding up, engine running?'); 'clips' something
    **{(",", "engine", on): (",", "engine", "on") for on in ("running", "engaged")},
    # (not 'started off moving slowly': 'started moving' is when a motion begins)
    **{(start, "off", ing): (start, ing) for start in ("start", "starts", "started", "starting")
       for ing in ("speeding", "accelerating")},
    **{(clips, the): (hits, the) for clips, hits in (("clips", "hits"), ("clipped", "hit"))
       for the in ("the", "a", "an", "something", "anything", "into")},
    **{("after", "this", "part", "where", "it", stopped): ("after", "the", "cut") for stopped in (
        "stopped", "stops", "ends", "ended")},
    **{(have, "collision"): (collide,) for have, collide in (("have", "collide"), ("has", "collides"),
                                                            ("had", "collided"), ("having", "colliding"))},
    **{(do, "collision", "with"): (collide, "with") for do, collide in (("does", "collides"), ("do", "collide"))},
    **{("following", "the", "stop", "of", "the", video): ("after", "the", video, "stops")
       for video in ("video", "clip", "footage")},
    # a learner's comparisons and speeding up ('slow than the gray bus', 'more and more fast', 'get more speed')
    **{(slow, "than"): (slower, "than") for slow, slower in (("slow", "slower"), ("fast", "faster"),
                                                            ("quick", "quicker"))},
    # (said as they are: the longest phrase wins, so 'less fast than' and 'got more speed than' keep their words)
    **{(less, slow, "than"): (less, slow, "than") for less in ("less", "more") for slow in ("slow", "fast", "quick")},
    ("more", "and", "more", "fast"): ("faster", "and", "faster"),
    **{(get, "more", "speed"): (gain, "speed") for get, gain in (("get", "gain"), ("gets", "gains"),
                                                                ("getting", "gaining"), ("got", "gained"))},
    **{(get, "more", "speed", "than"): (get, "more", "speed", "than") for get in ("get", "gets", "getting", "got")},
    ("without", "fall"): (),
    # a terse note's times: 'static from start' (the condition's 'from the start'), the whole video, the cut, a
    # speed at the start asked alone ('Red sedan's starting speed?' read as speeding up; not a condition's: 'if its
    # starting speed had been slow')
    ("from", "start"): ("from", "the", "start"),
    **{(*f, s, "to", *t, e): ("during", "the", "video") for f in (("from",), ()) for s, e in (
        ("start", "finish"), ("beginning", "end"), ("start", "end"), ("end", "end")) for t in ((), ("the",))},
    **{(*f, *t, "first", m, "to", *t, "last"): ("during", "the", "video") for f in (("from",), ())   # a physicist's
       for t in ((), ("the",)) for m in ("moment", "frame", "instant")},                            # 'first moment to last'
    **{("the", "point", *where, "it", stops): ("the", "cut") for where in (("where",), ("at", "which"), ("when",))
       for stops in ("stops", "ends", "cuts", "stopped", "ended", "pauses", "paused")},
    **{(first, "speed", "?"): ("speed", "at", "the", "start", "?") for first in ("starting", "initial")},
    # a machine translator's: 'in case' of a condition, the start as a time ('at beginning time', 'the start time'),
    # a topic marker ('Blue SUV as for, ...'), a tag ('..., is it so?')
    ("in", "case"): ("if",),
    **{(*at, first, "time"): _START for at in ((), ("at",), ("at", "the"), ("the",), ("in",), ("in", "the"))
       for first in ("beginning", "start", "starting")},
    ("as", "for", ","): (",",), **{(",", "is", "it", so, "?"): ("?",) for so in ("so", "right", "true", "correct")},
    # a course is a heading ('What course was the scooter on when it struck the pickup?' was read as its speed)
    **{(which, "course"): (which, "direction") for which in ("what", "which")},
    ("on", "the", "grid"): (), ("parked", "up"): ("parked",), ("on", "the", "deck"): ("on", "the", "ground"),
    **{(come, "out", "of", "the", g): (start,) for come, start in (("come", "started"), ("came", "started"),
                                                                  ("comes", "starts"), ("coming", "starting"))
       for g in ("blocks", "gate", "gates", "stalls")},
    # ... the broadcast and its cameras: the video ('we've paused the tape: ...', 'if we'd kept rolling the cameras')
    **{("the", b): ("the", "video") for b in ("broadcast", "telecast")},
    **{(who, *have, paused, "the", film): ("the", film, "is", "paused") for who in ("we", "i", "they", "you")
       for have in ((), ("'", "ve"), ("have",), ("'", "d"), ("had",))
       for paused in ("paused", "stopped", "frozen", "halted")
       for film in ("video", "clip", "tape", "footage", "feed", "film", "recording")},
    **{("if", who, *had, "kept", rolling, *cameras): ("if", "the", "video", "had", "kept", "going")
       for who in ("we", "they", "you") for had in (("'", "d"), ("had",)) for rolling in ("rolling", "filming")
       for cameras in ((), ("the", "cameras"), ("the", "camera"), ("the", "tape"))},
    # 'directly at the start' (a translation's; 'directly' was read as the direction)
    **{(just, "at", the, start): ("right", "at", "the", start) for just in ("directly", "immediately", "exactly",
                                                                             "precisely") for the in ("the", "its")
       for start in ("start", "beginning", "outset")},
    # a Romance-language learner's 'in movement' and 'each time faster' ('was the bus not in movement at the start',
    # 'had been going each time more rapid')
    ("in", "movement"): ("moving",),
    **{("each", "time", *more): ("faster", "and", "faster") for more in (
        ("faster",), ("quicker",), ("more", "rapid"), ("more", "rapidly"), ("more", "fast"), ("more", "quickly"))},
    # Indian English: 'dashing with' a vehicle collides with it ('at the time of dashing with the green jet'), 'the
    # starting' is the start ('in the starting of the video', 'from the starting itself'), 'kindly tell' asks
    **{(dash, w): (collide, w) for dash, collide in (("dash", "collide"), ("dashes", "collides"),
                                                     ("dashed", "collided"), ("dashing", "colliding"))
       for w in ("with", "against", "into")},
    **{(dash, "each", "other"): (collide, "with", "each", "other") for dash, collide in (
        ("dash", "collide"), ("dashing", "colliding"), ("dashed", "collided"))},
    ("at", "the", "time", "of", "dashing"): ("at", "the", "time", "of", "collision"),
    ("in", "the", "starting"): ("at", "the", "start"), ("from", "the", "starting"): ("from", "the", "start"),
    ("the", "starting", "of"): ("the", "start", "of"), ("start", "itself"): ("start",),
    **{("kindly", "tell", w): ("tell", "me", w) for w in ("the", "what", "which", "whether", "if", "how")},
    # Nigerian English: to 'jam' a vehicle is to hit it ('will the red vehicle jam another vehicle?')
    **{(jam, w): (hit, w) for jam, hit in (("jam", "hit"), ("jams", "hits"), ("jammed", "hit"), ("jamming", "hitting"))
       for w in ("the", "another", "each", "anything", "something", "any", "a", "an")},
    # the frames shown are the video ('Has the brown object been in a crash in the shown frames?' was read after it)
    **{(p, "the", *frames): ("in", "the", "video") for p in ("in", "within", "during", "throughout", "across")
       for shown in ("shown", "observed", "given", "visible", "displayed")
       for frames in (("frames", shown), (shown, "frames"))},
    # ... and after them, or after 'this' said of the video, is after it ('After the visible frames, is the brown
    # dirtbike going to collide with ...?', 'after this will the cyan road bike hit anything')
    **{("after", "this", w): ("after", "the", "video", w) for w in ("will", "is", "are", "does", "do", "would", ",",
                                                                    "?")},
    **{(p, "the", *frames): ("after", "the", "video") for p in ("after", "beyond", "past")
       for shown in ("shown", "observed", "given", "visible", "displayed")
       for frames in (("frames", shown), (shown, "frames"))},
    # a Chinese learner's 'if let' ('If let yellow vehicle start fast, it will collide with blue object?')
    ("if", "let"): ("if",),
    # the property asked first, before a colon ('Which colour: the thing that is accelerating at the start?')
    **{(which, colour, ":"): ("what", "color", "is") for which in ("which", "what") for colour in ("colour", "color")},
    **{(which, *of, kind, ":"): ("what", "kind", "of", "vehicle", "is") for which in ("which", "what")
       for of in ((), ("kind", "of")) for kind in ("type", "kind", "model", "vehicle")
       if (of, kind) != (("kind", "of"), "kind")},
    # a note's property after a colon ('Purple double bus @ start: speed?')
    **{(":", speed, "?"): (":", "what", "speed", "?") for speed in ("speed", "velocity")},
    # a video that opens ('had it been moving at high speed when the clip opens')
    **{(when, "the", film, opens): _START for when in ("when", "as") for film in ("video", "clip", "footage", "film")
       for opens in ("opens", "opened")},
    # a commentator's 'out-pacing' ('is the purple one out-pacing the green aeroplane?') and 'set to' of what will be
    # ('is the car set to run into the aeroplane?')
    **{said: ("faster", "than") for pacing in ("pacing", "running", "speeding", "stripping")
       for said in (("out", "-", pacing), ("out", pacing), ("out" + pacing,))},
    **{("set", "to", v): ("going", "to", v) for v in ("run", "hit", "collide", "crash", "smash", "bump", "strike",
                                                     "slam", "plough", "plow", "meet", "clip", "tangle")},
    # 'would you (happen to) know the colour of ...' asks it as 'do you know' does
    **{("would", "you", *happen, "know"): ("do", "you", "know") for happen in ((), ("happen", "to"))},
    # a moment asked of as a time ('Is there any moment when the yellow car crashes with ...?')
    **{(be, "there", a, moment, when): (be, "there", "any", "time", "when") for be in ("is", "was")
       for a in ("a", "any", "ever", "some") for moment in ("moment", "instant") for when in ("when", "where")},
    # Upper Midwest and Pittsburgh tags ('..., don'tcha know?', '..., n'at?': 'and that'), a rapper's closing
    # lines (', don't lie?', ', tell me true?', ', know what I mean?'), a nature film's 'in its path' of what a
    # vehicle hits (not its route), a racetrack's 'on the track' (read as 'on the truck'), the starting blocks
    **{(*c, *dont, "know"): () for c in ((), (",",)) for dont in (("don", "'", "tcha"), ("dontcha",), ("doncha",))},
    (",", "n", "'", "at"): (), ("n", "'", "at", "?"): ("?",),
    **{(",", *t, "?"): ("?",) for t in (("do", "not", "lie"), ("tell", "me", "true"), ("know", "what", "i", "mean"),
                                        ("you", "feel", "me"), ("what", "you", "got"), ("spit", "it", "back"))},
    **{(w, "in", p, "path"): (w,) for w in ("anything", "something", "anyone", "everything")
       for p in ("its", "his", "her", "the")},
    ("on", "the", "track"): (),
    # a consultant's look at something ('Let's double-click on the biplane's incident:', 'Circling back on the log,'),
    # its fillers ('net-net', 'so we're all aligned'), a showman's 'step right up'
    **{(*d, c, "on"): ("look", "at") for d in ((), ("double", "-")) for c in ("click", "drill", "deep", "dive")},
    **{(*d, c, "on"): ("looking", "at") for d in ((), ("double", "-")) for c in ("clicking", "drilling")},
    **{(c, "back", o): (look, "at") for c, look in (("circle", "look"), ("circling", "looking")) for o in ("on", "to")},
    # ... and an email's reminders before the question ('Circling back once more: was there ...?', 'Reminding you
    # once again:', 'Sorry to bother you again (not really):'), whose 'back' and 'again' ask no direction or count
    **{(*j, *c, *again, *p): () for j in ((), ("just",)) for c in (("circling", "back"), ("reminding", "you"),
                                                                 ("sorry", "to", "bother", "you"))
       for again in ((), ("again",), ("once", "again"), ("once", "more"), ("one", "more", "time"))
       for p in ((":",), (",",), ("(", "not", "really", ")", ":"))},
    **{(*w, "we", c, "back", *o): () for w in (("before",), ("when",), ("once",), ("as",)) for c in ("circle", "loop")
       for o in ((), ("on", "it"))},
    ("net", "-", "net", ","): (), ("net", "-", "net"): (), (",", "so", "we", "'", "re", "all", "aligned"): (),
    # a pastiche's 'meet with a crash' (have one), 'tell me true ,'; an audio guide's 'ask yourself :'; a rapper's
    # ', straight up ,' (truly), 'in its lane', 'with a thud' (how a collision sounds), 'when the clip kicked in' (the
    # start), its closing lines
    **{(m, "with", a, c): (h, a, c) for m, h in (("meet", "have"), ("meets", "has"), ("met", "had"))
       for a in ("a", "an") for c in ("crash", "collision", "accident", "impact", "smash", "bump")},
    ("tell", "me", "true", ","): (), **{("ask", "yourself", p): () for p in (":", ",")},
    **{(*c, "and", "ask", "yourself", ":"): (":",) for c in ((), (",",))},
    (",", "straight", "up", ","): (",",),
    **{("in", d, "lane"): () for d in ("the", "its", "his", "her", "their", "a")},
    **{("with", a, t): () for a in ("a", "an") for t in ("thud", "bang", "crunch", "clang", "boom", "wallop", "thump")},
    **{(w, "the", f, k, "in"): _START for w in ("when", "as") for f in ("video", "clip", "footage", "film")
       for k in ("kicked", "kicks")},
    **{(",", *t, "?"): ("?",) for t in (("what", "'", "s", "up"), ("that", "'", "s", "the", "score"),
                                        ("is", "that", "a", "fact"))},
    # a West African's 'small-small' (slowly), a chess commentator's tempo (pace), a gangster's tags, 'slug' (hit)
    **{("small", *d, "small"): ("slowly",) for d in ((), ("-",))},
    **{(p, "up", "tempo"): (p, "up", "speed") for p in ("pick", "picks", "picking", "picked")},
    **{(",", t, "?"): ("?",) for t in ("see", "capiche", "capisce", "savvy")}, ("tell", "me", "straight", ","): (),
    # a Brummie's 'ar' (yes), 'our kid' (whom it is asked), 'the frames what's left', 'tara' (goodbye)
    ("ar", "or", "no"): ("yes", "or", "no"), (",", "our", "kid"): (), ("our", "kid", ","): (),
    **{(p, "the", "frames", "what", "'", "s", "left"): ("after", "the", "video", "ends") for p in ("in", "during")},
    **{(p, "what", "'", "s", "left", "of", "the", v): ("after", "the", "video", "ends") for p in ("in", "during")
       for v in ("video", "clip", "footage", "film")},
    (",", "tara"): (), ("tara", ","): (), ("then", "tara"): (),
    # Cornwall's 'my 'ansum' (whom it is asked) and a closing ', then'; a question's 'tell me (the truth) ,' said
    # within it ('At first, tell me, is ...'), 'straight up' (honestly) before or after it; 'goes and hits' (hits)
    **{(*c, "my", "'", "ansum", *e): () for c, e in (((",",), ()), ((), (",",)))},
    (",", "then", ",", "my"): (",", "my"), **{(",", "then", e): (e,) for e in ("?", "!")},
    **{(",", "tell", "me", *t, ","): (",",) for t in ((), ("the", "truth"), ("true",), ("straight",))},
    ("tell", "me", "the", "truth", ","): (),
    **{("straight", "up", ",", aux): (aux,) for aux in ("is", "was", "does", "did", "will", "are", "were", "do", "has",
                                                       "would", "when", "at", "in", "what", "which", "how")},
    (",", "straight", "up", "?"): ("?",),
    **{(g, "and", v): (v,) for g in ("go", "goes", "went", "going") for v in (
        "hit", "hits", "strike", "strikes", "struck", "crash", "crashes", "crashed", "smash", "smashes", "smashed",
        "bump", "bumps", "bumped", "bang", "bangs", "banged", "slam", "slams", "slammed", "run", "runs", "ran")},
    # a Londoner's rhyming slang ('the old jam jar', a car; 'no porkies', no lies) and pace ('at a fair old lick',
    # 'like the clappers'), a New Yorker's 'whaddaya think'
    ("jam", "jar"): ("car",), ("no", "porkies", "now", ":"): (), ("no", "porkies", ","): (),
    **{(*a, "fair", "old", "lick"): ("fast",) for a in (("at", "a"), ("a",))}, ("like", "the", "clappers"): ("fast",),
    **{(",", w, "think", "?"): ("?",) for w in ("whaddaya", "whaddya", "watcha", "whatcha")},
    # a showman's 'my friends' and 'keep your eyes on'; a coach's 'let's unpack this (moment)', 'lean into it'; an
    # esports caster's 'rotates into view' (comes into it) and 'ramping up', 'land a hit on'; a librarian's 'softly
    # now'
    **{(",", "my", f, e): (e,) for f in ("friends", "people", "dear") for e in (",", ":", "?", "!")},
    **{(k, "your", e, "on"): ("look", "at") for k in ("keep", "fix") for e in ("eyes", "eye", "gaze")},
    **{(d, "your", g, "to"): ("look", "at") for d in ("direct", "turn", "cast") for g in ("gaze", "eye", "eyes")},
    **{("let", "'", "s", "unpack", "this", *m, ":"): () for m in ((), ("moment",), ("crash", "moment"), ("one",),
                                                                  ("moment", "of", "impact"))},
    **{(*l, "lean", "into", *it, ":"): () for l in ((), ("let", "'", "s")) for it in (
        ("it",), ("it", "with", "me"), ("this",), ("the", "comparison"))},
    **{(r, i, *t): (c, "into", "view") for r, c in (("rotates", "comes"), ("rotating", "coming"), ("rotated", "came"),
                                                    ("rotate", "come")) for i, t in (("into", ("view",)),
                                                                                    ("into", ("frame",)), ("in", ()))},
    ("ramping", "up"): ("speeding", "up"), ("ramps", "up"): ("speeds", "up"),
    **{(l, "a", "hit", "on"): (h,) for l, h in (("land", "hit"), ("lands", "hits"), ("landed", "hit"))},
    **{("softly", *n, p): () for n in ((), ("now",)) for p in (",", ":")},
    # a call-centre agent's courtesies ('Thank you for your patience;', 'This call may be recorded for quality
    # purposes;', 'Just to confirm on my end,') and requests ('may I confirm whether ...', 'may I ask which ...'); a
    # toastmaster's and a butler's ('Ladies and gentlemen,', 'if I may have your attention:')
    **{(*t, "for", *h, p): () for t in (("thank", "you"), ("thanks",), ("thanks", "ever", "so", "much"),
                                         ("thank", "you", "ever", "so", "much"), ("thanks", "so", "much"))
       for h in (("your", "patience"), ("holding",), ("waiting",), ("calling",)) for p in (";", ",", ":", ".")},
    **{(*l, "thank", "you", p): () for l in (("lovely", ","), ()) for p in (";", ":")},
    **{("this", "call", "may", "be", "recorded", "for", "quality", "purposes", p): () for p in (";", ",", ".", ":")},
    **{("just", "to", c, "on", "my", "end", ","): () for c in ("confirm", "check", "verify")},
    **{("may", "i", v): ("tell", "me") for v in ("confirm", "ask", "check", "verify")},
    **{(c, "you", "confirm", "the"): ("tell", "me", "the") for c in ("could", "can", "would")},
    **{(*c, "ladies", "and", g, p): (p,) * (c != () and p in (":", "!")) for c in ((), (",",))
       for g in ("gentlemen", "gents") for p in (",", ":", "!")},
    **{("if", "i", "may", "have", "your", "attention", p): () for p in (",", ":")},
    # a teacher's 'can anyone tell me'; a controller's 'say again' (read as how often) and ', over?'; a preacher's
    # and a host's forms of address; a ghost story's 'and nobody knows why ...' (read as asking why); 'do we think?'
    **{(c, who, "tell", "me"): ("tell", "me") for c in ("can", "could", "will", "would")
       for who in ("anyone", "anybody", "someone", "somebody", "everyone", "everybody")},
    **{(*c, "say", "again", p): () for c in ((), ("roger", ",")) for p in (",", ":", ";")},
    **{(",", "say", "again", "?"): ("?",), (",", "over", "?"): ("?",)},
    **{(",", d, a, p): (p,) for d in ("dear", "good", "my") for a in ("flock", "people", "brethren", "children",
                                                                     "friends", "listeners", "contestants", "lovelies",
                                                                     "love")
       for p in (",", ":", "?", ";", "!")},
    **{(",", "ma", "'", "am", p): (p,) for p in (",", ":", "?", ";", "!")},
    **{(*c, *a, *n, "why"): () for c in ((",",), ()) for a in (("and",), ()) for n in (
        ("nobody", "knows"), ("no", "one", "knows"), ("none", "can", "say"), ("who", "knows"))},
    **{(",", w, "we", t, "?"): ("?",) for w in ("do", "would") for t in ("think", "reckon", "know", "say")},
    **{(q, s): (s,) for q in ("perfectly", "utterly") for s in ("still", "static", "stationary", "motionless")},
    **{("hang", "onto", "your", "hats", p): () for p in (":", ",", "!", ";")},
    # a quiz host's stakes ('Contestant, for double points: does ...'), which no vehicle points
    **{(*c, "for", *n, "points", p): () for c in ((",",), ()) for p in (":", ",", "!", ";")
       for n in (("double",), ("triple",), ("bonus",), ("extra",), ("all", "the"), ("the", "bonus"))},
    # ... and whom the answer is told ('Can you tell our studio audience what colour ...?')
    **{(tell, our, *studio, audience): (tell, "me") for tell in ("tell", "show") for our in ("our", "the")
       for studio in ((), ("studio",), ("lovely",), ("home",)) for audience in ("audience", "viewers", "listeners")},
    # a children's presenter's 'boys and girls' and '? What do you think?'; a jazz host's 'cool cats' (read as 'car');
    # a soap narrator's 'Previously on 'Fast Hearts':'
    **{(",", "boys", "and", "girls", p): (p,) for p in (",", "?", ":", "!")}, ("boys", "and", "girls", ","): (),
    **{("?", "what", "do", "you", t, "?"): ("?",) for t in ("think", "imagine", "reckon")},
    **{(",", *c, "cats", p): (p,) for c in ((), ("cool",)) for p in (",", "?", ":", ";")},
    ("previously", "on"): (),
    # a commentator's 'on that play'; a news anchor's 'Reports are coming in about X:'; a Regency lady's 'I dare say',
    # 'pray,', ', I should like to know,'; a quest giver's 'what manner of vehicle', 'Tell me true,'; a grandmother's
    # 'Bless them both,', 'Tell your old nan,'
    ("on", "that", "play"): ("at", "that", "moment"),
    ("reports", "are", "coming", "in", "about"): ("about",),
    **{(*s, "i", *d): () for s in ((), (",",)) for d in (("dare", "say"), ("daresay",))},
    **{(p, "pray", ","): (p,) for p in (",", ";", ":", ".")}, ("pray", ","): (),
    **{(",", "i", w, "like", "to", "know", ","): () for w in ("should", "would")}, (",", "i", "must", "ask", ","): (),
    **{("tell", "me", *t, ":"): () for t in (("true",), ("the", "truth"), ("straight",))},
    **{("tell", "me", "true", ","): ()},
    ("what", "manner", "of"): ("what", "kind", "of"),
    **{(w, "that", "be", "?"): ("is", "that", "?") for w in ("would", "might", "could")},
    **{("bless", *b, p): () for b in (("them", "both"), ("them",), ("it",), ("him",), ("her",), ("its", "heart"))
       for p in (",", "!")},
    **{("tell", "your", *o, n, ","): ("tell", "me", ",") for o in ((), ("old",)) for n in ("nan", "gran", "granny",
                                                                                        "grandma", "nana")},
    # 'building up speed' (read as 'frame up'); a lifeguard's 'Heads up,'; a safari guide's 'Look there,'; a caller's
    # 'You heard it here first:'
    **{(b, "up", *i, "speed"): (s, "up") for b, s in (("building", "speeding"), ("builds", "speeds"),
                                                     ("built", "sped"), ("build", "speed"))
       for i in ((), ("its",), ("some",), ("a", "bit", "of"))},
    **{(h, "up", p): () for h in ("heads", "head") for p in (",", ":", "!")},
    **{("look", "there", p): () for p in (",", "!")},
    **{("you", "heard", "it", "here", "first", p): () for p in (":", ",", ";", "-", "!", ".")},
    # a train conductor's 'Next stop,'; a bingo caller's 'Eyes down,'; a sailor's 'driftin' slow' (not a turn); a
    # scribe's 'of what colour', 'Tell me truly,'
    ("next", "stop", ","): (), **{("eyes", "down", p): () for p in (",", ":", "!")},
    ("eyes", "down", "for"): ("look", "at"),
    **{(d, s): (m, "slowly") for d, m in (("drifting", "moving"), ("drifts", "moves"), ("drift", "move"),
                                          ("drifted", "moved")) for s in ("slow", "slowly")},
    **{("of", "what", q): ("what", q) for q in ("colour", "color", "model", "kind", "type", "shape", "sort", "speed")},
    ("tell", "me", "truly", ","): (), ("tell", "me", "honestly", ","): (), ("honestly", ",", "tell", "me", "-"): (),
    # a war correspondent's 'Reporting from the front' and 'front line' (no direction); a rodeo announcer's 'Right out
    # of the chute'; a birdwatcher's 'through my binoculars'; a lecturer's 'as we saw last week'
    **{(*c, "reporting", "from", "the", "front", *line): () for c in ((), (",",)) for line in ((), ("line",))},
    **{(p, "the", "front", "line"): () for p in ("from", "at", "on")},
    **{(*r, "out", "of", "the", "chute", *a): t for r in ((), ("right",)) for a, t in (
        ((",",), ("at", "the", "start", ",")), (("at",), ("at",)))},
    **{(*a, t, d, "binoculars"): () for a in ((), ("as", "seen")) for t in ("through", "in")
       for d in ("my", "the", "our")},
    **{(*c, "as", "we", v, *last, "week", *p): () for c, p in (((",",), ()), ((), (",",)), ((), (":",)))
       for v in ("saw", "discussed", "covered", "learned", "learnt", "said") for last in (("last",), ("in", "last"))},
    **{(",", "please", p): (p,) for p in (":", ";")},
    # a submarine captain's 'Steady as she goes;', 'Sonar reports ...', 'at fewer knots than'
    **{("steady", "as", s, "goes", p): () for s in ("she", "it") for p in (";", ",", ".", ":", "!")},
    **{(d, r): () for d in ("sonar", "radar") for r in ("reports", "shows", "says")},
    **{("at", m, "knots", "than"): (c, "than") for m, c in (("fewer", "slower"), ("more", "faster"))},
    # a border officer's 'Anything to declare about the red one:'; a Briton's 'early doors' (early on)
    **{(a, "to", "declare", "about"): ("about",) for a in ("anything", "something")},
    ("early", "doors"): _START,
    # a meditation teacher's ('let your eyes rest on the vehicle that is stationary;', 'simply notice the minivan')
    **{("let", "your", e, v, *g, on): ("look", "at") for e in ("eyes", "eye", "gaze", "awareness", "attention", "mind")
       for v in ("rest", "soften", "settle", "fall") for g in ((), ("gently",), ("softly",)) for on in ("on", "upon")},
    **{(q, v): (v,) for q in ("simply", "gently", "just") for v in ("notice", "observe")},
    **{(",", "without", j, p): (p,) for j in ("judgement", "judgment") for p in (",", ":", ";", "?")},
    **{(",", "and", *i, "want", "to", "know", p): (".",) for i in (("i",), ("we",)) for p in (":", ",")},
    ("quick", "level", "-", "set"): ("quick", "note"), ("step", "right", "up", ","): (), ("step", "right", "up"): (),
    **{(*r, o, "the", b): _START for r in ((), ("right",)) for o in ("off", "out", "outta")
       for b in ("block", "blocks", "gate", "gates")},
    # a racing commentator's starting stalls and straights ('had it come out of the stalls fast', 'as they break
    # from the stalls', 'down the home straight'; not the front of a vehicle)
    **{(*o, "the", "stalls"): _START for o in (("out", "of"), ("from",), ("in",), ("outta",))},
    **{(*c, *a, "the", "stalls", *f, "open", *e): _START for c in ((), (",",)) for a in (("as",), ("when",))
       for f in (("fly",), ("flew",), ("swing",), ("burst",), ("spring",)) for e in ((), (",",))},
    **{(*c, d, "the", *h, "straight", *e): ((",",) if c and e else ()) for c in ((), (",",))
       for d in ("down", "up", "along", "into", "on") for h in (("home",), ("back",), ("far",), ())
       for e in ((), (",",))},
    # ... a runner breaking or flying from the stalls starts ('breaks from the stalls', 'had broken fast from the
    # start', 'had flown out of the stalls fast': no collision's break, no floating), and 'all race long'
    **{(b, o, "the", g): (start,) for b, start in (("break", "start"), ("breaks", "starts"), ("broke", "started"),
                                                   ("broken", "started"), ("breaking", "starting"),
                                                   ("fly", "start"), ("flies", "starts"), ("flew", "started"),
                                                   ("flown", "started"), ("flying", "starting"))
       for o in ("from", "out") for g in ("stalls", "gates", "gate", "blocks")},
    **{(b, "out", "of", "the", g): (start,) for b, start in (("fly", "start"), ("flies", "starts"),
                                                            ("flew", "started"), ("flown", "started"),
                                                            ("flying", "starting"), ("broke", "started"),
                                                            ("broken", "started"), ("breaks", "starts"))
       for g in ("stalls", "gates", "gate", "blocks")},
    **{(b, pace): ("started", pace) for b in ("broke", "broken") for pace in ("fast", "slow", "slowly", "quickly")},
    ("all", "race", "long"): (),
    **{(*c, "in", "the", "thick", "of", *it): () for c in ((), (",",))
       for it in (("it",), ("things",), ("the", "action"))},
    # 'Turn back the clock, imagine ...': the imagining's own opener
    **{(*t, *e): () for t in (("turn", "back", "the", "clock"), ("turn", "the", "clock", "back"),
                              ("turning", "back", "the", "clock"), ("turning", "the", "clock", "back"))
       for e in ((",",), (":",), (";",), ("-",))},
    # a therapist's ('Let us gently sit with the moment they collide :', 'in your own time', 'there are no wrong
    # answers here :') and a ringmaster's ('Behold the bus , children of all ages :', 'feast your eyes on')
    **{(*let, *g, v, "with"): () for let in (("let", "us"), ("let", "'", "s"), ("lets",))
       for g in ((), ("gently",), ("just",)) for v in ("sit", "rest", "stay", "be")},
    **{(*c, *a, "in", "your", "own", "time", *e): () for c, e in (((), (",",)), ((",",), ()), ((), (":",)), ((), ()))
       for a in ((), ("and",))},
    **{(*c, *a, "there", *are, "no", "wrong", "answers", *h, e): () for c in ((), (",",)) for a in ((), ("and",))
       for are in (("are",), ("'", "re")) for h in ((), ("here",)) for e in (",", ":", ";", ".", "-")},
    **{(f, "your", "eyes", "on"): ("look", "at") for f in ("feast", "cast", "rest")},
    ("behold",): ("look", "at"),
    **{(*c, "children", "of", "all", "ages", *e): () for c, e in (((), (",",)), ((",",), ()))},
    **{(*c, "under", "the", "big", "top", *t, *e): () for c, e in (((), (",",)), ((",",), ()), ((), ()))
       for t in ((), ("tonight",))},
    ("death", "-", "defying"): (),
    # a wizard's ('My scrying glass shows the car as the clip begins ;', 'speak truly ,', 'By the ancient runes ,'),
    # a fortune teller's crystal ball, a gangster's ('No funny business now ,', '..., or is somebody pulling my leg ?')
    **{(*m, *g, v): () for m in (("my",), ("the",), ("our",)) for g in (("scrying", "glass"), ("scrying", "pool"),
                                                                      ("crystal", "ball"), ("seeing", "stone"))
       for v in ("shows", "reveals", "showed", "revealed", "gazes", "looks", "peers", "sees")},
    **{("speak", "truly", p): () for p in (",", ":", ";", "-")},
    **{("by", "the", *a, "runes", p): () for a in ((), ("ancient",), ("old",)) for p in (",", ":")},
    **{("no", "funny", "business", *n, p): () for n in ((), ("now",)) for p in (",", ";", ":", ".", "-")},
    **{(",", "or", "is", s, v, *w): ("?",) for s in ("somebody", "someone", "anybody", "anyone")
       for v, w in (("pulling", ("my", "leg", "?")), ("pullin", ("my", "leg", "?")),
                    ("feeding", ("me", "a", "line", "?")), ("feedin", ("me", "a", "line", "?")))},
    # an archaeologist's ('..., as found in situ ?', 'Let us record ...') and a wizard's 'come to pass'
    **{(",", *a, "found", "in", "situ"): () for a in ((), ("as",))},
    ("come", "to", "pass"): ("happen",),
    **{("caught", *u, "in"): ("involved", "in") for u in ((), ("up",))},
    ("steady", "now", ","): (),
    # a historian's ('..., historians would later ask, was the minivan ...', 'as historians are wont to do ,', 'when
    # they met in collision', 'at the hour they collided')
    **{(*c, *who, m, *a, v, e): (",",) * bool(c) for c in ((), (",",))
       for who in (("historians",), ("scholars",), ("people",), ("some",), ("many",), ("one",), ("you",), ("critics",),
                   ("viewers",), ("fans",), ("someone",), ("somebody",))
       for m in ("would", "might", "may", "will", "could", "must") for a in ((), ("later",), ("well",), ("rightly",))
       for v in ("ask", "wonder") for e in (",", ":", ";", "-")},
    **{(",", "as", who, "are", *wont, "to", "do", ","): (",",) for who in ("historians", "scholars", "people", "we",
                                                                          "they") for wont in (("wont",), ("will", "not"))},
    **{("met", "in", *a, "collision"): ("collided",) for a in ((), ("a",))},
    ("at", "the", "hour"): ("at", "the", "moment"),
    # a pharmacist's ('Just to be on the safe side ,') and an astronaut's ('From up here in orbit ,')
    **{(*j, "to", "be", "on", "the", "safe", "side", p): () for j in ((), ("just",)) for p in (",", ":")},
    **{(*f, "up", "here", *o, p): () for f in ((), ("from",)) for o in ((), ("in", "orbit"), ("in", "space"))
       for p in (",", ":")},
    # a boxing announcer's ('In this corner , the red SUV !', 'had it come out of its corner fast', 'Let's get ready
    # to rumble !', 'when round one began', 'as the bus lands its hit on the bike', 'that challenger')
    **{("in", t, "corner", p): () for t in ("this", "that", "the", "blue", "red") for p in (",", ":")},
    **{(*o, w, "corner"): () for o in (("in",), ("out", "of"), ("from",)) for w in ("its", "her", "their", "the")},
    **{(come, "out", "of", w, "corner"): (start,) for come, start in (("come", "started"), ("came", "started"),
                                                                     ("comes", "starts"), ("coming", "starting"))
       for w in ("its", "her", "their")},
    **{(*l, "get", "ready", "to", "rumble", p): () for l in (("let", "'", "s"), ("lets",)) for p in ("!", ",", ".")},
    **{(w, "round", "one", b): (w, "the", "video", b) for w in ("when", "as") for b in (
        "began", "begins", "starts", "started", "kicks", "kicked")},
    **{(v, *a, h, "on"): (hits,) for v, hits in (("lands", "hits"), ("landed", "hit"), ("landing", "hitting"),
                                                 ("land", "hit")) for a in ((), ("its",), ("a",), ("her",))
       for h in ("hit", "blow", "punch")},
    ("introducing",): ("look", "at"),
    # a dentist's ('Just a little pressure here —') and a bartender's ('What'll it be ?', 'Last orders ,', 'Pull up
    # a stool , friend —', 'while you're thinking ,', 'Have this one on the house and tell me :')
    **{(*a, "pressure", *h, p): () for a in (("just", "a", "little"), ("a", "little"), ("gentle",), ("little",),
                                           ("just", "a", "bit", "more"), ("a", "bit", "more"), ("a", "bit", "of"))
       for h in ((), ("here",), ("now",)) for p in ("-", ",", ";", ":")},
    **{("open", "wide", p): () for p in (",", "-", ";", ":", "!")},
    **{("what", "'", "ll", "it", "be", *m, p, *a): () for m in ((), (",", "mate"), (",", "friend"), (",", "pal"))
       for p in ("?", ",") for a in ((), ("and",))},
    **{(*a, "while", *you, v, p): () for a in ((), ("and",)) for you, v in (
        (("you", "'", "re"), "thinking"), (("you", "are"), "thinking"), (("you",), "decide"), (("i",), "pour"),
        (("you",), "think"), (("you",), "wait")) for p in (",", "-", ";", ":")},
    **{("last", o, *b, *f, p): () for o in ("orders", "call") for b in ((), ("at", "the", "bar"))
       for f in ((), (",", "friend"), (",", "folks"), (",", "mate")) for p in (",", ":", "-", ";")},
    **{("pull", "up", "a", s, *f, p): () for s in ("stool", "chair", "seat") for f in ((), (",", "friend"))
       for p in (",", "-", ":", ";")},
    **{("have", "this", "one", "on", "the", "house", *a): a for a in ((",",), ("and",))},
    ("tell", "me", "straight", "-"): (), ("tell", "me", "straight", ":"): (),
    # a zookeeper's ('Please don't tap the glass , folks —', 'our resident blue bus', 'Feeding time in the bus house :')
    **{(*p, *d, "tap", "the", "glass", *f, e): () for p in ((), ("please",)) for d in (("do", "not"), ("don", "t"))
       for f in ((), (",", "folks"), (",", "everyone"), (",", "little", "ones"), (",", "kids")) for e in ("-", ",", ":")},
    **{(o, "resident"): ("the",) for o in ("our", "the", "my")},
    **{(*a, "feeding", "time", p): (p,) * bool(a) for a in ((), ("at",), ("after",), ("before",))
       for p in (",", ":", "-", ";")},
    **{("feeding", "time", "in", "the", v, "house", p): () for v in ("bus", "car", "bike", "plane", "jet", "truck")
       for p in (",", ":", "-", ";")},
    # a nurse's ('Next patient , the gray mountain bike :', ', for the chart :'), a herald's ('in the lists'), a
    # flight attendant's ('For your safety ,', 'please remain seated while we ask :'), a cabbie's (', you know what I
    # mean ?', ', right , so what colour ...'), a gossip's ('Mark my words and tell me ,', 'Purl two and', ', did you
    # hear ?') and a ballet teacher's ('again , with feeling ,', '? From the top , please .')
    **{("next", "patient", p): () for p in (",", ":", "-", ";", "!", ".")},
    **{(*c, "for", "the", r, p): (p,) * (p == ":" and c != ()) for c in ((), (",",))
       for r in ("chart", "record", "notes", "file") for p in (",", ":")},
    ("in", "the", "lists"): (),
    **{("for", "your", "safety", p): () for p in (",", ":")},
    **{("please", "remain", "seated", *w, p): () for w in ((), ("while", "we", "ask")) for p in (",", ":", ";", ".")},
    (",", "you", "know", "what", "i", "mean", "?"): ("?",),
    **{(",", "right", ",", *so, w): (",", w) for so in (("so",), ()) for w in (
        "would", "will", "is", "was", "did", "does", "what", "which", "how")},
    **{("mark", "my", "words", p): () for p in (",", "and", ":")},
    **{("purl", n, p): () for n in ("one", "two", "three") for p in (",", "and", ":")},
    **{(",", "did", "you", "hear", "?"): ("?",), (",", "have", "you", "heard", "anything", ","): (",",),
       ("have", "you", "heard", "anything", ","): ()},
    **{(*c, "again", ",", "with", "feeling", p): () for c in ((), (",",)) for p in (",", ":")},
    **{("?", "from", "the", "top", *p, "."): ("?",) for p in ((), (",", "please"))},
    # a knight's ('Upon mine honour ,', ', I ask upon mine honour ?', 'by my sword', 'in this quest') and a tabloid's
    # ('Sources close to the production reveal ...'), a trainspotter's ('? Ooh, that'd be a first for me.')
    **{(*c, *i, u, m, h, p): (p,) * (p == "?") for c in ((), (",",)) for i in ((), ("i", "ask")) for u in ("upon", "on")
       for m in ("mine", "my") for h in ("honour", "honor") for p in (",", "?", ":", "!")},
    **{(",", "i", "ask", *b, "?"): ("?",) for b in ((), ("by", "my", "sword"), ("thee",), ("you",))},
    ("in", "this", "quest"): (), ("forsooth", ","): (), ("by", "my", "troth", ","): (),
    **{("sources", "close", "to", "the", x, v, *t): () for x in ("set", "production", "race", "wreck", "star", "crash",
                                                               "scene", "studio", "palace", "team")
       for v in ("reveal", "say", "tell", "claim", "confirm", "reveals", "says") for t in ((), ("that",))},
    **{("?", *o, "that", *b, "be", "a", "first", "for", "me", e): ("?",) for o in ((), ("ooh", ","), ("now",))
       for b in (("'", "d"), ("'", "ll"), ("would",), ("will",)) for e in (".", "!")},
    **{(",", "right", "-", w): ("-", w) for w in ("would", "will", "is", "was", "did", "does", "what", "which", "how")},
    # a physio's 'Where does it hurt ?' before the question; a tabloid's 'this high-flying show-off' (one floating)
    # the picture starting is the video's ('when this here picture starts rollin'': read with 'galloping' as
    # moving, it was a vehicle coming into view)
    **{(*d, "picture", v, *r): ("the", "video", v) for d in (("the",), ("this",), ("this", "here"))
       for v in ("starts", "begins", "started", "began") for r in ((), ("rolling",), ("rollin",))},
    # a bard's ('..., fa-la-la ?', 'Hark , and I shall sing of a chopper :', 'A tale of the red aeroplane , so the
    # minstrels say :'), a trader's ('Green SUV , one careful owner —', 'Go on then ,'), a podcaster's ('Welcome back
    # to the show :', 'Stay tuned , because', 'Our listeners wrote in about the biplane :') and an antiques dealer's
    # ('..., or do my old eyes deceive me ?', ', for my records')
    **{(*c, "fa", "-", "la", "-", "la", *p): p if c else () for c in ((), (",",))
       for p in ((",",), (":",), ("?",), ("!",), (".",), ())},
    **{(*h, "i", "shall", "sing", "of"): ("look", "at") for h in (("hark", ",", "and"), ("hark", ","), ())},
    ("a", "tale", "of"): ("look", "at"),
    **{(",", "so", "the", w, "say"): () for w in ("minstrels", "bards", "songs", "stories", "legends", "poets")},
    **{(",", "one", "careful", "owner", p): (p,) * (p != ",") for p in (",", "-", ":", ";")},
    **{(",", "lovely", "bit", "of", "kit", p): (p,) * (p != ",") for p in (",", "-", ":", ";")},
    **{("go", "on", "then", p): () for p in (",", "-", ":")},
    **{("welcome", "back", *t, p): () for t in ((), ("to", "the", "show"), (",", "folks"), (",", "listeners"),
                                              (",", "true", "-", "crime", "fans"), (",", "everyone"))
       for p in (",", ":", "!", "-")},
    **{("stay", "tuned", p, *b): () for p in (",", ":") for b in ((), ("because",))},
    **{("our", "listeners", "wrote", "in", "about"): ("look", "at"), ("our", "listeners", "wrote", "in", ":"): ()},
    **{("here", "'", "s", *w, p): () for w in (("our", "first", "clue", "of", "the", "evening"), ("the", "cliffhanger"),
                                             ("the", "cliffhanger", ",", "folks")) for p in (",", ":", "-")},
    **{(",", "or", "do", "my", *o, "eyes", "deceive", "me", "?"): ("?",) for o in ((), ("old",))},
    **{(",", "for", w, r): () for w in ("my", "the", "our") for r in ("records", "record", "catalogue", "files")},
    # a football manager's 'at the end of the day' (in the end: no time of the video's), 'we go again', 'credit where
    # it's due'; a comic's '? Anybody? Is this thing on?', '? Tough crowd.'; a dinner lady's ('Eat up , love :', 'Is
    # it right , pet , that ...', 'No running in the hall ,')
    **{(*c, "at", "the", e, "of", "the", "day", *p): (",",) * (c != () and p != ()) for c in ((), (",",))
       for e in ("end", "ends") for p in ((), (",",))},
    **{(*c, "we", "go", "again", *p): (",",) * (c != () and p != ()) for c in ((), (",",)) for p in ((), (",",))},
    **{(",", "credit", "where", "it", "'", "s", "due"): ()},
    **{("?", a, "?"): ("?",) for a in ("anyone", "anybody", "hello", "no")},
    **{("is", "this", "thing", "on", "?"): (), ("?", "tough", "crowd", "."): ("?",), ("?", "tough", "crowd", "!"): ("?",),
       ("?", "anybody", "awake", "out", "there", "?"): ("?",), ("?", "anyone", "awake", "out", "there", "?"): ("?",),
       ("?", "do", "not", "all", "answer", "at", "once", "."): ("?",)},
    **{("is", "it", "right", *c, "that"): ("is", "it", "true", "that") for c in ((), (",",))},
    **{(*c, e, "up", *a, p): () for c in ((), (",", "come", "on", ",")) for e in ("eat", "plates")
       for a in ((), (",", "love"), (",", "pet"), (",", "come", "on")) for p in (",", ":", "!", ".", "-")},
    **{("come", "on", p): () for p in (",", ":", "!", "-")},
    **{("no", "running", "in", "the", h, *z, p): () for h in ("hall", "corridor", "corridors")
       for z in ((), (",", "and", "no", "zooming", "neither")) for p in (",", ":", "!", "-", ";")},
    # a tax inspector's (', and I will need that in writing ,', ', per section four ,', 'strictly for the audit
    # trail ,') and a night guard's ('Scrolling through the feed :', 'across my screen')
    **{(",", "and", *i, w, t, "in", "writing", p): (p,) for i, w in ((("i", "will"), "need"), (("i", "shall"), "need"),
                                                                (("i", "shall"), "want"), (("i", "will"), "want"),
                                                                (("i", "'", "ll"), "need"), (("may", "i"), "have"))
       for t in ("that", "this", "it") for p in (",", "?")},
    **{(",", "per", "section", n, p): (p,) for n in ("one", "two", "three", "four", "five", "six") for p in (",", "?")},
    **{(*s, "for", "the", "audit", "trail", p): () for s in ((), ("strictly",), ("purely",)) for p in (",", ":")},
    **{("scrolling", "through", "the", f, p): () for f in ("feed", "footage", "tape") for p in (",", ":")},
    **{("across", "my", "screen"): (), ("on", "my", "screen"): ()},
    **{("by", "the", t, "field", p): () for t in ("top", "bottom", "low", "far") for p in (",", ":")},   # a farmer's
    ("where", "does", "it", "hurt", "?"): (), ("high", "-", "flying"): ("floating",), ("show", "-", "off"): ("one",),
    # a carnival barker's ('Don't be shy , folks ,', 'Come closer , come closer ,', 'step up and tell me'), a rapper's
    # 'Straight up ,' (honestly), a spelling-bee host's ('Take your time with this one , speller :')
    **{(*d, "be", "shy", *n, *f, p): () for d in (("do", "not"), ("don", "t")) for n in ((), ("now",))
       for f in ((), (",", "folks"), (",", "everyone")) for p in (",", ":", "-", "!")},
    **{("come", "closer", ",", *c): () for c in ((), ("come", "closer", ","))},
    **{("step", "up", "and", "tell", "me"): ("tell", "me"), ("step", "right", "this", "way", "into"): ("imagine",)},
    **{("straight", "up", p): () for p in (",", "-", ":")},
    **{(*a, "take", "your", "time", *w, p): () for w in ((), ("with", "this", "one"), ("with", "this", "one", ",", "speller"))
       for p in (",", ":", ";", "-") for a in ((), ("and",))},
    # an air traffic controller's 'stopped dead' and 'that traffic' (the one aircraft named before: 'One unit
    # hovering at the start. Say colour of that traffic.')
    **{(st, "dead"): (st,) for st in ("stopped", "stop", "stops", "halted", "stood", "sat")},
    **{(d, "traffic"): (d, "vehicle") for d in ("that", "this")},
    # a cartographer's path that brings a vehicle into collision, or a track that shows one ('would its path have
    # brought it into collision with the cruiser', 'does the scooter's track show a collision with anything')
    **{("its", p, "have", "brought", "it", "into", *a, "collision", "with"): ("it", "have", "collided", "with")
       for p in ("path", "route", "track", "course", "trajectory") for a in ((), ("a",))},
    **{("'", "s", p, show, "a", "collision"): ("have", "a", "collision")
       for p in ("path", "route", "track", "course", "trajectory") for show in ("show", "record", "mark")},
    # a data scientist's vectors ('direction vector for the tandem at the start: which way is it heading?')
    **{(q, "vector"): (q,) for q in ("direction", "heading")},   # (a velocity vector is no speed class)
    # a mathematician's 'strictly less than that of' (a speed's, the one quantity compared here) and 'is there an
    # instant in the video at which they collide'
    **{("strictly", c): (c,) for c in ("less", "greater", "smaller", "larger", "lower", "higher", "slower", "faster")},
    **{(*st, c, "than", "that", "of"): (k, "than", "that", "of") for st in ((), ("strictly",))
       for c, k in (("less", "lower"), ("smaller", "lower"), ("greater", "higher"), ("larger", "higher"),
                    ("bigger", "higher"))},
    **{("is", "there", a, i, "in", "the", f, "at", w): ("do",) for a in ("a", "an", "any", "some")
       for i in ("instant", "moment", "time", "point", "frame") for f in FILM_WORDS for w in ("which", "when")},
    # the frames the speaker has seen ('after the frames we've watched', 'after the frames we have beheld'), and a
    # speaker's word before the choices ('..., I'm talking static, slow or fast?', 'and I'll give ya the options,')
    **{("after", "the", f, "we", *a, v): ("after", "the", "video") for f in ("frames", "footage", "clip", "video")
       for a in ((), ("'", "ve"), ("have",), ("'", "ve", "been"), ("have", "been"), ("were",), ("'", "re"))
       for v in ("seen", "watched", "beheld", "shown", "viewed", "got", "given", "saw")},
    **{(",", "i", "'", "m", "talking"): (",",), (",", "and", "i", "'", "ll", "give", "you", "the", "options", ","): (",",),
       (",", "and", "i", "'", "ll", "give", "ya", "the", "options", ","): (",",)},
    # a contract's name for a party ('the cyan cruiser, hereinafter the Party of the First Part, ...')
    **{(",", "hereinafter", *r, "the", "party", "of", "the", o, "part", p): (p,)
       for r in ((), ("referred", "to", "as"), ("called",)) for o in ("first", "second", "third") for p in (",", "?")},
    # a support agent's 'can you help me identify' (tell me)
    **{(*c, "help", "me", v): ("tell", "me") for c in ((), ("can", "you"), ("could", "you"))
       for v in ("identify", "find", "determine", "tell", "figure", "establish", "confirm", "know")},
    # an architect's 'along what heading' (the direction), a duration the whole video lasts, a vehicle's finish (its paint),
    # 'how would one categorise the bus's speed', 'does the bus carry the greater speed of the two'
    **{(p, w, h): ("in", w, "direction") for p in ("along", "under", "with") for w in ("what", "which")
       for h in ("heading", "bearing", "course", "direction")},
    **{(o, "the", *f, "duration", "of", "the"): ("in", "the") for o in ("over", "for", "during", "throughout")
       for f in ((), ("full",), ("entire",), ("whole",))},
    **{(c, "is", "its", f): (c, "is", "it") for c in ("colour", "color") for f in ("finish", "paint", "paintwork")},
    **{("how", "would", w, v): ("what", "is") for w in ("one", "you", "we", "i")
       for v in ("categorise", "categorize", "classify", "describe", "rate", "class")},
    **{(c, "the", g, "speed", "of", "the", "two"): ("move", "faster") for g in ("greater", "higher")
       for c in ("carry", "have", "carries", "has", "hold", "holds")},
    **{(c, "the", g, "speed", "of", "the", "two"): ("move", "slower") for g in ("lesser", "lower", "smaller")
       for c in ("carry", "have", "carries", "has", "hold", "holds")},
    # a barrister's 'I'll ask you to assume ...' (the condition's own opener)
    **{(*i, "ask", "you", "to", a): (a,) for i in (("i", "'", "ll"), ("i", "will"), ("i", "'", "d"), ("i", "would"),
                                                   ("let", "me"))
       for a in ("assume", "suppose", "imagine", "consider", "accept")},
    # a scout leader's ('eyes peeled ,', 'Think back over the clip , troop :')
    **{(*k, "eyes", "peeled", *p): () for k in ((), ("keep", "your")) for p in ((), (",",))},
    **{("think", "back", o, "the", f, p): () for o in ("over", "to", "on") for f in ("clip", "video", "footage")
       for p in (",", ":")},
    # a therapist's 'With no pressure at all ,' and 'imagine a gentler world where ...'
    **{(*w, "no", "pressure", *a, p): () for w in ((), ("with",)) for a in ((), ("at", "all")) for p in (",", ":")},
    **{("a", g, "world", "where"): ("a", "world", "where") for g in ("gentler", "kinder", "different", "parallel",
                                                                  "alternate", "alternative", "calmer", "quieter")},
    # 'going ever faster' (faster and faster), 'right down to the wire' (to the end), 'one of its rivals'
    **{(g, "ever", c): (g, c, "and", c) for c in ("faster", "quicker") for g in (
        "going", "getting", "moving", "growing", "travelling", "traveling", "driving", "flying", "rolling")},
    **{(*c, *r, "down", "to", "the", "wire", *e): () for c, e in (((), (",",)), ((",",), ()), ((), ()))
       for r in ((), ("right",))},
    **{("one", "of", w, r): ("something",) for w in ("its", "the", "their") for r in ("rivals", "competitors",
                                                                                    "opponents")},
    # a racing commentator's 'left in the stalls' (static at the start)
    **{("left", *s, "in", "the", "stalls"): ("stationary", "at", "the", "start") for s in ((), ("standing",))},
    # a wizard's and an astronomer's instruments ('passes into the view of my scrying glass', 'drifts into the
    # eyepiece's field'), and 'quickening its pace' (accelerating)
    **{(*i, "the", *v, *m, *d, *f): ("into", "view") for i in (("into",), ("in",)) for v, f in (
        (("view", "of"), ()), (("field", "of"), ()), ((), ("'", "s", "field")), ((), ("'", "s", "view")))
       for m in ((), ("my",), ("our",), ("the",)) if bool(m) == bool(v) for d in (
        ("scrying", "glass"), ("crystal", "ball"), ("eyepiece",), ("telescope",), ("scope",), ("lens",))},
    **{(q, w, "pace"): (a,) for q, a in (("quickening", "accelerating"), ("quickens", "accelerates"),
                                         ("quicken", "accelerate"), ("quickened", "accelerated"))
       for w in ("its", "her", "the", "his")},
    **{("tell", d, "old", m): ("tell", "me") for d in ("an", "this", "your") for m in ("man", "woman", "angler")},
    # a listing's ('upon its entry into view'), a yarn's ('when the show first starts', 'further down the line')
    **{("entry", "into", v): ("coming", "into", v) for v in ("view", "frame", "sight", "shot")},
    **{("the", "show", *f, v): ("the", "video", v) for f in ((), ("first",))
       for v in ("starts", "begins", "opens", "started", "began", "opened", "ends", "stops", "ended", "stopped")},
    **{(*f, "down", "the", "line"): ("later",) for f in (("further",), ("farther",), ("somewhere",))},
    # 'the footage stops but the future does not :', 'the tape is frozen but destiny rolls on': the video's stop
    **{(*c, "but", *t, x, *v, p): (p,) for c in ((), (",",)) for t in ((), ("the",))
       for x in ("future", "run", "story", "tale", "world", "race", "game", "destiny", "fate", "action", "time", "life")
       for v in (("does", "not"), ("did", "not"), ("goes", "on"), ("rolls", "on"), ("carries", "on"),
                 ("keeps", "going"), ("continues",), ("marches", "on")) for p in (":", ";", ",")},
    # an office's form letter: 'the undersigned requires ...', 'this office seeks written confirmation as to whether'
    **{(*who, *v): ("tell", "me") for who in (("the", "undersigned"), ("this", "office"), ("the", "office"),
                                             ("the", "bureau"), ("the", "department"), ("this", "department"))
       for v in (("requires",), ("requests",), ("respectfully", "requests"), ("must", "establish"),
                 ("must", "ascertain"), ("is", "required", "to", "establish"), ("seeks",), ("needs",),
                 ("hereby", "requests"), ("requests", "that", "you", "state"))},
    **{(*a, c, *t): ("whether",) for a in ((), ("a",), ("written",), ("a", "written")) for c in (
        "confirmation", "determination", "statement") for t in (("of", "whether"), ("as", "to", "whether"))},
    # 'had been floating all along (from the start)', 'anywhere in the video'; an auditor's 'for completeness of the
    # file ,'
    **{("anywhere", "in", "the", *w, f): ("in", "the", f) for f in FILM_WORDS for w in ((), ("whole",), ("entire",))},
    ("all", "along"): _START, **{("all", "along", w, "the", "start"): _START for w in ("at", "from")},
    **{("for", *t, "completeness", *f, p): () for t in ((), ("the", "sake", "of")) for p in (",", ";", ":")
       for f in ((), ("of", "the", "file"), ("of", "the", "record"), ("'", "s", "sake"))},
}.items())
COMING = ("comes", "come", "came", "coming")
SPEED_CARRIED = {"carrying": "moving", "carry": "move", "carried": "moved", "carries": "moves"}
CARRIED_UNTIL = {"at", "when", "as", "right", "just", "on", "upon", "in", "during", "once"}   # a time after it
APPEARING = ("appears", "appear", "appeared", "appearing")


PERSONS_HIT = {"anyone": "anything", "anybody": "anything", "someone": "something", "somebody": "something"}
DESCRIBED = {"speed", "velocity", "direction", "heading", "color", "kind", "type", "motion", "movement"}


# A simile after a speed or a rest says that speed again ('still as a stone', 'slow as a snail', 'quick as the wind',
# 'frozen like a statue', 'tearing along like a spooked horse', 'tractor-slow'): dropped, so that its noun is not
# read as a vehicle no video shows ('tractor'). Not a comparison with a vehicle ('as fast as the bus', 'slow as the
# red one'): the noun phrase names none, and no 'as' comes before the speed; nor a time ('slowly as the footage
# begins'): a simile of 'as' has 'a' or 'an', or is 'as the wind'.
SIMILE_SPEEDS = {"still", "motionless", "stationary", "static", "frozen", "parked", "slow", "slowly", "fast", "quick",
                 "quickly", "swift", "swiftly", "fleet", "rapid", "rapidly", "speedy"}
SIMILE_MOTIONS = {"tearing", "racing", "crawling", "creeping", "zooming", "flying", "going", "moving", "running",
                  "sitting", "standing", "bombing", "shooting", "charging", "moseying", "plodding", "drifting",
                  "air", "aloft", "airborne", "floating", "hovering"}   # 'up in the air like a real high-flier'

_SIMILE_ENDS = {",", "?", ".", "!", ":", ";", "or", "and", "when", "at", "as", "just", "from", "in", "right", "while",
                "on", "during", "before", "after", "then", "would", "will", "does", "did", "is", "was", "?"}
_TIMES_SAID = {"time", "start", "beginning", "end", "frame", "frames", "first", "moment", "outset", "opening", "point",
               "now", "then", "here", "there", "it", "them", "collision", "impact", "crash"}
_NAMES_NONE = {"one", "it", "its", "them", "that", "this", "other", "another", "vehicle", "object", "thing"}


SIMILE_AFTER = {"along", "start", "starts", "begins", "outset", "first", "beginning", "frames", "video", "clip",
                "partway", "halfway", "midway", "early", "short"}   # (and the video stopped: 'cuts out partway , like ...')
# ('from the start , like ...', 'at the start of the video , like a runaway balloon :')
SIMILE_OPENERS = {"like", "as"}
AFLOAT_RESTATED = {"up", "aloft", "floating", "hovering", "drifting"}
SIMILE_SPEEDS_SAID = SIMILE_SPEEDS | SIMILE_MOTIONS | {"slower", "faster", "quicker", "stopped"}


def _set_off_simile(words: list[str], k: int) -> int | None:
    """Where a simile set off by a comma at words[k] ends (', like a tired rope team on the scree :', a fisherman's ',
    patient as an old angler ?', ', sure as the tide turns ?', ', snagged like a hook on a log ?', a vet's ', the way a
    frightened rabbit freezes :'): the clause mark after it, where the simile names no vehicle, colour, time or
    collision and asks nothing; else None. Its
    likeness (the words before 'like' or 'as') says nothing either, or is a speed the question has said already ('...
    slower than the bus , slow as the river on a summer's day ?')."""
    opener = max((j for j in range(k + 1, min(len(words), k + 4)) if words[j] in SIMILE_OPENERS
                  or words[j - 1:j + 1] == ["the", "way"]), default=None)
    if words[k] != "," or opener is None:
        return None
    likeness = [w for w in words[k + 1:opener] if w not in ("as", "just", "same", "the")]
    # ('as though' and 'as if' open one alone: ', as though borne by angels ?'; a likeness of height restates a
    # floating the question has said: '... floats in the air , lifted up like a hymn ?')
    alone = words[opener:opener + 2] in (["as", "though"], ["as", "if"])
    afloat = any(w.startswith(("float", "hover")) or w == "air" for w in words[:k])
    if words[opener] == "as" and not words[k + 1:opener] and not alone or not all(w.isalpha() for w in likeness) or \
            any(w in SIMILE_SPEEDS and not SIMILE_SPEEDS_SAID.intersection(words[:k]) for w in likeness) or \
            _says_something([w for w in likeness if w not in SIMILE_SPEEDS and not (afloat and w in AFLOAT_RESTATED)]):
        return None
    end = next((e for e in range(opener + 1, min(len(words), opener + 12)) if words[e] in CLAUSE_MARKS), None)
    said = words[opener + 1 + alone:end] if end else []
    # (not a speed offered among others: 'still as a stone , slow as a cloud , or fast as a star ?'; nor a gloss
    # without an article: ', like speeding up with the engine on ?')
    if SIMILE_SPEEDS.intersection(likeness) and "or" in words[end:end + 3] or {"or", "and"} & set(likeness) or \
            said[:1] not in (["a"], ["an"], ["the"], ["my"]) and any(
                w in SPEED_CLASS_WORDS | {"engine"} or w.startswith(("speed", "accelerat"))
                for w in said):
        return None
    if not said or asks_impact(said) or any(
            v in OBJECT_WORDS | set(COLOR_NAMES) | _NAMES_NONE - {"its", "this"} | _TIMES_SAID | FILM_WORDS
            | START_WORDS | QUESTION_OPENERS | {"if", "had", "would", "not", "never", "he", "she"} for v in said):
        return None
    return end


def similes_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'is the suv still as a sleeping stone , slow as a wandering cloud , or fast as a falling star ?' -> 'is the suv
    still , slow , or fast ?' (`SIMILE_SPEEDS`); and one set off by a comma after a speed or a motion, or closing the
    question ('... creeping along slowly , like a tired rope team on the scree : ...', '... pick up speed at first ,
    like a lead climber breaking trail ?'). With the similes dropped."""
    out, read, k = [], [], 0
    while k < len(words):
        w = words[k]
        end = _set_off_simile(words, k)
        # (after a motion, closing the question, or between commas before it: 'When that grey sedan first shows
        # itself, like a ewe coming out of the mist, is it ...?')
        if end is not None and (out and out[-1] in SIMILE_SPEEDS_SAID | SIMILE_AFTER
                                or end == len(words) - 1
                                or words[end] == "," and words[end + 1:end + 2] != []
                                and words[end + 1] in QUESTION_OPENERS):
            read.append((" ".join(words[k:end]), "nothing, a simile"))
            k = end
            continue
        # 'tractor-slow', 'snail - slow' (not a dash before the choices: 'for the first time - static, slow or fast',
        # '... when the jet and the car collide - static, slow, or fast?')
        if words[k + 1:k + 2] == ["-"] and words[k + 2:k + 3] and words[k + 2] in SIMILE_SPEEDS and w.isalpha() \
                and w not in OBJECT_WORDS | set(COLOR_NAMES) | SIMILE_SPEEDS | FILM_WORDS | _TIMES_SAID \
                and words[k + 3:k + 4] not in ([","], ["or"]) and not asks_impact([w]):
            read.append((" ".join(words[k:k + 3]), words[k + 2]))
            out.append(words[k + 2])
            k += 3
            continue
        out.append(w)
        k += 1
        speed = w in SIMILE_SPEEDS and (len(out) < 2 or out[-2] != "as")
        motion = w in SIMILE_MOTIONS or (w == "along" and len(out) > 1 and out[-2] in SIMILE_MOTIONS)
        if not (speed or motion) or k >= len(words) or words[k] not in ("as", "like") or (
                motion and words[k] != "like"):
            continue
        # a simile has its article ('slow as a snail'; 'as the video begins' is a time, 'like mad' an idiom, and so
        # is 'like the clappers')
        article = words[k + 1:k + 2]
        if article not in (["a"], ["an"], ["the"]) or article == ["the"] and words[k] == "as" and \
                words[k + 2:k + 3] not in (["wind"], ["breeze"], ["grave"]) or \
                any(tuple(words[k:k + len(p)]) == p for p, _ in IDIOMS.get(words[k], ())):
            continue
        j = k + 2
        end = j
        # (of up to three words, hyphened or possessive: 'a real high-flier', 'the cat's pajamas'; a dash before a
        # question ends it: 'like a meringue - what colour is it?')
        while end < len(words) and end - j < 8 and words[end] not in _SIMILE_ENDS and not (
                words[end] == "-" and words[end + 1:end + 2] and words[end + 1] in QUESTION_OPENERS):
            end += 1
        # (closing the question, up to six: 'quick as a trout spotting a shadow ?')
        # (up to five before a clause's mark: 'sat still like a sheep chewing the cud , slow , or fast ?')
        phrase = [v for v in words[j:end] if v not in ("-", "'")]
        longest = 6 if words[end:] == ["?"] else 5 if words[end:end + 1] in ([","], [";"], [":"]) else 3
        if not phrase or len(phrase) > longest + (words[j:end].count("'") > 0) or \
                (end < len(words) and words[end] not in _SIMILE_ENDS) or any(
                v in OBJECT_WORDS or v in COLOR_NAMES or v in _NAMES_NONE or not v.isalpha() for v in phrase):
            continue
        read.append((" ".join(words[k:end]), "nothing, a simile"))
        k = end
    return out, tuple(read)


def pair_colour_shared(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'two cyan creatures collide , the minivan and the cruiser ; ...' -> '... , the cyan minivan and the cyan
    cruiser ; ...': a colour said of two vehicles together is each one's (read alone, 'the cruiser' was any cruiser).
    With the words read so, or the words as they are and ()."""
    k = next((k for k in range(len(words) - 2) if words[k] in ("two", "both") and words[k + 1] in COLOR_NAMES), None)
    if k is None:
        return words, ()
    colour = words[k + 1]
    for j in range(k + 3, len(words) - 6):
        if words[j] == "," and words[j + 1] == "the" and words[j + 2] in OBJECT_WORDS and \
                words[j + 3:j + 5] == ["and", "the"] and words[j + 5] in OBJECT_WORDS and \
                not {w for w in words[j + 2:j + 6]} & set(COLOR_NAMES):
            out = [*words[:j + 2], colour, words[j + 2], "and", "the", colour, *words[j + 5:]]
            return out, ((" ".join(words[k:k + 2]), f"the {colour} one and the {colour} one"),)
    return words, ()


def idioms_as_said(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'is it going flat out right off the bat' -> 'is it going fast at the start'. With the idioms read so."""
    read = ()
    if words[:1] and words[0] in IMAGINING | {"imagine", "suppose"} and words[1:3] in (["this", ":"], ["this", ","],
                                                                                   ["that", ":"], ["this", "-"]):
        read, words = ((" ".join(words[:3]), "imagine"),), ["imagine", *words[3:]]   # 'Picture this: the bus ...'
    if words[:1] and words[0] in IMAGINING:
        out, more = phrases_as_said(words[1:], IDIOMS)
        return ["imagine", *out], (*read, (words[0], "imagine"), *more)
    # a request to describe a property, said first, asks it ('Describe the velocity class of the purple object when
    # the video begins?'; not 'would that describe the pace of ...')
    if words[:2] == ["describe", "the"] and words[2:3] and words[2] in DESCRIBED:
        read, words = (*read, ("describe", "what is")), ["what", "is", *words[1:]]
    # a condition in the simple past before or after 'would' ('If the green wagon stayed still, would it hit the
    # bus?', 'Would the cruiser hit the sedan if it never moved?'; the decoder read no condition): the grammar's past
    # perfect, as a context's condition is said (`context._condition_said`); not a video's stop ('if the clip were
    # paused')
    words, perfect = _condition_perfect(words)
    read += perfect
    out, more = phrases_as_said(words, IDIOMS)
    read += more
    # a speed said twice once its idiom is read ('bombing along fast' is 'moving fast fast')
    out = [w for k, w in enumerate(out) if not (k and w == out[k - 1] and w in ("fast", "slow", "slowly"))]
    # what a vehicle hits said as a person ('does the chopper touch anyone?'): only vehicles are there to hit
    for k, w in enumerate(out):
        if w in PERSONS_HIT and k and (asks_impact(out[max(k - 2, 0):k]) or out[k - 1].startswith("touch")):
            out[k] = PERSONS_HIT[w]
            read += ((w, out[k]),)
    # 'imagine the bus was parked the whole time. would ...?': the condition said in the simple past (or, a sentence
    # of its own, in the present) is the grammar's 'had been' (it was read as whether the bus is parked at the
    # collision)
    if out[:1] and out[0] in ("imagine", "suppose", "supposing"):
        end = next((k for k, w in enumerate(out) if w in (".", ",", ";", ":", "-", "?")), len(out))
        now = ("is", "are") if out[end:end + 1] in ([":"], ["."], [";"]) else ()
        k = next((k for k in range(1, end) if out[k] in ("was", "were", *now)), None)
        if k is not None and not cut_premise(out[1:end]):   # 'suppose the video is cut off partway; would ...'
            read += ((out[k], "had been"),)
            out[k:k + 1] = ["had", "been"]
    # the same condition inverted: 'had the plane stayed still , would it ...' (read as had it stayed in the air)
    if out[:1] == ["had"]:
        end = next((k for k, w in enumerate(out) if w in (",", "?")), len(out))
        k = next((k for k in range(2, end - 1) if out[k] in STAYED and out[k + 1] in STILL), None)
        if k is not None:
            read += ((f"{out[k]} {out[k + 1]}", "been static"),)
            out[k:k + 2] = ["been", "static"]
    # 'what speed was the suv carrying (when it hit the bus)' is the speed it moves at (refused as what a vehicle
    # carries)
    for k in range(1, len(out)):
        if out[k] in SPEED_CARRIED and {"speed", "pace"}.intersection(out[:k]) and out[k + 1:k + 2] in (
                [], ["?"], ["-"], [","], ["."], [":"], *([w] for w in CARRIED_UNTIL)):
            read += ((out[k], SPEED_CARRIED[out[k]]),)
            out[k] = SPEED_CARRIED[out[k]]
    # 'when it comes into view for the first time' is the grammar's 'when it first comes into view' (it was read as
    # the start)
    # (and a learner's 'when it comes into view first time')
    for k in range(len(out)):
        said = next((n for n in (4, 3, 2) if out[k:k + n] == ["for", "the", "first", "time"][4 - n:]), None)
        if said:
            seen = next((n for n in (4, 3, 2, 1) if k >= n and (out[k - n:k] in (
                [c, "into", "view"] for c in COMING) or out[k - n:k] in ([a] for a in APPEARING))), None)
            if seen:
                read += ((" ".join(out[k - seen:k + said]), f"first {' '.join(out[k - seen:k])}"),)
                out[k - seen:k + said] = ["first", *out[k - seen:k]]
                break
    # 'speeding' alone is going fast, as the grammar's 'speeding along' ('is the car speeding?' was read as
    # accelerating, the grammar's 'speeding up')
    speeding = [k for k, w in enumerate(out) if w == "speeding" and out[k + 1:k + 2] not in (["up"], ["along"])]
    for k in reversed(speeding):
        out[k + 1:k + 1] = ["along"]
    return out, read + (("speeding", "speeding along"),) * bool(speeding)


def _condition_perfect(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'if the green wagon stayed still , would ...' -> 'if the green wagon had stayed still , would ...' (and 'if it
    never moved' -> 'if it had never moved', 'if the bus was fast' -> 'if the bus had been fast'), where 'would'
    asks of it; with the words read so."""
    # ('would' of the question's own vehicle: not 'what would happen if ...', which no family asks)
    if "if" not in words or not any(a == "would" and (b in ("it", "they", "there", "the", "a", "an", "this", "that")
                                                      or b in OBJECT_WORDS) for a, b in zip(words, words[1:])):
        return words, ()
    k = words.index("if")
    end = next((j for j in range(k + 1, len(words)) if words[j] in (",", "?", ".", "would", "then")), len(words))
    clause, named = words[k + 1:end], mentions(words[k + 1:end])
    subject = named[0][1] if named and named[0][0] <= 1 else 1 if clause[:1] == ["it"] else None
    if subject is None or "had" in clause or cut_premise(clause):
        return words, ()
    j = k + 1 + subject
    never = words[j:j + 1] == ["never"]
    verb = words[j + never] if j + never < len(words) else None
    if verb in ("was", "were") and not never and words[j + 1:j + 2] and words[j + 1] in STATES_SAID:
        return words[:j] + ["had", "been"] + words[j + 1:], ((verb, "had been"),)
    if verb in PARTICIPLES and verb not in ("is", "was"):
        said = ["had", *["never"] * never, PARTICIPLES[verb]]
        return words[:j] + said + words[j + 1 + never:], ((" ".join(words[j:j + 1 + never]), " ".join(said)),)
    return words, ()


def tail_as_question(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """A question whose asking comes last: '..., yes or no?' and the other answer offered in a clause of its own
    ('..., or did it miss it?', '... or is it on the ground?', '... or not?': the asking dropped, a yes/no question
    says it) and '... is what?' (the question word put first: 'the red sedan speed at the start is what?' -> 'what
    is the red sedan speed at the start?'). With the words read so, or the words as they are and ()."""
    end = words[-1:] if words[-1:] in (["?"], ["."]) else []
    body = words[:len(words) - len(end)]
    for tail in ([",", "yes", "or", "no"], ["?", "yes", "or", "no"], [".", "yes", "or", "no"], ["yes", "or", "no"]):
        if body[-len(tail):] == tail and len(body) > len(tail):
            return body[:-len(tail)] + (end or ["?"]), ((" ".join(tail), "?"),)
    k = max((i for i, w in enumerate(body) if w == "or"), default=0)
    other = body[k + 1:]
    clause = other == ["not"] or other[:1] and other[0] in YES_NO_OPENERS and other[1:2] and (
        other[1] in TAG_PRONOUNS or other[1:3] in (["not", "it"], ["not", "they"]))   # shares none of the question
    if k > 1 and clause and not OBJECT_WORDS.intersection(other) and (NEGATIONS | OPPOSITES).intersection(other):
        return body[:k - (body[k - 1] == ",")] + (end or ["?"]), ((" ".join(body[k:]), "?"),)
    if body[-2:] in (["is", "what"], ["was", "what"]) and len(body) > 2 and body[0] not in ASKING | {"how"}:
        return ["what", body[-2], *body[:-2], *end], ((f"... {body[-2]} what", f"what {body[-2]} ..."),)
    # '(at the start ,) the red sedan is moving at what speed ?': the asking where a statement has its answer
    k = next((i for i in range(len(body)) if body[i:i + 3] in IN_PLACE), None)
    first = body.index(",") + 1 if "," in body[:k or 0] else 0
    c = next((i for i in range(first + 1, k or 0) if body[i] in ("is", "was")), None)
    if c is not None and body[first] not in ASKING | YES_NO_OPENERS | {"how", "tell"}:
        phrase = body[k:k + 3]
        return ([*body[:first], *phrase, body[c], *body[first:c], *body[c + 1:k], *body[k + 3:], *end],
                ((" ".join(phrase), "said first"),))
    return words, ()


IN_PLACE = (["at", "what", "speed"], ["at", "which", "speed"], ["at", "what", "velocity"], ["with", "what", "speed"],
            ["with", "which", "speed"], ["with", "what", "velocity"])


# A comparative said with 'more' or 'less' ('is the red car more fast than the bus?'), as the grammar says it
COMPARATIVES = {("more", "quick"): "quicker", ("less", "fast"): "slower", ("less", "quick"): "slower",
                ("less", "slow"): "faster",
                # 'the more leisurely one'
                **{("more", w): "slower" for w in ("slow", "leisurely", "sluggish", "sedate", "unhurried")},
                **{("more", w): "faster" for w in ("fast", "rapid", "speedy", "swift", "hasty")}}
# ... and an adverb's, only before 'than' ('moving more rapidly than the bus'; 'is it moving more slowly?' compares
# it with itself)
COMPARED_ADVERBS = {**{("more", w): "slower" for w in ("slowly", "sluggishly")},
                    **{("more", w): "faster" for w in ("quickly", "rapidly", "swiftly")}}
# longest first
PAIR_SAID = (["of", "the", "two", "vehicles"], ["of", "the", "two"], ["of", "both"], ["of", "the", "pair"])


def comparative_as_said(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'more fast' -> 'faster', 'less fast' -> 'slower' (the decoder read 'more fast' as 'fast'), 'the faster of the
    two' -> 'the faster one' (no family was read). With the words read so, or the words as they are and ()."""
    out, read, k = [], [], 0
    while k < len(words):
        # 'more slowly' compares with what follows ('than'), or with the other vehicle of a collision said ('At the
        # moment the yellow bus crashes into the cyan bus, is the yellow one moving more slowly?')
        said = COMPARATIVES.get(tuple(words[k:k + 2])) or (
            COMPARED_ADVERBS.get(tuple(words[k:k + 2])) if words[k + 2:k + 3] == ["than"] or words[k + 2:k + 3] in (
                [], ["?"], ["."]) and asks_impact(words) else None)
        pair = next((p for p in PAIR_SAID if words[k:k + len(p)] == p), None) if out and out[-1] in COMPARISONS \
            else None
        if said:
            out.append(said)
            read.append((" ".join(words[k:k + 2]), said))
            k += 2
        elif pair:
            out.append("one")
            read.append((" ".join(pair), "one"))
            k += len(pair)
        else:
            out.append(words[k])
            k += 1
    return out, tuple(read)


OFFERS = ((SPEED_CHOICES, "static , slow or fast", {"slow", "fast"}),
          (DIRECTION_CHOICES, "front , back , left , right , up or down", set(DIRECTION_CHOICES.values())))
# 'to the left or right of the bus' says where it is, not where it goes
PLACE_BEFORE = {"the", "to", "its", "of", "on"}


def _choice(words: list[str], k: int, choices: dict) -> tuple[str, int] | None:
    """The choice said at words[k] and how many words say it (the longest, with an adverb that says it again:
    'creeping along slowly', 'zipping by fast'), or None."""
    hit = max(((c, len(w)) for w, c in choices.items() if tuple(words[k:k + len(w)]) == w),
              key=lambda hit: hit[1], default=None)
    if hit and hit[1] > 1 and choices.get(tuple(words[k + hit[1]:k + hit[1] + 1])) == hit[0]:
        return hit[0], hit[1] + 1
    return hit


def attributes_offered_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'what sort of aeroplane is hovering at the start , airliner , fighter , jet or biplane ?' -> '... at the start
    ?': the colours or types offered to choose from by a question asking for one, which its answer names anyway.
    With the choices read as nothing, or the words as they are and ()."""
    if words[-1:] != ["?"] or not ATTRIBUTE_NOUNS & set(words[:8]) or not {"what", "which"} & set(words[:6]):
        return words, ()
    for k in (j for j, w in enumerate(words) if w in (",", ":")):
        listed = words[k + 1:-1]
        names = [w for w in listed if w not in {",", "or", "a", "an", "the", "one", "of", "those", "these", "old"}]
        if "or" in listed and len(names) >= 2 and all(w in OBJECT_WORDS or w[:-1] in OBJECT_WORDS for w in names):
            return words[:k] + ["?"], ((" ".join(words[k:-1]), "nothing, the choices offered"),)
    return words, ()


CLEFT_COMPARED = (["faster"], ["slower"], ["quicker"], ["more", "slowly"], ["more", "quickly"], ["less", "quickly"],
                  ["less", "slowly"])


def _cleft_manner(words: list[str]) -> list[str]:
    """'was it at high speed that the chopper hit the minivan ?' -> 'was the chopper at high speed when it hit the
    minivan ?': a speed said in a cleft is the collision's; [] where the words are no such cleft."""
    m = next((k for k in range(3, min(len(words), 8)) if words[k] == "that"), None)
    if m is None or not SPEED_CLASS_WORDS & set(words[2:m]) or NAMING & set(words[2:m]) or \
            words[m + 1:m + 2] != ["the"]:
        return []
    j = m + 2
    while words[j:j + 1] and words[j] in NAMING:
        j += 1
    if j == m + 2 or not asks_impact(words[j:j + 3]):
        return []
    return [words[0], *words[m + 1:j], *words[2:m], "when", "it", *words[j:]]


def cleft_as_asked(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'is it the red car that is fast at the start ?' -> 'is the red car fast at the start ?'; a comparison in it
    is with the other vehicle its collision names ('is it the car that is moving more slowly when it and the bus
    collide ?' -> '... moving more slowly than the bus when they collide ?'). With the words read so, or the words as
    they are and ()."""
    if words[:2] in (["is", "it"], ["was", "it"]):
        manner = _cleft_manner(words)
        if manner:
            return manner, ((" ".join(words), " ".join(manner)),)
    if words[:3] not in (["is", "it", "the"], ["was", "it", "the"]):
        return words, ()
    j = 3
    while words[j:j + 1] and words[j] in OBJECT_WORDS:
        j += 1
    if j == 3 or words[j:j + 1] not in (["that"], ["which"]) or words[j + 1:j + 2] not in (["is"], ["was"]):
        return words, ()
    out = [words[0], *words[2:j], *words[j + 2:]]
    c = next(((k, len(p)) for k in range(len(out)) for p in CLEFT_COMPARED if out[k:k + len(p)] == p), None)
    m = next((k for k in range(len(out)) if out[k:k + 4] == ["when", "it", "and", "the"]), None)
    if c and out[c[0] + c[1]:c[0] + c[1] + 1] != ["than"] and m is not None:
        e = m + 4
        while out[e:e + 1] and out[e] in OBJECT_WORDS:
            e += 1
        if e > m + 4 and out[e:e + 1] in (["collide"], ["collided"], ["crash"], ["crashed"]):
            other = out[m + 3:e]
            out = out[:c[0] + c[1]] + ["than", *other] + out[c[0] + c[1]:m] + ["when", "they"] + out[e:]
    return out, ((" ".join(words), " ".join(out)),)


TYPE_WORDS = OBJECT_WORDS - set(COLOR_NAMES)
ARTICLES = {"a", "an"}   # (not 'the': 'is it the bus or the car that ...' picks one of two vehicles)


def _offered_names(words: list[str], k: int) -> tuple[str, int] | None:
    """The kind of names offered from words[k] on ('an airliner , a fighter , a jet or a biplane': 'type'; 'red ,
    blue or green': 'color') and where the list ends; None unless two names at least, one after 'or', all of one
    kind."""
    kinds, names, said_or = set(), 0, False
    while True:
        k += words[k:k + 1] != [] and words[k] in ARTICLES
        start = k
        if words[k:k + 1] == ["the"]:
            return None
        while words[k:k + 1] and words[k] in OBJECT_WORDS:
            k += 1
        if k == start:
            return None
        kinds.add("type" if set(words[start:k]) <= TYPE_WORDS else "color" if k - start == 1 else "both")
        names += 1
        sep = next((n for n in ([",", "or"], ["or"], [","]) if words[k:k + len(n)] == n), None)
        if said_or or not sep:
            break
        said_or = "or" in sep
        k += len(sep)
    return (kinds.pop(), k) if names >= 2 and said_or and len(kinds) == 1 and "both" not in kinds else None


def choices_as_which(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'is it an airliner , a fighter , a jet or a biplane that is hovering at the start ?' and 'which is hovering at
    the start : an airliner , a fighter , a jet or a biplane ?' -> 'what type of vehicle is hovering at the start ?':
    a vehicle's types (or colours) offered as the answers ask which one, as a family asks its attribute. With the words
    read so, or the words as they are and ()."""
    def which(kind: str, rest: list[str]) -> list[str]:
        return ["what", "type", "of", "vehicle", *rest] if kind == "type" else ["what", "color", "is", "the",
                                                                              "vehicle", "that", *rest]
    # a cleft: 'is it A , B or C that ...'
    if words[:2] in (["is", "it"], ["was", "it"]) and (offered := _offered_names(words, 2)):
        kind, k = offered
        if words[k:k + 1] in (["that"], ["which"]) and words[k + 1:k + 2] in (["is"], ["was"]):
            out = which(kind, words[k + 1:])
            return out, ((" ".join(words), " ".join(out)),)
    # 'which (one / vehicle / of the following / of these) is ... : A , B or C ?' (the lexicon has read 'following'
    # as 'next' and 'these' as 'you' by now)
    if words[:1] == ["which"] and words[-1:] == ["?"]:
        j = 1 + (words[1:2] in (["one"], ["vehicle"]))
        j += 2 * (words[1:3] in (["of", "you"], ["of", "these"], ["of", "those"])) \
            + 3 * (words[1:4] in (["of", "the", "next"], ["of", "the", "following"]))
        for k in (k for k, w in enumerate(words) if w in (":", ",", "-") and k > j):
            offered = _offered_names(words, k + 1)
            if offered and offered[1] == len(words) - 1 and words[j:j + 1] in (["is"], ["was"]):
                out = which(offered[0], words[j:k] + ["?"])
                return out, ((" ".join(words), " ".join(out)),)
    return words, ()


OPPOSED = (["as", "opposed", "to"], ["rather", "than"], ["instead", "of"], ["and", "not"])
OPPOSED_SPEEDS = {"static", "slow", "fast", "still", "standing", "going", "moving", "being", "parked", "stopped", "or",
                  ",", "either", "quickly", "slowly", "quick", "not", "at", "all", "stationary", "motionless",
                  "speeding"}


def opposed_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'is it slow , as opposed to standing still or going fast ?' -> 'is it slow ?': the speeds it is asked against
    say again what a yes or no means (read as which speed is asked). With the words read so, or the words as they
    are and ()."""
    for k in range(1, len(words) - 2):
        said = next((o for o in OPPOSED if words[k:k + len(o)] == o), None)
        rest = words[k + len(said):-1] if said else []
        if rest and words[-1] == "?" and set(rest) <= OPPOSED_SPEEDS and SPEED_CLASS_WORDS & set(words[:k]):
            j = k - (words[k - 1] == ",")
            return [*words[:j], "?"], ((" ".join(words[j:-1]), "nothing, the speeds it is asked against"),)
    return words, ()


_SPEED_SAID = {w for choice in SPEED_CHOICES for w in choice if len(choice) == 1}
_OTHER_ASKED = (["or"], *(["or", a, p] for a in ("is", "was", "are", "were") for p in ("it", "they", "she", "he")))


def _alternative_moved(words: list[str]) -> list[str]:
    """'is the red car fast at the start or slow ?', '..., or is it slow ?' -> 'is the red car fast or slow at the
    start ?': a speed offered after the time, moved beside the one it is the other choice to (read as it stood,
    the question asked whether the car was fast)."""
    if words[-1:] not in (["?"], ["."]) or len(words) < 5:
        return words
    for asked in _OTHER_ASKED:
        j = len(words) - 2 - len(asked)
        other = words[-2]
        if j < 2 or words[j:j + len(asked)] != asked or other not in _SPEED_SAID:
            continue
        first = max((m for m in range(j) if words[m] in _SPEED_SAID), default=None)
        if first is None or SPEED_CHOICES[(words[first],)] == SPEED_CHOICES[(other,)]:
            continue
        return [*words[:first + 1], "or", other, *words[first + 1:j - (words[j - 1] == ",")], words[-1]]
    return words


def alternatives_as_asked(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'is the red car fast or slow ...?' -> 'is the red car static, slow or fast ...?', 'is it going left or right?'
    -> 'is it going front, back, left, right, up or down?': speed classes or directions offered as alternatives ask
    which one, as the grammar's lists of them do (the decoder read 'fast or slow' as 'is it fast?', 'left or right'
    as the speed). Two choices at least, of speeds one slow or fast. With the words read so, or the words as they
    are and ()."""
    # asked as yes or no: an auxiliary first, or before its subject after the vehicle or a clause said first ('the
    # red car at the start , is it fast or slow'), or a statement asked ('the school bus is moving fast or slow ?')
    as_said, words = words, _alternative_moved(words)
    moved = ((" ".join(as_said), " ".join(words)),) if words != as_said else ()
    asking = [m for m, w in enumerate(words) if w in AUXILIARIES and (m == 0 or words[m + 1:m + 2] and (
        words[m + 1] in SUBJECT_STARTS or words[m + 1] in OBJECT_WORDS) or words[-1:] == ["?"]
        and words[m - 1] in OBJECT_WORDS and words[m - 1] not in COLOR_NAMES)]
    if not asking:
        return as_said, ()
    for i in range(asking[0] + 1, len(words)):
        for choices, listed, needed in OFFERS:
            first = _choice(words, i, choices)
            if not first or choices is DIRECTION_CHOICES and words[i - 1:i] and words[i - 1] in PLACE_BEFORE:
                continue
            said, k = [first[0]], i + first[1]
            while True:
                # (or none: a speech recogniser's list without its commas, 'is it not moving slow or fast')
                sep = next((s for s in ([",", "or"], ["or"], [","], []) if words[k:k + len(s)] == s), None)
                nxt = _choice(words, k + len(sep), choices)
                if not nxt:
                    break
                said.append(nxt[0])
                k += len(sep) + nxt[1]
            if len(set(said)) >= 2 and set(said) & needed and "or" in words[i:k]:
                return (words[:i] + listed.split() + words[k:],
                        (*moved, (" ".join(words[i:k]).replace(" ,", ","), listed.replace(" ,", ","))))
    return as_said, ()


# A speed said as the subject of a yes/no question ('is the red car's speed low?'), by the word the grammar says
SPEED_PREDICATES = {"low": "slow", "slow": "slow", "high": "fast", "fast": "fast", "great": "fast", "zero": "static",
                    "0": "static", "nil": "static"}


# A collision said as trajectories that intersect ('would its trajectory still intersect the chopper's in a collision?',
# 'does the blue airliner's trajectory intersect another vehicle's?'); 'the trajectories of A and B intersect' is
# read by the idioms
INTERSECTING = {"intersect": "collide", "intersects": "collides", "intersected": "collided", "cross": "collide",
                "crosses": "collides", "crossed": "collided", "meet": "collide", "meets": "collides"}


def let_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'if the gray bicycle let be fast from the start , then it crash into ...' -> 'if the gray bicycle be fast ...':
    a translation's 'let' after a condition's vehicle (Vietnamese, Thai, Indonesian 'cho', 'hai', 'biar'). With the
    words read so, or the words as they are and ()."""
    k = next((k for k in range(1, len(words)) if words[k] == "let" and words[k - 1] in NAMING
              and "if" in words[:k]), None)
    return (words[:k] + words[k + 1:], (("let", "nothing, a translation's particle"),)) if k else (words, ())


def trajectory_as_collision(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'would its trajectory still intersect the chopper ' s in a collision ?' -> 'would it still collide with the
    chopper ?'. With the words read so, or the words as they are and ()."""
    k = next((k for k, w in enumerate(words) if w == "trajectory"), None)
    if k is None or not k:
        return words, ()
    j = k + 1 + (words[k + 1:k + 2] == ["still"])
    if words[j:j + 1] == [] or words[j] not in INTERSECTING:
        return words, ()
    # its owner: 'its', or a vehicle's "' s"
    start = k - 1 if words[k - 1] == "its" else k - 2 if words[k - 2:k] == ["'", "s"] else None
    if start is None:
        return words, ()
    end = next((m for m in range(j + 1, len(words)) if words[m] in ("?", ".") or words[m:m + 3] == [
        "in", "a", "collision"]), len(words))
    other = words[j + 1:end]
    other = other[:-2] if other[-2:] == ["'", "s"] else other
    said = (["it"] if words[start] == "its" else []) + words[k + 1:j] + [INTERSECTING[words[j]], "with", *other]
    past = end + 3 * (words[end:end + 3] == ["in", "a", "collision"])
    return words[:start] + said + words[past:], ((" ".join(words[start:past]), " ".join(said)),)


TIMES_AFTER_SPEED = (["at", "the", "start"], ["at", "the", "beginning"], ["at", "the", "outset"], ["initially"],
                     ["at", "first"])


def speed_as_subject(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'is the red car's (initial) speed low ?', 'is the (initial) speed of the red car high at the start ?': the
    object as the subject, 'is the red car slow (at the start) ?', which the grammar says; the decoder read the speed
    as the subject as a question about accelerating or a query of the speed. With the words read so, or the words as
    they are and (). A time may come first ('at the start , is the green airliner's speed fast ?') or after the speed
    ('is the green airliner's speed at the start fast ?')."""
    comma = words.index(",") if "," in words[:12] else None
    # (a clause of time: 'at the start , ...', 'at the moment of impact with the brown truck , ...')
    fronted = comma is not None and words[0] in TIME_OPENERS | {"at", "on", "upon", "in"} and (
        bool(START_WORDS & set(words[:comma])) or asks_impact(words[:comma]))
    if fronted:
        out, read = speed_as_subject(words[comma + 1:])
        return (words[:comma + 1] + out, read) if read else (words, ())
    if words[:1] not in (["is"], ["was"]) or words[1:2] != ["the"]:
        return words, ()
    k = 2
    while words[k:k + 1] and words[k] in OBJECT_WORDS:
        k += 1
    if k > 2 and words[k:k + 2] == ["'", "s"]:                  # 'is the red car 's initial speed low'
        thing, k = words[1:k], k + 2
        start = words[k:k + 1] != [] and words[k] in START_ADJECTIVES
        k += start
        if words[k:k + 1] not in (["speed"], ["velocity"]):
            return words, ()
        k += 1
    else:                                                        # 'is the initial speed of the red car low'
        start = words[2:3] != [] and words[2] in START_ADJECTIVES
        k = 2 + start
        if words[k:k + 1] not in (["speed"], ["velocity"]) or words[k + 1:k + 3] != ["of", "the"]:
            return words, ()
        j = k + 2
        k += 3
        while words[k:k + 1] and words[k] in OBJECT_WORDS:
            k += 1
        thing = words[j:k]
        if len(thing) < 2:
            return words, ()
    time = next((t for t in TIMES_AFTER_SPEED if words[k:k + len(t)] == t), [])
    k += len(time)
    if not words[k:k + 1] or words[k] not in SPEED_PREDICATES:
        return words, ()
    rest = time + words[k + 1:]
    when = ["at", "the", "start"] if start and not {"start", "beginning", "first", "initially"} & set(rest) else []
    end = len(rest) - (rest[-1:] == ["?"])
    out = ["is", *thing, SPEED_PREDICATES[words[k]], *rest[:end], *when, *rest[end:]]
    return out, ((" ".join(words[:k + 1]).replace(" ' ", "'"), " ".join(out[:len(thing) + 2])),)


OPPOSITES = {w for reversers in REVERSERS.values() for w in reversers}


# Yoda's order, and a poet's: the predicate said first, the subject and its auxiliary last ('faster than the bus at
# the start , the gray jet is ?', 'collide with the red bike , did the gray suv ?', 'into the bus crash the jet will ?')
INVERTED_AUXILIARIES = {"is", "was", "are", "were", "did", "does", "do", "will", "would", "went", "moved", "travelled",
                        "traveled", "drove"}
PAST_MOTION = {"went": "going", "moved": "moving", "travelled": "travelling", "traveled": "travelling",
               "drove": "driving"}
# a value said first in a condition ('if slow it had been going ...', 'if motionless the cruiser had stayed ...')
FRONTABLE_VALUES = {"slow", "slowly", "fast", "quickly", "static", "still", "motionless", "stationary", "parked",
                    "accelerating", "floating", "hovering"}


def _subject_at_end(clause: list[str]) -> int | None:
    """Where the vehicle that ends `clause` begins ('the gray fighter' in '..., the gray fighter'), or None."""
    named = [m for m in mentions(clause) if m[1] == len(clause) or m[1] == len(clause) - 1 and clause[-1] in (
        "one", "thing", "vehicle")]
    if not named:
        return None
    k = named[0][0]
    return k - 1 if k and clause[k - 1] in DETERMINERS else k


# a verb phrase's first word that the inverted order puts first ('outpace the blue one does the red one')
VERBS_FIRST = {"outpace", "outpaces", "outrun", "lag", "trail", "move", "go", "float", "hover", "accelerate",
               "speed", "run", "drive", "travel", "overtake", "beat", "stand", "sit", "stay", "remain"}
WH_NOUNS = {"way", "direction", "speed", "fast", "color", "kind", "type", "sort", "pace"}
INVERTED_TAGS = {"hmm", "hm", "yes", "no", "eh", "huh", "mm"}
TIME_CLAUSE_OPENERS = TIME_OPENERS | {"when", "after", "before", "once", "if"}


def _predicate_clause(lead: list[str]) -> tuple[list[str], list[str]]:
    """The clauses said before an inverted subject ('lag behind the bike , at the start ,'): those of time, kept
    first, and the last other one, the predicate (without its separator)."""
    clauses, start = [], 0
    for k, w in enumerate(lead):
        if w in (",", "-", ":"):
            clauses.append(lead[start:k + 1])
            start = k + 1
    if lead[start:]:
        clauses.append(lead[start:])
    k = next((k for k in reversed(range(len(clauses))) if clauses[k][:1] and
              clauses[k][0] not in TIME_CLAUSE_OPENERS), None)
    if k is None:
        return lead, []
    predicate = clauses[k][:-1] if clauses[k][-1:] and clauses[k][-1] in (",", "-", ":") else clauses[k]
    return [w for c in clauses[:k] + clauses[k + 1:] for w in c], predicate


def _is_verb(word: str) -> bool:
    return word.endswith("ing") or asks_impact([word]) or word in MOTION_WORDS


def _verb_moved(subject: list[str], predicate: list[str]) -> list[str]:
    """The subject, then the predicate's last word where it is its verb ('into the bus crash' -> 'the jet crash into
    the bus'), else the predicate after it."""
    if predicate and _is_verb(predicate[-1]):
        return [*subject, predicate[-1], *predicate[:-1]]
    if predicate and _is_verb(predicate[0]):   # 'moving slower than the chopper'
        return [*subject, *predicate]
    return [*subject, *predicate]


def _condition_value_moved(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'if slow it had been going at the start' -> 'if it had been going slow at the start'."""
    for k in range(len(words) - 3):
        if words[k] == "if" and (k == 0 or words[k - 1] in (",", ".", "-")) and words[k + 1] in FRONTABLE_VALUES:
            had = next((j for j in range(k + 3, min(k + 10, len(words) - 1)) if words[j] == "had"), None)
            if had is None or set(words[k + 2:had]) & {",", "would", "."}:
                continue
            j = had + 2 + (words[had + 1] == "been" and words[had + 2].endswith("ing"))
            return [*words[:k + 1], *words[k + 2:j], words[k + 1], *words[j:]], ((f"if {words[k + 1]}", "if"),)
    return words, ()


def _question_word_first(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """A question word, then the subject before its auxiliary: 'what way it was travelling when ...', 'toward which
    way the red jet was travelling', 'at what speed the bicycle was' -> '... was the bicycle'."""
    for k in range(len(words) - 3):
        if words[k] not in ("which", "what", "how") or k and words[k - 1] not in (",", "-", ":", "toward", "towards",
                                                                                  "at", "in"):
            continue
        j = k + 1 + (words[k + 1] in WH_NOUNS)
        s = 1 if words[j:j + 1] in (["it"], ["they"]) else next(
            (m[1] for m in mentions(words[j:j + 6]) if m[0] == (words[j] in DETERMINERS)), None)
        if words[j:j + 1] in (["it"], ["they"], ["the"], ["that"], ["this"]) and s and j + s < len(words) and \
                words[j + s] in ("was", "is", "were", "are") and j > k + 1:
            start = k - (k > 0 and words[k - 1] in ("toward", "towards"))
            said = [*words[k:j], words[j + s], *words[j:j + s]]
            return [*words[:start], *said, *words[j + s + 1:]], ((" ".join(words[start:j + s + 1]), " ".join(said)),)
    return words, ()


def _subject_last(lead: list[str], last: list[str]) -> tuple[list[str], list[str]] | None:
    """The question's lead and its words put in order, where its last clause ends with the subject and its
    auxiliary ('..., the gray jet is', 'moving the school bus was') or the auxiliary and the subject after a verb
    phrase ('collide with the bike , did the suv', 'outpace the blue one does the red one'); else None."""
    if len(last) >= 2 and last[-1] in INVERTED_AUXILIARIES:
        s = _subject_at_end(last[:-1])
        # (not a comparison's ellipsis: 'is the biplane faster than the truck is ?', nor an order's: 'who hits the
        # van after the bus does ?')
        if s is not None and not (s == 0 and not lead) and last[s - 1:s] not in (["than"], ["after"], ["before"]) and \
                not set(last[:s]) & (AUXILIARIES | {"will", "would", "can", "could", "has", "have", "had"}):
            subject, predicate, aux = last[s:-1], last[:s], last[-1]
            if not predicate or len(predicate) == 1 and _is_verb(predicate[0]):
                # '..., the gray jet is ?', '..., moving the bus was ?': a clause before says what is asked
                lead, more = _predicate_clause(lead)
                predicate = [*predicate, *more]
            if predicate and predicate[0] not in QUESTION_OPENERS | ASKING:
                if aux in PAST_MOTION:   # '..., the blue minivan went ?'
                    return lead, ["was", *subject, PAST_MOTION[aux], *predicate]
                return lead, [aux, *_verb_moved(subject, predicate)]
    s = _subject_at_end(last)
    if s is not None and s >= 1 and last[s - 1] in AUXILIARIES | {"will", "would"}:
        aux, subject, predicate = last[s - 1], last[s:], last[:s - 1]
        if not predicate and lead:
            lead, predicate = _predicate_clause(lead)
        if predicate and (asks_impact(predicate[:1]) or predicate[0] in VERBS_FIRST):
            return lead, [aux, *subject, *predicate]
    return None


def inverted_as_asked(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'faster than the bus at the start , the jet is ?' -> 'is the jet faster than the bus at the start ?';
    'collide with the bike , did the suv ?' -> 'did the suv collide with the bike ?'; 'if slow it had been going at
    the start , ...' -> 'if it had been going slow at the start , ...'. Clauses of time said first stay first. With
    the words read so, or the words as they are and ()."""
    out, moved = _condition_value_moved(words)
    out, first = _question_word_first(out)
    read = moved + first
    if out[-1:] == ["?"]:
        body = out[:-1]
        if body[-2:-1] == [","] and body[-1] in INVERTED_TAGS:   # '..., did the suv , hmm ?'
            body = body[:-2]
        cut = max((k for k, w in enumerate(body) if w in (",", "-", ":")), default=-1)
        ordered = _subject_last(body[:cut + 1], body[cut + 1:])
        if ordered:
            lead, said = ordered
            return [*lead, *said, "?"], (*read, (" ".join(body), " ".join(said)))
    return (out, read) if read else (words, ())


# A comparison said as a contest ('does the chopper beat the pickup for speed', 'is the pickup trailing the biplane
# for speed'): the verb, the other vehicle, then what it is contested in
CONTESTS = {"beat": ("move", "faster"), "beats": ("moves", "faster"), "beating": ("moving", "faster"),
            "outdo": ("move", "faster"), "outdoes": ("moves", "faster"), "trail": ("move", "slower"),
            "trails": ("moves", "slower"), "trailing": ("moving", "slower")}


def contest_as_compared(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'does the chopper beat the pickup for speed ...' -> 'does the chopper move faster than the pickup ...'. With
    the words read so, or the words as they are and ()."""
    for k, w in enumerate(words):
        if w not in CONTESTS:
            continue
        named = next((m for m in mentions(words[k + 1:k + 7]) if m[0] <= 1), None)
        if named is None:
            continue
        end = k + 1 + named[1] + (words[k + 1 + named[1]:k + 2 + named[1]] == ["one"])
        if words[end:end + 1] in (["for"], ["in"], ["on"]) and words[end + 1:end + 2] in (["speed"], ["pace"]):
            said = [*CONTESTS[w], "than", *words[k + 1:end]]
            return [*words[:k], *said, *words[end + 2:]], ((" ".join(words[k:end + 2]), " ".join(said)),)
    return words, ()


# a contact or a collision in the passive, its maker named last ('whether contact with the bus would have been made
# by the scooter had ...', 'Would a collision with the blue pickup have been caused by the school bus if ...?'; the
# decoder read the contact's object as its subject): the maker first, as the grammar says it
CONTACT_NOUNS = (("contact", "with"), ("a", "collision", "with"), ("collision", "with"), ("a", "crash", "with"))
CONTACT_MADE = {(*aux, made, "by"): active for made in ("made", "caused") for aux, active in (
    (("would", "have", "been"), ("would", "have", "hit")), (("have", "been"), ("have", "hit")), (("was",), ("hit",)),
    (("is",), ("hits",)), (("will", "be"), ("will", "hit")), (("has", "been"), ("has", "hit")),
    (("had", "been"), ("had", "hit")))}


def contact_made_as_active(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'contact with the bus would have been made by the scooter' -> 'the scooter would have hit the bus'. With the
    words read so, or the words as they are and ()."""
    named = mentions(words)
    for k in range(len(words) - 1):
        noun = next((n for n in CONTACT_NOUNS if tuple(words[k:k + len(n)]) == n), None)
        if not noun:
            continue
        struck = next((end for start, end, _ in named if start in (k + len(noun), k + len(noun) + 1)), None)
        made = struck and next((p for p in CONTACT_MADE if tuple(words[struck:struck + len(p)]) == p), None)
        if not made:
            continue
        after = struck + len(made)
        maker = next((end for start, end, _ in named if start in (after, after + 1)), None)
        if maker is None:
            continue
        active = words[after:maker] + list(CONTACT_MADE[made]) + words[k + len(noun):struck]
        return words[:k] + active + words[maker:], ((" ".join(words[k:maker]), " ".join(active)),)
    return words, ()


# a condition said as the vehicle's state or start ('Would a hovering airliner have hit the red road bike?', 'Would a
# fast start make the scooter crash into the green car?'): the grammar's 'if ... had been ..., would ...'
STATE_NAMED = {"hovering", "floating", "static", "stationary", "parked", "motionless", "accelerating", "speeding",
               "fast", "slow"}
START_MADE = (("make",), ("have", "made"), ("cause",), ("have", "caused"), ("lead",), ("have", "led"))


def condition_named_as_said(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'would a hovering airliner have hit the bike ?' -> 'would the airliner have hit the bike if it had been
    hovering ?'; 'would a fast start make the scooter crash into the car ?' -> 'if the scooter had started fast ,
    would it crash into the car ?'. With the words read so, or the words as they are and ()."""
    if words[:2] not in (["would", "a"], ["would", "an"]) or words[2:3] == [] or words[2] not in STATE_NAMED:
        return words, ()
    state, named = words[2], mentions(words)
    if words[3:4] == ["start"]:
        made = next((m for m in START_MADE if tuple(words[4:4 + len(m)]) == m), None)
        subject = made and next(((a, b) for a, b, _ in named if a in (4 + len(made), 5 + len(made))), None)
        if not subject:
            return words, ()
        b = subject[1]
        said = ["if", *words[4 + len(made):b], "had", "started", state, ",", "would", "it"]
        rest = words[b:]
        rest = rest[1:] if rest[:1] == ["to"] else rest   # 'lead the bus to hit ...'
        return said + rest, ((" ".join(words[:b]), " ".join(said)),)
    subject = next(((a, b) for a, b, _ in named if a == 3), None)
    if subject is None or words[subject[1]:subject[1] + 1] != ["have"]:
        return words, ()
    end = len(words) - (words[-1:] in (["?"], ["."]))
    out = ["would", "the", *words[3:end], "if", "it", "had", "been", state, *words[end:]]
    return out, ((" ".join(words[:subject[1]]), " ".join(["would", "the", *words[3:subject[1]]])),)


# a collision in the passive between two named vehicles ('By the time the red car is hit by the purple motorbike, at
# what speed is the motorbike travelling?', 'Is the blue jet ever hit by the red SUV?', 'Would the airliner have been
# collided with by the gray one, had ...?'): the striker first, as the grammar says it (the decoder asked of the one
# struck, and imagined it otherwise)
STRUCK = (("hit",), ("struck",), ("rammed",), ("bumped",), ("clipped",), ("smashed",), ("knocked",),
          *((v, "into") for v in ("run", "bumped", "crashed", "smashed", "slammed", "rammed", "driven", "ploughed")),
          ("collided", "with"), ("crashed", "with"))
BE_SAID = {"is": "hits", "'s": "hits", "gets": "hits", "get": "hit", "was": "hit", "got": "hit", "be": "hit",
           "been": "hit"}
ORDER_ASKED = {"if", "had", "would", "suppose", "imagine", "speed", "fast", "slow", "faster", "slower", "quicker",
               "direction", "way", "heading", "moving", "going", "travelling", "traveling", "static", "stationary",
               "velocity", "pace", "colour", "color", "kind", "type"}
CHAIN_KEPT = {"will", "would", "have", "has", "had", "ever", "first", "actually", "really", "then", "later", "also",
              "eventually", "finally", "ultimately", "still", "not", "never"}


def _phrase_start(words: list[str], start: int) -> int:
    """Where a mention's noun phrase starts: at its article or demonstrative, if it has one."""
    return start - (start > 0 and words[start - 1] in ("the", "a", "an", "this", "that"))


def struck_as_active(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'the red car is hit by the purple motorbike' -> 'the purple motorbike hits the red car'; 'is the jet ever hit by
    the suv ?' -> 'does the suv ever hit the jet ?'; 'would the airliner have been collided with by the gray one' ->
    'would the gray one have hit the airliner'. Only where the order says whom the question asks of: a whether two
    collide ('was the scooter hit by the truck ?') asks of both. With the words read so, or the words as they are and
    ()."""
    if not ORDER_ASKED & set(words):
        return words, ()
    named = mentions(words)
    for b, w in enumerate(words):
        if w != "by":
            continue
        verb = next((v for v in STRUCK if tuple(words[b - len(v):b]) == v), None)
        striker = verb and next(((s, e) for s, e, _ in named if s in (b + 1, b + 2)), None)
        struck = striker and next(((s, e) for s, e, _ in reversed(named) if e <= b - len(verb)), None)
        if not struck:
            continue
        chain = words[struck[1]:b - len(verb)]
        if not set(chain) <= set(BE_SAID) | CHAIN_KEPT:
            continue
        x0, y0 = _phrase_start(words, struck[0]), _phrase_start(words, striker[0])
        x, y = words[x0:struck[1]], words[y0:striker[1]]
        be = [c for c in chain if c in BE_SAID]
        kept = [c for c in chain if c not in BE_SAID]
        if len(be) == 1:   # 'the car is hit by the bike', 'would the jet have been hit by the bus'
            said = y + kept + ["hit" if kept and kept[-1] in ("will", "would", "have", "has", "had") or
                               be[0] in ("be", "been") else BE_SAID[be[0]]] + x
            return words[:x0] + said + words[striker[1]:], ((" ".join(words[x0:striker[1]]), " ".join(said)),)
        if not be and x0 and words[x0 - 1] in ("is", "was"):   # 'is the jet ever hit by the suv ?'
            said = ["does" if words[x0 - 1] == "is" else "did", *y, *kept, "hit", *x]
            return words[:x0 - 1] + said + words[striker[1]:], ((" ".join(words[x0 - 1:striker[1]]),
                                                                  " ".join(said)),)
    return words, ()
