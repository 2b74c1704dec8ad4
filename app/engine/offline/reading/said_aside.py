"""Sentences and clauses said beside the request, dropped: a cue ("Go!", "Rolling!", "Action!"), the object pointed out
("See this little wooden chest?"), an apology or thanks
with nothing to do in it ("Sorry if that's a silly request.", "Thanks so much!"), what is about to happen ("it's about
to boil over") and how it works ("- that's what sets the turntable going -"). Before this stage "go" was a verb with nothing to move and "a silly request" a part the asset lacked."""

from __future__ import annotations

from app.engine.lexicon.verbs import VERBS
from app.engine.offline.reading.part_words import kind_of_word
from app.engine.offline.reading.token import Token

_CUES = frozenset({"go", "rolling", "action", "and_action", "ready", "now", "cut", "okay", "ok", "done", "that's_it", "thanks", "cheers"})
_COURTESY = frozenset({"sorry", "apologies", "thanks", "thank", "cheers", "hope", "hopefully", "cool"})
_POINTING = frozenset({"see", "notice", "spot", "recognise", "recognize"})
_CORRECTING = frozenset({"make", "meant", "mean", "instead", "actually", "no", "not", "other", "rather"})
_ABOUT_TO = frozenset({"it's", "they're", "is", "are", "was", "were", "it"})
_AROUND = frozenset({"behind", "around", "round", "past", "under", "beneath", "underneath", "over", "between"})
_MOTION_NOUNS = frozenset({"rotation", "rotating", "tilt", "tilting", "change", "translation", "spin", "spinning", "turning", "yaw", "roll",
                           "pitch", "lift", "lifting", "sliding", "drift", "wobble"})
_WANTING = frozenset({"i_want", "i_need", "we_need", "we_want", "i_just_want"})
_LIKE_AMOUNTS = frozenset({"halfway", "half", "a_bit", "a_little", "a_quarter", "a", "about", "all_the_way", "fully", "most", "90", "45"})
_DESCRIBED_AS = frozenset({"move", "gesture", "touch", "flourish", "moment", "beat", "shot", "scene", "motion", "reveal", "entrance", "exit"})
_CLAUSE_ENDS = frozenset({",", ".", "!", "?", ";", ":", "and", "so", "then", "but"})


def _sentences(tokens: list[Token]) -> list[tuple[int, int]]:
    spans, start = [], 0
    for k, t in enumerate(tokens):
        if t.is_sentence_end:
            spans.append((start, k + 1))
            start = k + 1
    if start < len(tokens):
        spans.append((start, len(tokens)))
    return spans


def _aside(words: list[Token]) -> bool:
    said = [t for t in words if not t.is_punct]
    if [t.text for t in said[:2]] in (["expected", ":"], ["expected", "result"], ["result", ":"], ["outcome", ":"], ["expectation", ":"]) or (
            [t.text for t in words[:2]] in (["expected", ":"], ["result", ":"], ["outcome", ":"])):
        return True  # "Repro: ... Expected: only the dial rotates.": what should be seen, not more steps
    if said and said[0].text in _POINTING and words[-1].text == "?" and len(said) <= 6:
        return True  # "See this little wooden chest?": pointing the object out
    if said and all(t.text in _CUES for t in said):
        return True  # "Go!", "Rolling!"
    return bool(said) and said[0].text in _COURTESY and not any(
        t.lemma in VERBS or kind_of_word(t.text) is not None or t.number is not None or t.text in _CORRECTING for t in said[1:])  # "Sorry if
    # that's a silly request.", not "sorry, make that 30 degrees"


