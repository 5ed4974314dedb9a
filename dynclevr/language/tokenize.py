"""Question text -> word tokens: lower-case, words and punctuation apart, a few spellings unified."""

from __future__ import annotations

import re
import unicodedata

_TOKEN = re.compile(r"[a-z0-9]+|[^\sa-z0-9]")
# One spelling per word, so that the vocabulary (built from generated questions) covers common variants.
SPELLINGS = {"grey": "gray", "colour": "color", "colours": "colors", "airplane": "aeroplane",
             "airplanes": "aeroplanes", "motorcycle": "motorbike", "motorcycles": "motorbikes",
             "u": "you", "ur": "your", "thru": "through",   # and a phone's ('can u tell me')
             "vid": "video", "spd": "speed", "dir": "direction", "@": "at",   # and a note's ('spd @ start')
             "vel": "velocity", "mtn": "mountain",
             "wat": "what", "wut": "what", "wht": "what", "rly": "really", "secs": "seconds",
             "b4": "before", "r": "are", "smth": "something", "sth": "something", "bc": "because",   # and a text's
             "hypoth": "hypothetical"}   # and a note to self's ('(hypoth.)')
_QUOTES = str.maketrans({"\u2018": "'", "\u2019": "'", "\u201c": '"', "\u201d": '"', "\u2013": "-", "\u2014": "-"})
# Negations written short, as the grammar says them in full ("isn't moving" is "is not moving"), also typed without
# the apostrophe ("isnt", "didnt"); "'s" stays, being a possessive as often as "is".
_NOT = re.compile(r"\b(is|was|are|were|do|does|did|has|have|had|would|could|should|wo|ca)n'?t\b")
_NOT_STEMS = {"wo": "will", "ca": "can"}
# "ain't" is a negated 'is' (or 'has', 'did'), and "ain't never" a 'never' ('the wagon ain't never moved')
_AINT = re.compile(r"\bain'?t( never\b)?")
# A dropped g written with an apostrophe ("movin'", "drivin'") is the word in full
_DROPPED_G = re.compile(r"(?<!')\b([a-z]{2,}in)'(?!s\b)")   # not a quoted word ("the 'spin'")
# A chat's mention of someone ("@luna which type ...", "... ? @sam"), first or last; '@' alone is a note's 'at'
_MENTION = re.compile(r"^\s*@[a-z]\w*\s*[,:]?|(?<=\s)@[a-z]\w*(?=\s*(?:[,:!?.]|$))")
# A report's abbreviations keep their word and lose the full stop, which would end a sentence there ('what was the
# approx. speed class of the veh.'): 'approx' and 'veh' are read by synonyms.txt; 'i.e.' and 'e.g.' open a gloss
_ABBREVIATED = re.compile(r"\b(approx|apprx|veh|esp|incl|resp)\.")
_GLOSS = re.compile(r"\b([ie])\.\s?([eg])\.?(?=[\s,:)]|$)")


# A chat's formatting before the question: a list's bullet or a quote's '>' ('- where is ...', '> did ...'), a bot's
# slash command ('/ask would the bus ...')
_LEAD = re.compile(r"^\s*(?:(?:[-*\u2022>]+|/[a-z]+)\s+)+")
# 'it'd been' is 'it had been' ('it'd had' and "I'd like" the rules read as said)
_HAD = re.compile(r"\b([a-z]+)'d(?= been\b)")
# a drawl's 'would it've hit' is 'would it have hit', and 'the bit we've seen' 'we have'
_IT_HAVE = re.compile(r"\b(it|they|we|you|i)'ve\b")
# a briefing's hour of the start ('at H-hour', 'from T-zero'), and mission control's loss of signal, the video's end
# ('Post-LOS projection: ...', read before a heading's words are weighed)
_ZERO_HOUR = re.compile(r"\b(?:h-hour|t-zero|t-0|h hour)\b")
# a note's '1st' (not a word of SPELLINGS, which a misread print would reach: 'ist' is one confusion from it)
_FIRST = re.compile(r"\b1st\b")
_SIGNAL_LOST = re.compile(r"\b(?:post|after)[- ]?los\b|\bafter (?:the )?loss of signal\b")
# 'faster an' faster', 'the car an' the bus'
_AN = re.compile(r"\ban'(?=\s|$)")
# a Northern English speaker's article and elisions ('at t' start o' the video', 'the purple 'un', 'would it 'ave
# hit'): 't'' only before a word, so that a symbol's t' ('at t' > t_c') stays one
_ELIDED = {"t'": "the", "o'": "of", "'un": "one", "'ave": "have", "'ad": "had"}
_ELISION = re.compile(r"\b[to]'(?= +[a-z])|(?<![a-z])'(?:un|ave|ad)\b")
# a Cajun's or a Caribbean's 'th' said 't'' ('de t'ing', 'somet'in''), before 't'' could be read as a symbol's
_TH = re.compile(r"\b(some|any|no|every)?t'in(?:g\b|'|\b)")
# a Canadian's 'give'r' (go all out: fast), 'givin'r'
_GIVER = re.compile(r"\bgiv(e|es|in|ing)'e?r\b")
_GONE_ALL_OUT = {"e": "go fast", "es": "goes fast", "in": "going fast", "ing": "going fast"}
# 'the plane that's hovering' is 'that is' (a relative clause's, as the grammar says it)
_THAT_IS = re.compile(r"\b(that|which|who)'s(?= (?:[a-z]+ing|still|parked|static|stationary|fast|slow|moving)\b)")


