"""``interaction.json``: where an external actor touches the object, as pydantic models.

Input: :class:`ActuatedPhase` records, one per phase that needs an actor (a control
actuated, a part moved by hand, the whole object pushed). Effects that follow a control
(a lid opened by a pedal) are not actuated phases. Output: :class:`InteractionDocument`.

Frame: the URDF world (the root link's frame at rest, +Z up), metres, seconds.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import BaseModel, ConfigDict, Field, model_validator

ActuationKind = Literal["control_actuation", "direct_manipulation", "whole_object_push"]
Action = Literal["push", "pull", "turn"]
ContactFeature = Literal["handle", "free_edge", "tread", "face_centre", "rear_face"]
Time = Annotated[float, Field(ge=0.0, allow_inf_nan=False)]
Finite = Annotated[float, Field(allow_inf_nan=False)]
Vector3 = tuple[Finite, Finite, Finite]


class _Frozen(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


class ActuatedPhase(_Frozen):
    """A phase in which an external actor moves ``link``.

    ``joint`` is the movable joint that moves it (``None`` for a whole-object push, which
    moves the base). ``action`` may be given by the caller (the causal contract's verb);
    when ``None`` it is decided from the geometry and the motion.
    """

    link: str
    joint: str | None
    t0: Time
    t1: Time
    kind: ActuationKind
    action: Action | None = None

    @model_validator(mode="after")
    def _ordered(self) -> ActuatedPhase:
        if self.t1 <= self.t0:
            raise ValueError(f"t1 ({self.t1}) must be greater than t0 ({self.t0})")
        if (self.joint is None) != (self.kind == "whole_object_push"):
            raise ValueError("joint is None exactly for a whole_object_push")
        return self


class PathSample(_Frozen):
    """The contact point at one frame: world position (m) and the link's world orientation."""

    time_s: Time
    position: Vector3
    orientation_xyzw: tuple[Finite, Finite, Finite, Finite]


class Interaction(_Frozen):
    """One actuated phase: what to touch, where, and along which path.

    Attributes
    ----------
    link, joint : the link touched and the joint it moves (``None``: the base, a push)
    t0, t1 : the phase's time window (s)
    contact_point : world position at the frame at or just before ``t0`` (on the link's surface)
    contact_normal : outward unit surface normal there (world)
    path : the contact point at every frame from the one at or before ``t0`` to the one at
        or after ``t1``, moving rigidly with the link
    action : push, pull or turn
    direction : unit world vector at ``t0``: how the contact point starts to move (push,
        pull), or the signed rotation axis by the right-hand rule (turn)
    kind : control_actuation, direct_manipulation or whole_object_push
    feature : which part of the mesh was chosen (handle, free_edge, tread, face_centre, rear_face)
    """

    link: str
    joint: str | None
    t0: Time
    t1: Time
    contact_point: Vector3
    contact_normal: Vector3
    path: list[PathSample]
    action: Action
    direction: Vector3
    kind: ActuationKind
    feature: ContactFeature


class InteractionDocument(_Frozen):
    """The content of ``interaction.json``."""

    frame: Literal["urdf_world"] = "urdf_world"
    interactions: list[Interaction] = Field(default_factory=list)
    notes: list[str] = Field(default_factory=list)
    """Actuated phases that got no record, and why (e.g. a link without geometry)."""

    def dumps(self) -> str:
        return self.model_dump_json(indent=2)
