"""What is said around the question: `QuestionParser._words`' rewrites (each `f(words) -> (words, read_as)`) that drop
what asks nothing, or read a wrapping as the grammar's own words. Dropped: a speaker's correction of a vehicle's name
(`corrections_dropped`), a doubt around the question (`hedges_dropped`), a prompt's wrapping (`prompt_dropped`), a
vehicle said as someone's (`owners_dropped`), labels, remarks and asides (`asides_dropped`), the interjections it opens
with (`interjections_dropped`), digressions between commas (`digressions_dropped`), and a preamble that frames it
(`framing_dropped`, `preamble_dropped`). Read as the grammar's 'is it true that' or 'tell me': a witness examined
(`examination_as_asked`), a wager (`wagers_read`), a request in a report's words (`requested_as_asked`), a hypothesis
put to a test (`hypothesis_as_asked`); a ticket's fields as the question and its context (`ticket_fields_read`); and
vehicles said first, then asked about as 'they' or 'it', as the question's subject (`dislocated_as_asked`)."""

from __future__ import annotations

import re

from dynclevr.colors import COLOR_NAMES
from dynclevr.language.checks import SPEEDING_UP
from dynclevr.language.context import _sentence_spans, coordinated_subject
from dynclevr.language.references import EVERYDAY_NAMES, OBJECT_WORDS, catalogue_names, generalises, mentions
from dynclevr.language.tokenize import tokenize
from dynclevr.language.times import END_SAID, FILM_WORDS, TIME_ZERO, _video_end, video_end_as_said
from dynclevr.language.words import (AFLOAT_SAID, AGREEING_TAGS, ASKING, AUXILIARIES, CHAT, CLAUSE_CONJUNCTIONS,
                                     CLAUSE_MARKS, CLOSING_INTERJECTIONS, COMES_IN_WORDS, COMMA_INTERJECTIONS,
                                     COMPARING, CONDITION_LABELS, CONDITION_OPENERS, CONDITION_WORDS, DETERMINERS,
                                     DIRECTION_WORDS, DURATIONS, END_WORDS, FILLERS, FLOATING_WORDS, FUTURE_CUES,
                                     GENERIC, GENERIC_NOUNS, HEADING_KEPT, IMAGINED_SAID, IMAGINING, IMAGINING_LABELS,
                                     INTERJECTIONS, LATER_TIMES, LOOKS, MATERIALS, MOTION_DESCRIPTIONS, MOTION_WORDS,
                                     NAMING, NEGATIONS, NOUNS_SAID, NUMBERS, OTHER_COLOURS, PARTICLES, PEOPLE, PLURALS,
                                     QUERY_NOUNS, QUESTION_OPENERS, RESTING, REST_WORDS, SENTENCE_ENDS, SIGHT_WORDS,
                                     SPEAKER_AND_LISTENER, SPEED_CHOICES, SPEED_CLASS_WORDS, START_ADJECTIVES,
                                     START_WORDS, STATIC_SAID, STOP_CUES, STREAM_EMOTES, TIME_OPENERS, UNNAMED,
                                     YES_NO_OPENERS, asks_impact, impact_like, phrase_starts)

# whom a spoken question is addressed to, after a greeting ('hey assistant, does ...', 'ok google is ...', 'yo chat')
VOCATIVES = {"assistant", "chat", "folks", "guys", "everyone", "everybody", "siri", "alexa", "google", "computer",
             "bot", "buddy", "mate", "matey", "dude", "bro", "friend", "friends", "team", "y'all", "all", "support",
             "there", "sir", "madam", "colleagues", "staff", "helpdesk"}   # and a letter's ('Dear support,')
# ... and a child's or to a child, said alone before a comma or between commas ('Mummy, how fast ...', 'Can you tell
# me, sweetie, is ...'): 'daddy' was read as 'pops' (into view)
ADDRESSED = {"mummy", "mommy", "mum", "mom", "mama", "momma", "mamma", "daddy", "dad", "papa", "grandma", "granny",
             "gran", "nana", "grandpa", "grandad", "granddad", "gramps", "sweetie", "sweetheart", "honey", "darling",
             "kiddo", "kids", "children", "class", "teacher", "auntie", "aunty", "uncle", "pal", "guys", "folks",
             "everyone", "chat", "bro", "dude", "mate", "buddy", "sis", "fam",
             "machan", "pet", "flight",   # a Sri Lankan's friend, a Geordie's 'pet', mission control's flight director
             "bab", "darlin", "sugar", "doll",   # a Brummie's 'bab', a gossip's and a gangster's
             "sir", "madam", "maam",   # a butler's ('There is an object going ever faster, sir; what colour ...')
             "friends", "people",   # a showman's ('Now observe the gray airliner, my friends: ...')
             "brethren", "flock", "congregation", "contestants", "recruit", "recruits",   # a vicar's, a host's
             "traveller", "traveler", "seeker", "adventurer", "nan",   # a quest giver's, a grandmother's
             "squad", "crew", "swimmers",   # a cheer captain's, a lifeguard's
             "man", "matey", "lovelies", "love",   # a beat poet's, a sailor's, a bingo caller's, a hairdresser's
             "apprentice", "angler",   # a wizard's, a fisherman's
             "troop", "scouts", "cubs", "houston",   # a scout leader's, an astronaut's
             "gentles", "guv", "squire", "maiden",   # a herald's ('good gentles'), a cabbie's, a knight's
             "duck", "captain",   # a dinner lady's ('my duck'), a starship computer's
             "reader", "brother",   # a scribe's ('O gentle reader,', 'Prithee, good brother,')
             "brothers", "sisters", "beloved", "guest", "guests",   # a priest's ('my brothers and sisters'), a count's
             "earthling", "earthlings", "host"}   # a visitor's from elsewhere ('esteemed earthling', 'honoured host')
ADDRESS_ADJECTIVES = {"old", "young", "dear", "my", "good", "little", "fair", "gentle", "o", "honoured", "honored",
                      "esteemed", "noble", "worthy", "dearest"}
# A letter's sign-off after its question ('? Many thanks, Nadia', '? Best regards', '? I would appreciate your
# prediction.'): it asks nothing, and its name is an unknown word
SIGN_OFFS = {"thanks", "thank", "many", "best", "regards", "kind", "kindest", "cheers", "sincerely", "warm", "warmest",
             "yours", "ta", "appreciate", "appreciated", "respectfully", "looking", "hope", "have", "i", "all", "much",
             "greetings", "with",
             "just", "asking", "need", "let"}   # a helpdesk's ('? Just need a yes or no for the ticket.')
THANKING = {"thanks", "thank", "cheers", "ta", "many"}
# how a caller's remark after the question opens: the speaker or the question itself ('that's my question')
SPEAKER_REMARKS = (("i",), ("that", "'", "s"), ("that", "is"), ("'", "cause"), ("cause",), ("cos",), ("because", "i"),
                   ("y", "'", "all"), ("you", "all"), ("me", "and"), ("just", "wondering"), ("just", "curious"))
INTERJECTION_ENDS = {",", ".", "-", "!", "?", ":", ";"}
DOUBTS = (["or", "is", "that"], ["or", "was", "that"], ["or", "am", "i"], ["or", "is", "it"], ["or", "was", "it"])


def _says_nothing(tail: list[str]) -> bool:
    """Whether words after a question say nothing of a vehicle, a time, a motion or a collision, nor ask anything
    ('? couldn't see', '? Many thanks, Nadia'; not '? Give its colour.')."""
    return not asks_impact(tail) and not set(tail) & (
        OBJECT_WORDS | FILM_WORDS | START_WORDS | HEADING_KEPT | MOTION_WORDS | MOTION_DESCRIPTIONS | QUERY_NOUNS
        | {"?", "which", "what", "how"}) and tail[0] not in ("give", "tell", "name", "state", "say")


# how the question after a remark's dash opens ('These young bikers never learn - is the yellow motorbike ...'; not
# a hyphen's second word: 'after block-in')
AFTER_DASH = QUESTION_OPENERS | CONDITION_OPENERS | {"when", "if", "had", "suppose", "imagine"}
# whom a remark is about: people and vehicles at large ('Blasted scooters and choppers -', 'Young hooligans -'), never
# one of the video's ('the one sitting at a simmer from the get-go - what kind of vehicle is that?')
REMARKED = PEOPLE | {"nobody", "folk", "youngsters", "hooligans", "tearaways", "bikers", "hogs", "fool", "hothead"}
UNREMARKED = {"one", "ones", "something", "somethin", "thing", "things", "vehicle", "vehicles", "object", "objects",
              "it", "its", "them", "this", "that"}


def _at_large(words: list[str]) -> bool:
    """Whether words speak of people or vehicles at large and of none of the video's ('Blasted scooters and choppers',
    'Back in my day bus drivers knew better'; not 'the one sitting at a simmer', 'the white sedan')."""
    return any(w in REMARKED or w in PLURALS or w[-1:] == "s" and (w[:-1] in OBJECT_WORDS or w[:-2] in OBJECT_WORDS)
               for w in words) and not set(words) & (set(COLOR_NAMES) | OTHER_COLOURS | UNREMARKED) and \
        not any(w in OBJECT_WORDS and nxt not in PEOPLE for w, nxt in zip(words, words[1:] + [""]))


def _grumbled(tail: list[str]) -> bool:
    """Whether a sentence after the question is a remark on vehicles or people at large ('? Back in my day bus
    drivers knew better.'): a statement that names no time, motion, speed or property, asks nothing and says no
    collision."""
    return tail[-1:] in ([","], ["."], ["!"]) and len(tail) <= 14 and _at_large(tail) and not asks_impact(tail) and \
        not set(tail) & (START_WORDS | END_WORDS | FILM_WORDS | MOTION_WORDS | SPEED_CLASS_WORDS | QUERY_NOUNS
                         | NEGATIONS | {"?", "mean", "meant"}) and tail[0] not in ("give", "tell", "name", "state")


# what a statement after the question may not name, so that it stays: a vehicle and what is asked of one, a time,
# the video, a premise or a request to read it otherwise ('? I mean the red one.', '? At the start, that is.')
AFTER_REMARK_NAMES = (OBJECT_WORDS | set(COLOR_NAMES) | OTHER_COLOURS | FILM_WORDS | START_WORDS
                      | END_WORDS - {"finishes", "finished", "ended"}   # the dog's biscuit, not the video
                      | QUERY_NOUNS | LOOKS | MOTION_WORDS | MOTION_DESCRIPTIONS | DIRECTION_WORDS | FLOATING_WORDS
                      | {"?", "which", "what", "how", "one", "ones", "mean", "meant", "instead", "rather", "moment",
                         "instant", "frame", "frames", "time", "future", "later", "afterwards", "predict", "stop",
                         "stops", "stopped", "cut", "if", "had", "would", "were", "different", "other", "another",
                         "else", "pair"})


def _remarked_after(tail: list[str]) -> bool:
    """Whether a statement after the question is a remark on anything but the video (a vet's '? I'll ask while the
    Labrador finishes his biscuit.', '? Pure guesswork, like predicting when a cat will come out from under the
    bed.'): closed by a full stop or '!', asking nothing and naming nothing the question could mean."""
    named = {w for j, w in enumerate(tail) if not (w == "which" and j and tail[j - 1] == ",")}   # ', which is ...'
    # (not a request, but one for the answer just asked: '? State it for the officer.')
    request = tail[0] in ("give", "tell", "name", "state", "say", "answer") and tail[1:2] != ["it"]
    return tail[-1:] in (["."], ["!"]) and len(tail) <= 24 and not asks_impact(tail) and \
        not named & AFTER_REMARK_NAMES and not request


def _unremarked(remark: list[str]) -> list[str]:
    """A caller's remark without the words that only look like asking ('that's what I'm wondering', 'I'll hang up')."""
    out, k = [], 0
    while k < len(remark):
        if remark[k:k + 2] in (["hang", "up"], ["what", "i"], ["what", "we"]):
            k += 2
            continue
        out.append(remark[k])
        k += 1
    return out


# An auctioneer's calls ('Lot seven, ... is the jet moving fast, do I hear a yes, do I hear a no, going once, going
# twice, sold?'): the lot's number and the closing count say nothing, the calls for bids offer the answers
CALLS = (["do", "i", "hear"], ["gimme"], ["give", "me"], ["who", "'", "ll", "say"], ["who", "'", "ll", "give", "me"],
         ["who", "'", "ll", "name", "me"], ["who", "'", "ll", "name"], ["let", "'", "s", "hear", "it"])
LOT_NUMBERS = {"number", "no", "-", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten",
               "eleven", "twelve", "thirteen", "fourteen", "fifteen", "sixteen", "seventeen", "eighteen", "nineteen",
               "twenty", "thirty", "forty", "fifty", "sixty", "seventy", "eighty", "ninety"}
BIDS = {"yes", "no", "static", "slow", "fast", "left", "right", "front", "back", "up", "down"}   # a call offers
CALLED_FOR = {"answer", "bid", "colour", "color", "direction", "model", "type", "kind", "speed"}


def _call(words: list[str], k: int) -> int:
    """How many words a call for a bid takes at words[k] ('do i hear a', 'gimme an', a second's 'or a'); 0 where
    none."""
    n = next((len(c) for c in (*CALLS, ["or"]) if words[k:k + len(c)] == c), 0)
    if n == 1 and words[k] == "or" and not (k and words[k - 1] in BIDS and words[k + 1:k + 2] in (["a"], ["an"])):
        return 0
    return n + (words[k + n:k + n + 1] in (["a"], ["an"])) if n else 0


