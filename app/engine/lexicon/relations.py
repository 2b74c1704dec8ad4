"""Words that place a part relative to another part or to the viewer ("the key right above the 5", "the knob to the
left of the dial", "the dial closest to me"), and the prepositions that make a noun a place ("push it along the table")."""

from __future__ import annotations

RELATIONS = {"below": "below", "under": "below", "beneath": "below", "underneath": "below", "above": "above", "over": "above",
             "next_to": "beside", "beside": "beside", "to_the_left": "left", "to_the_right": "right", "left_of": "left", "right_of": "right",
             "nearest": "near", "closest": "near", "nearer": "near", "closer": "near", "furthest": "far", "farthest": "far",
             "farther": "far", "further": "far", "behind": "behind", "in_front_of": "in_front"}
"""A relation word -> how the part sits relative to the one named after it."""
VIEWERS = frozenset({"me", "you", "us", "viewer", "user"})
"""After "closest to" / "furthest from": the viewer, who stands at the front."""
VIEWER_WORDS = frozenset({*VIEWERS, "camera"})
"""The viewer in a direction ("toward me", "the side facing the camera")."""
RELATION_ADVERBS = frozenset({"right", "just", "directly", "immediately", "straight"})
"""Before a relation word, they only sharpen it: "the key directly under the 5"."""
RESTING = frozenset({"sits", "sitting", "rests", "resting", "seated", "perched"})
RELATIVE = frozenset({"that's", "that", "which", "which's", "is", *RESTING})
PLACE_PREPS = frozenset({"on", "off", "onto", "from", "along", "across", "against", "over", "under", "at", "to", "toward", "towards", "into",
                         "in", "by", "near", "beside", "next_to", "on_top_of"})
"""Before a noun, they make it a place ("push it along the table"), not the object itself."""
FRONT_RELATIVE_RELATIONS = frozenset({"left", "right", "behind", "in_front"})
"""Relations read as seen from the object's front ("the knob left of the dial", "the tray behind the door")."""
