"""Where parts sit (as seen from the object's front) and which joint end is closed, open and rest."""

from __future__ import annotations

from pathlib import Path

from support.primitive_assets import box, joint, link, robot, write_asset

from app.engine.asset.layout import asset_layout, direction_name
from app.engine.asset.loader import load_asset


def _chest(tmp_path: Path, drawers: int) -> Path:
    """A tall box with ``drawers`` stacked drawers on its -X face, each labelled "drawer" in semantics.txt."""
    links = [link("body", box((0.5, 1.0, 2.0), xyz=(0.0, 0.0, 1.0)))]
    joints = []
    lines = [f"link_{drawers} heavy body"]
    for index in range(drawers):
        z = 0.25 + index * (1.5 / max(drawers - 1, 1))
        links.append(link(f"link_{index}", box((0.2, 0.9, 0.3), xyz=(0.0, 0.0, 0.0))))
        joints.append(joint(f"joint_{index}", "prismatic", "body", f"link_{index}", xyz=(-0.15, 0.0, z),
                            axis=(-1.0, 0.0, 0.0), limit=(0.0, 0.4)))
        lines.append(f"link_{index} slider drawer")
    urdf = robot(*links, *joints).replace('name="body"', f'name="link_{drawers}"').replace('link="body"', f'link="link_{drawers}"')
    return write_asset(tmp_path / f"chest{drawers}", urdf, {"semantics.txt": "\n".join(lines) + "\n"})


def test_two_drawers_are_upper_and_lower_and_open_outwards(tmp_path: Path) -> None:
    layout = asset_layout(load_asset(_chest(tmp_path, 2)))
    assert direction_name(layout.front) == "-X"
    names = {p.link: p.name for p in layout.parts}
    assert (names["link_0"], names["link_1"]) == ("drawer (lower, link_0)", "drawer (upper, link_1)")
    drawer = next(p for p in layout.parts if p.link == "link_1")
    assert (drawer.vertical, drawer.side, drawer.depth, drawer.joint) == ("top", "center", "front", "joint_1")
    ends = next(j for j in layout.joints if j.joint == "joint_0")
    assert (ends.closed_end, ends.open_end, ends.rest_end, ends.closed, ends.open) == ("lower", "upper", "lower", 0.0, 0.4)


def test_three_and_five_same_label_parts_get_ordered_words(tmp_path: Path) -> None:
    three = {p.link: p.name for p in asset_layout(load_asset(_chest(tmp_path, 3))).parts}
    assert [three[f"link_{i}"] for i in range(3)] == ["drawer (bottom, link_0)", "drawer (middle, link_1)", "drawer (top, link_2)"]
    five = {p.link: p.name for p in asset_layout(load_asset(_chest(tmp_path, 5))).parts}
    assert five["link_4"] == "drawer (top, link_4)" and five["link_3"] == "drawer (2nd from top, link_3)"
    assert five["link_0"] == "drawer (5th from top, link_0)"


def test_four_wheels_are_placed_along_both_axes_as_seen_from_the_front(examples_dir: Path) -> None:
    layout = asset_layout(load_asset(examples_dir / "toy_car"))
    assert direction_name(layout.front) == "+X" and direction_name(layout.right) == "+Y"
    names = {p.link: p.name for p in layout.parts}
    # the car's own left is the viewer's right when facing its front
    assert names["wheel_front_left"] == "wheel (front right, wheel_front_left)"
    assert names["wheel_rear_right"] == "wheel (back left, wheel_rear_right)"
    wheel = next(p for p in layout.parts if p.link == "wheel_front_left")
    assert (wheel.vertical, wheel.side, wheel.depth) == ("bottom", "right", "front")
    axle = next(j for j in layout.joints if j.joint == "wheel_front_left_axle")
    assert (axle.closed, axle.open, axle.rest_end) == (None, None, None)


def test_a_closed_end_at_the_negative_limit_is_read_from_the_geometry(examples_dir: Path) -> None:
    ends = {j.joint: j for j in asset_layout(load_asset(examples_dir / "cabinet")).joints}
    door = ends["door_hinge"]
    assert (door.closed_end, door.open_end, door.rest_end, door.open) == ("upper", "lower", "upper", -1.75)
