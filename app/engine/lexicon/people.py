"""Who acts in a scene: people, robot hands, and things or animals that push parts about. None of them is ever a part."""

from __future__ import annotations

_PEOPLE = frozenset({"character", "actor", "person", "user", "operator", "chef", "cook", "kid", "child", "man", "woman", "narrator", "thief",
                     "burglar", "guard", "player", "hero", "villain", "customer", "worker", "technician", "mechanic", "nurse", "waiter", "janitor", "guy",
                     "girl", "boy", "owner", "tenant", "mom", "dad", "grandma", "grandpa", "mum", "granny", "grandad", "grandfather", "grandmother", "wife",
                     "husband", "son", "daughter", "sister", "brother", "flatmate", "roommate", "friend", "partner", "boss", "detective", "spy", "robber",
                     "intruder", "officer", "scientist", "visitor", "guest", "tourist", "client", "patient", "colleague",
                     "teacher", "magician", "assistant", "butler", "maid", "cleaner", "inspector", "landlord", "landlady", "host", "stranger",
                     "mother", "father", "uncle", "aunt", "baby", "toddler", "teenager", "student", "guide", "curator", "tester"})
PERSON_NOUNS = _PEOPLE | frozenset(f"{w}s" for w in _PEOPLE) | frozenset(
    {"children", "men", "women", "people", "folks", "effector", "end-effector", "manipulator", "gripper",
     "he", "she", "he'd", "she'd", "he's", "she's", "he'll", "she'll", "him"})
"""People (and robot hands) in a scene: never a part ("the thief yanks the lower drawer open": the drawer; "visitors often ask
how it was secured")."""
CAUSER_NOUNS = frozenset({"draft", "draught", "wind", "breeze", "gust", "steam", "pressure", "cat", "dog", "puppy", "kitten", "gravity",
                          "vibration", "earthquake", "tremor"})
"""Things and animals that move a part in a scene ("a draft catches the door and pushes it partway open", "the steam keeps
bumping the lid up"): like a person, the subject of what happens, never a part."""
ACTOR_NOUNS = PERSON_NOUNS | CAUSER_NOUNS
AGENT_NOUNS = PERSON_NOUNS | CAUSER_NOUNS | frozenset({"robot", "arm", "hand", "hands", "thumb", "finger", "fingers", "foot", "feet", "camera", "viewer",
                                        "audience"})
"""Who (or what) acts on the object in a scene: a clause whose subject this is and that names no part ("then the arm lets
go") says nothing to animate."""
