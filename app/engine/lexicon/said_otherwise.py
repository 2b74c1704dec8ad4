"""Words said another way: chat shorthand, adverbs that say what a particle says, and phrases that mean exactly what a
word the lexicon knows means. Each is replaced before the words are read."""

from __future__ import annotations

from collections.abc import Mapping
from types import MappingProxyType

SHORTHAND: Mapping[str, str] = MappingProxyType({
    # text-speak and chat abbreviations -> the word they stand for
    "till": "until", "til": "until", "'til": "until", "u": "you", "ur": "your", "cn": "can", "cud": "could", "wud": "would", "r": "are", "thx": "thanks", "thnx": "thanks", "thanx": "thanks", "tnx": "thanks", "ty": "thanks", "tho": "though",
    "b4": "before", "n": "and", "w": "with", "w/": "with", "abt": "about", "approx": "about", "approx.": "about", "ca.": "about", "ya": "you", "yer": "your", "btw": "by the way", "rn": "now",
    "asap": "quickly", "gotta": "need to", "hafta": "need to", "it'll": "it will", "it'l": "it will", "itll": "it will", "they'll": "they will", "thatll": "that will", "msec": "ms", "secs": "seconds", "mins": "minutes", "degs": "degrees", "deg.": "degrees", "plz": "please",
    "thats": "that's", "theres": "there's", "whats": "what's", "isnt": "isn't", "didnt": "didn't", "youre": "you're",
    "rite": "right", "lft": "left", "btn": "button", "btns": "buttons", "seq": "sequence", "fwd": "forward", "bwd": "backward", "rev": "revolution", "revs": "revolutions",
})
"""Abbreviations typed in chats and on phones: replaced before spelling correction (too short to correct)."""
ADVERB_PARTICLES: Mapping[str, str] = MappingProxyType({"outward": "out", "outwards": "out", "inward": "in", "inwards": "in"})
"""Adverbs that say what a particle says ("push the sash outward" = push it out)."""
SAME_MEANING: Mapping[str, str] = MappingProxyType({
    "shall": "must", "shan't": "mustn't", "apart_from": "except", "except_for": "except", "aside_from": "except", "other_than": "except", "last_of_all": "finally", "a_tiny_bit": "a_little_bit", "a_wee_bit": "a_little_bit",
    "a_teeny_bit": "a_little_bit",
    "'s_got": "has", "'s_been": "has", "has_got": "has", "have_got": "have", "'ve_got": "have", "i_only_want": "i_want", "i_just_want": "i_want",
    "i_really_want": "i_want", "i_only_need": "i_need", "i_just_need": "i_need", "i_really_need": "i_need",
    "let_it_lie": "rest", "let_them_lie": "rest", "let_it_sit": "rest",  # "just let it lie against the rim": it stays there
    "which_means_that": ";", "which_means": ";", "that_means_that": ";", "that_means": ";", "this_means_that": ";", "this_means": ";",
    "gust_of_wind": "gust", "puff_of_wind": "gust", "blast_of_wind": "gust", "gust_of_air": "gust", "rush_of_air": "gust"})
"""Words that say exactly what a word the lexicon knows says (the modal of specifications: "the lid shall be opened"):
replaced without a note, as no guess is made."""
WHILE_PHRASES = frozenset({"the_whole_time", "the_entire_time", "all_the_while", "all_the_time", "for_as_long_as", "the_whole_while"})
"""Phrases that say "while" when a clause follows ("keep the door open the whole time the plate is going round"); at the end
of a clause ("hold it open the whole time") they say only how long."""