def said_aside(tokens: list[Token]) -> list[Token]:
    """``tokens`` without cue, apology and thanks sentences (when something else is asked) and "about to" clauses."""
    spans = _sentences(tokens)
    kept = [(a, b) for a, b in spans if not _aside(tokens[a:b])]
    out = [t for a, b in (kept or spans) for t in tokens[a:b]]
    while len(out) > 1 and out[0].is_punct and len(kept) < len(spans):
        out = out[1:]  # "Sorry... could you open ...": the dots left by the dropped sentence
    k, result = 0, list[Token]()
    while k < len(out):
        if out[k].text in ("i_need", "we_need", "i_want") and [t.text for t in out[k + 1:k + 3]] == ["to", "get"] and k + 3 < len(out) and (
                out[k + 3].text in _AROUND):  # "I need to get behind it": where the user goes, no part opened
            k = next((j for j in range(k + 3, len(out)) if out[j].text in _CLAUSE_ENDS), len(out))
            continue
        if (out[k].text == "given" and (k == 0 or out[k - 1].is_sentence_end)) or (out[k].text in ("got", "i've_got", "we've_got") and (
                k == 0 or out[k - 1].is_sentence_end) and k + 1 < len(out) and out[k + 1].text in ("a", "an", "some")) or (
                out[k].text in _WANTING and k + 1 < len(out) and out[k + 1].text in ("a", "an", "some") and any(
                    t.lemma in VERBS and (j == 0 or result[j - 1].is_punct) for j, t in enumerate(result))):
            k = next((j for j in range(k + 1, len(out)) if out[j].text in (",", ".", ";", "!", "?")), len(out))
            continue  # "Given the open laptop, ...", "Got a tray of croissants going in.", "..., I just want a warm rinse"
        if [t.text for t in out[k:k + 3]] in (["no", "other", "part"], ["no", "other", "parts"], ["nothing", "else", "moves"]):
            k = next((j for j in range(k + 1, len(out)) if out[j].text in (",", ".", ";", "!", "?")), len(out))
            continue  # "... and no other part moves": it does not, unless asked
        if out[k].text in ("a", "an") and k and out[k - 1].text == "," and (end := next((j for j in range(k + 1, len(out)) if out[j].is_sentence_end), len(out))) and (
                out[end - 1].text in _DESCRIBED_AS and not any(t.number is not None or kind_of_word(t.text) is not None for t in out[k:end])):
            k = end
            continue  # "She taps the top-left key — a quiet, almost tentative first move.": the step described, nothing more
        if out[k].text in ("that's", "which's") and [t.text for t in out[k + 1:k + 2]] == ["what"] and k and out[k - 1].text in (",", ";", ":"):
            k = next((j for j in range(k + 2, len(out)) if out[j].text in (",", ".", ";", "!", "?")), len(out))
            continue  # "- that's what sets the turntable going -": how it works, said beside the steps
        if out[k].text == "possibly" and k and out[k - 1].text in ("can", "could", "will", "would"):
            k += 1
            continue  # "as far as it can possibly go": as far as it can go
        if out[k].text == "like" and k + 1 < len(out) and (out[k + 1].number is not None or out[k + 1].text in _LIKE_AMOUNTS) and k and (
                not out[k - 1].is_punct):
            k += 1
            continue  # "open the drawer like halfway": about halfway
        if out[k].text == "no" and k + 1 < len(out) and out[k + 1].text in _MOTION_NOUNS and k and out[k - 1].text in (",", ";"):
            k = next((j for j in range(k + 2, len(out)) if out[j].text in (",", ".", ";", "!", "and", "then")), len(out))
            continue  # "..., no rotation, no change in height": the motion asked is pure already
        if out[k].text == "about" and k + 2 < len(out) and out[k + 1].text == "to" and k and out[k - 1].text in _ABOUT_TO:
            start = k - 1 if out[k - 1].text in ("it's", "they're") else k - 2 if k > 1 and out[k - 2].text in ("it", "they") else k - 1
            end = next((j for j in range(k + 2, len(out)) if out[j].text in _CLAUSE_ENDS), len(out))
            del result[len(result) - (k - start):]
            k = end
            continue
        result.append(out[k])
        k += 1
    return result if result else out
