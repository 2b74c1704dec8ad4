"""Resolve a benchmark annotation's ``subject`` (joint, link or ``base``) against an asset.

A joint name means that joint; a link name means its parent joint (the object's base when
the link is the root link); ``base`` means the whole object. A name that is both a joint
and a link is read as the joint.
"""

from __future__ import annotations

from dataclasses import dataclass

from app.engine.asset.model import ArticulatedAsset
from app.engine.errors import MetricError
from app.engine.metrics.annotation import BASE_SUBJECT

MAX_LISTED_NAMES = 12
"""How many known names an error message lists."""


@dataclass(frozen=True)
class Subject:
    """A resolved subject: ``joint`` is ``None`` when the subject is the base."""

    name: str
    joint: str | None

    @property
    def is_base(self) -> bool:
        return self.joint is None


def _listing(names: tuple[str, ...]) -> str:
    shown = ", ".join(names[:MAX_LISTED_NAMES])
    return shown + (", ..." if len(names) > MAX_LISTED_NAMES else "")


def resolve_subject(asset: ArticulatedAsset, subject: str, where: str) -> Subject:
    """Map ``subject`` to a joint of ``asset`` or to the base.

    Raises
    ------
    MetricError
        ``subject`` names no joint, link or ``base`` (the message starts with ``where``).
    """
    if subject == BASE_SUBJECT:
        return Subject(name=subject, joint=None)
    if subject in asset.joints:
        return Subject(name=subject, joint=subject)
    if subject in asset.links:
        parent = asset.parent_joint(subject)
        return Subject(name=subject, joint=None if parent is None else parent.name)
    raise MetricError(
        f"{where}: subject '{subject}' is not a joint, link or '{BASE_SUBJECT}' of asset {asset.name} "
        f"(joints: {_listing(asset.joint_order)}; links: {_listing(asset.link_order)})"
    )


def moved_links(asset: ArticulatedAsset, joints: set[str]) -> set[str]:
    """Links moved by ``joints``: each joint's child and all its descendants.

    Mimic joints whose leader is in ``joints`` move with it, so their subtrees are
    included too (they are the same degree of freedom).
    """
    movers = set(joints)
    changed = True
    while changed:
        followers = {n for n, j in asset.joints.items() if j.mimic is not None and j.mimic.joint in movers}
        changed = not followers <= movers
        movers |= followers
    links: set[str] = set()
    for name in movers:
        links.update(asset.moving_links(name))
    return links