# A fan's honorific on a vehicle's name ('Bus-senpai', 'bicycle-chan'), a kaomoji ('(ﾟoﾟ;)'), a script's beat
_HONORIFIC = re.compile(r"-(?:chan|kun|senpai|sama|san|tan)\b")
_KAOMOJI = re.compile(r"\((?=[^()\s]*[;^\u00b0\u309a\u309c\u00b4`~\u03c9])[^()\s]{1,12}\)"
                      r"|\((?:a )?(?:beat|pause|long beat)\)")


_SAID_MARKS = {"comma": " , ", "question mark": " ? ", "full stop": " . ", "period": " . ", "new line": " ",
               "new paragraph": " ", "exclamation mark": " ! ", "exclamation point": " ! "}
_DICTATED = re.compile(r"\b(comma|question mark|new line|new paragraph|exclamation (?:mark|point))\b"
                       r"|\b(full stop|period)(?=\s*(?:new line|new paragraph)?\s*$)")
_HASHTAGS = re.compile(r"(?:\s+#[a-z]\w*)+\s*$")
_AND = re.compile(r"(?<=[a-z] )n(?= [a-z])")   # a text's 'n' between words ('the sedan n the bus'), not 'y/n'
# a text's '1' for 'one' where it names a vehicle ('the faster 1', 'the red 1'), never a number of something
# a speech recogniser's letters of an initialism ('the s u v', 's.u.v.'), before 'u' is read as 'you'
_SPELT = re.compile(r"\bs[\s.]+u[\s.]+v\b\.?")
_ONE = re.compile(r"\b(the|that|this|which|faster|slower|other|gray|grey|red|blue|green|brown|purple|cyan|yellow)"
                  r"\s+1\b(?!\s*(?:s\b|sec|second|frame|minute|m\b|km|mph|%))")


def tokenize(text: str) -> list[str]:
    """'Is the grey SUV moving?' -> ['is', 'the', 'gray', 'suv', 'moving', '?']; "isn't" -> ['is', 'not']. Never
    raises on a str."""
    text = unicodedata.normalize("NFKC", text).translate(_QUOTES).lower()
    # accents folded ('début', 'vídeo', 'naïve'): the parser's words are written without them
    text = "".join(c for c in unicodedata.normalize("NFKD", text) if not unicodedata.combining(c))
    text = _AINT.sub(lambda m: "never" if m.group(1) else "is not", text)
    text = _NOT.sub(lambda m: _NOT_STEMS.get(m.group(1), m.group(1)) + " not", text)
    text = _SIGNAL_LOST.sub("after the video ends", text)
    text = _GIVER.sub(lambda m: _GONE_ALL_OUT[m.group(1)], _TH.sub(lambda m: (m.group(1) or "") + "thing", text))
    text = _DROPPED_G.sub(r"\1g", _AN.sub("and", _FIRST.sub("first", _ZERO_HOUR.sub("the start", text))))
    text = _ELISION.sub(lambda m: _ELIDED[m.group(0)], text)
    text = _THAT_IS.sub(r"\1 is", _HAD.sub(r"\1 had", _IT_HAVE.sub(r"\1 have", _LEAD.sub("", text))))
    text = _KAOMOJI.sub(" ", _HONORIFIC.sub("", text))
    text = _MENTION.sub(" ", text)
    text = _GLOSS.sub(lambda m: " " + m.group(1) + m.group(2) + " " if m.group(1) + m.group(2) in ("ie", "eg")
                      else m.group(0), text)
    text = _ABBREVIATED.sub(r"\1", text)
    said = text.rstrip()
    if said.endswith(" question mark") or said == "question mark":   # dictated
        text = said[:-len("question mark")].rstrip() + "?"
    # punctuation dictated in words ('the dirt bike comma when it ... full stop'), a post's trailing hashtags
    text = _DICTATED.sub(lambda m: _SAID_MARKS[m.group(1) or m.group(2)], text)
    text = _HASHTAGS.sub("", text)
    text = _ONE.sub(r"\1 one", _SPELT.sub("suv", text))
    text = _AND.sub("and", text)
    return [SPELLINGS.get(t, t) for t in _TOKEN.findall(text)]