def calls_read(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'lot nine , is it fast , do i hear a yes , do i hear a no , going once , going twice ?' -> 'is it fast , yes
    or no ?'. With the calls read so, or the words as they are and ()."""
    if not any(words[k:k + 3] in (["going", "once", ","], ["do", "i", "hear"]) for k in range(len(words))):
        return words, ()
    out, read = list(words), []
    # the lot's number, first or between commas ('Lot twenty-two , ...', '... , lot fifty-three , going once')
    for k in [k for k, w in enumerate(out) if w == "lot" and (k == 0 or out[k - 1] == ",")][::-1]:
        end = next((e for e in range(k + 1, min(len(out), k + 6)) if out[e] in (",", ":", "!", ".", "?")), None)
        if end and all(w in LOT_NUMBERS or w.isdigit() for w in out[k + 1:end]):
            start, end = (k, end + 1) if k == 0 else (k - 1, end)
            read.append((" ".join(out[start:end]), "nothing, a lot's number"))
            out = out[:start] + out[end:]
    going = next((k for k in range(len(out)) if out[k:k + 6] == [",", "going", "once", ",", "going", "twice"]), None)
    if going is not None:
        end = going + 6 + 2 * (out[going + 6:going + 8] in ([",", "sold"], [",", "gone"]))
        read.append((" ".join(out[going:end]), "nothing, the closing count"))
        out = out[:going] + (["?"] if out[end:] == ["!"] else out[end:])   # a question, however loudly closed
    k = 0
    while k < len(out):
        n = _call(out, k)
        if not n:
            k += 1
            continue
        offered, j = [], k
        while (n := _call(out, j)) and (end := next((e for e in range(j + n, min(j + n + 4, len(out) + 1))
                                                     if e == len(out) or out[e] in (",", "?", "!", ".", "or")), None)):
            offered.append(out[j + n:end])
            j = end + 1 if out[end:end + 1] == [","] and _call(out, end + 1) else end
        if not offered:
            k += 1
            continue
        if offered[0] and offered[0][-1] in CALLED_FOR and len(offered) == 1:
            said = []   # a call for what the question asks ('what colour is it , do i hear a colour ?')
        elif len(offered) == 1:
            said = offered[0]   # the answers listed after one call ('do i hear left , right , ... or down')
        else:
            said = [w for o in offered[:-2] for w in (*o, ",")] + offered[-2] + ["or"] + offered[-1]
        read.append((" ".join(out[k:j]), " ".join(said) or "nothing, a call for bids"))
        out = out[:k] + said + out[j:]
        k += len(said) + 1
    return out, tuple(read)


# how a description or a purpose closing the question opens (', as befits such a quiet street ?', a scribe's ', that
# it may be inked in the ledger ?', ', as far as thine eyes can tell ?')
DESCRIPTION_OPENERS = (["as", "befits"], ["as", "you"], ["as", "i"], ["as", "far"], ["that", "i"], ["that", "it"])
# ... and the asker's purpose (a pharmacist's ', just so I have it right ?', ', so I can tick the box ?'), whose
# 'right' is no direction offered
PURPOSE_OPENERS = (["so", "that"], ["so", "i"], ["so", "we"], ["just", "so"])


# a caller's haste ('real quick ,', an Upper Midwesterner's 'real quick there ,')
HASTE = [["real", q, *there, ","] for q in ("quick", "fast") for there in ((), ("there",))]


def _exclaimed(words: list[str], k: int) -> int:
    """Where an exclamation that names no vehicle, time or property, opening words[k:], ends ('what a smash ,', 'what a
    day !'); 0 where none opens them."""
    end = next((e for e in range(k + 3, k + 6) if words[e:e + 1] in ([","], ["!"])), None)
    if words[k:k + 2] not in (["what", "a"], ["what", "an"]) or end is None or set(words[k + 2:end]) & (
            OBJECT_WORDS | FILM_WORDS | START_WORDS | QUERY_NOUNS | MOTION_WORDS | {"?", "which", "what", "how"}):
        return 0
    return end


# ... and a streamer's or a presenter's audience, spoken to without a comma before ('paused here chat , is ...',
# 'paused chat PauseChamp , is ...')
AUDIENCES = {"chat", "guys", "folks"}
AUDIENCE_AFTER = {"here", "there", "now", "again", "today", "tonight", "-"}   # (not an Australian's 'flat chat')


def _addressed(words: list[str]) -> list[range]:
    """Where the question names whom it is asked, between commas, first or at the end ('is it fast , honey ?'), with
    its adjectives (', old friend ,', a scribe's opening 'O gentle reader ,', a priest's ', my brothers and sisters
    :')."""
    return [range(j - n, j + 1) for j in range(1, len(words) - 1) if words[j] in ADDRESSED
            and words[j + 1] in {",", "?", "!", ".", ":", ";"} | STREAM_EMOTES for n in (0, 1, 2, 3)
            if (j - n == 0 or j - n > 0 and words[j - n - 1] == ",") and (
                set(words[j - n:j]) <= ADDRESS_ADJECTIVES or "and" in words[j - n:j]
                and set(words[j - n:j]) <= ADDRESS_ADJECTIVES | ADDRESSED | {"and"})
            or n == 0 and words[j] in AUDIENCES and (words[j - 1] in AUDIENCE_AFTER or words[j + 1] in STREAM_EMOTES)]


def _without(words: list[str], addressed: list[range]) -> list[str]:
    dropped = {k for a in addressed for k in (a.start - 1, *a) if k >= a.start or words[k] == ","}
    return [w for j, w in enumerate(words) if j not in dropped]


def addressees_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'suppose , dear guest , the cruiser had ...' -> 'suppose , the cruiser had ...': whom the question is asked,
    said after its first words, before a condition's comma is read (so that what it imagines follows it); those in
    its opening interjections are `interjections_dropped`'s, which they tell where the question starts. With the
    addressees read as nothing, or the words as they are and ()."""
    opening = next((k for k, w in enumerate(words) if w not in INTERJECTIONS | VOCATIVES | ADDRESSED
                    | ADDRESS_ADJECTIVES | {",", "and"}), len(words))
    addressed = [a for a in _addressed(words) if a.start > opening]
    if not addressed:
        return words, ()
    return _without(words, addressed), \
        ((" ".join(" ".join(words[j] for j in a) for a in addressed), "nothing, whom it is asked"),)


def interjections_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """The question after the interjections it opens with ('so , um , does ...' -> 'does ...'), where a question
    follows them. With the interjections read as nothing, or the words as they are and ()."""
    particles = [j for j in range(1, len(words) - 1) if words[j] in PARTICLES and words[j + 1] in (",", "?", "!", ".")]
    said = tuple((words[j], "nothing, a particle") for j in particles)
    words = [w for j, w in enumerate(words) if j not in particles]
    addressed = _addressed(words)
    addressees = " ".join(" ".join(words[j] for j in a) for a in addressed)
    words = _without(words, addressed)
    # a caller's '(now) real quick ,' asks in haste, of no vehicle's speed
    # (and an Upper Midwesterner's 'real quick there ,')
    k = next((j + len(h) for j in (0, 1, 2) for h in HASTE if words[j:j + len(h)] == h
              and (j == 0 or words[0] in INTERJECTIONS | COMMA_INTERJECTIONS and set(words[1:j]) <= {","})), 0)
    # 'like' after another interjection needs no comma ('so like does ...'), nor whom the question is addressed to;
    # an exclamation of no vehicle ('wowee , what a smash , as they collide is ...')
    # (and a teller's 'and' or 'but' opening the question: 'And when the jet shows up , is it ...?')
    while k < len(words) and ((exclaimed := _exclaimed(words, k)) or words[k] in INTERJECTIONS
                              or k == 0 and words[0] in ("and", "but")
                              or words[k] in COMMA_INTERJECTIONS | ADDRESSED
                              and words[k + 1:k + 2] and words[k + 1] in INTERJECTION_ENDS
                              or k and words[k - 1] in INTERJECTIONS | VOCATIVES and words[k] in VOCATIVES | {"like"}):
        k = exclaimed or k + 1
        while k < len(words) and words[k] in INTERJECTION_ENDS:
            k += 1
    end = len(words)
    while end > k and (words[end - 1] in CLOSING_INTERJECTIONS or words[end - 1] in INTERJECTION_ENDS
                       and end - 1 > k and words[end - 2] in CLOSING_INTERJECTIONS):
        end -= 1
    # ... and a letter's sign-off or a short remark after the question ('? couldn't see'), where it says nothing of
    # a vehicle, a time, a motion or a collision
    # ... and a question after it about the asking itself ('? Sorry, is that okay to ask?', '? That's a fair thing to
    # ask, right?')
    first = next((j for j in range(k, end) if words[j] == "?"), None)
    about = words[first + 1:end] if first is not None else []
    if about[-1:] == ["?"] and "?" not in about[:-1] and {"ask", "asking", "question"} & set(about) and \
            _says_nothing(about[:-1]):
        said += ((" ".join(about), "nothing, a question about the asking"),)
        words, end = words[:first + 1], first + 1
    # ... and a doubt said as the other choice of a question that asks yes or no (', or is that just Mr Jenkins
    # stirring ?', ', or is that just my eyes ?'), where the doubt names nothing the question could mean
    doubt = next((j for j in range(k + 2, end - 3) if words[j - 1] == "," and words[j:j + 3] in DOUBTS), None)
    if doubt and words[end - 1] == "?" and "?" not in words[doubt:end - 1] and \
            _remarked_after([*words[doubt + 3:end - 1], "."]):
        said += ((" ".join(words[doubt - 1:end - 1]), "nothing, a doubt"),)
        words, end = [*words[:doubt - 1], *words[end - 1:]], doubt
    asked = max((j for j in range(k, end) if words[j] == "?"), default=None)
    tail = words[asked + 1:end] if asked is not None else []
    # (a thanks closes whatever it thanks for: '? Thank you for flying with us, and mind the overhead lockers.')
    thanks = tail[:1] and tail[0] in THANKING and tail[-1:] in (["."], ["!"]) and not mentions(tail) and \
        not {"?", "whether", "which", "what", "how", "if"} & set(tail)
    if tail and ((tail[0] in SIGN_OFFS or len(tail) <= 4 or len(tail) <= 6 and tail[-1] == ".") and _says_nothing(tail)
                 or _grumbled(tail) or _remarked_after(tail) or thanks):
        end = asked + 1
    # ... or a remark after a semicolon closing a request ('Determine whether it is moving slowly at that instant; a
    # yes or no will suffice.')
    last = end - (words[end - 1:end] in (["?"], ["."], ["!"]))
    semi = max((j for j in range(k, last) if words[j] == ";"), default=None) if "?" not in words[k:last] else None
    if semi is not None and _remarked_after([*words[semi + 1:last], "."]) and \
            not {"which", "what", "how", "whether", "who", "tell", "say", "name", "give"} & set(words[semi + 1:last]):
        words = [*words[:semi], *(words[last:end] or ["."]), *words[semi + 1:last], *words[end:]]
        end, asked = semi + 1, (semi if words[semi] == "?" else None)   # the question's own mark, moved
    # ... or a description closing it after its last comma (an estate agent's ', a well-kept little runaround ?', ',
    # as befits such a quiet street ?'; not ', a car or a bus ?')
    comma = next((j for j in range(max(k, (asked or 0) - 14), asked or 0) if words[j] == "," and (
        words[j + 1:j + 2] in (["a"], ["an"]) or words[j + 1:j + 3] in DESCRIPTION_OPENERS + PURPOSE_OPENERS)), None)
    described = words[comma + 1:asked] if comma is not None else []
    offered = set() if described[:2] in PURPOSE_OPENERS else BIDS
    if described and _says_nothing(described) and not set(described) & (offered | set(COLOR_NAMES) | {"or", "not"}):
        words, end, asked = words[:comma] + words[asked:], end - len(described) - 1, comma
        said += ((" ".join(described), "nothing, a description"),)
    # ... or after a request closed by a full stop ('I should like to know whether ... . Thank you kindly.')
    thanked = max((j for j in range(k, end - 1) if words[j] == "." and words[j + 1] in THANKING), default=None)
    if asked is None and thanked is not None and _says_nothing(words[thanked + 1:end]):
        end = thanked + 1
    # without a question mark, a chat's remark after the question ('..., i missed it', '... ngl cant tell')
    remark = next((j for j in range(k + 3, end) if asked is None and (words[j] in CHAT or words[j - 1] == ","
                                                                        and words[j] == "i"
                                                                        or tuple(words[j:j + 4]) in VIEWER_DOUBTS
                                                                        or tuple(words[j:j + 3]) in VIEWER_DOUBTS)
                   and len(words[j:end]) <= 6 and _says_nothing(words[j:end])), None)
    if remark:
        end = remark - (words[remark - 1] == ",")
    # a caller's remark closing the question after its last comma (', that's my question .', ', I'll hang up and
    # listen .', ", 'cause I missed it if it did ?", ', y'all ?'): the question mark it carried stays
    last = end - (words[end - 1:end] in (["?"], ["."], ["!"]))
    remark = next((j for j in range(k + 4, last) if words[j - 1] == "," and last - j <= 14
                   and any(tuple(words[j:j + len(r)]) == r for r in SPEAKER_REMARKS)
                   and "?" not in words[j:last] and _says_nothing(_unremarked(words[j:last]))), None)
    if remark and QUESTION_OPENERS.union(YES_NO_OPENERS).intersection(words[k:remark]):
        words, end = [*words[:remark - 1], "?", *words[remark - 1:]], remark
    closing = ((" ".join(words[end:]), "nothing, an interjection"),) if words[end:] else ()
    # a speaker's fillers within the question ('the um green sedan'), with the commas around them
    within = [j for j in range(k, end) if words[j] in FILLERS]
    if within:
        fillers = set(within) | {j + 1 for j in within if words[j + 1:j + 2] == [","]   # (an emote ends its clause)
                                 and words[j] not in STREAM_EMOTES} | {
            j - 1 for j in within if words[j - 1] == "," and words[j + 1:j + 2] in ([","], ["?"], ["."], [])}
        closing = ((" ".join(words[j] for j in within), "nothing, a filler"), *closing)
        kept = [w for j, w in enumerate(words[:end]) if j not in fillers]
        words, end = kept + words[end:], len(kept)
    closing = said + ((addressees, "nothing, whom it is asked"),) * bool(addressed) + closing
    # (a speaker's 'um so' before a vehicle said first: 'um so the one that's going really fast ... what kind of ...';
    # and whom it is asked after the interjection: 'Right , troop , the cruiser crashes into something : ...'; and a
    # Briton's 'Right ,' before anything but another direction, after another interjection too: 'Right , anywhere in
    # the video , is there ...', 'Ugh , right , the brown SUV at the beginning : is it ...')
    if k == 0 or k == len(words) or words[k] not in QUESTION_OPENERS | TIME_OPENERS | CONDITION_WORDS \
            | CONDITION_OPENERS | {"tell", "let", "say"} and not ADDRESSED & set(words[:k]) and \
            not any(a.start - 1 < k for a in addressed) and \
            not (any(words[j] == "right" and words[j + 1] in (",", "-") for j in range(k))
                 and words[k] not in DIRECTION_WORDS | {"or", "and"}
                 and QUESTION_OPENERS.intersection(words[k:])) and \
            not (words[k] == "the" and set(words[:k]) <= FILLERS | {"so", "well"} and FILLERS & set(words[:k])):
        return words[:end], closing
    return words[k:end], ((" ".join(words[:k]), "nothing, an interjection"), *closing)


# A clause of time said first is never a digression, whatever its verb ('As they bash, is the wagon slower ...?' was
# read at the start)
CLAUSES_OF_TIME = (*([c] for c in sorted(CLAUSE_CONJUNCTIONS)), ["as", "they"], ["as", "it"], ["the", "moment"],
                   ["at", "the", "moment"], ["the", "instant"], ["at", "the", "instant"])


# A digression between commas, or before the first, that says nothing the question could need ('So, Jen, and this
# is the part I love, was the red sedan ...', 'at what speed, I wonder, was it moving?'): no vehicle, motion,
# collision, time, place, condition, negation or asking in it.


TIME_PREFIXES = {"post", "pre", "mid", "after", "end"}


def _says_something(span: list[str]) -> bool:
    # (an impact's word misspelt too: 'wen they colide ,'; a hyphen inside a word says nothing, 'self - indulgent',
    # unless it may be a time's: 'post - haste' may be 'post - video')
    span = [w for k, w in enumerate(span) if not (w == "-" and 0 < k < len(span) - 1 and span[k - 1].isalpha()
                                                  and span[k + 1].isalpha() and span[k - 1] not in TIME_PREFIXES)]
    return bool(set(span) & SAYING) or asks_impact(span) or any(span[:len(t)] == t for t in CLAUSES_OF_TIME) or any(
        w.startswith(("accelerat", "speed", "float", "hover")) or w.isdigit() or len(w) > 4 and impact_like(w)
        for w in span)


# what a courtesy between commas may say beside the speaker or listener ('..., if I may respectfully inquire, ...', ',
# in your considered opinion ,', ', I ask with caution ,')
COURTEOUS = {"if", "would", "could", "may", "might", "ask", "asking", "inquire", "enquire", "opinion", "view",
             "humble", "respectfully", "kind", "so", "put", "it", "say", "indulgence", "pardon", "permit", "in", "with"}


def _courtesy(span: list[str]) -> bool:
    """Whether a span between commas is the speaker's courtesy: it speaks of the speaker or the listener, names no
    vehicle, and says nothing else the question could need."""
    return bool(SPEAKER_AND_LISTENER & set(span)) and not mentions(span) and not asks_impact(span) and \
        set(span) & SAYING <= COURTEOUS


def _offers_speed(span: list[str]) -> bool:
    return any(tuple(span[k:k + len(c)]) == c for k in range(len(span)) for c in SPEED_CHOICES)


REFERENCE_WORDS = {"ref", "reference", "case", "file", "form", "item", "section", "schedule", "docket", "claim",
                   "policy", "ticket", "invoice", "account"}


def digressions_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'so , jen , and this is the part i love , was the red sedan moving ?' -> 'was the red sedan moving ?'. With
    the digressions read as nothing, or the words as they are and ()."""
    # (a transcript's stage direction in square brackets, never a unit: 'in the first frames [ indicating ] ,')
    opened = next((k for k, w in enumerate(words) if w == "["), None)
    closed = next((k for k in range(opened + 2, min(len(words), opened + 16)) if words[k] == "]"), None) \
        if opened is not None else None
    if closed is not None and not _says_something(words[opened + 1:closed]) and \
            _says_something(words[:opened] + words[closed + 1:]):
        rest, read = digressions_dropped(words[:opened] + words[closed + 1:])
        return rest, ((" ".join(words[opened:closed + 1]), "nothing, a stage direction"), *read)
    # (an aside in brackets: 'supposing the minivan had been moving rapidly ( mark this , apprentice ) , would ...')
    opened = next((k for k, w in enumerate(words) if w == "("), None)
    closed = next((k for k in range(opened + 3, min(len(words), opened + 16)) if words[k] == ")"), None) \
        if opened is not None else None
    # (of two words or more: 'time ( s )' is a unit; or a note after the question, whatever colour it names: a
    # scribe's '? (Marginal note: the cyan ink is nearly spent.)')
    inside = words[opened + 1:closed] if closed is not None else []
    noted = bool(inside) and words[opened - 1:opened] == ["?"] and words[closed + 1:] in ([], ["."]) and not (
        set(inside) - set(COLOR_NAMES)) & SAYING and not asks_impact(inside)
    # (a form's reference, its number no time: '(ref. DIR-0402)', '(case no. 55-Q)')
    cited = inside[:1] and inside[0] in REFERENCE_WORDS and not mentions(inside) and not asks_impact(inside)
    if closed is not None and (noted or cited or not _says_something(inside)) and \
            _says_something(words[:opened] + words[closed + 1:]):
        aside = words[opened:closed + 1]
        rest, read = digressions_dropped(words[:opened] + words[closed + 1:])
        return rest, ((" ".join(aside), "nothing, a digression"), *read)
    # (a clause of the scene's own closing it, without a comma: '... while the hall was meant to be quiet ?', its
    # 'hall' was fixed as 'shall' and read as the future)
    end = len(words) - (words[-1:] in (["?"], ["."]))
    scene = next((w for w in range(3, end - 2) if words[w] in ("while", "whilst") and words[w + 1] == "the"
                  and end - w <= 10 and not {"it", "they", ","} & set(words[w:end])
                  and not _says_something(words[w + 1:end])), None)
    if scene is not None and _says_something(words[:scene]):
        return words[:scene] + words[end:], ((" ".join(words[scene:end]), "nothing, a digression"),)
    commas = [k for k, w in enumerate(words) if w == ","]
    if not commas:
        return words, ()
    drop, read, start = set(), [], 0
    for c in commas:
        span = words[start:c]
        # (not a speed offered to choose: 'is it still , dawdling , or hurrying ?')
        if span and (not _says_something(span) or _courtesy(span)) and not (
                words[c + 1:c + 2] == ["or"] and _offers_speed(span)):
            drop |= set(range(start, c + 1))
            read.append(" ".join(span))
        start = c + 1
    # ... and after the last comma, before the question mark ('..., my dear fellow?'), where it asks nothing itself
    # (', is it crawlig?' is the question, its slip not yet read)
    # (or a longer one that sets the scene: a lighthouse keeper's ', by the old lamp's glow ?', ', with the old lamp
    # burning ?', ', as the old lamp sees it ?'; its possessive "'s" asks nothing)
    end = len(words) - (words[-1:] in (["?"], ["."]))
    closing = words[start:end]
    # (a collision question's other side, closing it: ', or will it carry on unscathed ?', ', or did it keep out of
    # trouble like a sensible chap ?', ', or was it all quiet ?': 'quiet' was read as still, at the collision)
    other = closing[:1] == ["or"] and closing[1:2] and closing[1] in DISLOCATED_ASKS and closing[2:3] == ["it"] and \
        closing[3:4] and (closing[3] in ESCAPING or CALM.intersection(closing[3:5])) and asks_impact(words[:start])
    # (a clause of time whose subject is the scene's: ', while the old lamp kept its watch ?')
    scene = closing[1:] if closing[:1] in (["while"], ["as"]) and closing[1:2] == ["the"] and \
        not {"it", "they"} & set(closing) else closing
    if other or scene and (len(closing) <= 4 or len(closing) <= 12 and closing[0] in SCENE_OPENERS) and \
            not _says_something(scene) and not _offers_speed(closing) and \
            not (YES_NO_OPENERS | QUESTION_OPENERS | ({"it", "they"} if len(closing) <= 4 else set())).intersection(
                w for k, w in enumerate(closing) if ["'", "s"] not in (closing[k - 1:k + 1], closing[k:k + 2])):
        drop |= set(range(start - 1, end))
        read.append(" ".join(words[start:end]))
    rest = [w for k, w in enumerate(words) if k not in drop]
    if not read or not _says_something(rest):
        return words, ()
    return rest, tuple((r, "nothing, a digression") for r in read)


# (`digressions_dropped`) how a collision question's other answer goes on ('or will it carry on ...', 'or was it all
# quiet'), and how a scene closing the question opens
ESCAPING = {"carry", "keep", "stay", "go", "escape", "get", "come", "avoid", "remain", "steer", "make"}
CALM = {"quiet", "calm", "peaceful", "clear", "clean", "safe", "fine", "uneventful"}
SCENE_OPENERS = {"by", "under", "beneath", "below", "beside", "near", "with", "while", "on", "in", "amid", "as"}


DISLOCATED_ASKS = {"are", "were", "will", "would", "did", "do", "does", "is", "was", "have", "had"}


# A speaker's doubt around the question: said first ('Not sure, but ...', 'I could be off here, but ...', 'Since the
# clip cuts off, I can't be sure: ...'), or after it (', or am I misremembering?', '; is that right?')
# a viewer who cannot make it out ('ngl cant tell, ...', '... cant see it rly')
VIEWER_DOUBTS = tuple((*i, can, "not", *quite, see) for i in ((), ("i",)) for can in ("can", "could")
                      for quite in ((), ("quite",), ("really",)) for see in ("tell", "see")) + (("hard", "to", "tell"),)
HEDGE_STARTS = (("not", "sure"), ("not", "certain"), ("unless",), ("maybe",), ("correct", "me"), ("no", "idea"),
                ("hard", "to", "say"), *VIEWER_DOUBTS)
HEDGE_ENDS = ((",", "but"), (",", "so"), (":",), (";",), ("-",), (",",))
DOUBTING = {"am", "did", "do", "have", "was", "is", "could"}
# ... and what a doubt said first never says: a question's words, a time, a motion, a vehicle unnamed
ASKED_IN_DOUBT = {"if", "suppose", "had", "when", "?", "which", "what", "how", "where", "who", "whether", "tell",
                  "give", "name", "direction", "speed", "colour", "color", "type", "kind", "hover", "hovers",
                  "hovered", "float", "floats", "floated"}


# what an apology before the question leads into ('Sorry to ask a what-if, but if ...', '... but imagine ...')
APOLOGY_THEN = {"if", "imagine", "suppose", "say", "picture", "had", "after", "once", "let", "let's"}
# a courtesy said first ('If it's okay to ask, ...', 'If it isn't too much trouble, ...', 'If you wouldn't mind
# guessing, ...')
POLITE_IF = re.compile(r"^(?:if (?:it (?:' s |is )(?:not )?(?:too much (?:trouble|bother)|(?:ok|okay|alright|fine|all "
                       r"right))(?: (?:to|for) [a-z ]+?)?|you (?:do not|would not|don ' t) mind(?: [a-z]+ing)?"
                       r"|i (?:may|might)(?: ask)?|you (?:please|can|could)) , )")
APOLOGISING = {"sorry", "silly", "dumb", "stupid", "apologies", "apologise", "apologize", "forgive", "excuse",
               "pardon", "basic", "obvious"}   # ('This might be a silly one, sorry, but ...': 'one' is no vehicle)
SOFTENED = {"was", "is", "were", "are", "did", "does", "do", "will", "has", "had"}   # not 'could', 'might', 'would'
SOFTENERS = {"possibly", "perhaps", "probably", "maybe"}


# A premise of the viewer's, or of the footage, said first: no change to what the video shows ('If I'm seeing it
# right, ...', 'Assuming the footage is accurate, ...', 'Unless I missed something, ...', 'Provided I've identified the
# fighter jet correctly, supposing it had ...')
PREMISE_OPENERS = (["if"], ["assuming", "that"], ["assuming"], ["provided", "that"], ["provided"], ["providing"],
                   ["supposing"], ["unless"], ["as", "long", "as"])
VIEWER_WORDS = {"i", "me", "my", "we", "our", "us", "you", "your", "memory", "eyes"}
FOOTAGE_WORDS = {"footage", "clip", "video", "camera", "frames", "recording", "colors", "hues", "edited", "cropped"}
IDENTIFYING = {"right", "correct", "correctly", "identified", "spotted", "straight"}
GOING_ON = {"continued", "continues", "kept", "keeps", "went", "gone", "goes", "on", "playing", "watching", "rolling",
            "running", "longer", "further", "more"}


def _viewer_premise(words: list[str]) -> int | None:
    """Where a premise of the viewer's said first ends (past its comma), or None."""
    opener = next((o for o in PREMISE_OPENERS if words[:len(o)] == o), None)
    end = next((k for k in range(len(opener or []), min(len(words), 16)) if words[k] == ","), None)
    if opener is None or end is None or not words[end + 1:end + 2]:
        return None
    clause = set(words[len(opener):end])
    said = clause & (VIEWER_WORDS | FOOTAGE_WORDS)
    # (a motion, a time, a condition or the video going on is no viewer's premise: 'if the video went on , ...')
    told = {"had", "were", "would"} | GOING_ON | MOTION_WORDS | SPEED_CLASS_WORDS | STATIC_SAID - {"not"} | \
        AFLOAT_SAID | END_WORDS | STOP_CUES | START_WORDS
    if not said or clause & told or \
            asks_impact(list(clause)) and not clause & VIEWER_WORDS or \
            NAMING & clause and not (clause & IDENTIFYING and clause & VIEWER_WORDS):
        return None
    after = words[end + 1]
    return end + 1 if after in QUESTION_OPENERS | TIME_OPENERS | {"had", "if", "suppose", "supposing", "what",
                                                                  "which", "how"} else None


def hedges_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'not sure , but did the sedan hit the bus ?' and 'sorry if this is a silly question , but does ...' -> 'did the
    sedan hit the bus ?', 'does ...'; 'was it slower , or am i misremembering ?' -> 'was it slower ?'; '...; is that
    right ?' -> '..., is that right ?' (a tag, read as one by `negative_question_as_asked`). A doubt said first names
    no vehicle. With the words read so, or the words as they are and ()."""
    out, read = list(words), []
    ends = [(k, len(e)) for k in range(1, min(len(out), 16)) for e in HEDGE_ENDS if tuple(out[k:k + len(e)]) == e]
    opened = lambda said: said[next((j for j, w in enumerate(said) if w not in INTERJECTIONS | {","}), len(said)):]
    first_person = lambda said: bool({"i", "me", "my"} & set(said)) or any(opened(said)[:len(h)] == list(h)
                                                                          for h in HEDGE_STARTS)
    undoubted = NAMING | ASKED_IN_DOUBT | UNNAMED | START_WORDS | MOTION_WORDS | AFLOAT_SAID | END_WORDS
    # an apology before the question needs no 'I' ('sorry if this is a silly question , but does ...')
    unapologetic = NAMING | GENERIC_NOUNS | START_WORDS | MOTION_WORDS | MOTION_DESCRIPTIONS | FLOATING_WORDS
    apology = lambda k, n: n == 2 and out[k + 1] == "but" and out[k + 2:k + 3] and out[k + 2] in (
        QUESTION_OPENERS | TIME_OPENERS | APOLOGY_THEN)
    doubted = lambda said: next((opened(said)[len(v):] for v in VIEWER_DOUBTS if opened(said)[:len(v)] == list(v)),
                                said)
    cut = max((k + n for k, n in ends if (first_person(out[:k]) and not undoubted & set(doubted(out[:k]))
                                          or apology(k, n) and (not unapologetic & set(out[:k]) or APOLOGISING
                                                                & set(out[:k]) and not OBJECT_WORDS & set(out[:k])))
               and not asks_impact(out[:k]) and out[k + n:]), default=None)
    if cut is not None:
        read.append((" ".join(out[:cut]), "nothing, a doubt"))
        out = out[cut:]
    premise = _viewer_premise(out)
    if premise:
        read.append((" ".join(out[:premise]), "nothing, a premise of the viewer's"))
        out = out[premise:]
    polite = POLITE_IF.match(" ".join(out))
    if polite and not NAMING & set(polite.group(0).split()):
        read.append((polite.group(0).strip(), "nothing, a courtesy"))
        out = out[len(polite.group(0).split()):]
    # a shy speaker's softener in a question of fact ('was the cruiser possibly going fast ...', 'is it kind of
    # slow'): not what could happen, which 'could' or 'might' ask
    soft = [k for k, w in enumerate(out) if out[:1] and out[0] in SOFTENED and k > 1 and (
        w in SOFTENERS or out[k:k + 2] in (["kind", "of"], ["sort", "of"]) and out[k + 2:k + 3] and
        out[k + 2] in SPEED_CLASS_WORDS | STATIC_SAID | MOTION_WORDS)]
    if soft:
        k = soft[0]
        n = 1 + (out[k] in ("kind", "sort"))
        read.append((" ".join(out[k:k + n]), "nothing, a softener"))
        out = out[:k] + out[k + n:]
    # a courtesy or a musing after the question (', if you don't mind my asking?', ', I wonder?')
    tail = next((k for k in range(max(1, len(out) - 12), len(out) - 2) if out[k] == "," and (
        out[k + 1] == "if" and {"you", "i", "it", "my"} & set(out[k + 2:-1]) and "guess" not in out[k:] or out[
            k + 1:-1] in (
            ["i", "wonder"], ["i", "suppose"], ["i", "wonder", "?"]))), None)
    if tail and out[-1:] == ["?"] and not (NAMING | START_WORDS | END_WORDS | MOTION_WORDS | AFLOAT_SAID) & set(
            out[tail:]) and not asks_impact(out[tail:]) and tail > 3:
        read.append((" ".join(out[tail:-1]), "nothing, a courtesy"))
        out = out[:tail] + ["?"]
    if out[-1:] == ["?"]:
        doubt = next((k for k in range(1, len(out) - 3) if out[k:k + 2] == [",", "or"] and out[k + 2] in DOUBTING
                      and "i" in out[k + 2:k + 5] and not NAMING & set(out[k:])), None)
        if doubt is not None:
            read.append((" ".join(out[doubt:-1]), "nothing, a doubt"))
            out = out[:doubt] + ["?"]
    tag = next((k for k in range(1, len(out) - 2) if out[k] == ";" and list(out[k + 1:-1]) in AGREEING_TAGS), None)
    if tag is not None and out[-1:] == ["?"]:
        read.append((";", ","))
        out[tag] = ","
    return (out, tuple(read)) if read else (words, ())


HUNCHES = ("hunch", "gut", "guess", "bet", "forecast", "prediction", "feeling", "instinct", "theory", "money")
# A witness examined ('I put it to you that the bus was parked. Is that correct?', 'You'd concede, wouldn't you,
# that ...', 'Would it be accurate to say that ...'): a statement put to be confirmed, the grammar's 'is it true that'
_AGREE = ("agree", "accept", "concede", "admit", "acknowledge")
_TAGGED = ([], *([",", aux, *you_not, ","] for aux in ("would", "do", "will") for you_not in (["not", "you"],
                                                                                              ["you", "not"])))
# a report, heard ('Sources tell us the bus was parked; can we confirm that?'; 'Rumour has it the bus hit something,
# darling, so what colour ...?': a premise, its question after it)
HEARSAY = {(*said, *that) for said in (
    ("sources", "tell", "us"), ("sources", "tell", "me"), ("sources", "say"), ("my", "sources", "say"),
    ("my", "sources", "tell", "me"), ("we", "are", "told"), ("we", "'", "re", "told"), ("i", "am", "told"),
    ("i", "'", "m", "told"), ("reports", "say"), ("word", "is"), ("word", "has", "it"), ("rumour", "has", "it"),
    ("rumor", "has", "it"), ("a", "little", "bird", "says"), ("a", "little", "bird", "tells", "me"),
    ("a", "little", "bird", "told", "me")) for that in ((), ("that",))} | {
    (*reports, "that") for reports in (("reports", "are", "coming", "in"), ("reports", "come", "in"))}
CONFIRMING = {*((*you, verb, *tag, *that) for you in (["you"], ["you", "would"], ["you", "'", "d"], ["you", "will"])
                for verb in _AGREE for tag in _TAGGED for that in (["that"], []) if that or not tag),
              # a sceptic's ('Wouldn't you say ...', 'Am I to believe ...', 'Don't tell me ...')
              *((*lead, *that) for lead in (("would", "not", "you", "say"), ("would", "you", "say"),
                                            ("do", "not", "you", "think"), ("am", "i", "to", "believe"),
                                            ("are", "we", "to", "believe"), ("do", "not", "tell", "me"))
                for that in ((), ("that",))),
              *((*ask, "you", verb, *me, "that") for ask in (["would"], ["do"], ["will"], ["can"], ["could"])
                for verb in _AGREE for me in ([], ["with", "me"])),
              *(("i", "put", "it", *to, "that") for to in ([], ["to", "you"])),
              *(("i", "suggest", *to, "that") for to in ([], ["to", "you"])),
              *((*be, fair, "to", "say", "that") for be in (["would", "it", "be"], ["is", "it"])
                for fair in ("accurate", "fair", "correct", "right", "true")),
              *(("is", "it", "your", view, "that") for view in ("opinion", "view", "evidence", "testimony",
                                                               "position", "understanding", "belief", "assessment",
                                                               "contention", "recollection")),
              *(("is", "it", "not", *case, "that") for case in (("true",), ("correct",), ("right",), ("the", "case"))),
              *(("is", "not", "it", *case, "that") for case in (("true",), ("correct",), ("right",), ("the", "case"))),
              # ('It is true, is it not, that ...')
              *(("it", "is", *case, ",", "is", "it", "not", ",", "that") for case in (("true",), ("correct",),
                                                                                   ("right",), ("the", "case"))),
              ("is", "it", "the", "case", "that"),
              # British indirectness ('Am I right in thinking ...', 'I don't suppose the bus was ..., was it?')
              *((*am, right, "in", think, *that) for am in (("am", "i"), ("would", "i", "be")) for right in (
                  "right", "correct") for think in ("thinking", "supposing", "saying", "believing")
                for that in ((), ("that",))),
              *(("am", "i", right, "that") for right in ("right", "correct")),
              *(("i", *rather, *verb, *that) for rather in ((), ("rather",)) for verb in (
                  ("do", "not", "suppose"), ("suspect",), ("suppose",), ("gather",)) for that in ((), ("that",))),
              # a report put to be confirmed ('Sources tell us the bus was parked; can we confirm that?')
              *HEARSAY,
              # ... or someone's ('Someone says the bus was parked. Was it?', 'A friend claims that ...')
              *((*who, said, *that) for who in (["someone"], ["somebody"], ["a", "friend"], ["my", "friend"],
                                                ["a", "colleague"], ["a", "viewer"], ["a", "witness"], ["people"],
                                                ["management"], ["the", "client"])
                for said in ("says", "said", "claims", "claimed", "reports", "reported", "predicts", "predicted",
                             "thinks", "reckons", "insists", "argues", "swears", "asserts", "asserted", "states",
                             "stated", "maintains") for that in ((), ("that",))),
              # ... or an auditor's ('We seek assurance that ...; is that the case?')
              *(("we", seek, "assurance", "that") for seek in ("seek", "require", "need", "request")),
              # ... or one's own hunch ('My hunch says ...', 'my forecast is that ...', 'Here's my bet: ...')
              *((*mine, hunch, *said) for mine in (["my"], ["here", "'", "s", "my"]) for hunch in HUNCHES
                for said in ([":"], ["says"], ["says", "that"], ["is", "that"], ["tells", "me"])
                if (mine == ["my"]) != (said == [":"]))}
# a claim put under a label ('Claim: the bus was parked. Correct?', 'Statement: ... True or false?'), where a
# statement, not a question, follows it
CLAIM_LABELS = sorted({(*label, ":") for label in (["claim"], ["claim", "to", "check"], ["claim", "under", "review"],
                                                   ["statement"], ["check", "this"], ["check", "this", "claim"],
                                                   ["check", "this", "prediction"], ["fact", "check"],
                                                   ["fact", "-", "check"], ["true", "or", "false"], ["assertion"],
                                                   ["hypothesis"])}, key=len, reverse=True)
# ... closed by a question of its own ('. Is that correct?', '. Do you agree?', '. Was it?'): the statement's question
# mark
CONFIRM_ENDS = [[end, *q, "?"] for end in (".", ";", ",")
                for q in (*([aux, this, judged] for aux in ("is", "was") for this in ("that", "this", "it")
                            for judged in ("correct", "right", "true", "so", "accurate")),
                          ["is", "that", "not", "so"], ["is", "not", "that", "so"], ["correct"], ["accurate"],
                          ["yes"], ["right"], ["do", "you", "agree"], ["would", "you", "agree"], ["agreed"], ["true"],
                          ["am", "i", "right"], ["am", "i", "correct"],
                          *([aux, this, "the", "case"] for aux in ("is", "was") for this in ("that", "this", "it")),
                          *([can, who, "confirm", "the", what] for can in ("can", "could") for who in ("we", "you")
                            for what in ("assertion", "claim", "statement")),
                          ["true", "or", "false"], ["can", "we", "confirm", "that"], ["can", "you", "confirm", "that"],
                          ["can", "anyone", "confirm", "that"], ["can", "we", "confirm"], ["can", "you", "confirm"],
                          *(["does", that, "hold", *up] for that in ("that", "this", "it") for up in ([], ["up"])),
                          *([aux, *n, it] for aux in ("does", "do", "did", "will", "would", "is", "was", "are",
                                                      "were", "can", "could") for n in ([], ["not"])
                            for it in ("it", "they", "you")))]
# asides of an examination, which ask nothing ('in your own words', 'if you know', 'for the sake of argument')
EXAMINATION_ASIDES = sorted({("in", "your", "own", "words"), ("if", "you", "know"), ("if", "you", "can"),
                             ("if", "you", "recall"), ("if", "you", "remember"), ("as", "best", "you", "can"),
                             *(("to", "the", "best", "of", "your", m) for m in ("knowledge", "recollection",
                                                                               "memory", "ability")),
                             ("as", "far", "as", "you", "know"), ("as", "far", "as", "you", "can", "tell"),
                             ("for", "the", "sake", "of", "argument"), ("for", "argument", "'", "s", "sake"),
                             *(("in", "your", *expert, view) for expert in ((), ("expert",), ("professional",),
                                                                           ("honest",), ("considered",))
                               for view in ("opinion", "view", "assessment", "judgement", "judgment",
                                            "estimation")),
                             *(("correct", "me", "if", *i, "wrong", *but) for i in (("i", "'", "m"), ("i", "am"))
                               for but in ((), (",", "but"), ("but",))),
                             # a formal speaker's ('what kind of vehicle, if one may so ask, is ...')
                             *(("if", who, may, *so, ask) for who in ("i", "one", "we") for may in ("may", "might")
                               for ask in ("ask", "enquire", "inquire", "confirm", "check", "clarify")
                               for so in ((), ("so",)))}, key=len, reverse=True)
# the court said for 'me' ('Tell the court whether ...', 'Explain to the jury how fast ...', 'Walk us through ...')
AUDIENCE = (["the", "court"], ["the", "jury"], ["the", "panel"], ["the", "tribunal"], ["the", "committee"], ["us"],
            ["me"])
EXAMINATION_ASKS = sorted({*((verb, *a) for verb in ("tell", "show") for a in AUDIENCE if a != ["me"]),
                           *(("walk", *a, "through") for a in AUDIENCE),
                           *((verb, to, *a) for verb in ("describe", "explain") for to in ("to", "for")
                             for a in AUDIENCE)}, key=len, reverse=True)
ATTENTION_TO = sorted({(verb, *whose, "attention", "to") for verb in ("directing", "direct", "turning", "turn",
                                                                    "drawing", "draw")
                       for whose in (["your"], ["the", "court", "'", "s"], ["the", "jury", "'", "s"])},
                      key=len, reverse=True)


# how a question of its own opens after a premise heard ('..., so what colour ...', '...; is it ...')
ASKED_AFTER = {"what", "which", "how", "at", "will", "is", "does", "do", "did", "was"}


def _asked_after(words: list[str], k: int) -> bool:
    """Whether a question of its own follows the clause at words[k:] ('..., so what colour is ...', '...; what kind of
    vehicle is it?'), not a confirmation ('...; can we confirm that?', '...; is that true , darling ?')."""
    if words[-3:-2] == [","] and words[-2] in ADDRESSED:
        words = words[:-3] + words[-1:]
    for j in range(k, len(words) - 1):
        opener = j + 1 + (words[j + 1] in ("so", "then"))
        if words[j] in (",", ";", ".", ":", "-") and words[opener:opener + 1] and words[opener] in ASKED_AFTER and \
                words[j:] not in CONFIRM_ENDS:
            return True
    return False


def examination_as_asked(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'i put it to you that the bus was parked . is that correct ?' -> 'is it true that the bus was parked ?';
    'explain to the jury how fast ...' -> 'tell me how fast ...'; 'directing your attention to the start , ...' ->
    'at the start , ...'; asides that ask nothing dropped with their commas ('what type of vehicle , if you know ,
    was ...'). With the words read so, or the words as they are and ()."""
    out, read, k = [], [], 0
    while k < len(words):
        aside = next((a for a in phrase_starts(EXAMINATION_ASIDES).get(words[k], ())
                      if tuple(words[k:k + len(a)]) == a), None)
        if aside:
            end = k + len(aside)
            between = out[-1:] == [","] and words[end:end + 1] == [","]
            read.append((" ".join(words[k - between:end + between]), "nothing, an aside"))
            out = out[:-1] if between else out
            k = end + between + (not out and words[end:end + 1] == [","])
            continue
        # (a lead with nothing after it is a tag: '...; would you say so?')
        confirm = max((c for c in phrase_starts(CONFIRMING).get(words[k], ()) if tuple(words[k:k + len(c)]) == c
                       and words[k + len(c):k + len(c) + 1] not in ([], ["so"], ["?"], ["."])), key=len, default=None) \
            or next((c for c in phrase_starts(CLAIM_LABELS).get(words[k], ()) if tuple(words[k:k + len(c)]) == c
                     and (k == 0 or words[k - 1] in SENTENCE_ENDS) and words[k + len(c):k + len(c) + 1]
                     and words[k + len(c)] not in QUESTION_OPENERS), None)
        asks = next((a for a in phrase_starts(EXAMINATION_ASKS).get(words[k], ()) if tuple(words[k:k + len(a)]) == a),
                    None)
        attention = next((a for a in phrase_starts(ATTENTION_TO).get(words[k], ())
                          if tuple(words[k:k + len(a)]) == a), None)
        if confirm in HEARSAY and _asked_after(words, k + len(confirm)):
            read.append((" ".join(confirm), "nothing, a premise"))
            k += len(confirm)
        elif confirm or asks:
            said = ["is", "it", "true", "that"] if confirm else ["tell", "me"]
            if confirm and out[-2:] == [",", "and"]:   # 'the clip stops early , and my forecast is that ...'
                out[-2:] = ["."]
            read.append((" ".join(confirm or asks), " ".join(said)))
            out += said
            k += len(confirm or asks)
        elif attention:
            at = words[k + len(attention) + 1:k + len(attention) + 2]
            said = ["at"] if at and at[0] in START_ADJECTIVES | START_WORDS | TIME_SAID else ["look", "at"]
            read.append((" ".join(attention), " ".join(said)))
            out += said
            k += len(attention)
        else:
            out.append(words[k])
            k += 1
    if read and any(c in ("is it true that", "nothing, an aside") for _, c in read):
        if out[-3:-2] == [","] and out[-2] in ADDRESSED and out[-1] == "?":   # '...; is that true , darling ?'
            read.append((out[-2], "nothing, whom it is asked"))
            out = out[:-3] + ["?"]
        end = next((e for e in CONFIRM_ENDS if out[-len(e):] == e), None)
        if end:
            read.append((" ".join(end), "?"))
            out = out[:-len(end)] + ["?"]
    # an explanation asked of how fast or which way is the grammar's 'tell me' ('explain how fast it was going')
    if out[:2] in (["explain", "how"], ["explain", "what"], ["explain", "which"]):
        read.append(("explain", "tell me"))
        out = ["tell", "me", *out[1:]]
    return (out, tuple(read)) if read else (words, ())


# A request put in a third person's or a report's words ('The authors should clarify how fast ...', 'Reviewer 3 would
# like to know how quickly ...', 'It is not evident from the footage whether ...', 'Action item: confirm how fast
# ...'): a preamble that names no vehicle and sets no condition, ending on a verb of asking or of what is unknown,
# then what is asked. Read as the grammar's 'tell me' (or 'is it true that' before 'that'); a clause said before it
# ('Given that the clip is cut short, ...') stays. A remark after it that says nothing ('; confirmation is
# requested.', 'The submission does not say.', '; could the authors comment?') is dropped.
REQUESTING = {"clarify", "clarified", "state", "stated", "specify", "specified", "report", "reported", "confirm",
              "confirmed", "indicate", "indicated", "explain", "explained", "establish", "established", "determine",
              "determined", "know", "advise", "predict", "enquire", "enquires", "inquire", "inquires", "ask", "asks",
              "seek", "seeks", "request", "requests", "requested", "speculate", "forecast", "evident", "clear",
              "obvious", "unclear", "sure", "certain", "tell", "verify", "verified", "document", "documented",
              # a question relayed ('A coworker asked me how quickly ...', 'Mum wondered which colour ...')
              "asked", "wondered", "wonders", "curious", "pestering",
              # ... and British indirectness ('One can't help wondering in which direction ...')
              "wondering"}
_REQUESTED = ("whether", "if", "how", "what", "which", "that", "the")
CONFIRMING_VERBS = {"confirm", "confirmed", "verify", "verified", "establish", "established"}
OBJECT_TAKING = CONFIRMING_VERBS | {"state", "report", "specify", "clarify", "indicate", "determine", "explain",
                                    "predict", "forecast", "document"}
_ASKED_FOR = (["confirmation"], ["clarification"], ["a", "statement", "of"], ["confirmation", "of"])
_ASKED_AS = (["as", "to"], ["on"], ["me", "about"], ["me"], ["about"], ["from", "the", "footage"],
             ["from", "the", "video"], ["from", "the", "clip"], ["in", "the", "footage"], ["in", "the", "video"])
# (nor a question of its own: 'what is the motion state of ...')
_NOT_PREAMBLE = {"if", "had", "suppose", "imagine", "when", "after", "before", "were", "?", ".", "!", ";", "what",
                 "which", "how", "where", "who", "why"}


def _requested_at(words: list[str], k: int) -> int | None:
    """Where what is asked begins after a verb of asking at words[k] ('clarify how', 'seeks confirmation that',
    'not evident from the footage whether'), or None."""
    j = k + 1
    for skip in (_ASKED_FOR, _ASKED_AS):
        j += next((len(s) for s in skip if words[j:j + len(s)] == s), 0)
    j += words[j:j + 1] == ["in"] and words[j + 1:j + 2] in (["what"], ["which"])   # 'to know in what direction
    # 'report the speed of', never 'ask the authors'; 'not evident whether', never 'dead certain the ...'
    asked = _REQUESTED[:5] + ("that",) * (j > k + 1 or words[k] in CONFIRMING_VERBS) + \
        ("the",) * (words[k] in OBJECT_TAKING)
    return j if words[j:j + 1] and words[j] in asked else None


# A hypothesis put to a test ('H0: the green motorbike is moving fast at the very beginning. Do the data support
# it?', 'Test the hypothesis that the blue SUV is static at the start: accept or reject?'): whether it holds, the
# grammar's 'is it true that'. Asked whether it is rejected, the answer is the other way round, and it stays unread.
HYPOTHESES = (["h0", ":"], ["h1", ":"], ["ha", ":"], ["null", "hypothesis", ":"], ["hypothesis", ":"],
              ["alternative", "hypothesis", ":"], ["test", "the", "hypothesis", "that"], ["our", "null", "says"],
              ["the", "null", "says"], ["hypothesis", "that"])
HOLDING = {"support", "supported", "supports", "true", "accept", "accepted", "retained", "retain", "hold", "holds",
           "confirmed", "correct", "consistent"}


def hypothesis_as_asked(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'h0 : the bus is parked at the start . do the data support it ?' -> 'is it true that the bus is parked at the
    start ?'. With the words read so, or the words as they are and ()."""
    label = next((h for h in HYPOTHESES if words[:len(h)] == h), None)
    if label is None:
        return words, ()
    end = next((k for k in range(len(label), len(words)) if words[k] in (".", ":", "?", ";")), len(words))
    claim, closing = words[len(label):end], words[end + 1:]
    rejected = "reject" in closing or "rejected" in closing
    either = any(closing[k:k + 3] in (["accept", "or", "reject"], ["reject", "or", "accept"])
                 for k in range(len(closing)))
    if not claim or closing and (not HOLDING & set(closing) or rejected and not either):
        return words, ()
    return ["is", "it", "true", "that", *claim, "?"], ((" ".join(label), "is it true that"),
                                                      *(((" ".join(words[end:]), "?"),) if closing else ()))


# An exercise's 'show that ..., or else show that it is not' (a lecturer's 'Prove or disprove that ...'): whether the
# claim holds, the grammar's 'is it true that'
PROOF_OPENERS = (["show", "that"], ["prove", "that"], ["prove", "or", "disprove", "that"],
                 ["show", "or", "disprove", "that"], ["demonstrate", "that"])
PROOF_CLOSERS = (["or", "else", "show", "that", "it", "is", "not"], ["or", "show", "that", "it", "is", "not"],
                 ["or", "else", "that", "it", "is", "not"], ["or", "disprove", "it"], ["or", "else", "disprove", "it"],
                 ["or", "refute", "it"], ["or", "otherwise"], ["or", "not"])


def proof_as_asked(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'show that the aeroplane is moving slowly when the video starts , or else show that it is not .' -> 'is it true
    that the aeroplane is moving slowly when the video starts ?': a claim to prove or disprove, at the start of a
    sentence. A claim to prove alone ('Show that it is slow.') presumes its answer and stays. With the words read
    so, or the words as they are and ()."""
    for k in range(len(words)):
        opener = next((o for o in PROOF_OPENERS if words[k:k + len(o)] == o), None)
        if opener is None or k and words[k - 1] not in (".", ";", ":"):
            continue
        both = opener[1:2] == ["or"]
        end = next((j for j in range(k, len(words)) if words[j] in (".", "?", ";", "!")), len(words))
        close = next((j for j in range(k, end) for c in PROOF_CLOSERS if words[j:j + len(c)] == c
                      and j + len(c) == end), None)
        if close is None and not both:
            return words, ()
        claim_end = (close if close is not None else end) - (words[(close or end) - 1] == ",")
        claim = words[k + len(opener):claim_end]
        if not claim:
            return words, ()
        read = ((" ".join(opener), "is it true that"),)
        if close is not None:
            read += ((" ".join(words[claim_end:end]), "nothing, the other side of the proof"),)
        return [*words[:k], "is", "it", "true", "that", *claim, "?", *words[end + 1:]], read
    return words, ()


def requested_as_asked(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'the authors should clarify how fast the red sedan is ...' -> 'tell me how fast the red sedan is ...';
    'reviewer 4 seeks confirmation that the scooter is ...' -> 'is it true that the scooter is ...'. With the words
    read so, or the words as they are and ()."""
    for k in range(min(len(words), 24)):
        if words[k] not in REQUESTING or not _requested_at(words, k) or \
                k and words[k - 1] in DETERMINERS | {"its", "their", "motion", "kinetic"}:   # 'the motion state of'
            continue
        first = max((j + 1 for j in range(k) if words[j] in (",", "-", ":")), default=0)
        # before it nothing, a label, or a clause that says the video stopped ('given that the clip is cut short ,')
        before = words[:first]
        opening = k > first or words[k] not in ("tell", "state", "know") and words[_requested_at(words, k)] != "the"
        if not NAMING & set(words[:k]) and not _NOT_PREAMBLE & set(words[first:k]) and k - first <= 10 and \
                (not _says_something(before) or FILM_WORDS & set(before)) and opening:
            break
    else:
        return words, ()
    j = _requested_at(words, k)
    # ('establish whether ...', 'confirm the bus was parked' ask whether it holds; 'confirm the colour of ...' and
    # 'confirm the motion state of ...' ask it)
    confirmed = words[j] == "that" or words[j] in ("the", "whether", "if") and words[k] in CONFIRMING_VERBS and \
        not (words[j] == "the" and words[j + 1:j + 2] and words[j + 1] in QUERY_NOUNS | STATE_NOUNS)
    said = ["is", "it", "true", "that"] if confirmed else ["tell", "me"]
    dropped = words[j] in ("that", "whether", "if") and confirmed
    out = words[:first] + said + words[j + dropped:]
    read = [(" ".join(words[first:j + dropped]), " ".join(said))]
    # the remark after it
    cut = max((m for m in range(len(out) - 1) if out[m] in (";", ".", "?", "-") or out[m] == "," and
               out[m + 1:m + 2] == ["and"]), default=None)   # '..., and i said i'd ask you .'
    tail = out[cut + 1:] if cut is not None else []
    if tail and len(tail) <= 10 and _says_nothing([w for w in tail if w not in ("?", ".", "no")]):   # 'no idea'
        read.append((" ".join(out[cut:]), "nothing, a remark"))
        out = out[:cut] + ["."]
    return out, tuple(read)


STATE_NOUNS = {"motion", "state", "status", "movement"}


# A wager around the question. A stake says nothing the question asks ('I've a tenner on yes.', 'Fiver says no.',
# '... and I'll pay out', 'Freeze-frame punt:', ', so it's an in-play bet:') and is dropped; a claim bet on ('I bet
# the sedan hits the bus. Does it?', 'Is it a lock that ...?', 'Fiver says the tandem is faster ..., do I collect?')
# is put to be confirmed, the grammar's 'is it true that'.
WAGER_WORDS = {"bet", "bets", "betting", "wager", "wagers", "wagered", "wagering", "stake", "stakes", "staked",
               "tenner", "fiver", "quid", "bucks", "odds", "punt", "bookie", "bookies", "bookmaker", "favourite",
               "favorite", "money", "pot", "kitty", "sweepstake", "payout", "cert", "collect", "settles",
               "backing", "tipping", "wins", "lock"}
_STAKES = (["a", "fiver"], ["a", "tenner"], ["fiver"], ["tenner"], ["my", "money"], ["money"], ["a", "quid"])
WAGER_CLAIMS = sorted({*((*i, bet, *you) for i in (["i"], ["i", "'", "d"], ["i", "'", "ll"], ["i", "would"], [])
                         for bet in ("bet", "wager") for you in ([], ["you"])),
                       *((*stake, "says") for stake in _STAKES),
                       *(("is", "it", "a", *lock) for lock in (["lock"], ["sure", "thing"], ["dead", "cert"],
                                                              ["safe", "bet"], ["done", "deal"])),
                       ("odds", "-", "on"), ("odds", "on")}, key=len, reverse=True)
BACKING = [[*i, backing] for i in (["i", "'", "m"], ["i", "am"], []) for backing in ("backing", "tipping")]
# a wager's stake said before its claim ('Wagering my lunch money that ...', 'I'm betting a fiver that ...')
WAGERING = {"wagering", "betting", "bet", "wager"}
# ... closed by the claim's own question ('. Does it?', ', do I collect?')
WAGER_ENDS = [[end, *q, "?"] for end in (".", ";", ",", "-")
              for q in (["do", "i", "collect"], ["do", "i", "win"], ["am", "i", "right"], ["yes", "or", "no"],
                        *([aux, *n, it] for aux in ("does", "do", "did", "will", "would", "is", "was", "are", "were")
                          for n in ([], ["not"]) for it in ("it", "they")))]


def _wagered(words: list[str]) -> bool:
    return bool(WAGER_WORDS & set(words)) or any(a == "pay" and b == "out" for a, b in zip(words, words[1:]))


def wagers_read(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'was it parked ? i have a tenner on yes .' -> 'was it parked ?'; 'i bet the sedan hits the bus . does it ?'
    -> 'is it true that the sedan hits the bus ?'. With the words read so, or the words as they are and ()."""
    if not _wagered(words):
        return words, ()
    out, read = list(words), []
    # the claim bet on, where it opens the question or a sentence of it
    asked = out.index("?") if "?" in out else len(out)
    for k in range(asked):
        if k and out[k - 1] not in SENTENCE_ENDS | {":", ",", ";"}:
            continue
        claim = next((c for c in WAGER_CLAIMS if tuple(out[k:k + len(c)]) == c), None)
        stake = None if claim or out[k:k + 1] == ["what"] else next(
            (j for j in range(k, min(k + 8, len(out))) if out[j] == "that" and WAGERING & set(out[k:j])
             and not NAMING & set(out[k:j])), None)
        backing = next((len(b) for b in BACKING if out[k:k + len(b)] == b), 0)
        to = next((j for j in range(k + backing + 1, min(k + backing + 7, len(out))) if out[j] == "to"
                   and NAMING & set(out[k + backing:j])), None) if backing else None
        if to is not None:   # 'i'm backing the dirt bike to crash into something' -> '... the dirtbike will crash'
            read.append((" ".join(out[k:to + 1]), "is it true that " + " ".join(out[k + backing:to]) + " will"))
            out[k:to + 1] = ["is", "it", "true", "that", *out[k + backing:to], "will"]
            claim = ("is", "it", "true", "that")
        elif claim or stake is not None:
            end = k + len(claim) if claim else stake + 1
            end += out[end:end + 1] == ["that"]
            read.append((" ".join(out[k:end]), "is it true that"))
            out[k:end] = ["is", "it", "true", "that"]
        if claim or stake is not None:
            close = next((e for e in WAGER_ENDS if out[-len(e):] == e), None)
            if close:
                read.append((" ".join(close), "?"))
                out = out[:-len(close)] + ["?"]
            elif out[-1:] in (["."], ["!"]):
                out[-1] = "?"
            break
    # the stakes: a part between commas, or a sentence, that names no vehicle, or any sentence after the question's
    # ('My stake's on a motorbike.': a guess at the answer)
    kept, start = [], 0
    parts = [k + 1 for k, w in enumerate(out) if w in SENTENCE_ENDS | {",", ":", ";"}
             or out[k + 1:k + 3] == ["and", "i"]]   # '... and i'll pay out'
    parts = sorted(set(parts))
    for end in parts + [len(out)] * (not parts or parts[-1] != len(out)):
        part = out[start:end]
        said = [w for w in part if w not in SENTENCE_ENDS | {",", ":", ";", "and", "but", "so"}]
        if _wagered(said) and not (NAMING & set(said) and "?" not in kept) and not {"true", "?"} & set(part):
            read.append((" ".join(part), "nothing, a wager"))
        else:
            kept += part
        start = end
    kept = kept[:-1] + ["?"] if kept[-1:] == [","] else kept
    return (kept, tuple(read)) if read and kept else (words, ())


# A ticket's or a form's fields around the question ('Steps: watch clip; Expected: partner identified; Question:
# ...'). What a ticket expects, its priority or status, and a step that only watches the video say nothing the
# question asks; the other fields' items (a step that sets a condition, a summary that says the clip ends early) are
# context, a sentence each. A field that asks for the answer ('prediction needed -') says nothing either.
TICKET_FIELDS = {"question", "q", "steps", "step", "repro", "summary", "issue", "description", "context", "title",
                 "request", "note", "notes", "ticket", "details", "scenario"}
TICKET_NOISE = {"expected", "actual", "priority", "severity", "status", "component", "assignee", "reporter",
                "environment", "version", "eta", "labels", "tags", "result", "outcome", "deliverable", "format"}
WATCHING = {"watch", "view", "play", "open", "replay", "load", "review", "rewatch"}
ANSWER_NEEDED = [[asked, needed, *end] for asked in ("prediction", "answer", "response", "confirmation", "input",
                                                     "clarification", "verdict", "ruling")
                 for needed in ("needed", "required", "requested", "wanted") for end in ([":"], ["-"], [","], [])]


def ticket_fields_read(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'steps : watch clip ; expected : partner identified ; question : what type ... ?' -> 'what type ... ?';
    'summary : clip ends early ; prediction needed - do ...' -> 'clip ends early . do ...'. With the fields read so,
    or the words as they are and ()."""
    out, read = list(words), []
    for k in range(len(out)):
        need = next((n for n in phrase_starts(ANSWER_NEEDED).get(out[k], ()) if tuple(out[k:k + len(n)]) == n), None)
        if need and (k == 0 or out[k - 1] in {";", ".", ",", ":"}):
            read.append((" ".join(need), "nothing, a ticket's field"))
            out = out[:k] + out[k + len(need):]
            break
    labels = [k for k in range(len(out) - 1) if out[k + 1] == ":" and out[k] in TICKET_FIELDS | TICKET_NOISE
              and (k == 0 or out[k - 1] in {";", ".", ",", "-", "|"})]
    if len(labels) < 2:
        return (out, tuple(read)) if read else (words, ())
    kept = out[:labels[0]]
    for k, end in zip(labels, labels[1:] + [len(out)]):
        field = out[k + 2:end]
        if out[k] in TICKET_NOISE or not field:
            read.append((" ".join(out[k:end]), "nothing, a ticket's field"))
            continue
        items, start = [], 0
        for m in [j + 1 for j, w in enumerate(field) if w in (";", "|")] + [len(field)]:
            item = [w for w in field[start:m] if w not in (";", "|")]
            start = m
            if item and item[0] in WATCHING and not NAMING & set(item):
                read.append((" ".join(item), "nothing, a ticket's step"))
            elif item:
                items.append(item + ["."] * (item[-1] not in SENTENCE_ENDS))
        kept += [w for item in items for w in item]
        read.append((" ".join(out[k:k + 2]), "nothing, a ticket's label"))
    # the question's own field last: its words as they are
    return (kept, tuple(read)) if kept and kept[-1] in SENTENCE_ENDS else (words, ())


def dislocated_as_asked(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'blue minivan and green chopper , they collide ?' -> 'do blue minivan and green chopper collide ?', and 'the
    sedan , it is fast ?' -> 'is the sedan fast ?': the vehicles said first, then asked about as 'they' or 'it' in
    a statement with a question mark. With the words read so, or the words as they are and ()."""
    # 'sedan and bus , at the start , sedan is more fast than bus ?': the vehicles said first as a topic (after a
    # clause of time: 'when they collide , the blue pickup and the bike , the pickup is ...'), then named again in
    # the question itself (a learner's topic and comment): the question, its shorter mentions named as the topic
    # names them
    lead = words.index(",") + 1 if words[:1] and words[0] in TIME_OPENERS and "," in words else 0
    topic = coordinated_subject(words[lead:]) if words[-1:] == ["?"] else None
    end = lead + topic[0] if topic else 0
    if topic and len(topic[1]) == 2 and words[end:end + 1] == [","] and \
            words[end + 1:end + 2] not in (["they"], ["it"]) and not SENTENCE_ENDS & set(words[end + 1:-1]):
        named = [(words[lead + i:lead + j], ref) for i, j, ref in mentions(words[lead:end])]
        out, k = words[:lead], end + 1
        for i, j, ref in mentions(words[end + 1:]):
            full = next((said for said, whole in named if generalises(ref, whole)), None)
            out += words[k:end + 1 + i] + (full or words[end + 1 + i:end + 1 + j])
            k = end + 1 + j
        again = [ref for _, _, ref in mentions(words[end + 1:])]
        if all(any(generalises(r, whole) for r in again) for _, whole in named):
            return out + words[k:], ((" ".join(words[lead:end + 1]), "nothing, the vehicles said first"),)
    subject = coordinated_subject(words) if words[-1:] == ["?"] else None
    if subject is None:
        return words, ()
    end, named = subject
    pronoun = ["they"] if len(named) == 2 else ["it"]
    one = end + (words[end:end + 1] == ["one"])   # 'the green one'
    if words[one:one + 1] in ([","], ["-"], [":"]) and words[one + 1:one + 2] != pronoun:
        return _topic_as_named(words, one, pronoun[0])
    if words[end:end + 2] != [","] + pronoun or not words[end + 2:end + 3]:
        return words, ()
    verb, rest = words[end + 2], words[end + 3:]
    # (a question word left in place keeps the statement's order: 'the blue biplane , it is moving which way ...')
    said = [*words[:end], verb, *rest] if {"which", "what", "how"} & set(rest[:4]) else \
        [verb, *words[:end], *rest] if verb in DISLOCATED_ASKS else \
        ["do" if len(named) == 2 else "does", *words[:end], verb, *rest]
    return said, ((" ".join(words[end:end + 3]), " ".join(said[:1])),)


SUBJECT_AFTER = {"when", "once", "as", "after", "before", "while", "until", "till", "since"}


def _topic_as_named(words: list[str], end: int, pronoun: str) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'the motorbike , once the clip cuts off , is it going to hit ...' -> 'once the clip cuts off , is the motorbike
    going to hit ...'; 'the bus and the car - at any point collide , do they ?' -> 'do the bus and the car at any
    point collide ?': a topic said first, then a question (after a clause of time, or a condition) that asks about
    it as 'it' or 'they'. With the words read so, or the words as they are and ()."""
    topic, rest = words[:end], words[end + 1:]
    read = ((" ".join(words[:end + 1]), "nothing, the vehicle said first"),)
    if len(rest) > 4 and rest[-4:] in ([",", a, pronoun, "?"] for a in AUXILIARIES | {"will", "would"}) and \
            pronoun not in rest[:-4] and not set(rest[:-4]) & (QUESTION_OPENERS | SENTENCE_ENDS):
        return [rest[-3], *topic, *rest[:-4], "?"], read
    # (the clause of time to its comma, or to the question's colon: 'the bus and the car , in the video : do they')
    sep = next((j for j, w in enumerate(rest) if w in (",", ":")), None)
    start = sep + 1 if rest[:1] and rest[0] in TIME_OPENERS | {"once", "after", "before", "over", "throughout"} and \
        sep is not None else 0
    own = {"it": "its", "they": "their"}[pronoun]
    # (the first 'it', or the subject of the clause of time: 'the purple one , as soon as it appears , how quick is
    # it ...'; not in an inverted clause's: 'when into the purple wagon it bumped')
    k = next((k for k in range(1, start) if rest[k] == pronoun and rest[k - 1] in SUBJECT_AFTER), None) or next(
        (k for k in range(start, len(rest)) if rest[k] in (pronoun, own)), None)
    if rest[start:start + 1] and rest[start] in QUESTION_OPENERS | {"suppose", "if", "imagine"} and k is not None \
            and rest[start:start + 3] != ["what", "-", "if"]:   # (a label: 'mountain bike , what-if : fast ...')
        # ('what was its speed the moment it ...' -> 'what was the red fighter 's speed ...')
        return [*rest[:k], *topic, *(["'", "s"] if rest[k] == own else []), *rest[k + 1:]], read
    return words, ()


# A speaker correcting a vehicle's name as they say it ('the red no the blue sedan', 'the gray jet no sorry the gray
# biplane', 'the bus I mean the truck'): the words after the correction stand for the ones before it.
CORRECTING = {"no", "wait", "sorry", "mean", "rather", "oops", "correction", "scratch", "actually"}
CORRECTION_WORDS = CORRECTING | {"i", "or", "that", ","} | FILLERS   # 'uh wait no', 'I mean', 'or rather'


def corrections_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'does the red no the blue sedan hit ...' -> 'does the blue sedan hit ...': a vehicle's name said, corrected
    ('no', 'sorry', 'I mean', 'uh', commas around them) and said again from its article. With the correction read
    so, or the words as they are and ()."""
    for k in range(1, len(words)):
        if words[k - 1] not in NAMING:
            continue
        j = k
        while words[j:j + 1] and words[j] in CORRECTION_WORDS:
            j += 1
        marker = [w for w in words[k:j] if w != ","]
        # a word that corrects, or a speaker's filler alone ('the blue uh the purple bus'); 'or' and 'that' only in
        # 'or rather' and 'scratch that' ('the red car or the blue bus' offers two)
        if not marker or not (CORRECTING.intersection(marker) or set(marker) <= FILLERS) or \
                "or" in marker and "rather" not in marker or "that" in marker and "scratch" not in marker:
            continue
        if not (words[j:j + 1] and words[j] in ("the", "a", "an", "that") and words[j + 1:j + 2]
                and words[j + 1] in NAMING):
            continue
        start = k - 1
        while start > 0 and words[start - 1] in NAMING:
            start -= 1
        start -= start > 0 and words[start - 1] in ("the", "a", "an", "that", "this")
        return words[:start] + words[j:], ((" ".join(words[start:j]), "nothing, a correction"),)
    return words, ()


MEANT = ([",", "i", "mean"], [",", "i", "meant"], [",", "or", "rather"], [",", "that", "is"])
SAID_OF_MOTION = MOTION_WORDS | MOTION_DESCRIPTIONS | {"really", "very", "pretty", "quite", "real", "is", "was"}


def restatements_read(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'is the suv moving fast , I mean going fast , at that moment ?' -> 'is the suv going fast at that moment ?': a
    motion said, then said again after 'I mean' between commas; the second is what is asked. With the first read as
    the second, or the words as they are and ()."""
    for k in range(1, len(words) - 3):
        meant = next((m for m in MEANT if words[k:k + len(m)] == m), None)
        if meant is None:
            continue
        b = k + len(meant)
        e = next((j for j in range(b, len(words)) if words[j] in (",", "?", ".")), len(words))
        again = words[b:e]
        if not again or not set(again) <= SAID_OF_MOTION or not MOTION_DESCRIPTIONS.intersection(again):
            continue
        # the verb said again ('I mean going fast') restates the verb too; a speed alone ('I mean fast') the speed
        kept = SAID_OF_MOTION - {"is", "was"} if MOTION_WORDS.intersection(again) else MOTION_DESCRIPTIONS
        a = k
        while a > 0 and words[a - 1] in kept:
            a -= 1
        if a == k:
            continue
        return [*words[:a], *again, *words[e + (words[e:e + 1] == [","]):]], (
            (" ".join(words[a:e]), " ".join(again)),)
    return words, ()


OWNERS = {"my", "our", "your", "yer", "ma", "me"}   # 'yer grey city bike', 'me little bus' as said in Ireland
TOYS = {"toy", "toys", "model", "little", "wee"}
# ... and fondness ('that sweet blue tandem bike', 'poor gray mountain bike', 'our trusty old pickup'; an estate
# agent's 'the charming cyan double-decker', a safari guide's 'a magnificent red double-decker')
FOND = {"sweet", "poor", "lovely", "old", "grand", "beautiful", "trusty", "beloved", "dear", "brave", "plucky",
        "faithful", "gorgeous", "cute", "darling", "precious", "adorable", "bonny", "pretty", "mighty", "gallant",
        "charming", "magnificent", "splendid", "majestic"}


def owners_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'is my purple road bike faster ...' -> 'is the purple road bike faster ...': a vehicle said as someone's
    ('my', 'our toy', 'your little') is the video's, named by its article; 'toy' after its name goes too. A size or
    a material before a vehicle's colour or kind goes as well ('the shiny blue bus', 'that tiny scooter'): the
    vehicles differ only by colour and kind, so it describes one and picks none out; but not two materials set
    against each other ('the metal bus ... the rubber car'), which pick by what none has. With the words read so, or
    the words as they are and ()."""
    decorative = TOYS | FOND | (LOOKS if len(MATERIALS.intersection(words)) < 2 else set())
    out, read, k = [], [], 0
    while k < len(words):
        j = k + (words[k] in OWNERS)
        while words[j:j + 1] and words[j] in decorative:
            j += 1
        # ('the red little jet': after the colour too, fondness, not CLEVR's size; 'Little grey biplane, were you
        # ...': a vehicle spoken to)
        if j > k and words[j:j + 1] and words[j] in NAMING and (words[k] in OWNERS or not out or out[-1] == "," or
                                                                out[-1] in DETERMINERS or out[-1] in COLOR_NAMES):
            said = ["the"] if words[k] in OWNERS else []
            read.append((" ".join(words[k:j]), " ".join(said) or "nothing"))
            out += said
            k = j
            while words[k:k + 1] and words[k] in NAMING:
                out.append(words[k])
                k += 1
            if words[k:k + 1] and words[k] in TOYS - {"little", "wee"}:
                read.append((words[k], "nothing"))
                k += 1
            continue
        out.append(words[k])
        k += 1
    return out, tuple(read)



# where a speaker's place is said ('hovering above my domain', 'across my lawn'): the videos show no place but the
# vehicles' ground, so it picks none out; a place that is the picture stays ('in my view', 'on my screen')
SPEAKER_PLACE_PREPOSITIONS = {"across", "above", "over", "beneath", "below", "under", "underneath", "through", "past",
                              "around", "round", "about", "along", "in", "on", "by", "near", "outside", "throughout"}
PICTURE_PLACES = {"view", "sight", "frame", "frames", "shot", "video", "clip", "picture", "screen", "footage"}


def speaker_asides_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """What the speaker says of themselves inside or after the question, which asks nothing: their place ('is the
    blue suv heading across my domain' -> 'is the blue suv heading'), a closing likeness to how anyone would act
    ('..., as any sensible cat would ?') and a closing disclaimer ('..., not that it truly concerns me ?'). With the
    words read so, or the words as they are and ()."""
    out, read, k = [], [], 0
    while k < len(words):
        if words[k] in SPEAKER_PLACE_PREPOSITIONS and words[k + 1:k + 2] in (["my"], ["our"]) and \
                words[k + 2:k + 3] != [] and words[k + 2].isalpha() and \
                words[k + 2] not in OBJECT_WORDS | PICTURE_PLACES | GENERIC_NOUNS:
            read.append((" ".join(words[k:k + 3]), "nothing, the speaker's place"))
            k += 3
            continue
        out.append(words[k])
        k += 1
    close = next((k for k in range(len(out) - 3, 0, -1) if out[k] == ","), None)
    tail = out[close + 1:-1] if close and out[-1] in ("?", ".", "!") else []
    likeness = tail[:1] == ["as"] and tail[1:2] and tail[1] in ("any", "every", "a", "an", "the") and \
        len(tail) <= 6 and tail[-1] in ("would", "does", "did", "do", "should", "might", "could", "will")
    disclaimer = tail[:2] == ["not", "that"] and len(tail) <= 10 and SPEAKER_AND_LISTENER & set(tail) and \
        not mentions(tail)
    if likeness or disclaimer:
        read.append((" ".join(out[close:-1]), "nothing, the speaker's aside"))
        out[close:-1] = []
    return out, tuple(read)

# A vehicle spoken to ('Blue bus, did you bump into the green car?', 'Hey, red sedan, were you moving ...'): 'you'
# is the vehicle named before the comma, as 'it' ('Blue bus, did it ...', which the parser reads)
AS_IT = {("are", "you"): ("is", "it"), ("were", "you"): ("was", "it"), ("you", "are"): ("it", "is"),
         ("you", "were"): ("it", "was"), ("you", "'", "re"): ("it", "is"), ("you", "'", "ve"): ("it", "has"),
         ("you", "have"): ("it", "has"), ("you", "'", "d", "have"): ("it", "would", "have"),
         ("you", "'", "d"): ("it", "had"), ("you",): ("it",), ("your",): ("its",), ("yourself",): ("itself",),
         ("you", "'", "ll"): ("it", "will")}


def addressed_as_named(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'blue bus , did you bump into the green car ?' -> 'blue bus , did it bump into the green car ?': a vehicle
    named first and spoken to, before a comma, is the 'you' of the question. With the words read so, or the words as
    they are and ()."""
    k = next((n for n in range(min(len(words), 4)) if words[n] not in INTERJECTIONS | {",", "hey", "oi", "yo", "o"}),
             len(words))
    j = k
    while words[j:j + 1] and words[j] in NAMING:
        j += 1
    if j == k or words[j:j + 1] != [","] or not {"you", "your"} & set(words[j:]) or {"i", "me", "we"} & set(words):
        return words, ()
    # (where 'it' is another vehicle, 'you' is said by the name: 'when you hit the grey car, were you slower than
    # it was?')
    named = ["the", *words[k:j]] if {"it", "its"} & set(words[j:]) else None
    out, n = words[:j], j
    while n < len(words):
        said = next((a for a in sorted(AS_IT, key=len, reverse=True) if tuple(words[n:n + len(a)]) == a), None)
        if said and named:
            said = said[:2] if said[:1] in (("are",), ("were",)) else said[:1]   # 'were you' -> 'was the bus'
            out += {"are": ["is"], "were": ["was"]}.get(said[0], []) + (named if "you" in said else [*named, "'", "s"])
        else:
            out += AS_IT[said] if said else [words[n]]
        n += len(said) if said else 1
    return out, ((" ".join(words[j + 1:]), " ".join(out[j + 1:])),)


# Radio brevity's imperatives before a vehicle said without its article ('Say speed of the blue bus at contact ...',
# 'Report purple cruiser's speed class ...', 'Verify green dirt bike running fast at first frame, over.')
RADIO_ASKS = {"say": ["tell", "me"], "report": ["tell", "me"], "verify": ["is", "it", "true", "that"],
              "confirm": ["is", "it", "true", "that"]}
OVER = ([",", "over", "."], [",", "over"], ["over", "."], [",", "over", "and", "out", "."])   # a radio's sign-off


def radio_as_asked(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'say speed of the blue bus ...' -> 'tell me the speed of the blue bus ...'; 'verify green dirtbike running fast
    ...' -> 'is it true that the green dirtbike running fast ...'. With the words read so, or the words as they are
    and ()."""
    said = RADIO_ASKS.get(words[0]) if words else None
    if said is None or not words[1:2] or words[1] in DETERMINERS | QUESTION_OPENERS | {"whether", "if", "me", ":"}:
        return words, ()
    # a vehicle or what is asked of it follows ('say again', 'verify the claim' are no such request)
    if words[1] not in NAMING and (said[0] == "is" or words[1] not in QUERY_NOUNS | {"heading"}):
        return words, ()
    out = [*said, "the", *words[1:]]
    end = next((e for e in OVER if out[-len(e):] == e), None)
    out = out[:-len(end)] + ["."] if end else out
    return out, ((" ".join(words[:2]), " ".join([*said, "the", words[1]])),)


# A label the question is put under ('Q1:', 'Question 3:', 'Quick question:'), and an aside in brackets that only
# says again what the object is ('the red sedan (the car)'): they ask nothing ('quick' read as a speed, and each
# bracket is an unknown word).
LABEL_WORDS = {"q", "question", "quick", "simple", "short", "small", "one", "another", "next", "last", "final",
               "first", "second", "third", "follow", "up", "-", "#", "no", "number", "a", "my", "here", "s", "'",
               "is", "the", "an", "easy", "hard", "tough", "tricky", "bonus", "query", "check", "hypothetical",
               "from", "newbie", "noob", "novice", "beginner", "rookie", "newcomer",   # 'Quick one from a newbie:'
               "sneaky", "toughie", "stumper", "doozy", "teaser"}   # (a quiz host's 'Here's a sneaky one!')
# ('Here's an easy one:': 'easy' is slow; 'Hi, quick check - is ...': a greeting before it, 'quick' is fast)
ASIDE_WORDS = {"the", "a", "an", "that", "this", "one", "vehicle", "thing", "object"} | NOUNS_SAID


# ... after a greeting, or naming which clip it is about ('Hi team, re clip 3: at the moment ...')
CLIP_NAMED = {",", "re", "regarding", "concerning", "about", "on", "for", "video", "clip"} | {
    str(n) for n in range(100)}


def _label(word: str) -> bool:
    return word in LABEL_WORDS or re.fullmatch(r"q?\d+[a-z]?", word) is not None


def _decimal(words: list[str], k: int) -> bool:
    """Whether words[k] is the point of a number ('3 . 2 s')."""
    return words[k] == "." and 0 < k < len(words) - 1 and words[k - 1].isdigit() and words[k + 1][:1].isdigit()


QUICK_LABELS = {"one", "check", "question", "q", "note", "thing", "query"}


def _purpose(heading: list[str], rest: list[str]) -> bool:
    """Whether a heading before a colon only says who asks or what for, the question after it whole: it names no
    vehicle and no time, and a collision or a condition it speaks of the question says itself ('For my
    accident-reconstruction class: at the instant the pickup and the wagon collide, ...')."""
    return bool(heading) and "?" in rest and bool(OBJECT_WORDS.intersection(rest)) and \
        not set(heading) & (OBJECT_WORDS | HEADING_KEPT | START_WORDS | FILM_WORDS | FLOATING_WORDS - {"up"}) and \
        (not asks_impact(heading) or asks_impact(rest)) and \
        (not (CONDITION_OPENERS | IMAGINING | IMAGINED_SAID | CONDITION_LABELS).intersection(heading)
         or bool(CONDITION_WORDS.intersection(rest)))


# A prompt's wrapping around the question, as people paste it to an assistant ('Act as a mechanic: ...', 'Yes or no
# only: ...', 'Q: ... ? A (yes/no):'): a role, and a heading of instructions that asks nothing
PROMPT_WORDS = {"yes", "or", "no", "only", "answer", "respond", "reply", "with", "one", "word", "a", "an", "the",
                "single", "step", "by", "-", "reasoning", "is", "welcome", "fine", "but", "end", "think", "query",
                "question", "q", "task", "and", "/", "(", ")", "vehicle", "type", "colour", "expect",
                "color", "output", "format", "please", "briefly", "just", "your", "final", "instruction", "prompt",
                "following", "true", "false", "in", "words", "short", "answers", "aloud", "first", "then"}
ROLE_ENDS = {"and", ":", ",", "."}
# a sentence after the question that says how to answer, and the answers it may offer
ANSWER_VERBS = {"answer", "respond", "reply", "choose", "select", "pick", "output", "give", "return", "write",
                "options", "choices", "state", "say"}
OFFERED_WORDS = ANSWER_VERBS | {":", ",", ".", ";", "!", "letter", "letters", "correct", "right", "best", "option",
                                "choice", "from", "of", "following", "below", "these", "nothing", "else", "lowercase",
                                "static", "slow", "fast", "left", "right", "up", "down", "forward", "backward",
                                "forwards", "backwards", "front", "back", "none", "above", "exactly", "word",
                                "only", "must", "be", "put", "brackets", "box", "at"} | set(COLOR_NAMES) | OBJECT_WORDS
POST_LABELS = (["thread"], ["psa"], ["hot", "take"], ["genuine", "question"], ["honest", "question"],
               ["serious", "question"], ["asking", "for", "a", "friend"], ["update"], ["edit"])


EMOJI_WORDS = {"emoji", "emojis", "emoticon", "emoticons"}
FIGURE_WORDS = {"fig", "figs", "figure", "figures", "table", "eq", "supplementary"}


def prompt_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'act as a physics expert and tell me how fast ...' -> 'tell me how fast ...'; 'yes or no only : is it ...' ->
    'is it ...'; '... ? a ( yes / no ) :' -> '... ?'. With the wrapping read as nothing, or the words as they are
    and ()."""
    out, read = list(words), []
    # a placeholder where a model's prompt puts the video ('<video>', '[video]')
    while (held := next((k for k in range(len(out) - 2) if (out[k], out[k + 2]) in (("<", ">"), ("[", "]"))
                         and out[k + 1] in FILM_WORDS | {"image", "frames"}), None)) is not None:
        read.append((" ".join(out[held:held + 3]), "nothing, the video's place"))
        out = out[:held] + out[held + 3:]
    # a post's emoji said in words, anywhere ('(airplane emoji)', '(bus emoji x2)', '(thinking face)'), and a paper's
    # figure ('(Fig. 1a)', '(see Table 2)')
    while (held := next((k for k in range(len(out)) if out[k] == "(" and ")" in out[k + 2:k + 7] and (
            EMOJI_WORDS & set(out[k + 1:out.index(")", k)]) or out[out.index(")", k) - 1] == "face"
            or out[k + 1] in FIGURE_WORDS or out[k + 1:k + 3] in (["see", f] for f in FIGURE_WORDS))),
                        None)) is not None:
        close = out.index(")", held)
        read.append((" ".join(out[held:close + 1]), "nothing, an emoji" if out[held + 1] not in FIGURE_WORDS | {"see"}
                     else "nothing, a figure"))
        out = out[:held] + out[close + 1:]
    # a post's labels said first ('thread', '1/', '(9/74)', 'PSA', 'hot take:', 'genuine question:', 'asking for a
    # friend')
    while label := next((p for p in POST_LABELS if out[:len(p)] == p), None) or \
            (out[:2] if out[:1] and out[0].isdigit() and out[1:2] == ["/"] else None) or \
            (out[:5] if out[:1] == ["("] and out[2:3] == ["/"] and out[4:5] == [")"] and out[1].isdigit()
             and out[3].isdigit() else None):
        read.append((" ".join(label), "nothing, a label"))
        out = out[len(label) + (out[len(label):len(label) + 1] == [":"]):]
    if out[:2] == ["act", "as"]:
        end = next((k for k in range(2, min(len(out), 10)) if out[k] in ROLE_ENDS), None)
        if end is not None and not OBJECT_WORDS.intersection(out[:end]):
            read.append((" ".join(out[:end + 1]), "nothing, a role"))
            out = out[end + 1:]
    # a reasoning step asked first ('First describe the motion of each vehicle, then answer: ...')
    then = next((k for k in range(2, min(len(out) - 3, 24)) if out[k - 1:k + 2] in ([",", "then", "answer"],
                                                                                 ["then", "answer", ":"])), None)
    if out[:1] == ["first"] and then is not None and "?" not in out[:then]:
        end = then + 2 + (out[then + 2:then + 3] == [":"])
        read.append((" ".join(out[:end]), "nothing, an instruction"))
        out = out[end:]
    colon = out.index(":") if ":" in out[:12] else None
    if colon and set(out[:colon]) <= PROMPT_WORDS and out[colon + 1:]:
        read.append((" ".join(out[:colon + 1]), "nothing, an instruction"))
        out = out[colon + 1:]
    asked = max((k for k, w in enumerate(out) if w == "?"), default=None)
    if asked is not None and out[asked + 1:] and out[asked + 1] == "a" and set(out[asked + 1:]) <= PROMPT_WORDS | {
            ":"}:
        read.append((" ".join(out[asked + 1:]), "nothing, an answer's place"))
        out = out[:asked + 1]
    # how to answer, said after the question ('... ? Respond with yes or no only.', 'Choose from: static, slow,
    # fast. Answer:', 'Please output only the letter of the correct option.')
    tail = out[asked + 1:] if asked is not None else []
    told = tail[1:] if tail[:1] == ["please"] else tail
    if told and (told[0] in ANSWER_VERBS or told[:2] == ["final", "answer"] or told[:3] == ["put", "your", "final"]) \
            and set(tail) <= PROMPT_WORDS | OFFERED_WORDS:
        read.append((" ".join(tail), "nothing, how to answer"))
        out = out[:asked + 1]
    return (out, tuple(read)) if read else (words, ())


def attribute_kept(dropped: list[str], question: list[str]) -> list[str]:
    """The question after words dropped before it, which asks which vehicle in the attribute they named ('give the
    colour only : which vehicle is moving slowly ...' -> 'what colour is the vehicle that is moving slowly ...')."""
    asked = next((w for w in dropped if w in ("color", "type", "kind", "sort", "shape")), None)
    if asked is None or question[:2] not in (["which", "vehicle"], ["which", "one"]):
        return question
    return (["what", "color", "is", "the", "vehicle", "that"] if asked == "color" else
            ["what", "type", "of", "vehicle"]) + question[2:]


def _headline(heading: list[str], question: list[str]) -> bool:
    """Whether a heading before a colon is a headline over a question that names its own vehicles ('bus horror :
    how fast was the green motorbike ...'): a few words with no article, not a vehicle's name alone ('red car : is
    it ...' points at it), nothing imagined or said of a time, no collision the question does not speak of ('for my
    accident class :'), and the question's first vehicle named before its first pronoun."""
    runs = mentions(question)
    pronoun = next((k for k, w in enumerate(question) if w in ("it", "its", "they", "them", "their")), len(question))
    said = DETERMINERS | CONDITION_OPENERS | IMAGINING_LABELS | IMAGINING | HEADING_KEPT | START_WORDS | FILM_WORDS
    return 0 < len(heading) <= 4 and not set(heading) <= OBJECT_WORDS and not set(heading) & said \
        and question[:1] != [] and question[0] in QUESTION_OPENERS | {"in", "at", "which", "if", "when"} and \
        bool(runs) and runs[0][0] < pronoun and (asks_impact(question) or not asks_impact(heading))


# A vehicle said only to set the asked one apart or to set the scene ('Ignoring the parked green bus, was the red
# sedan ...?', 'Not the yellow one - the blue scooter: did it ...?', 'Of the two cars, the red one: ...', 'While the
# bus sat there, ...', '... - not the road bike, the mountain bike?', 'The red jet has nothing to do with it.')
DISTRACTOR_LEADS = (("ignoring",), ("leaving",), ("setting",), ("putting",), ("forget",), ("forgetting",),
                    ("never", "mind"), ("not", "counting"), ("apart", "from"), ("aside", "from"), ("besides",),
                    ("except", "for"), ("excluding",), ("disregarding",), ("while",), ("not",), ("of", "the"))


def distractors_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """The question without the vehicles it names only to set the asked one apart (`DISTRACTOR_LEADS`): a clause
    said first that names a vehicle and asks nothing, where the rest names one; a clause with a collision, a start,
    an end or a condition in it is no such clause ('while they collide', not 'as for the bus,', a topic). With the
    words read so, or the words as they are and ()."""
    out, read = list(words), []
    lead = next((d for d in DISTRACTOR_LEADS if tuple(out[:len(d)]) == d), None)
    end = next((k for k in range(len(lead or ()), len(out)) if out[k] in (",", "-", ":", ";")), None)
    if lead and end:
        clause, rest = out[:end], out[end + 1:]
        timed = asks_impact(clause) or set(clause) & (START_WORDS | END_WORDS | COMES_IN_WORDS | IMAGINED_SAID
                                                      | {"when", "if", "had", "would"})
        named = mentions(rest)
        if mentions(clause) and (named or lead not in (("not",), ("of", "the"))) and not timed and (
                lead != ("not",) or named[0][0] <= 2) and (
                lead != ("of", "the") or clause[2:3] and clause[2] in NUMBERS | {"both", "several"}):
            read.append((" ".join(out[:end + 1]), "nothing, a vehicle set apart"))
            out = rest
            if lead == ("of", "the"):   # 'of the two green vehicles, the motorbike': its colour and kind said there
                i, j, _ = named[0]
                colours = [] if set(rest[i:j]) & set(COLOR_NAMES) else [w for w in clause if w in COLOR_NAMES]
                kinds = [w[:-1] for w in clause if w.endswith("s") and w[:-1] in OBJECT_WORDS]
                kind = kinds[:1] if rest[j - 1] == "one" and kinds else rest[j - 1:j]
                out = [*rest[:j - 1], *colours, *kind, *rest[j:]]
    if "?" in out and (k := next((k for k in range(len(out) - 3) if out[k:k + 2] in ([",", "not"], ["-", "not"])
                                  and out[k + 2] in ("the", *OBJECT_WORDS) and out.index("?") > k), None)) is not None \
            and mentions(out[k + 2:out.index("?")]) and len(mentions(out[:k])) >= 1:
        read.append((" ".join(out[k:out.index("?")]), "nothing, a vehicle set apart"))
        out = out[:k] + out[out.index("?"):]
    spans = _sentence_spans(out)
    kept = [out[a:b] for a, b in spans if not (out[a:b][-1:] == ["."] and "nothing" in out[a:b] and
                                               "do" in out[a:b] and mentions(out[a:b]))]
    if len(kept) < len(spans):
        read.append(("... has nothing to do with it .", "nothing, a vehicle set apart"))
        out = [w for s in kept for w in s]
    return (out, tuple(read)) if read else (words, ())


RAMBLE_FILLERS = {"like", "i", "mean", "anyway", "okay", "ok", "so", "honestly", "um", "uh", ",", "well", "then"}


def ramble_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """A long ramble before the question, ended by ', but' ('I kind of love how detailed these toys are, ..., and the
    red wagon is cute too, but I mean was the purple chopper going fast ...?'): the question is what follows the last
    ', but'; the ramble, where it says no collision and no time, is its context, a sentence of its own, from which
    its shorter mentions and its 'it' are read.
    With the words read so, or the words as they are and ()."""
    if words[-1:] != ["?"]:
        return words, ()
    k = next((k for k in range(len(words) - 2, 7, -1) if words[k - 1:k + 1] == [",", "but"]), None)
    # (only a ramble that says no collision and no time: 'It looked like the bike was standing still when it
    # collided with the bus, but was it really?' is a claim doubted)
    if k is None or k < 12 or asks_impact(words[:k]) or set(words[:k]) & (START_WORDS | END_WORDS | COMES_IN_WORDS):
        return words, ()
    j = k + 1
    while j < len(words) and words[j] in RAMBLE_FILLERS:
        j += 1
    rest = words[j:]
    if not rest[:1] or rest[0] not in QUESTION_OPENERS | YES_NO_OPENERS | TIME_OPENERS | {
            "if", "suppose", "had", "what", "when", "after", "once", "which", "who", "the", "does", "did"} or \
            "?" in rest[:-1]:
        return words, ()
    return [*words[:k - 1], ".", *rest], ((" ".join(words[k - 1:j]), "."),)


def hooks_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """A promo's teaser asked before the question ('Will sparks fly?! Do the red sedan and the bus crash ...?', 'Who's
    got the edge? In the opening seconds, ...?'): a first short question that names no vehicle, no time and no
    collision, before a question that names one, asks nothing itself. With the words read so, or the words as they
    are and ()."""
    read = []
    # ... and a call to answer after it ('Name it to claim it!', 'Spill it!', 'Only true fans know!', 'Say yes or no
    # and the prize is yours!')
    last = len(words) - 1 - words[::-1].index("?") if "?" in words else None
    if last is not None and words[-1:] == ["!"] and 0 < len(words) - last - 1 <= 12 and \
            not set(words[last + 1:]) & (NAMING | START_WORDS | END_WORDS) and not asks_impact(words[last + 1:]):
        read.append((" ".join(words[last + 1:]), "nothing, a call to answer"))
        words = words[:last + 1]
    # ... and one asked after it, of who leads ('... faster than the brown cruiser? Who's got the edge?')
    if last is not None and words[-1:] == ["?"] and "?" in words[:last] and not read:
        end = len(words) - 1 - words[-2::-1].index("?") - 1
        tail = words[end + 1:]
        if tail[:1] == ["who"] and len(tail) <= 8 and not set(tail) & (NAMING | START_WORDS | END_WORDS | {"it"}) \
                and not asks_impact(tail) and mentions(words[:end]):
            read.append((" ".join(tail), "nothing, a teaser"))
            words = words[:end + 1]
    # (a motion or a collision it may say: 'Speed demon spotted! What kind of vehicle is zooming ...?')
    end = next((k for k, w in enumerate(words) if w in ("?", "!")), None)
    if end is None or not 0 < end <= 6 or "?" not in words[end + 1:] or not mentions(words[end + 1:]) or \
            set(words[:end]) & (NAMING | GENERIC_NOUNS | START_WORDS | END_WORDS | FILM_WORDS
                                | {"it", "they", "then", "that"}) \
            or asks_impact(words[:end]) and not asks_impact(words[end + 1:]):
        return (words, tuple(read)) if read else (words, ())
    while words[end + 1:end + 2] in (["!"], ["?"]):
        end += 1
    return words[end + 1:], (*read, (" ".join(words[:end + 1]), "nothing, a teaser"))


def grumble_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'blasted scooters and choppers - are the yellow scooter and the red chopper going to crash ...' -> 'are the
    yellow scooter and the red chopper going to crash ...': a remark before a dash on vehicles or people at large
    (plural, or a vehicle's word before its driver's: 'bus drivers'), naming no colour, time or condition. With the
    remark read as nothing, or the words as they are and ()."""
    k = next((k for k in range(2, len(words) - 1) if words[k] == "-" and words[k + 1] in AFTER_DASH), None)
    if k is None:
        return words, ()
    head = words[:k]
    if not _at_large(head) or set(head) & (START_WORDS | END_WORDS | FILM_WORDS | CONDITION_OPENERS | IMAGINING
                                           | {"?", "if", "had"}):
        return words, ()
    return words[k + 1:], ((" ".join(words[:k + 1]), "nothing, a remark"),)


# A meditation teacher's instructions to the listener ('breathe softly and notice :', 'Breathing in , breathing out ,',
# 'relax your jaw and notice the bus ...', 'allow your attention to settle :'): they ask nothing of the video
SOOTHING = {"breathe", "breathing", "relax", "relaxing", "allow", "settle", "soften", "let"}
ATTENDING_VERBS = {"notice", "observe", "watch", "look", "see", "consider", "focus"}


def _soothing(clause: list[str]) -> bool:
    """Whether a clause is an instruction to the listener's body or breath that names no vehicle, time, motion,
    property or collision ('let your breath be easy and simply observe'; not 'let the bus go faster')."""
    return bool(clause) and clause[0] in SOOTHING and (clause[0] != "let" or clause[1:2] == ["your"]) and \
        not asks_impact(clause) and not set(clause) & (
            OBJECT_WORDS | set(COLOR_NAMES) | START_WORDS | END_WORDS | FILM_WORDS | FUTURE_CUES | QUERY_NOUNS
            | SPEED_CLASS_WORDS | MOTION_WORDS | CONDITION_OPENERS | GENERIC | GENERIC_NOUNS | NOUNS_SAID
            | DETERMINERS | {"?", "if", "had", "ahead", "past", "future", "it", "they", "them", "one"})


def soothing_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'as the truck hits the van , breathe softly and notice : is the truck ...?' -> 'as the truck hits the van , is
    the truck ...?': each clause that only soothes the listener, with the mark after it; and the first half of one
    joined by 'and' to a look at a vehicle ('relax your jaw and notice the bus ...' -> 'notice the bus ...'). With
    the clauses read as nothing, or the words as they are and ()."""
    out, read, k = [], [], 0
    while k < len(words):
        end = next((j for j in range(k, len(words)) if words[j] in CLAUSE_MARKS - {"!"}), len(words))
        clause = words[k:end]
        joined = next((j for j in range(k + 2, end) if words[j] == "and" and _soothing(words[k:j])), None)
        if words[end:end + 1] != ["?"] and _soothing(clause):
            read.append((" ".join(words[k:end + 1]), "nothing, a soothing word"))
            k = end + 1
            continue
        if joined is not None and words[joined + 1:joined + 2] and words[joined + 1] in ATTENDING_VERBS:
            read.append((" ".join(words[k:joined + 1]), "nothing, a soothing word"))
            k = joined + 1
            continue
        out += words[k:end + 1]
        k = end + 1
    if not read or not QUESTION_OPENERS.intersection(out):
        return words, ()
    return out, tuple(read)


def _then_said(words: list[str]) -> bool:
    """Whether words point back at a time said before ('then', 'at that moment', 'in this instant', 'at that
    crash')."""
    return "then" in words or any(a in ("that", "this") and b in ("moment", "instant", "point", "time", "crash",
                                                                  "collision", "impact", "event")
                                  for a, b in zip(words, words[1:]))


def asides_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """The question without its label, the remarks before it and its asides ('q1 : there are many vehicles here .
    how fast is this red sedan ( the car ) ...' -> 'how fast is the red sedan ...'). A remark is a first sentence,
    or a heading before a colon ('cycling coach here :'), that names no vehicle, motion or collision and imagines
    nothing; a heading that says a time stays. With the words read as nothing, or the words as they are and ()."""
    read = []
    while True:
        end = next((k for k, w in enumerate(words) if w in (".", "!", ":") and not _decimal(words, k)), None)
        heading = [w for j, w in enumerate(words[:end or 0]) if not (w == "quick" and words[j + 1:j + 2] and
                                                                     words[j + 1] in QUICK_LABELS)]   # 'quick one'
        if end is not None and words[end] == ":" and words[1:3] == ["'", "s"] and \
                words[3:4] in (["question"], ["questions"], ["query"], ["note"], ["corner"]):
            # someone's label, whatever it says ("Coach's question for film session:"; 'coach' is read as a bus)
            read.append((" ".join(words[:end + 1]), "nothing, a remark"))
            words = words[end + 1:]
            continue
        if end is not None and "or" in heading and _offers_speed(heading):
            break   # the answers offered first ('Static, slow or fast: which describes the bike when ...?')
        if end is not None and " what - if " in f" {' '.join(heading)} " and not (
                {"if", "suppose", "imagine", "had", "were"} & set(words[end + 1:])):
            break   # the label of a condition said after it ('What-if for you: bicycle stopped dead from the start.')
        if end is not None and _purpose(words[:end], words[end + 1:]) and words[end] == ":":
            pass   # 'For my accident-reconstruction class:', 'Teacher here, setting up a what-if for my class:'
        elif end is not None and words[end] == ":" and _headline(heading, words[end + 1:]):
            pass   # 'BUS HORROR: how fast was the green motorbike ... when it hit the blue double-decker?'
        elif end is None or end + 1 == len(words) or set(heading) & (
                OBJECT_WORDS | GENERIC_NOUNS | CONDITION_OPENERS | IMAGINING_LABELS | IMAGINING
                | MOTION_WORDS | MOTION_DESCRIPTIONS | FLOATING_WORDS | STATIC_SAID) or asks_impact(heading) or \
                _video_end(words[:end + 1]):
            break   # one that says what is asked stays, and one that says the video stopped ('video stops here .')
        # and so does a heading that says when or how to answer ('at the start :', 'true or false :'), and a first
        # sentence that says when the question's 'then' is ('Think about the last moment of the clip. ... then?', 'The
        # video starts. ... at that moment?')
        # (and the property asked before a colon: 'Which colour: the thing that is accelerating at the start?')
        if words[end] == ":" and set(words[:end]) & (HEADING_KEPT | START_WORDS | FILM_WORDS) or \
                words[end] == ":" and words[:1] in (["which"], ["what"]) and end <= 4 and \
                set(words[1:end]) & {"colour", "color", "type", "kind", "model", "vehicle"} or \
                words[end] == "." and _then_said(words[end + 1:]) and \
                set(words[:end]) & (HEADING_KEPT | START_WORDS) - {"true", "false", "yes", "no"}:
            break
        read.append((" ".join(words[:end + 1]), "nothing, a remark"))
        words = attribute_kept(words[:end], words[end + 1:])
    if any(a == "this" and b in OBJECT_WORDS for a, b in zip(words, words[1:])):   # 'is this green bus ...'
        read.append(("this", "the"))
        words = ["the" if w == "this" and b in OBJECT_WORDS else w for w, b in zip(words, words[1:] + [""])]
    # ('Quick one, is ...': the label's comma, where 'quick' would be read as a speed)
    end = next((k for k, w in enumerate(words[:9]) if w in (":", ".", "-", "!") or
                w == "," and k == 2 and words[0] == "quick" and words[1] in QUICK_LABELS), None)
    if end and all(_label(w) or w in INTERJECTIONS | VOCATIVES | CLIP_NAMED for w in words[:end]) and \
            any(map(_label, words[:end])) and words[end + 1:end + 2] and \
            words[end + 1] in QUESTION_OPENERS | TIME_OPENERS | CONDITION_WORDS:   # 'Q2: at the start, is ...'
        read.append((" ".join(words[:end + 1]), "nothing, a label"))
        words = words[end + 1:]
    out, k = [], 0
    while k < len(words):
        close = next((j for j in range(k + 1, min(k + 10, len(words))) if words[j] == ")"), None) \
            if words[k] == "(" and out and out[-1] in OBJECT_WORDS else None
        # ... or the vehicle named again in other words ('the blue suv ( the big car on the left )')
        if close and close > k + 1 and (ASIDE_WORDS.issuperset(words[k + 1:close]) or words[k + 1] in DETERMINERS
                                        and RENAMING.issuperset(words[k + 1:close]) and _coloured_before(out, len(out))
                                        and set(words[k + 1:close]) & set(COLOR_NAMES) <= set(out[-4:])):
            read.append((" ".join(words[k:close + 1]), "nothing, an aside"))
            k = close + 1
            continue
        # ... or a note that what it says is imagined, where a label or 'would' says so too ('Scenario: the red
        # object is stationary when the video begins (counterfactual). Would it have ...?')
        if words[k] == "(" and words[k + 2:k + 3] == [")"] and words[k + 1] in IMAGINING_LABELS | CONDITION_LABELS \
                and (CONDITION_LABELS & set(out[:3]) or "would" in words[k + 3:]):
            read.append((" ".join(words[k:k + 3]), "nothing, said again"))
            k += 3
            continue
        # ... or the start said again ('at the outset ( frame 0 )')
        close = words.index(")", k) if words[k] == "(" and ")" in words[k:k + 5] else None
        if close and words[k + 1:close] in (*TIME_ZERO, ["the", "start"], ["at", "the", "start"]) and \
                START_WORDS & set(out):
            read.append((" ".join(words[k:close + 1]), "nothing, the start said again"))
            k = close + 1
            continue
        out.append(words[k])
        k += 1
    # a clause or appositive between commas after a vehicle already named by colour and type ('the red sedan , which
    # later hits the bus ,', a critic's 'the red scooter , that scarlet flourish against a drab palette ,'; not 'that
    # is', nor a moment or a motion: ', that moment purple motorbike go fast ,'): it says more about a vehicle it does
    # not pick out
    k = 0
    while k < len(out):
        close = next((j for j in range(k + 2, min(k + 12, len(out))) if out[j] == ","), None) \
            if out[k] == "," and out[k + 1:k + 2] and (out[k + 1] in ASIDE_STARTS or out[k + 1] == "that" and out[
                k + 2:k + 3] not in (["is"], ["was"], ["'"]) and not (SPEED_CLASS_WORDS | MOTION_WORDS | MOMENTS)
                & set((out[k + 2:] + [","])[:(out[k + 2:] + [","]).index(",")])) and _coloured_before(out, k) \
            else None
        # not where only the asking follows it ('..., the fighter it is going slow, yes or no?': the question itself)
        # (nor where speeds are offered after it: '..., the velocity of the suv is static, slow or fast?')
        rest = set(out[close + 1:]) if close else set()
        # (nor a clause where the vehicle itself collides: 'the thing it crashes into', 'with anything it collides',
        # a translator's 'the brown station wagon , with red scooter bumping moment , is slowly moving one ?')
        own_impact = asks_impact(out[k:close]) and ({"it", "they"} & set(out[k:close]) or not RELATIVES & set(
            out[k:close])) if close else False
        # (nor a time said with a postposition, as a translator leaves it: ', the start at ,', ', the video end at ,')
        timed = bool(out[close - 1] in ("at", "in", "on", "during") and (START_WORDS | END_WORDS | {"middle"}) &
                     set(out[k:close])) if close else False
        # (nor the question itself, its answers offered after it: ', which way is the gray minivan going : front ,',
        # ', which way is the purple bus travelling - forward ,', ', in which direction is it going : front ,')
        opens = k + 1 + (out[k + 1:k + 2] in (["in"], ["at"], ["to"]))
        asked = "?" in out[k:close] or ":" in out[k:close] or out[opens] in ("which", "what", "how") and \
            out[opens + 1:opens + 2] != [] and out[opens + 1] in QUERY_NOUNS | {"way", "fast"} if close else False
        # (nor the statement a tag asks about: '..., the blue truck is not moving , is it ?')
        tag = out[close + 1:] if close else []
        tagged = 3 <= len(tag) <= 4 and tag[0] in AUXILIARIES and tag[-1] == "?" and \
            set(tag[1:-1]) <= {"not", "it", "they"}
        if close and not asked and rest - ASKING_ONLY and not ("or" in rest and rest <= SPEED_OFFERED) \
                and not own_impact and not timed and not tagged:
            read.append((" ".join(out[k:close + 1]), "nothing, an aside"))
            out[k:close + 1] = []
            continue
        k += 1
    # what a floating vehicle does, said again ('floating up in the air , not touching the floor ,'), or a 'not' said
    # again to stress it ('did not move at all , not one bit ,')
    for k in reversed(range(1, len(out) - 2)):
        gloss = next((g for g in (*GROUND_GLOSSES, *STRESSED_NOTS) if out[k:k + len(g)] == list(g) and (
            out[k - 1] == "," and out[k + len(g):k + len(g) + 1] in ([","], ["?"], ["."])
            or out[k - 1] == "(" and out[k + len(g):k + len(g) + 1] == [")"])), None)
        if gloss and (FLOATING_WORDS & set(out[:k]) if gloss in GROUND_GLOSSES else "not" in out[:k - 1]):
            read.append((out[k - 1] + " " + " ".join(gloss), "nothing, said again"))
            out[k - 1:k + len(gloss) + (out[k - 1] == "(")] = []
    # the ground a floating vehicle is not on, said as the other choice ('floating rather than sitting on the ground',
    # a flier's 'rather than sat on the deck')
    for k in reversed(range(1, len(out) - 3)):
        other = next((o for o in (["rather", "than"], ["instead", "of"]) if out[k:k + 2] == o), None)
        j = k + 2 + (out[k + 2:k + 3] != [] and out[k + 2] in RESTING)
        fall = other and out[k + 2:k + 3] in ([w] for w in ("falling", "dropping", "descending", "sinking", "fall",
                                                              "drop", "descend", "sink"))
        if other and (out[j:j + 2] == ["on", "the"] and out[j + 2:j + 3] in (["ground"], ["floor"], ["deck"])
                      or fall) and FLOATING_WORDS & set(out[:k]):
            end = k + 3 if fall else j + 3 + (out[k - 1] == "," and out[j + 3:j + 4] == [","])
            read.append((" ".join(out[k:end]), "nothing, said again"))
            out[k - (out[k - 1] == ","):end] = []
    # a condition's consequence closed by 'then' ('Would the bike crash into the dirt bike then?'); not the 'then' of
    # a moment, read from the context (`context_as_question`)
    if out[-2:] == ["then", "?"] and {"would", "if", "had", "suppose", "imagine", "were"} & set(out):
        read.append(("then", "nothing"))
        out[-2:-1] = []
    return out, tuple(read)


RELATIVES = {"which", "that", "who", "whom", "whose", "where"}   # a clause that describes ('..., which later hits ...')
GROUND_GLOSSES = tuple((*n, t, s) for n in (("not", "touching"), ("not", "on")) for t in ("the", "any")
                       for s in ("floor", "ground")) + (("off", "the", "ground"), ("off", "the", "floor"))
STRESSED_NOTS = (("not", "one", "bit"), ("not", "a", "bit"), ("not", "even", "a", "little"), ("not", "an", "inch"),
                 ("not", "at", "all"), ("not", "even", "a", "bit"))


RENAMING = ASIDE_WORDS | OBJECT_WORDS | set(COLOR_NAMES) | {"gray", "grey"} | {
    w for name in EVERYDAY_NAMES for w in name.split()} | {"big", "small", "little", "large", "long", "on", "in", "at",
                                                          "near", "by", "left", "right", "front", "back", "top",
                                                          "bottom", "side", "two", "seater", "-", "one", "far",
                                                          "middle", "centre", "center", "of", "picture", "frame"}
MOMENTS = {"moment", "instant", "time", "point", "second", "frame", "very", "same"}
ASIDE_STARTS = {"which", "who", "the", "a", "an", "by", "currently", "also", "incidentally", "with"}
ASKING_ONLY = {"yes", "or", "no", "true", "false", "right", "correct", "?", ".", "!"}
SPEED_OFFERED = ASKING_ONLY | {",", *(w for choice in SPEED_CHOICES for w in choice)}


def _coloured_before(words: list[str], k: int) -> bool:
    """Whether the words before k end with a vehicle named by its colour and type ('the red sedan')."""
    j = k
    while j and words[j - 1] in OBJECT_WORDS and words[j - 1] not in COLOR_NAMES:
        j -= 1
    return j < k and j > 0 and words[j - 1] in COLOR_NAMES


# A preamble that frames the question and asks nothing ('Thinking about the whole clip, do ...', 'Not sure about this
# one, but is ...'): the question is what follows it ('thinking' would be WordNet's 'imagine', a counterfactual's).
FRAMING = {"thinking", "looking", "watching", "considering", "judging", "going", "seeing", "observing", "viewing",
           "based"}
TIME_SAID = {"moment", "instant", "when", "while", "during"}   # a preamble saying when stays
# ... and one saying the video's end or after it, where the question does not ('Looking ahead past the end of the
# footage, does the bus collide with something?' was read within the video; a stop said there is read from the words
# as said: 'Going forward from where the video stops short, does ...')
AFTER_SAID = {"end", "ends", "ending", "after", "past", "beyond", "ahead", "later", "afterwards", "future", "next"}
POLITE = {"trouble", "mind", "possible", "bother"}


def framing_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """The question after a framing preamble that names no object (its 'it' would lose what it stands for): a
    participle's phrase, of one or more commas ('looking at the video ,'), a hedge ('if you had to guess ,'), or any
    phrase before ', but' ('not sure about this one , but'), where a question follows it and the preamble sets no
    condition and no time ('thinking only about the moment they collide ,' says when). With the preamble read as
    nothing, or the words as they are and ()."""
    # 'from the footage , at what speed ...': where the question looks, which is the video (the start was read)
    j = 1 + (words[1:2] in (["the"], ["this"]))
    if words[:1] == ["from"] and words[j:j + 2] and words[j] in FILM_WORDS and words[j + 1] == ",":
        return words[j + 2:], ((" ".join(words[:j + 2]), "nothing, a preamble"),)
    k = next((k for k, w in enumerate(words) if w == "," and words[k + 1 + (words[k + 1:k + 2] == ["but"]):][:1]
              and words[k + 1 + (words[k + 1:k + 2] == ["but"])] in QUESTION_OPENERS), None)
    if k is None:
        return words, ()
    main = words[k + 1 + (words[k + 1:k + 2] == ["but"]):]
    # 'if you had to guess', 'if it is not too much trouble': no counterfactual's condition
    hedge = words[:2] in (["if", "you"], ["if", "i"]) or words[:1] == ["if"] and bool(POLITE.intersection(words[:k]))
    framed = (words[0] in FRAMING or hedge or words[k + 1:k + 2] == ["but"]) and \
        not OBJECT_WORDS.intersection(words[:k])
    if not framed or (CONDITION_WORDS.intersection(words[:k]) and not hedge) or asks_impact(words[:k]) or \
            TIME_SAID.intersection(words[:k]) or \
            AFTER_SAID.intersection(words[:k]) and not FUTURE_CUES.intersection(main):
        return words, ()
    # the video's stop said of the preamble's video ('based on the video , which is stopped before the end , is ...')
    stop = main.index(",") if main[:1] == ["which"] and words[k - 1] in FILM_WORDS and "," in main else None
    if stop and STOP_CUES.intersection(main[:stop]) and main[stop + 1:]:
        said, ended = video_end_as_said(["the", words[k - 1], *main[1:stop], ".", *main[stop + 1:]])
        return said, ((" ".join(words[:k + 2]), f"the {words[k - 1]}"), *ended)
    return main, ((" ".join(words[:k]), "nothing, a preamble"),)


# A preamble before a colon or a dash (or a comma, before the question's opener) that says nothing the question needs:
# an office's ('Looping in the wider group -', 'Per the brief from leadership,', 'FYI, need a yes/no for the deck:'),
# or a reason given in jest ('Because obviously a school bus has nowhere to be:', 'As if gravity were optional:'),
# where the question names its own vehicles.
REASONS = (["because"], ["cause"], ["cos"], ["since"], ["as", "if"], ["given", "how"])
TAGGING = {"right", "yeah", "innit", "eh"}
PLACE_OPENERS = {"at", "in", "on", "during", "upon", "by", "from", "over", "throughout", "near", "around"}


# A forecaster's look past the video before a question about the future ('Plotting the trajectories forward beyond
# the recording , will ...', 'Looking ahead , beyond what we've seen together , will ...', 'Casting an eye past the
# line : will ...'): the question's 'will' already asks after the video, and the look's words ('paths') ask nothing
LOOKING_AHEAD = {"projecting", "project", "plotting", "plot", "extrapolating", "extrapolate", "forecasting", "looking",
                 "look", "peering", "peer", "gazing", "gaze", "casting", "cast", "peeking", "peek", "beyond", "past",
                 "thinking", "think", "running"}
AHEAD = {"beyond", "past", "ahead", "forward", "forwards", "onward", "onwards", "future", "after", "later", "on"}


def forecast_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'projecting the paths forward past the end of the recording , will the bus hit the car ?' -> 'will the bus
    hit the car ?'. With the look ahead read as nothing, or the words as they are and ()."""
    if not words or words[0] not in LOOKING_AHEAD:
        return words, ()
    k = next((k for k in range(2, min(len(words) - 2, 20)) if words[k] in (",", ":", ";", "-")
              and (words[k + 1] in ("will", "shall") or words[k + 1] in ("is", "are")
                   and ["going", "to"] in (words[j:j + 2] for j in range(k + 2, len(words) - 1)))), None)
    if k is None or not AHEAD.intersection(words[:k]) or "?" in words[:k] or \
            (OBJECT_WORDS | set(COLOR_NAMES) | GENERIC | GENERIC_NOUNS).intersection(words[:k]):
        return words, ()
    return words[k + 1:], ((" ".join(words[:k + 1]), "nothing, a look past the video"),)


def word_given_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """A spelling bee's word given before the question, however said and spelt ('your word is ' slowly ' , s - l - o
    - w - l - y : would you say ...' -> 'would you say ...'; its 'word is' is no hearsay). With the word given read as
    nothing, or the words as they are and ()."""
    if words[:3] not in (["your", "word", "is"], ["the", "word", "is"]):
        return words, ()
    k = next((k for k in range(4, min(len(words) - 1, 30)) if words[k] == ":"), None)
    if k is None or not mentions(words[k + 1:]):
        return words, ()
    return words[k + 1:], ((" ".join(words[:k + 1]), "nothing, a word given"),)


def _remarked(pre: list[str], mark: str, after: list[str]) -> bool:
    """Whether words before a dash are a remark of the speaker's, whatever its manner (a beekeeper's 'Gently , gently
    —', 'Steady with the smoker now —', a poet's 'A leaf meets a branch —'): short, naming no vehicle, time, speeding
    up or collision (unless the question asks one of its own), and offering no choice; and before the question itself
    (not a hyphen's 'post - haste , do ...')."""
    return mark == "-" and len(pre) <= 8 and after[:1] != [] and after[0] in QUESTION_OPENERS | CONDITION_OPENERS \
        | TIME_OPENERS | {"which", "what", "how", "when"} and not (asks_impact(pre) and not asks_impact(after)) \
        and not _offers_speed(pre) and not set(pre) & (
        OBJECT_WORDS | set(COLOR_NAMES) | FILM_WORDS | START_WORDS | TIME_SAID | GENERIC | GENERIC_NOUNS
        | QUESTION_OPENERS
        | {"or", "?", "not", "never", "if", "had", "after", "before", "then", "later", "future", "something",
           "anything", "thing", "one"}) and not any(w.startswith(("accelerat", "speed", "float", "hover")) for w in pre)


START_SAID = START_WORDS | START_ADJECTIVES | FILM_WORDS | {"as", "the", "very", "right", "early", "frames", "moments",
                                                           "opens", "open", "first", "when"}


def preamble_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'per the brief from leadership , what colour is ...' -> 'what colour is ...'. With the preamble read as
    nothing, or the words as they are and ()."""
    # (a reason's tag closes it: 'because slowing down solves everything , right ? if ...')
    k = next((k for k in range(1, min(len(words) - 1, 16)) if words[k] in (":", "-", ";") or words[k] == "," and (
        words[k + 1] in QUESTION_OPENERS | {"which"} or words[k + 1:k + 3] in (["please", v] for v in REQUESTING)) or
        words[k] == "?" and words[k - 1] in TAGGING),
             None)
    if k is None:
        return words, ()
    pre, main = words[:k], words[k + 1:]
    named = mentions(main) and (not {"it", "they"} & set(main) or not NAMING & set(pre))
    reason = any(pre[:len(r)] == r for r in REASONS) and named and not {"had", "?"} & set(pre)
    pre = pre[2 + (pre[2:3] == [","]):] if pre[:2] == ["going", "forward"] else pre   # an office's 'going forward'
    # ('need a yes / no for the deck :', 'per the brief from leadership ,'; not 'in the final frame ,'; and the start
    # a heading says where the question says it too: a forecaster's 'checking the barometer as the clip opens : what
    # kind of vehicle is the one moving fast right at the start ?')
    started = main[:1] != [] and main[0] not in ("and", "then") and bool(START_WORDS.intersection(main))
    filmed = bool(FILM_WORDS.intersection(main))   # ('per our review of the footage , ... during the video')
    said = [w for w in pre if w not in ("yes", "no", "/", "from", "in", "at", "on", "to", "of", "per")
            and not (started and w in START_SAID) and not (filmed and w in FILM_WORDS)
            and not (w in COLOR_NAMES and w in main)]   # a listing's 'rich brown tones :' of the brown sedan
    # (a clause of time, its word perhaps misspelt: 'at the very beginnng ,')
    quiet = words[k] != "?" and pre[0] not in TIME_OPENERS | PLACE_OPENERS and not _says_something(said) and not (
        STOP_CUES | FUTURE_CUES | CONDITION_LABELS | {"?", ".", "top", "bottom", "post"}) & set(said) or \
        set(pre) <= TAGGING or _remarked(pre, words[k], words[k + 1:])
    # (or a question of who leads, put first, after its time if any: a physio's 'in the opening frames , who's got
    # the better stride : is the road bike faster ...')
    who = next((w for w in range(len(pre)) if pre[w] == "who" and (w == 0 or pre[w - 1] == ",")), None)
    if who is not None and main[:1] and main[0] in QUESTION_OPENERS | {"what", "which"} and mentions(main) and \
            words[k] in (":", "-"):
        return words[:who] + main, ((" ".join(words[who:k + 1]), "nothing, a preamble"),)
    if not (reason or quiet) or not main or not (main[0] in QUESTION_OPENERS | {"which", "tell", "if", "when"}
                                                 or named):
        return words, ()
    return attribute_kept(pre, main), ((" ".join(words[:k + 1]), "nothing, a preamble"),)


# the words a digression (`digressions_dropped`) never says
SAYING = (NAMING | GENERIC | GENERIC_NOUNS | MOTION_WORDS | MOTION_DESCRIPTIONS | SPEED_CLASS_WORDS | FLOATING_WORDS
          | STATIC_SAID | REST_WORDS | START_WORDS | END_SAID | FILM_WORDS | CONDITION_OPENERS | CONDITION_WORDS
          | IMAGINING | IMAGINED_SAID | TIME_SAID | NEGATIONS | DIRECTION_WORDS | ASKING | set(COLOR_NAMES)
          | OTHER_COLOURS | PLURALS | QUERY_NOUNS | COMPARING | {"would", "could", "had", "were", "should", "shall"}
          | COMES_IN_WORDS | {"appearance", "arrival"}   # 'as soon as its appearance occurs'
          | {"at", "once", "upon", "how", "why", "where", "who", "whom", "whose", "then", "first", "after", "before",
             "until", "later", "end", "ends", "way", "each", "other", "both", "either", "anything", "something",
             "nothing", "same", "instead", "rather", "only", "just", "moment", "instant", "frame", "second", "seconds",
             "time", "point", "engine", "ground", "air", "sky", "future", "next", "last", "will", "gonna", "going",
             "frames", "from", "past", "beyond", "freeze", "afterwards", "afterward", "hereafter", "eventually",
             "through", "scale", "state", "tell", "give", "name", "describe", "identify", "determine", "report",
             "find", "list", "twice", "thrice", "again", "repeatedly"}
          | {w for t in LATER_TIMES for w in t} | START_ADJECTIVES | DURATIONS | NUMBERS
          | {"partway", "halfway", "midway", "middle", "stop", "stopped", "halted", "paused", "frozen", "froze",
             "freezes", "cut", "cuts", "terminates", "terminated", "truncated"}
          # coming into view ('as it comes into view , is ...', 'on entering the scene , ...')
          | COMES_IN_WORDS | {"coming", "entering", "entered", "appearing", "appeared", "emerging", "emerges"})


# who a speaker's remark is about: the speaker, the listener or a third person (a ventriloquist's 'Don't listen to
# him, he's all sawdust -'); the video's vehicles are never 'me' or 'you', and a 'he' before the question's own
# vehicles is someone else's (`she_as_it` reads the West Country's 'he' of a vehicle, after this)
PERSONS = SPEAKER_AND_LISTENER | {"he", "him", "his", "himself", "folks", "who", "whose"}
REMARK_TIMES = {"would", "when", "while", "once", "moment", "instant", "then", "later", "after", "before", "beyond",
                "future", "world", "scene", "frame", "frames", "paused", "stopped", "stops"}


def person_remark_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'do not listen to him , he is all sawdust - is the bus moving slowly when it bumps into the green chopper ?'
    -> 'is the bus moving ...': a remark about people (or told to the listener: 'do not ...', 'never mind ...')
    before a whole question, closed by a dash or a sentence's end. Whole: it names its own vehicles. A remark that
    names a vehicle, a collision, a time or the video, or imagines, is the question's context and stays ('I saw the
    gray airliner on the right. Was the airliner ...?', 'Looking beyond the final frame, ask yourself: ...'). With the
    remark read as nothing, or the words as they are and ()."""
    for k in range(1, min(len(words) - 2, 26)):
        main, pre = words[k + 1:], words[:k]
        told = pre[:2] in (["do", "not"], ["never", "mind"])
        if words[k] not in ("-", "!", "?", ".", ";", ":") or main[0] not in QUESTION_OPENERS | CONDITION_OPENERS \
                | TIME_OPENERS | {"when", "would"} or not (PERSONS & set(pre) or told):
            continue
        clauses = {w for j, w in enumerate(pre) if j == 0 or pre[j - 1] in (",", "-", "?", "!", ".", ";", ":")}
        if not mentions(main) or mentions(pre) or asks_impact(pre) \
                or set(pre) & (START_WORDS | END_WORDS | FILM_WORDS | TIME_SAID | CONDITION_OPENERS - {"had"}
                               | IMAGINING | IMAGINED_SAID | REMARK_TIMES) or clauses & {"had", "were", "as", "at"}:
            return words, ()
        return main, ((" ".join(words[:k + 1]), "nothing, a remark about people"),)
    return words, ()


# A clause of the speaker's own, about the speaker ('I want to know', 'so I label it right', 'for we must not forget
# the humble sedan', 'I keep mixing them up lol'), or of no one's: a simile ('..., like my old Evinrude', 'the way
# my line tangled'), a purpose ('..., for the finding aid'), anything said after the question ('? Lord, reminds me of
# Earl.'): read only where the parser would refuse the question for a word it does not know, and only the clauses
# that hold such a word and say nothing of a vehicle, a colour, a time, a motion, a collision or a person
# (`speaker_clauses_dropped`)
SPEAKER = {"i", "we", "my", "our", "me", "us"}
CLAUSE_LINKS = {"and", "but", "so", "for", "then", "now", "okay", "ok", "well", "oh", "because", "cause", "cos", "yet",
                "though", "although", "which", "that", "since"}
SIMILE_OPENERS = (["like"], ["just", "like"], ["the", "way"], ["sure", "as"], ["as", "though"], ["as", "if"],
                  ["with", "all", "the"],   # a narrator's ('..., with all the serene composure of a lady?')
                  # ... and a blessing closing it ('..., may they both find peace?', '..., God keep them both?')
                  *(["may", who] for who in ("they", "it", "he", "she", "both", "the")), ["god"], ["bless"],
                  ["rest", "in", "peace"], ["heaven"], ["lord"])
CLAUSE_BREAK = re.compile(r"((?:[,;:.!?…]+|\s[-—–]+)\s+)")
LETTER = re.compile(r"(?:my\s+)?(?:dear|dearest|darling|sweetheart)\b[^,;:.!?]{0,20},", re.I)   # 'Dear heart,'


# A question written as verse, its line breaks written ' / ' ('A cyan car, one fine day, / Hit the brown one, oh,
# what a fray! / At the instant they met, / ...'): four lines or more of three words or more, each break after a mark
# or before a capital (so that 'yes / no', 'front / back / left' and 'Item: SUV / When: start' stay as written)
VERSE_BREAK = re.compile(r"(?<=[,;:.!?…])\s+/\s+|\s+/\s+(?=[A-Z\"'(])")
VERSE_CLAUSE_BREAK = re.compile(r"((?:[,;:.!?…]+\s+/|\s/)\s+|(?:[,;:.!?…]+|\s[-—–]+)\s+)")


def in_verse(text: str) -> bool:
    lines = re.split(r"\s+/\s+", text)
    return len(lines) >= 4 and len(VERSE_BREAK.findall(text)) == len(lines) - 1 and "=" not in text and \
        all(len(line.split()) >= 3 for line in lines)


def verse_joined(text: str) -> str:
    """A question in verse as one run of prose: its line breaks as spaces (each line's own mark kept)."""
    return VERSE_BREAK.sub(" ", text) if in_verse(text) else text


VERSION = re.compile(r"\b(?:v|ver\.? ?|version ?|build ?)?\d+(?:\.\d+){2,3}\b|\bv\d+(?:\.\d+)*\b", re.IGNORECASE)


def _filler(words: list[str], unknown: set[str]) -> bool:
    """Whether a clause holds a word of `unknown` and says nothing of the domain."""
    return bool(set(words) & unknown) and not mentions(words) and not _says_something(words) and not set(words) & (
        set(COLOR_NAMES) | OTHER_COLOURS | PEOPLE | OBJECT_WORDS | UNREMARKED | {"?"})


# what opens an aside between commas ('as some in the village fear', 'so eager and so impatient', 'with all the
# sobriety one hopes for', 'an event which must surely be the talk of the county'), and what it may not say
ASIDE_OPENERS = {"as", "to", "with", "so", "an", "which", "by", "in", "much", "being"}
# the words that say a moment, which an aside or a riddle before the question may not say
MOMENTS = {"moment", "moments", "instant", "time", "frame", "frames", "last", "first", "second", "seconds", "minute",
           "minutes", "point", "now", "later", "earlier"}
ASIDE_KEEPS = NEGATIONS | CONDITION_OPENERS | IMAGINING | IMAGINED_SAID | DURATIONS | MOMENTS | {
    "then", "there", "when", "while", "until"}


def _news(words: list[str], unknown: set[str], kept: set[str] = frozenset()) -> bool:
    """Whether a letter's clause before its question holds a word of `unknown` and names no vehicle, colour, film or
    collision (nor a word of `kept`): its family's news ('I've finally finished that enormous jigsaw', 'the vicar's
    wife made a trifle that nobody could finish'), whose 'it', 'that' and 'finish' are not the question's."""
    return bool(set(words) & unknown) and not mentions(words) and not asks_impact(words) and not set(words) & (
        set(COLOR_NAMES) | OTHER_COLOURS | OBJECT_WORDS | FILM_WORDS | UNREMARKED - {"it", "that", "this"} | {"?"}
        | kept)


# what the speaker's own clause may not say to be read as its news ('I'm just sitting in the garden', 'I've got to
# run to a meeting in a sec': 'just', 'run' and 'sec' are the speaker's, not a vehicle's), where it names nothing
SPEAKER_KEEPS = (UNREMARKED | START_WORDS | START_ADJECTIVES | END_WORDS | END_SAID | COMES_IN_WORDS | SIGHT_WORDS
                 | CONDITION_OPENERS | CONDITION_WORDS | IMAGINING | IMAGINED_SAID | NEGATIONS | STATIC_SAID
                 | REST_WORDS | SPEED_CLASS_WORDS | FLOATING_WORDS | PEOPLE | {"when", "as", "moment", "instant"})


def speaker_clauses_dropped(text: str, unknown: set[str]) -> tuple[str, str] | None:
    """'Something runs into the gray minivan , and I want to know : what kind of vehicle is it ?' -> 'Something runs
    into the gray minivan , what kind of vehicle is it ?': the text without the clauses of the speaker's own (or a
    simile, a purpose, what follows the question) that hold a word of `unknown`, and those clauses; None where none
    is. In verse a clause is also a line, and any clause may be the rhyme's filler ('oh, what a fray!', 'with some
    pluck?'), whoever it opens on."""
    verse = in_verse(text)
    parts = (VERSE_CLAUSE_BREAK if verse else CLAUSE_BREAK).split(text)
    clauses, marks = parts[::2], [m.replace("/", "").rstrip() + " " for m in parts[1::2]] + [""]
    # (where the question is a request, its sentence's stop: 'Kindly indicate whether ... . Kindly sign and date.')
    asked = max((k for k, m in enumerate(marks) if "?" in m), default=None)
    if asked is None:
        asked = next((k for k, m in enumerate(marks) if "." in m and mentions(tokenize(" ".join(clauses[:k + 1])))),
                     len(clauses))
    # (a heading before the question's colon or dash: a bug report's 'Regression since 2.0.5 --'; in a letter, its
    # news before the question's sentence: 'Dear one, the plums are ripe and I've made jam; suppose ...?')
    heading = next((k for k, m in enumerate(marks[:asked]) if ":" in m or m.strip()[:1] in ("-", "—", "–")), -1)
    # (and anyone's news before it that names nothing and says no time or state: 'Tom once tried skydiving and
    # screamed the whole way down; anyway, which colour ...?')
    told = max([-1] + [k for k, m in enumerate(marks[:asked]) if re.search(r"[.;!:]", m)])
    letter = bool(LETTER.match(text))
    if letter:
        heading = max(heading, told)
    dropped = []
    for k, clause in enumerate(clauses):
        words = tokenize(VERSION.sub(" version ", clause))   # ('on 1.8.0', 'v3.8': no time)
        opening = next((w for w in words if w not in CLAUSE_LINKS), "")
        if opening == "let" and words[words.index("let") + 1:][:2] in (["'", "s"], ["us"]):   # 'Let's see if ...'
            opening = "us"
        own = verse or opening in SPEAKER or k > asked or k <= heading or \
            any(words[:len(o)] == o for o in SIMILE_OPENERS) or \
            k and words[:1] == ["for"]   # a purpose ('..., for entry in the accident register')
        # (a clause of the speaker's own time: 'before we loosen anything up', 'while I think')
        ours = words[:1] in (["before"], ["while"], ["until"]) and words[1:2] and words[1] in SPEAKER
        if ours and _filler(words[2:], unknown):
            own, words = True, words[2:]
        # ... and an aside between commas that says nothing the rest does not say too ('Is the utility bike, to the
        # considerable astonishment of all who observe it, faster than ...?')
        aside = 0 < k < len(clauses) - 1 and marks[k - 1].strip() == marks[k].strip() == "," and \
            opening in ASIDE_OPENERS
        own = own or k <= told
        news = own and (_news(words, unknown) if letter and k <= heading else _filler(words, unknown)) or \
            (own and opening in SPEAKER or k <= told) and _news(words, unknown, SPEAKER_KEEPS) or \
            aside and _news(words, unknown, ASIDE_KEEPS) and _said_too(words, tokenize(" ".join(
                c for j, c in enumerate(clauses) if j != k)))
        if not news:
            head, like, tail = clause.partition(" like ")   # a simile closing a clause ('engine open like my old ...')
            if like and head.strip() and _filler(tokenize(like + tail), unknown):
                dropped.append((like + tail).strip())
                clauses[k] = head
            continue
        dropped.append(clause)
        clauses[k] = ""
        if "?" in marks[k] and k and clauses[k - 1]:   # the question's own mark stays with it
            marks[k - 1] = marks[k - 1].rstrip().rstrip(",;:-—–") + "? "
        elif ":" in marks[k] and k and clauses[k - 1] and marks[k - 1].strip() == ",":
            marks[k - 1] = ": "   # and a heading's ('Quick one, no judgement pls: is ...')
        marks[k] = ""
    if not dropped or not any(c.strip() for c in clauses):
        return None
    return "".join(c + m for c, m in zip(clauses, marks)).strip(), " / ".join(dropped)


# A remark after the question ('...? looks parked but the motion estimate is noisy', '...? guessing yes, verify',
# '...? Over.'): read only where the parser would refuse the question with it, and only where the remark names no
# vehicle and says no time, condition, comparison, negation or collision that the question could be asking
# (`remark_after_dropped`)
REMARK_KEEPS = (CONDITION_OPENERS | CONDITION_WORDS | IMAGINED_SAID | IMAGINING | START_WORDS | START_ADJECTIVES
                | END_WORDS | END_SAID | FUTURE_CUES | TIME_SAID | NEGATIONS | COMPARING | COMES_IN_WORDS | NAMING
                | PLURALS | set(COLOR_NAMES) | OTHER_COLOURS
                | {"?", "after", "before", "later", "then", "until", "once", "beyond", "afterwards", "next", "would",
                   "will", "than", "first", "last", "end"}
                | {"yes", "no", "y", "n", "true", "false", "binary", "or"})   # an answer's form: '? (y/n)'


def simile_closing_dropped(text: str) -> tuple[str, str] | None:
    """'Is the red jet hovering in the air, like a meringue that won't settle?' -> ('Is the red jet hovering in the
    air?', 'like a meringue that won't settle'): a simile closing the question (after a comma, or a dash), or a
    closing clause of three words or more that says nothing at all ('..., the parties being duly bound?'; not a tag,
    ', genre?'), that names nothing the question could ask; None where there is none."""
    if not isinstance(text, str) or not text.rstrip().endswith("?"):
        return None
    body = text.rstrip()[:-1]
    cut = max(body.rfind(", "), body.rfind(" — "), body.rfind(" - "))
    # (or said within the clause: ', its engine awake like a dragon stirring from its hoard?')
    cut = body.rfind(" like ") if " like " in body[max(cut, 0):] and body.rfind(" like ") > cut + 3 else cut
    simile = body[cut:].lstrip(",—- ").strip() if cut > 0 else ""
    words = [] if re.search(r"[.?!:;…]", simile) else tokenize(simile)   # (the question's own last clause)
    if "or" in tokenize(body[:cut])[-6:]:
        return None   # (the question's other side: '..., or'd they pass like two boats on the lake?')
    if not words or not (any(words[:len(o)] == o for o in SIMILE_OPENERS) or words[0] == "as" and words[1:2] and
                         words[1] not in ASKING | {"it", "they", "the", "soon", "fast", "slow", "slowly", "quickly"}
                         | COMES_IN_WORDS or len(words) >= 3 and not _says_something(words)) or \
            mentions(words) or REMARK_KEEPS & set(words) - NEGATIONS - {"would", "will", "never"} or \
            asks_impact(words):   # (one that speaks of a collision stays: '..., the way my line tangled with ...?')
        return None
    return body[:cut].rstrip() + "?", simile


def heading_dropped(text: str) -> tuple[str, str] | None:
    """'Family-sized and refreshingly cyan: when the cyan station wagon hits the gray one, is it moving slower than
    the gray one?' -> ('when the cyan station wagon hits ...?', 'Family-sized and refreshingly cyan'): a heading
    before the question's colon that, beside the vehicles the question names again, says nothing the question does
    not say too (no time, stop, condition, setting or symbol); None where there is none ('Put the brown bus ... at the
    start of the video: is the brown bus travelling faster ...?' says a time the question does not)."""
    if not isinstance(text, str) or ":" not in text or not text.rstrip().endswith("?"):
        return None
    heading, _, question = text.partition(":")
    said, asked = tokenize(heading), tokenize(question)
    runs = mentions(said)
    # what the heading says beside its vehicles and the words the question says again: nothing, in words
    rest = [w for k, w in enumerate(said) if not any(a <= k < b for a, b, _ in runs) and w not in asked]
    if not said or not asked or re.search(r"[?!]", heading) or \
            not {tuple(r) for _, _, r in runs} <= {tuple(r) for _, _, r in mentions(asked)} or \
            _says_something(rest) or any(not (w.isalpha() or w in (",", "-", "'", ".")) for w in rest) or \
            (CONDITION_OPENERS | IMAGINED_SAID | IMAGINING | CONDITION_LABELS | STOP_CUES | FUTURE_CUES
             | {"set", "cut"}) & set(said) or asks_impact(said) and not asks_impact(asked):
        return None
    return question.strip(), heading.strip()


# A log's clock stamp before its entry ('0615h. Yellow biplane under continuous watch. ...'): the hour of the log, not
# the video's time (a watch log's '0000 hours' is its start: `times.TIME_ZERO`)
LOG_STAMP = re.compile(r"\d{3,4}(?:h|hrs|hours)")


# A support desk's reference to its ticket ('For ticket #27159, which type ...', 'Per case 12954,', 'regarding ticket
# 31148'): its number is no time or count of the video's
REFERENCE_LEADS = {"for", "per", "re", "regarding", "on", "about", "concerning", "under", "progress", "in", "with"}
REFERENCED = {"ticket", "case", "incident", "request", "ref", "reference", "claim", "issue", "complaint", "enquiry",
              "inquiry", "query"}


def reference_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'for ticket # 27159 , which type ...' -> 'which type ...'; 'to progress ticket # 34467 , could ...' -> 'could
    ...'. With each reference read as nothing, or the words as they are and ()."""
    out, read, k = [], [], 0
    while k < len(words):
        number = k + 2 + (words[k + 2:k + 3] == ["#"])
        if words[k] in REFERENCE_LEADS and words[k + 1:k + 2] and words[k + 1] in REFERENCED and \
                re.fullmatch(r"\d{3,}", words[number] if number < len(words) else ""):
            start = k - (words[k] == "progress" and out[-1:] == ["to"])
            out = out[:len(out) - (k - start)]
            # (its comma with it where it opens a clause)
            end = number + 1 + (words[number + 1:number + 2] == [","] and (not out or out[-1] in CLAUSE_MARKS))
            read.append((" ".join(words[start:end]), "nothing, a ticket's number"))
            k = end
            continue
        out.append(words[k])
        k += 1
    return (out, tuple(read)) if read else (words, ())


def log_stamp_dropped(words: list[str]) -> tuple[list[str], tuple[tuple[str, str], ...]]:
    """'0615h . yellow biplane ...' -> 'yellow biplane ...'. With the words read so, or the words as they are and
    ()."""
    if words[:1] and LOG_STAMP.fullmatch(words[0]) and words[0][:4] != "0000" and words[1:2] in ([","], ["."], [":"],
                                                                                                 ["-"]):
        return words[2:], ((" ".join(words[:2]), "nothing, a log's clock"),)
    return words, ()


TICKET_REMARKS = {"expected", "expecting", "actual", "actually", "got", "build", "version", "ver", "priority",
                  "severity", "filed", "repro", "reproduced", "regression", "tool", "observed", "result"}


CALLS_TO_VIEWERS = {"subscribe", "subscribed", "comment", "comments", "below", "like", "likes", "share", "bell",
                    "notification", "notifications", "channel"}


def remark_after_dropped(text: str) -> tuple[str, str] | None:
    """'Is the station wagon static at the start? looks parked but the motion estimate is noisy' -> ('Is the station
    wagon static at the start?', 'looks parked but the motion estimate is noisy'); None where nothing follows the
    question's last mark or what follows may say what is asked."""
    if not isinstance(text, str):
        return None
    asked = text.rfind("?")
    remark = text[asked + 1:].strip()
    words = tokenize(remark)
    if asked < 0 or not words:
        return None
    # (a video maker's call to its viewers, whatever its verbs: '? Smash that subscribe button and tell me!', '? Hit
    # like if you spotted it!')
    if CALLS_TO_VIEWERS & set(words) and not mentions(words) and not (CONDITION_OPENERS | IMAGINED_SAID) - {"if"} & set(
            words):
        return text[:asked + 1], remark
    # (a bug report's expected and actual answers and its version: '? Expected yes/no, actual null. v3.8')
    if words[0] in TICKET_REMARKS or VERSION.match(remark):
        return None if (CONDITION_OPENERS | IMAGINED_SAID) & set(words) else (text[:asked + 1], remark)
    if mentions(words) or REMARK_KEEPS & set(words) or asks_impact(words) or \
            any(impact_like(w) for w in words if len(w) > 4):
        return None
    return text[:asked + 1], remark


# A screenplay's page: its transitions and scene headings ('FADE IN: INT. EDITING BAY - DAY.') and the cue of the
# character who speaks the question ('MARCUS (flatly)'), capitals in the script's own text; the action lines between
# them stay (one may say the video stopped: 'The playback halts mid-clip.')
SCRIPT_TRANSITION = re.compile(r"(?:(?:FADE IN|(?:SMASH |MATCH )?CUT TO|DISSOLVE TO)\s*:\s*)+")
SCENE_HEADING = re.compile(r"(?:INT|EXT|INT\./EXT|I/E)\.\s+[A-Z0-9][A-Z0-9 '&/,-]*\.\s*")
CHARACTER_CUE = re.compile(r"(?:(?<=^)|(?<=[.!?]\s))((?:[A-Z][A-Z'-]*[A-Z]\.?|\d+)(?:\s+(?:[A-Z][A-Z'-]*[A-Z]\.?|\d+))*)"
                           r"(?:\s*\(([^()]*)\))?\s+(?=[\"“A-Z])")


# what an actor's parenthetical may say that the line needs, by kind: a kind the line says too it need not
CUE_KEEPS = (START_WORDS | START_ADJECTIVES, FUTURE_CUES | STOP_CUES | END_WORDS | END_SAID,
             CONDITION_OPENERS | CONDITION_WORDS | IMAGINED_SAID | IMAGINING, COMPARING, COMES_IN_WORDS,
             set(COLOR_NAMES) | OTHER_COLOURS | NAMING | PLURALS)


def script_cues_dropped(text: str) -> tuple[str, str] | None:
    """'INT. EDIT SUITE - NIGHT. FELIX (half to himself) Which way is the blue sedan heading when this thing
    starts?' -> ('Which way is the blue sedan heading when this thing starts?', 'INT. EDIT SUITE - NIGHT. FELIX (half
    to himself)'): a screenplay's transitions, scene headings and the speaker's cue; his parenthetical goes with it
    only where it names nothing the dialogue could need that the dialogue does not say (no vehicle, time, stop,
    condition or collision). None where there is no cue, or the cue is not before the question."""
    if not isinstance(text, str):
        return None
    head = SCRIPT_TRANSITION.match(text)
    start = head.end() if head else 0
    heading = SCENE_HEADING.match(text, start)
    start = heading.end() if heading else start
    cues = [m for m in CHARACTER_CUE.finditer(text, start) if m.start() >= start and
            not OBJECT_WORDS & set(tokenize(m.group(1))) and "?" in text[m.end():]]
    if not cues or "?" in text[:cues[-1].start()]:
        return None
    cue = cues[-1]
    spoken = tokenize(text[cue.end():])
    aside = tokenize(cue.group(2) or "")
    aside = [w for k, w in enumerate(aside) if not (w == "over" and aside[k + 1:k + 2] and
                                                    aside[k + 1] in DETERMINERS | OWNERS | {"his", "her", "their"})]
    if mentions(aside) or asks_impact(aside) and not asks_impact(spoken) or \
            any(kind & set(aside) and not kind & set(spoken) for kind in CUE_KEEPS):
        return None
    dropped = [text[:start].strip(), text[cue.start():cue.end()].strip()]
    return (text[start:cue.start()] + text[cue.end():]).strip(), " ".join(filter(None, dropped))


# A heading that describes its vehicles with a flourish before the question's colon (a menu's 'The purple biplane,
# served sizzling off the grill at the start of the video: is it moving fast?'): what the question needs of it is
# its vehicles, its time and a motion said first; the rest is read as nothing where it says nothing more
DESCRIBED_TIMES = START_WORDS | START_ADJECTIVES | COMES_IN_WORDS | {"moment", "moments", "instant", "whole", "entire",
                                                                     "course", "opens", "starts", "outset"}
TIME_LEADS = {"at", "as", "when", "just", "in", "during", "over", "throughout", "from", "upon", "right", "once", "the",
              "on"}
DESCRIBED_KEEPS = (STATIC_SAID | REST_WORDS | SPEED_CLASS_WORDS | FLOATING_WORDS | NEGATIONS | CONDITION_OPENERS
                   | CONDITION_WORDS | IMAGINED_SAID | IMAGINING | CONDITION_LABELS | FUTURE_CUES | COMPARING
                   | PLURALS | NAMING | set(COLOR_NAMES) | OTHER_COLOURS | FILM_WORDS
                   # (of the words that say a stop, those that say it without the video named: 'served sizzling off
                   # the grill' is no cut)
                   | STOP_CUES - {"in", "been", "has", "having", "goes", "gone", "went", "were", "between", "off",
                                  "out", "falls", "fell", "silent", "early", "short", "abruptly", "broke", "breaks",
                                  "broken", "drops", "dropped"}
                   | SIGHT_WORDS | QUERY_NOUNS | {"how", "what", "which", "whether", "who"}
                   | {"into", "slowly", "quickly", "engine", "accelerating", "speeding", "air", "sky", "?", "!", "name",
                      "kind", "type", "sort"})
# where a vehicle's name ends, the words after its colour ('the brown pickup') kept to the first of them
DESCRIBED_BOUNDS = {"and", "or", "with", "of", "beside", "alongside", "near", "off", "to", "into", "across", "by"}


def _time_in(segment: list[str]) -> tuple[int, int] | None:
    """Where a part of a heading says a time ('served sizzling off the grill at the start of the video', 'captured
    just as it strikes the bus'): from a word that leads a time to its end, or to an 'and' past which it says no time
    and no vehicle."""
    for o, w in enumerate(segment):
        rest = segment[o:]
        if w in TIME_LEADS and (w != "the" or rest[1:2] in (["moment"], ["instant"])) and (
                DESCRIBED_TIMES & set(rest[1:6]) or asks_impact(rest) and {"as", "when", "moment", "instant"} & set(
                    rest[:4])):
            end = next((a for a in range(o + 1, len(segment)) if segment[a] == "and" and not mentions(segment[a:])
                        and not DESCRIBED_TIMES & set(segment[a:]) and not asks_impact(segment[a:])), len(segment))
            return o, end
    return None


def description_dropped(text: str) -> tuple[str, str] | None:
    """'The purple biplane, served sizzling off the grill at the start of the video: is it moving fast?' -> ('The
    purple biplane, at the start of the video: is it moving fast?', 'served sizzling off the grill'): in a heading
    before the question's colon, the vehicles (from the first one's article to the last), the time (`_time_in`) and a
    motion said before it are kept, and the rest read as nothing where it says nothing the question could need (no
    state, speed, condition, stop, comparison, colour, film, property asked, or start, coming into view or collision
    the question does not say); None where there is nothing to drop."""
    if not isinstance(text, str) or ":" not in text or not text.rstrip().endswith("?"):
        return None
    heading, _, question = text.partition(":")
    said, asked = catalogue_names(tokenize(heading))[0], tokenize(question)
    # (the question after the colon one sentence: not 'Set v0(scooter) := fast. Does ...?')
    if not said or not asked or re.search(r"[?!]", heading) or re.search(r"[.!;?]", question.rstrip()[:-1]) or \
            not (mentions(said) or mentions(asked)):
        return None
    kept, dropped, k = [], [], 0
    while k < len(said):
        end = said.index(",", k) if "," in said[k:] else len(said)
        segment, runs = said[k:end], mentions(said[k:end])
        time = _time_in(segment)
        keep = set()
        if runs:
            first = runs[0][0] - (runs[0][0] > 0 and segment[runs[0][0] - 1] in DETERMINERS | OWNERS)
            # (with the noun after a colour that the parser reads later: 'the brown pickup', 'the purple one')
            last = runs[-1][1]
            while last < min(len(segment), runs[-1][1] + 2) and segment[last].isalpha() and \
                    segment[last] not in TIME_LEADS | DESCRIBED_BOUNDS and not segment[last].endswith(("ed", "ing")):
                last += 1
            keep |= set(range(first, last))
        if time:
            # (and a motion said before it: 'Moving slowly at the start of the video')
            motion = not runs and set(segment[:time[0]]) <= MOTION_WORDS | SPEED_CLASS_WORDS | {"slowly", "quickly"}
            keep |= set(range(0 if motion else time[0], time[1]))
        kept.append([w for j, w in enumerate(segment) if j in keep])
        dropped.append([w for j, w in enumerate(segment) if j not in keep])
        k = end + 1
    # (not a time's 'over the whole video')
    rest = [w for words in dropped for j, w in enumerate(words) if not (w == "over" and words[j + 1:j + 2] == ["the"])]
    # (a start or a coming into view it drops, the question or what is kept says too)
    said_too = set(asked) | {w for words in kept for w in words}
    if not rest or DESCRIBED_KEEPS & set(rest) or mentions(rest) or asks_impact(rest) and not asks_impact(asked) or \
            any(kind & set(rest) and not kind & said_too for kind in (START_WORDS | START_ADJECTIVES,
                                                                        COMES_IN_WORDS)) or \
            any(w[:-1] in OBJECT_WORDS or w[:-2] in OBJECT_WORDS for w in rest if w.endswith("s")):   # 'minivans'
        return None
    # a vehicle in a part of its own is another one, not the first named again ('The brown tandem bike, plated beside
    # the green one ...' is two bikes)
    heading, named = "", False
    for words in filter(None, kept):
        first = bool(mentions(words[:3]))
        heading += (" and " if first and named else ", " if heading else "") + " ".join(words)
        named |= first
    return heading + ": " + question.strip(), " ... ".join(" ".join(words) for words in dropped if words)


# An aside between dashes that says nothing the question could need ('The red scooter — reckless, wild, untamed — is
# it racing fast ...?', 'What kind of vehicle — oh, the treachery! — is getting faster ...?')
DASHED = re.compile(r"\s[—–-]{1,2}\s(.+?)\s[—–-]{1,2}\s")


def dashed_aside_dropped(text: str) -> tuple[str, str] | None:
    """'Does the green plane — so proud, so untouchable — ever slam into another vehicle?' -> ('Does the green plane
    ever slam into another vehicle?', 'so proud, so untouchable'); None where there is no such aside, or it names a
    vehicle, a time, a state or anything else the question could need (`DESCRIBED_KEEPS`)."""
    if not isinstance(text, str) or not (m := DASHED.search(text)):
        return None
    aside = tokenize(m.group(1))
    if not aside or mentions(aside) or DESCRIBED_KEEPS - {"!"} & set(aside) or asks_impact(aside) or \
            any(kind & set(aside) for kind in (START_WORDS | START_ADJECTIVES, COMES_IN_WORDS, SIGHT_WORDS)):
        return None
    return text[:m.start()] + " " + text[m.end():], m.group(1)


# A news ticker's headlines in capitals before the question, each closed by a separator ('STANDSTILL WATCH ///
# OPENING SECONDS /// Was the red motorbike sitting completely still when the clip began?')
HEADLINE_MARK = re.compile(r"\s*(?:/{2,}|>{2,}|\+{2,}|\*{2,}|-{2,3}|[•—–|:])\s*")
# the kinds of thing a headline may say that the question must say too, each in any of its words ('HOVER WATCH' and
# 'floating', 'OPENING SECONDS' and 'began')
HEADLINE_KINDS = (START_WORDS | START_ADJECTIVES | {"outset", "opens", "starts", "kickoff", "gun", "gate", "grid",
                                                   "early"},
                  COMES_IN_WORDS | SIGHT_WORDS | {"sighting", "enters", "entry"},
                  FLOATING_WORDS | AFLOAT_SAID | {"aloft", "hovered", "lift", "sky", "high"},
                  STATIC_SAID | REST_WORDS | {"standstill", "parked"},
                  SPEEDING_UP | {"acceleration", "accelerating", "accelerates"},
                  SPEED_CLASS_WORDS, NEGATIONS, COMPARING - {"more", "less"},
                  CONDITION_OPENERS | CONDITION_WORDS | IMAGINED_SAID | IMAGINING | CONDITION_LABELS
                  | {"hypothetical", "scenario", "alternate", "imagine", "what-if"},
                  FUTURE_CUES | END_WORDS | {"forecast", "outlook", "halted", "frozen", "cut", "after"})


def headlines_dropped(text: str) -> tuple[str, str] | None:
    """'CLIP HALTED • BLUE BUS OUTLOOK • Will the blue bus collide with anything after the video stops?' -> ('Will
    the blue bus collide ...?', 'CLIP HALTED / BLUE BUS OUTLOOK'): headlines in capitals, each closed by a separator,
    read as nothing where every vehicle they name the question names too (`generalises`) and every kind of thing they
    say (a time, a state, a comparison, a condition, a collision: `HEADLINE_KINDS`) the question says too; None where
    there are no such headlines."""
    if not isinstance(text, str) or not text.rstrip().endswith("?"):
        return None
    end = 0
    while (mark := HEADLINE_MARK.search(text, end)) and re.search(r"[A-Z]", text[end:mark.start()]) and \
            not re.search(r"[a-z]", text[end:mark.start()]):
        end = mark.end()
    question = text[end:]
    if not end or not re.match(r"[A-Z][a-z]", question):
        return None
    said = catalogue_names(tokenize(text[:end].lower()))[0]
    if FILM_WORDS & set(said):
        said = [w for w in said if w not in STATIC_SAID | REST_WORDS]   # (the film's: 'FOOTAGE FROZEN MID-CLIP')
    if not _said_too(said, catalogue_names(tokenize(question))[0]):
        return None
    return question, HEADLINE_MARK.sub(" / ", text[:end]).strip(" /")


def _said_too(said: list[str], asked: list[str]) -> bool:
    """Whether the question `asked` names every vehicle `said` names (`generalises`) and says every kind of thing it
    says (a time, a state, a comparison, a condition, a collision: `HEADLINE_KINDS`)."""
    named = [r for _, _, r in mentions(asked)]
    return all(any(generalises(r, full) for full in named) for _, _, r in mentions(said)) and \
        not (asks_impact(said) and not asks_impact(asked)) and \
        not any(kind & set(said) and not kind & set(asked) for kind in HEADLINE_KINDS)


# A koan's riddle before the question ('Does the wind touch the pine, or the pine the wind? Did the bus crash into any
# other object in the video?'): sentences naming no vehicle, that say nothing the question does not say too
RIDDLE_SENTENCE = re.compile(r"(?<=[.?!])\s+(?=[A-Z])")


def riddles_dropped(text: str) -> tuple[str, str] | None:
    """'Who strikes the bell, and who is the bell? What kind of vehicle is it that bangs into the cyan utility bike?'
    -> ('What kind of vehicle ...?', 'Who strikes the bell, and who is the bell?'): the sentences before the last one,
    read as nothing where they name no vehicle and say nothing the question does not say too (`_said_too`); None where
    there are none."""
    if not isinstance(text, str) or not text.rstrip().endswith("?"):
        return None
    sentences = RIDDLE_SENTENCE.split(text.strip())
    if len(sentences) < 2:
        return None
    said, asked = catalogue_names(tokenize(" ".join(sentences[:-1])))[0], catalogue_names(tokenize(sentences[-1]))[0]
    # (nor the film or a moment the question points back at: 'Think about the last moment of the clip. Is the grey
    # station wagon slower than the school bus then?')
    if mentions(said) or set(said) & (FILM_WORDS | MOMENTS) or set(asked) & {"then", "there"} or \
            not _said_too(said, asked):
        return None
    return sentences[-1], " ".join(sentences[:-1])
